// As-rigid-as-possible relaxation of a one-to-one map of a disk to the plane (Liu, Zhang, Xu,
// Gotsman & Gortler, "A Local/Global Approach to Mesh Parameterization", SGP 2008), kept
// one-to-one at every step.
//
//   uv (one-to-one) --local: per face, the rotation R_f nearest to its Jacobian (2x2 closed form)
//     --global: the cotangent Laplacian system L u = b(R), factorised once (sparse LDL^T), the
//       boundary free --> a target map u*
//     --line search: the largest step t <= 1 from uv towards u* at which no face turns over
//       (each face's signed area is a quadratic in t), times 0.8, then halved until the map is
//       one-to-one (checkUvAlongPositivePath: every face stayed positive on the way, so only the
//       boundary can have run over itself) --> uv
//     --again, while the ARAP energy sum_f A_f |J_f - R_f|^2 drops by more than `tolerance` of it
//       and is above `negligible` times the patch's area
//
// Why: the geodesic LLE map and Tutte's fallback are one-to-one but not isometric where the chart
// is curved or thin (Tutte's circle boundary squeezes an elongated chart); ARAP's energy is the
// distance to an isometry, so a few rounds bring the map near the chart's own least-stretched
// shape while the line search keeps it one-to-one. Faces of (near) zero 3D area carry no weight; a
// tiny proximal term keeps their vertices, and the system, well-posed.
//
// Cost per round: one local step O(F), one back-substitution O(nnz of the factor), one
// one-to-one check O(F); the factorisation once.
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/flatten/geodesic_lle.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct ArapParams {
  int rounds = 10;          ///< at most this many local/global rounds (>= 0; 0 = uv as it is)
  double tolerance = 1e-3;  ///< stop when a round lowers the energy by less than this share of it
  /// Stop (or do not start) when the energy is at most this share of the patch's area: the map is
  /// then isometric to well under a percent (a plane's LLE map: L2 stretch 1.00003 after 3 rounds,
  /// where 7 more rounds would cost a third of the flattening's time for the fifth decimal).
  double negligible = 1e-4;
};

struct ArapResult {
  int rounds = 0;             ///< rounds that moved the map
  double energyBefore = 0.0;  ///< ARAP energy of the map given (after scaling it to the patch's area)
  double energyAfter = 0.0;   ///< and of the map returned (the lowest met)
};

/// Relaxes `uv` (one UV per vertex of the disk `patch`, one-to-one and counter-clockwise on entry)
/// towards the ARAP minimiser; on return `uv` is the one-to-one map of lowest energy met, at the
/// patch's scale. Fails with InvalidInput if `uv` has the wrong size or is not one-to-one on entry
/// (then `uv` is unchanged), InternalError if the system cannot be factorised.
/// `checked`: the caller has just checked that `uv` is one-to-one (checkUvInjectivity), which is
/// then not checked again.
Expected<ArapResult> relaxAsRigidAsPossible(const TriMesh& patch, std::vector<Vec2>& uv, const ArapParams& params = {},
                                            bool checked = false);

}  // namespace gr
