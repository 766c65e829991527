#!/usr/bin/env bash
# Issue 17's A/B: geodesicDistance() of this tree against fastMarching() of 0eaa430 (before the
# issue), the same driver (bench/ab/geodesic_distance_ab.cpp) linked to each core, the two
# binaries alternated. Needs a built tree (scripts/build.sh) for the new core.
#   bash scripts/ab_geodesic_distance.sh [mesh.off] [subdivisions] [alternations] [calls]
#   bash scripts/ab_geodesic_distance.sh bunny00.off 0 20 15
#   bash scripts/ab_geodesic_distance.sh armadillo.off 3 5 3
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${BUILD_DIR:-$root/build}"
meshes="${GR_MESH_DIR:-$HOME/.cache/geodesic-remesh/meshes}"
vcg="$(find "$HOME/.cache/geodesic-remesh" -maxdepth 3 -name vcglib -type d | head -1)"
mesh="$meshes/${1:-bunny00.off}"
levels="${2:-0}" alternations="${3:-20}" calls="${4:-15}"
old="${AB_OLD_TREE:-/tmp/gr-ab-0eaa430}"
if [ ! -f "$old/build/core/libgr_core.a" ]; then
  [ -d "$old" ] || git -C "$root" worktree add -f "$old" 0eaa430 >/dev/null
  cmake -S "$old" -B "$old/build" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  cmake --build "$old/build" --target gr_core -j "$(nproc)" >/dev/null
fi
flags=(-std=c++17 -O2 -DNDEBUG -isystem "$vcg" -isystem /usr/include/eigen3)
g++ "${flags[@]}" -I"$old" "$root/bench/ab/geodesic_distance_ab.cpp" "$old/build/core/libgr_core.a" -lpthread \
  -o "$build/ab_old"
g++ "${flags[@]}" -DGR_AB_NEW -I"$root" "$root/bench/ab/geodesic_distance_ab.cpp" "$build/core/libgr_core.a" \
  -lpthread -o "$build/ab_new"
for _ in $(seq 1 "$alternations"); do
  "$build/ab_old" "$mesh" "$levels" "$calls"
  "$build/ab_new" "$mesh" "$levels" "$calls"
done
