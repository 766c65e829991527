#!/usr/bin/env bash
# Pictures rendered by MeshLab itself (the README's figures): each PLY is opened in the MeshLab GUI
# on a private virtual X display (Xvfb), the screen is captured (ImageMagick's import) and cropped
# to MeshLab's 3D view at its default window size; several inputs are put side by side.
#   bash scripts/render_meshlab.sh out.png a.ply [b.ply ...]
# MESHLAB (default: the staged build/stage/bin/meshlab, else /usr/bin/meshlab) picks the binary;
# LABELS="left|right" writes a caption under each view.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$1
shift
meshlab=${MESHLAB:-$root/build/stage/bin/meshlab}
[ -x "$meshlab" ] || meshlab=/usr/bin/meshlab
command -v import >/dev/null || sudo apt-get install -y imagemagick >/dev/null
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
IFS='|' read -r -a labels <<<"${LABELS:-}"
views=()
i=0
for ply in "$@"; do
  display=$((90 + RANDOM % 100))
  Xvfb ":$display" -screen 0 1280x960x24 >/dev/null 2>&1 &
  xvfb=$!
  sleep 2
  DISPLAY=":$display" "$meshlab" "$(realpath "$ply")" >/dev/null 2>&1 &
  gui=$!
  sleep 10  # MeshLab opens the mesh and draws it
  DISPLAY=":$display" import -window root "$tmp/screen$i.png"
  kill "$gui" "$xvfb" 2>/dev/null || true
  wait "$gui" "$xvfb" 2>/dev/null || true
  # MeshLab's 3D view in its default 846 x 718 window: 430 x 525 from (2, 73), above the info box.
  convert "$tmp/screen$i.png" -crop 430x525+2+73 +repage "$tmp/view$i.png"
  if [ -n "${labels[$i]:-}" ]; then
    convert "$tmp/view$i.png" -background white -fill black -font DejaVu-Sans -pointsize 16 label:"${labels[$i]}" -gravity center \
      -append "$tmp/view$i.png"
  fi
  views+=("$tmp/view$i.png")
  i=$((i + 1))
done
convert "${views[@]}" +append "$out"
echo "wrote $out"
