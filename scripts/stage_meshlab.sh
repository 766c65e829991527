#!/usr/bin/env bash
# Stages a MeshLab prefix that loads a freshly built plugin, without touching /usr:
#   STAGE/bin/{meshlab,meshlabserver}                       copies of the system binaries
#   STAGE/lib/x86_64-linux-gnu/meshlab/libmeshlab-common.so  link to the system library
#   STAGE/lib/x86_64-linux-gnu/meshlab/plugins/*.so          links to the system plugins + ours
# MeshLab finds plugins in <bindir>/../lib/x86_64-linux-gnu/meshlab/plugins; the binaries must be
# copies (a symlink resolves to /usr/bin and loads the system plugins only).
# Usage: stage_meshlab.sh <plugin.so> <stage-dir>
set -euo pipefail
plugin=$1
stage=$2
sys=/usr/lib/x86_64-linux-gnu/meshlab
[ -f "$plugin" ] || { echo "stage_meshlab.sh: no plugin at $plugin" >&2; exit 1; }
[ -x /usr/bin/meshlabserver ] || { echo "stage_meshlab.sh: MeshLab is not installed (run scripts/setup.sh)" >&2; exit 1; }
rm -rf "$stage"
mkdir -p "$stage/bin" "$stage/lib/x86_64-linux-gnu/meshlab/plugins"
cp /usr/bin/meshlabserver /usr/bin/meshlab "$stage/bin/"
ln -s "$sys/libmeshlab-common.so" "$stage/lib/x86_64-linux-gnu/meshlab/"
for f in "$sys"/plugins/*.so; do
  [ "$(basename "$f")" = "$(basename "$plugin")" ] || ln -s "$f" "$stage/lib/x86_64-linux-gnu/meshlab/plugins/"
done
cp "$plugin" "$stage/lib/x86_64-linux-gnu/meshlab/plugins/"
