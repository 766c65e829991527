// Speed F (and metric P = 1/F) from a per-vertex field q, for adaptive remeshing (paper §3.3-3.4).
//
// Fronts move at speed F, so farthest-point samples are spaced proportionally to F and their
// number per unit area goes as 1/F^2 (paper Fig. 6). Three mappings of q to F:
//
//   Direct      F = 1/r + (1 - 1/r) * min((q - qmin) / s, 1)   F in [1/r, 1], r = strength >= 1
//                 (F grows with q: sparser where q is large; any sign of q)
//   Attractive  F = 1 / (1 + mu * q / s)                        F in (0, 1], mu = strength >= 0
//                 (paper's F2, "edge attractive": denser where q is large; q >= 0)
//   Repulsive   F = 1 + eps * q / s                             F >= 1, eps = strength >= 0
//                 (paper's F1, "edge repulsive": sparser where q is large; q >= 0)
//
// s is a robust scale of the field, so that the same strength gives similar results on meshes of
// any size and units: the `percentile`-th percentile (nearest rank, over all vertices) of q for
// Attractive/Repulsive, of q - qmin for Direct. Deviation from the paper: the paper divides by
// max|grad I| (§3.3) or uses tau as is (§3.4); one outlier vertex would then flatten the whole
// field. In Direct, values above qmin + s saturate at F = 1 (with percentile = 100, Direct is the
// plain affine map of [qmin, qmax] onto [1/r, 1]). Attractive/Repulsive do not clamp: a vertex
// with q = 10 s is ten times "stronger" than the scale.
//
// Bad fields: a non-finite q, or a negative q with Attractive/Repulsive, is InvalidInput naming
// the vertex (a signed field - e.g. mean curvature - must be made non-negative by the caller, or
// used with Direct). Not errors, but fallbacks reported in `fallback`: a constant field gives a
// uniform speed; a zero scale (more than `percentile`% of the vertices at the minimum, i.e. at 0
// for Attractive/Repulsive) uses the largest value instead.
// Cost: O(V) (one nth_element for the percentile). Nothing is written into the mesh.
#pragma once

#include <string>
#include <vector>

#include "core/base/status.h"
#include "core/geodesic/metric.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// How a field q becomes a speed F (see the table at the top of speed_field.h).
enum class SpeedMapping {
  Direct,      ///< F affine in q, in [1/r, 1]: sparser where q is large
  Attractive,  ///< F = 1 / (1 + mu q/s) (paper's F2): denser where q is large
  Repulsive,   ///< F = 1 + eps q/s (paper's F1): sparser where q is large
};

constexpr int kSpeedMappingCount = 3;
/// Name of a mapping, for logs ("Attractive").
const char* toString(SpeedMapping mapping);

/// Options of the field-to-speed mapping (Peyré & Cohen 2006, §3.3-3.4).
struct SpeedFieldParams {
  SpeedMapping mapping = SpeedMapping::Attractive;
  /// r for Direct (ratio of the largest to the smallest speed, >= 1; 1 = uniform), mu for
  /// Attractive and eps for Repulsive (>= 0; 0 = uniform). Dimensionless: q is divided by the
  /// scale s first.
  double strength = 4.0;
  /// The scale s is this percentile of q (of q - qmin for Direct), in (0, 100]; 100 = the maximum.
  double percentile = 95.0;
};

struct SpeedFieldResult {
  std::vector<double> speed;  ///< F per vertex, finite and > 0
  Metric metric;              ///< P = 1/F per vertex; uniform (empty P) when F is constant
  double scale = 0.0;         ///< the scale s q was divided by (0 when the field is constant)
  double fieldMin = 0.0;      ///< smallest q
  double fieldMax = 0.0;      ///< largest q
  double speedMin = 1.0;      ///< smallest F
  double speedMax = 1.0;      ///< largest F
  /// Empty, or the fallback that was taken, as a sentence for the log (constant field, zero scale).
  std::string fallback;
  bool usedFallback() const { return !fallback.empty(); }
};

/// Fails (InvalidInput) when `field` does not have one value per vertex, a value is NaN or
/// infinite, a value is negative with Attractive/Repulsive (the message names the vertex), the
/// strength is NaN, infinite or out of range, the percentile is not in (0, 100], or the speed
/// underflows (F or 1/F not representable).
Expected<SpeedFieldResult> speedFromField(const TriMesh& mesh, const std::vector<double>& field,
                                          const SpeedFieldParams& params = {});

/// Gradation: lowers the speed (the local spacing of an adaptive sampling goes as F) so that it
/// grows by at most `growth` per unit of length along the mesh's edges,
/// F'(x) = min over y of F(y) + growth * d(x, y), d the shortest edge path (Dijkstra from every
/// vertex at once, O(E log V)). A spacing that changes fast over a short distance (a sharp edge's
/// dense band beside a flat face) cannot be triangulated with good angles; a bounded growth can.
/// Updates speedMax and the metric (P = 1/F); returns the vertices whose speed was lowered.
/// `growth` <= 0 or a uniform metric: nothing changes.
int limitSpeedGrowth(const TriMesh& mesh, double growth, SpeedFieldResult& speed);

}  // namespace gr
