// Each input vertex in a triangle of a base triangulation of the same surface (the geodesic remesh,
// paper §4.1), with its geodesic barycentric coordinates there (geodesic_barycentric.h).
//
//   input, base triangles over base vertices that are input vertices
//     --per base vertex a: one front on the input, alone, up to twice its longest straight base
//       edge--> d(x, a) for the input vertices x around a; the base edges' lengths
//     --per input vertex x: the base triangles whose three corners' fronts reached x; in each,
//       Heron's weights and excess from the six lengths--> the triangle of least excess
//
// On a plane the least excess is the triangle that holds x (excess 0 there, > 0 in the others),
// up to the fronts' error near the base edges. Which triangle a vertex on or near a base edge
// goes to decides nothing here: the map of each piece to its base triangle, the tiling and its
// injectivity are the next stage (issue 21). Cost: one front per base vertex over its star of
// base triangles (about 6 times the input, whatever the base count), O(candidates) Heron
// evaluations per input vertex.
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct BaseCoordinatesResult {
  /// Per input vertex, its base triangle; -1 where no triangle had all six lengths (its corners'
  /// fronts stop at twice their longest straight base edge: a base edge whose geodesic is longer
  /// than that, on a surface folded between its ends, has no length).
  std::vector<int> triangle;
  std::vector<Vec3> weights;       ///< per input vertex, of the triangle's corners (in its order)
  std::vector<double> excess;      ///< per input vertex, Heron's excess there (0 inside a flat triangle)
  std::vector<double> edgeLength;  ///< per base corner c (3 t + k): the geodesic length of the edge opposite it
  int unassigned = 0;              ///< input vertices in faces left at -1
};

/// `base`: triangles over base vertices 0..B-1; `baseVertex[i]`: the input vertex base vertex i is
/// (distinct). Distances are the uniform metric's on `input`. Fails (InvalidInput) on an empty base,
/// a base vertex out of range or repeated, or a base corner out of range.
Expected<BaseCoordinatesResult> baseCoordinates(const TriMesh& input, const std::vector<Tri>& base,
                                                const std::vector<int>& baseVertex);

}  // namespace gr
