// Geodesic LLE flattening of a disk with a Nyström extension (Peyré & Cohen 2006, §4.3): a map
// of a patch to the plane without a linear system over all its vertices.
//
//   patch (a topological disk) --farthestPointSampling, its first B/16 samples chosen in 3D
//     (farthestPointsIn3d: the greedy sampling's first fronts are its dearest)--> B base points;
//     bases one edge inside the boundary move onto it (the boundary vertices beside them would
//     see them an edge away and the other bases far on one side, and fold)
//     --B fronts (FastMarcher), each stopped at 2.3 covering radii of the sampling (farther where a
//       vertex sees fewer than 4 bases)--> d(v, base j) for the bases near each vertex v; between
//       bases, the fronts' own values, else the least d(v, i) + d(v, j) over the vertices both
//       reached, else shortest paths through the bases' graph
//     --per base i: its K nearest bases, the local Gram matrix of the geodesic distances
//       G_jk = (d_ij^2 + d_ik^2 - d_jk^2) / 2, weights w from (G + r tr(G)/K I) w = 1, sum w = 1
//       (Roweis & Saul 2000)--> W (B x B)
//     --the 2nd and 3rd eigenvectors of (I - W)^T (I - W) (Eigen, dense, B x B)--> y_1..y_B
//     --a 2x2 metric correction S (least squares: (y_i - y_j)^T S (y_i - y_j) = d_ij^2 over the
//       neighbour pairs; LLE's own normalisation makes the embedding's covariance the identity,
//       which squashes an elongated patch), then 60 rounds of stress majorisation on the same
//       pairs (LLE gives the layout's shape, not its lengths) --> base points in the plane
//     --Nyström (Bengio et al. 2003): each vertex's weights on its K nearest bases, from the same
//       distances (regulariser 0.1: a vertex's distances carry the fronts' error at the scale of
//       an edge), and uv_v = sum_j w_j y_j; then 20 rounds of harmonic smoothing (positive
//       cotangent weights) of the vertices that are neither bases nor on the boundary
//     --UV triangles turned over or of zero area, on at most 20% of the faces: their vertices
//       (and every 5 rounds a ring more) move to the mean of their neighbours' UVs, up to 60
//       rounds; the map is then checked one-to-one (uv_map_quality.h: no fold, no branch point,
//       a simple boundary). If it is not, the whole patch is mapped again by Tutte's embedding
//       (Floater's mean-value weights, positive; the boundary on a circle by arc length),
//       one-to-one by Floater's theorem; the result says so.
//     --with the Free boundary, `arapRounds` rounds of as-rigid-as-possible relaxation of that map
//       (arap_relaxation.h), kept one-to-one by a line search: LLE gives the layout, ARAP the
//       lengths (and Tutte's circle becomes the chart's own shape)
//
// Measured (tests/flatten): a plane and a cylinder cut open flatten with L2 stretch 1.0000 (1.008
// and 1.002 without ARAP); a 60-degree cap of 10k vertices 1.0014 without Tutte (1.012 without
// ARAP, 1.251 with the regulariser 1e-3 and no stress, smoothing or ARAP step).
//
// Boundary: Free (LLE's own) or Circle (Tutte's embedding from the start). Cost: B fronts over
// about a tenth of the patch each (at most B whole fronts, O(B V log V)), the 3D start O(B V / 16),
// the Nyström extension
// O(V K^3), the eigenproblem and the bases' graph O(B^3); the Tutte fallback one sparse solve; the
// ARAP relaxation one sparse factorisation and a back-substitution per round.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

using Vec2 = Eigen::Vector2d;

enum class LleBoundary { Free, Circle };

struct LleFlatteningParams {
  int basePoints = 100;  ///< B, farthest-point samples of the patch (the paper's 100); >= 4
  int neighbours = 8;    ///< K nearest base points per reconstruction, 3 <= K < B
  /// Tikhonov regulariser of the bases' local Gram matrices, relative to their trace / K (Roweis &
  /// Saul use 1e-3 when K exceeds the dimension, 2 here; 0.1 measured better on bunny00's charts:
  /// fewer folds, stretch 1.70 -> 1.04 over the atlas).
  double regularisation = 0.1;
  /// The same for the Nyström weights of the other vertices: larger than the bases' because a
  /// vertex's geodesic distances carry the fronts' error at the scale of one edge, which a small
  /// regulariser turns into UV jitter of that scale, hence folds.
  double extensionRegularisation = 0.1;
  /// Rounds of stress majorisation of the bases' layout on their K-neighbour distances after LLE
  /// (0 = LLE's layout with the 2x2 correction only).
  int stressRounds = 60;
  /// Rounds of harmonic smoothing of the extended UVs, the base points fixed (0 = the Nyström
  /// values as they are).
  int smoothingRounds = 20;
  /// Rounds of as-rigid-as-possible relaxation of the final map with the Free boundary (LLE's or
  /// Tutte's fallback; arap_relaxation.h: kept one-to-one), 0 = the map as LLE or Tutte gives it.
  int arapRounds = 10;
  LleBoundary boundary = LleBoundary::Free;
  unsigned seed = 0;  ///< the sampling's start
};

struct LleFlatteningResult {
  std::vector<Vec2> uv;          ///< per vertex of the patch
  std::vector<int> basePoints;   ///< the B base vertices
  int foldedBeforeRepair = 0;    ///< UV triangles turned over or of zero area after the Nyström step
                                 ///< (then untangled locally, or the map is Tutte's)
  bool tutte = false;            ///< the map is Tutte's embedding (Circle asked, or the repair)
  bool metricCorrected = false;  ///< the 2x2 correction was applied (positive definite fit)
  int arapRounds = 0;            ///< ARAP rounds that moved the map
};

/// Flattens `patch`, which must be one connected topological disk (one boundary loop, Euler
/// characteristic 1, manifold, coherently oriented). Fails with InvalidInput (not a disk: says which
/// of the counts is off; faces not coherently oriented; fewer vertices than B; B < 4; K out of
/// range; a non-finite position), NonManifold, or Cancelled.
Expected<LleFlatteningResult> flattenGeodesicLle(const TriMesh& patch, const LleFlatteningParams& params = {},
                                                 Progress progress = {});

/// Signed UV area of each face (positive: the face's orientation kept).
std::vector<double> uvSignedAreas(const TriMesh& mesh, const std::vector<Vec2>& uv);

}  // namespace gr
