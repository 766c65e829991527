#!/usr/bin/env bash
# The main job: a real mesh through the real meshlabserver with our plugin, and a report.
#   bash scripts/main.sh [mesh.off] [script.mlx]
# Default: fandisk.off, geodesic distance from vertex 0 (resources/fast_marching_vertex0.mlx).
# Writes output/<mesh>_geodesic.ply (per-vertex quality = distance, colour ramp) and prints
# MeshLab's log of the run. The plugin is loaded from a staged prefix (build/stage), not /usr.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh" --target filter_geodesic_remesh >/dev/null
build=${BUILD_DIR:-$root/build}
cache=${GEODESIC_REMESH_CACHE:-$HOME/.cache/geodesic-remesh}
mesh=${1:-$cache/meshes/fandisk.off}
script=${2:-$root/resources/fast_marching_vertex0.mlx}
stage="$build/stage"
bash "$root/scripts/stage_meshlab.sh" "$build/filter_geodesic_remesh/libfilter_geodesic_remesh.so" "$stage"
mkdir -p "$root/output"
out="$root/output/$(basename "${mesh%.*}")_geodesic.ply"
rm -f "$out"
echo "== meshlabserver: $(basename "$mesh") -> $out, script $(basename "$script")"
set +e
log=$(cd "$root/output" && xvfb-run -a stdbuf -oL "$stage/bin/meshlabserver" -i "$mesh" -o "$out" -m vq vc sa -s "$script" 2>&1)
rc=$?
set -e
# MeshLab's own log lines of the run (noise filtered out).
echo "$log" | grep -vE "^LOG: |XDG_RUNTIME_DIR|no additional memory|^Loading Plugins|^Total [0-9]+ (filtering|io)|Current Plugins Dir|^$" | sed 's/^/  /'
echo "== exit code $rc"
[ $rc -eq 0 ] && [ -s "$out" ] || { echo "main: meshlabserver failed" >&2; exit 1; }
nv=$(grep -m1 '^element vertex' "$out" | awk '{print $3}')
nf=$(grep -m1 '^element face' "$out" | awk '{print $3}')
echo "== wrote $out: $nv vertices, $nf faces, per-vertex quality (geodesic distance) and colour"
