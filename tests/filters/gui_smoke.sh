#!/usr/bin/env bash
# GUI smoke test: the real MeshLab GUI under Xvfb, with the staged plugin, opens a mesh and
# maps our plugin; a screenshot of the screen is kept as a test artefact.
# Usage: gui_smoke.sh <stage-dir> <mesh> <screenshot.png>
set -euo pipefail
stage=$1
mesh=$2
shot=$3
plugin="$stage/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_geodesic_remesh.so"
mkdir -p "$(dirname "$shot")"
rm -f "$shot"
inner=$(mktemp)
cat >"$inner" <<'INNER'
set -u
stage=$1; mesh=$2; shot=$3; plugin=$4
"$stage/bin/meshlab" "$mesh" >"$shot.log" 2>&1 &
pid=$!
mapped=0; window=0
for _ in $(seq 1 60); do
  sleep 1
  kill -0 $pid 2>/dev/null || break
  grep -q "$plugin" /proc/$pid/maps 2>/dev/null && mapped=1
  xwininfo -root -tree 2>/dev/null | grep -qi '"MeshLab' && window=1
  [ $mapped -eq 1 ] && [ $window -eq 1 ] && break
done
sleep 3   # let the first frame render
import -window root "$shot" 2>/dev/null
alive=0; kill -0 $pid 2>/dev/null && alive=1
xwininfo -root -tree 2>/dev/null | grep -i '"MeshLab' | head -n 3
kill $pid 2>/dev/null; wait $pid 2>/dev/null
echo "alive=$alive mapped=$mapped window=$window"
INNER
result=$(xvfb-run -a -s "-screen 0 1280x1024x24" bash "$inner" "$stage" "$mesh" "$shot" "$plugin")
rm -f "$inner"
echo "$result"
fail=0
echo "$result" | grep -q "alive=1" || { echo "FAIL: meshlab exited early (log: $shot.log)"; fail=1; }
echo "$result" | grep -q "mapped=1" || { echo "FAIL: meshlab did not map $plugin"; fail=1; }
echo "$result" | grep -q "window=1" || { echo "FAIL: no MeshLab window"; fail=1; }
[ -s "$shot" ] || { echo "FAIL: no screenshot"; fail=1; }
if [ -s "$shot" ]; then
  # A blank screen has zero spread of intensities.
  spread=$(convert "$shot" -colorspace Gray -format '%[fx:standard_deviation]' info:)
  echo "screenshot $shot, intensity standard deviation $spread"
  awk -v s="$spread" 'BEGIN { exit !(s > 0.01) }' || { echo "FAIL: the screenshot is blank"; fail=1; }
fi
exit $fail
