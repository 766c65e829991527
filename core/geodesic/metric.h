// Metric: the per-vertex cost P of the Eikonal equation |grad U| = P (paper §2.1, eq. 2).
//
// P = 1 / F, where F is the front speed. Distances are integrals of P along curves, so a
// constant P = c multiplies every distance by c. Inside a triangle the fast-marching update uses
// the mean of its vertices' P; along an edge, the mean of its two ends.
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct Metric {
  /// Per-vertex P; empty means P = 1 everywhere (plain geodesic distance).
  std::vector<double> P;

  bool isUniform() const { return P.empty(); }

  static Metric uniform() { return {}; }
  /// P = 1 / F. Fails (InvalidInput) if a speed is not finite or not > 0, naming the vertex.
  static Expected<Metric> fromSpeed(const TriMesh& mesh, const std::vector<double>& speed);
  /// P given directly. Same checks as fromSpeed.
  static Expected<Metric> fromCost(const TriMesh& mesh, std::vector<double> cost);
};

/// The metric of `from` at the points `at` of `from` (e.g. the vertices of a subdivision, by their
/// origin): P interpolated barycentrically, one value per point. A uniform metric stays uniform.
/// Fails (InvalidInput) if the metric does not have one P per vertex of `from`, or a point is out
/// of range.
Expected<Metric> transferMetric(const Metric& metric, const TriMesh& from, const std::vector<SurfacePoint>& at);

}  // namespace gr
