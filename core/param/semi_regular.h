// Semi-regular remeshing (paper §4.1, Fig. 8): the base domain's triangles subdivided 1-to-4
// `levels` times and mapped back onto the input through the geodesic barycentric
// parameterisation.
//
//   input --parameterizeOverBase (geodesic_parameterization.h)--> pieces mapped onto base triangles
//         --per base triangle, the points (a, b) / 2^levels of its domain:
//             corners: the base vertices;
//             sides: the point of the path at that fraction of its arc length (one point for
//               both triangles of the edge: no crack);
//             inside: the piece's face whose image holds the point, and the point's
//               barycentric coordinates there, on the input--> points on the input
//         --2^levels x 2^levels triangles per base triangle, oriented as it is-->
//         --tangential relaxation on the input (surface_relaxation.h, no flips: the
//           connectivity stays)--> SemiRegularResult
//
// Subdivision connectivity by construction: every vertex that is not a base vertex has valence 6
// (4 on the input's boundary); the output has the base's topology, which is the input's.
// Cost: parameterizeOverBase, then O(output + pieces' faces) for the point location.
#pragma once

#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"
#include "core/param/base_pieces.h"

namespace gr {

struct SemiRegularParams {
  BaseDomainParams base;  ///< base vertices (500), centroidal iterations, seed
  int levels = 3;         ///< 1-to-4 subdivisions of each base triangle, 0..kMaxLevels
  /// Rounds of tangential relaxation on the input after the mapping (0 = the parameterisation's
  /// points as they are): the points near the base edges, where the pieces' maps meet with
  /// different stretch, move toward their neighbours' mean, never lowering the smallest angle
  /// around them. 500 base vertices, 3 levels, smallest angle with 6 / 8 / 10 / 12 rounds: bunny00
  /// 26.9 / 28.6 / 28.6 / 28.6 degrees, armadillo 14.6 / 16.5 / 17.7 / 19.7 (about 15 ms a round
  /// on bunny00).
  int relaxationRounds = 10;
  /// Measure the two-sided Hausdorff distance to the input (SemiRegularResult::hausdorff), at
  /// surfaceDistance's samples (measure/) by remeshDistances (remesh/remesh_distance.h): each
  /// sample bounded near where it lies, the largest made exact.
  bool measureDistance = true;
  static constexpr int kMaxLevels = 6;
  static constexpr double kMaxFaces = 50e6;  ///< larger outputs are refused before any work
};

struct SemiRegularResult {
  /// The semi-regular mesh, oriented like the input: vertices 0 .. baseVertices - 1 are the base
  /// vertices, then the points of the base edges, then those inside the base triangles.
  TriMesh mesh;
  std::vector<SurfacePoint> origin;  ///< per output vertex, its point on the input (its faces as given)
  int baseVertices = 0;
  int baseTriangles = 0;
  int addedBaseVertices = 0;  ///< by the base domain's repair
  int splitEdges = 0;         ///< input edges split by the cut
  int heronPieces = 0;        ///< pieces mapped by Heron's coordinates
  int smoothedPieces = 0;     ///< by Heron's, with a band around their folds by mean value coordinates
  int repairedPieces = 0;     ///< pieces mapped by mean value coordinates (Heron's folded)
  int relaxationMoves = 0;
  int reorientedFaces = 0;  ///< input faces turned to agree with their neighbours
  /// Two-sided (measureDistance): from the output's vertices, edge midpoints and face centroids to
  /// the input, and from the input's vertices to the output.
  double hausdorff = 0.0;
};

/// Fails with InvalidInput on levels outside 0..kMaxLevels or an output over kMaxFaces faces
/// (both before any work), and as parameterizeOverBase does.
Expected<SemiRegularResult> semiRegularRemesh(const TriMesh& input, const SemiRegularParams& params = {},
                                              Progress progress = {});

}  // namespace gr
