#include "core/voronoi_boundary.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/eikonal_update.h"

namespace gr {
namespace {

/// Arrival time at vertex x of the front of region `region`, extended from x's neighbours in
/// that region (edge and triangle updates on the final field).
double extendedArrival(const TriMesh& m, const std::vector<double>& P, const std::vector<double>& U,
                       const std::vector<int>& label, int x, int region) {
  double best = std::numeric_limits<double>::infinity();
  const Vec3& px = m.positions[x];
  for (const int* it = m.cornersBegin(x); it != m.cornersEnd(x); ++it) {
    const int a = m.vertex(TriMesh::next(*it)), b = m.vertex(TriMesh::prev(*it));
    const bool inA = label[a] == region, inB = label[b] == region;
    const double la = (m.positions[a] - px).norm(), lb = (m.positions[b] - px).norm();
    if (inA) best = std::min(best, U[a] + 0.5 * (P[x] + P[a]) * la);
    if (inB) best = std::min(best, U[b] + 0.5 * (P[x] + P[b]) * lb);
    if (inA && inB) {
      const double p = (P[x] + P[a] + P[b]) / 3.0;
      const double lc = (m.positions[a] - m.positions[b]).norm();
      best = std::min(best, p * virtualSourceDistance(la, lb, lc, U[a] / p, U[b] / p));
    }
  }
  return best;
}

}  // namespace

std::vector<VoronoiEdgePoint> voronoiBoundaryPoints(const TriMesh& mesh, const Metric& metric,
                                                    const std::vector<double>& distance,
                                                    const std::vector<int>& label) {
  const std::vector<double> P = metric.isUniform() ? std::vector<double>(mesh.vertexCount(), 1.0) : metric.P;
  std::vector<VoronoiEdgePoint> points;
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int v1 = mesh.vertex(TriMesh::next(c)), v2 = mesh.vertex(TriMesh::prev(c));
    const int o = mesh.oppositeCorner[c];
    if (o >= 0 && o < c) continue;  // each interior edge once
    const int a = label[v1], b = label[v2];
    if (a < 0 || b < 0 || a == b) continue;
    const double d1a = distance[v1], d2b = distance[v2];
    const double d1b = extendedArrival(mesh, P, distance, label, v1, b);
    const double d2a = extendedArrival(mesh, P, distance, label, v2, a);
    const double num = d1b - d1a, den = (d1b - d1a) + (d2a - d2b);
    double lambda = 0.5;
    if (std::isfinite(num) && std::isfinite(den) && den > 0.0) lambda = std::clamp(num / den, 0.0, 1.0);
    points.push_back({v1, v2, a, b, lambda, (1.0 - lambda) * mesh.positions[v1] + lambda * mesh.positions[v2]});
  }
  return points;
}

}  // namespace gr
