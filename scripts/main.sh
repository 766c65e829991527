#!/usr/bin/env bash
# The main job: a real mesh through the real meshlabserver with our plugin, and a report.
#   bash scripts/main.sh [mesh.off]
# Runs three scripts on the mesh (default fandisk.off), each writing a PLY into output/:
#   resources/fast_marching_vertex0.mlx     -> <mesh>_geodesic.ply  (distance from vertex 0 in quality, colour ramp)
#   resources/uniform_remesh_10pct.mlx      -> <mesh>_remesh.ply    (geodesic uniform remeshing, new layer)
#   resources/adaptive_curvature_10pct.mlx  -> <mesh>_adaptive.ply  (curvature-adaptive remeshing, new layer)
# (the remeshing scripts ask for 647 vertices: 10% of fandisk), then the distance from vertex 0 on
# cheese.off, a CAD-like mesh of slivers: the log says its distances are exact (window propagation)
#   resources/fast_marching_vertex0.mlx     -> cheese_geodesic.ply
# and back on the mesh: resources/segmentation_50.mlx -> <mesh>_segmentation.ply (regions in face
#   quality and colour), resources/texture_atlas.mlx -> <mesh>_atlas.obj (+ .mtl and the
#   checkerboard <mesh>_geodesic_atlas.png: wedge texture coordinates of the geodesic atlas), and
#   the same atlas as <mesh>_atlas.ply for MeshLab; if Blender is installed, it opens the OBJ
#   (scripts/blender_open_obj.py: faces, UV layers, texture); resources/semi_regular_500_l3.mlx
#   -> <mesh>_semi_regular.ply and bunny00_semi_regular.off (semi-regular remeshes: 500 base
#   vertices, 3 levels), resources/geodesic_barycentric_100.mlx -> <mesh>_barycentric.ply (the
#   input cut into disks, one texture tile per base triangle, checkerboard
#   <mesh>_geodesic_barycentric.png)
# and prints MeshLab's log of each run. The plugin is loaded from a staged prefix (build/stage),
# not from /usr.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh" --target filter_geodesic_remesh >/dev/null
build=${BUILD_DIR:-$root/build}
cache=${GEODESIC_REMESH_CACHE:-$HOME/.cache/geodesic-remesh}
mesh=${1:-$cache/meshes/fandisk.off}
stage="$build/stage"
bash "$root/scripts/stage_meshlab.sh" "$build/filter_geodesic_remesh/libfilter_geodesic_remesh.so" "$stage"
mkdir -p "$root/output"
name=$(basename "${mesh%.*}")

run() {  # run <script.mlx> <output.ply> <what the output holds> [input mesh, default $mesh] [saved attributes]
  local script=$1 out=$2 what=$3
  local mesh=${4:-$mesh}
  local mask=${5:-vq vc sa}  # "none": no -m (positions and faces only)
  local maskArgs=(-m $mask)
  [ "$mask" = none ] && maskArgs=()
  rm -f "$out"
  echo "== meshlabserver: $(basename "$mesh") -> $out, script $(basename "$script")"
  set +e
  local log
  log=$(cd "$root/output" && xvfb-run -a stdbuf -oL "$stage/bin/meshlabserver" -i "$mesh" -o "$out" "${maskArgs[@]}" -s "$script" 2>&1)
  local rc=$?
  set -e
  # MeshLab's own log lines of the run (noise filtered out). meshlabserver prints our progress
  # labels with no line break, so a run of them can prefix the next log line: a label directly
  # followed by a letter (the next label or log line, with no space) is cut.
  echo "$log" | grep -vE "^LOG: |XDG_RUNTIME_DIR|no additional memory|^Loading Plugins|^Total [0-9]+ (filtering|io)|Current Plugins Dir|^$" |
    sed -E ':a; s/^(Farthest point sampling|Fast marching|intrinsic Delaunay refinement|Geodesic Delaunay repair|Relaxation|Curvature|Surface distance|Geodesic Lloyd|Texture atlas: flattening the charts|Texture atlas: packing|Cutting the surface along the base edges|Geodesic distances to the base vertices|Mapping the pieces onto their base triangles|Relaxing the semi-regular mesh on the input|Measuring the distance to the input)([A-Za-z])/\2/; ta' | sed 's/^/  /'
  echo "== exit code $rc"
  [ $rc -eq 0 ] && [ -s "$out" ] || { echo "main: meshlabserver failed" >&2; exit 1; }
  local nv nf
  if [[ $out == *.obj ]]; then
    nv=$(grep -c '^v ' "$out")
    nf=$(grep -c '^f ' "$out")
  elif [[ $out == *.off ]]; then
    read -r nv nf _ < <(sed -n 2p "$out")
  else
    nv=$(grep -a -m1 '^element vertex' "$out" | awk '{print $3}')
    nf=$(grep -a -m1 '^element face' "$out" | awk '{print $3}')
  fi
  echo "== wrote $out: $nv vertices, $nf faces; $what"
  echo
}
run "$root/resources/fast_marching_vertex0.mlx" "$root/output/${name}_geodesic.ply" \
    "per-vertex quality = geodesic distance from vertex 0, colour ramp"
run "$root/resources/uniform_remesh_10pct.mlx" "$root/output/${name}_remesh.ply" \
    "geodesic uniform remeshing, colour and quality carried from the input"
run "$root/resources/adaptive_curvature_10pct.mlx" "$root/output/${name}_adaptive.ply" \
    "curvature-adaptive geodesic remeshing (vertices gather on sharp edges)"
run "$root/resources/fast_marching_vertex0.mlx" "$root/output/cheese_geodesic.ply" \
    "distance from vertex 0 on cheese.off (slivers: exact geodesic distances by window propagation)" \
    "$cache/meshes/cheese.off"
run "$root/resources/segmentation_50.mlx" "$root/output/${name}_segmentation.ply" \
    "50 regions of a geodesic centroidal tessellation, each a disk: region in face quality, one colour per region" \
    "$mesh" "fq fc"
# The atlas writes its checkerboard PNG next to the mesh it reads: a copy of the mesh in output/.
atlas_input="$root/output/${name}.${mesh##*.}"
cp "$mesh" "$atlas_input"
run "$root/resources/texture_atlas.mlx" "$root/output/${name}_atlas.obj" \
    "geodesic texture atlas: per-wedge UVs, OBJ + MTL + checkerboard PNG (output/${name}_geodesic_atlas.png)" \
    "$atlas_input" "wt"
# The same as PLY (texture named in a header comment): what MeshLab 2020.09 opens (its OBJ importer
# aborts on OBJ files, its own included).
run "$root/resources/texture_atlas.mlx" "$root/output/${name}_atlas.ply" \
    "geodesic texture atlas as PLY with per-face texture coordinates, for MeshLab" "$atlas_input" "wt"
run "$root/resources/semi_regular_500_l3.mlx" "$root/output/${name}_semi_regular.ply" \
    "semi-regular remesh (500 base vertices, 3 levels): every vertex off the base vertices has valence 6" \
    "$mesh" "vc vq"
run "$root/resources/semi_regular_500_l3.mlx" "$root/output/bunny00_semi_regular.off" \
    "semi-regular remesh of bunny00 (the README's picture: scripts/color_semi_regular.py)" \
    "$cache/meshes/bunny00.off" none
run "$root/resources/geodesic_barycentric_100.mlx" "$root/output/${name}_barycentric.ply" \
    "geodesic barycentric parameterisation: base triangle in vertex quality and colour, one tile per base triangle (output/${name}_geodesic_barycentric.png)" \
    "$atlas_input" "wt vq vc"
# Blender (if installed; not needed otherwise) opens the atlas's OBJ + MTL + PNG.
if command -v blender > /dev/null 2>&1; then
  opened=$(blender -b --python "$root/scripts/blender_open_obj.py" -- "$root/output/${name}_atlas.obj" 2>&1 |
    sed -n 's/^BLENDER_OPENED //p')
  echo "== Blender 3.4 opens output/${name}_atlas.obj: ${opened:-FAILED}"
else
  echo "== Blender not installed: the check that it opens output/${name}_atlas.obj is skipped"
fi
