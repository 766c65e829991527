#include "core/geodesic/voronoi_boundary.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/geodesic/detail/eikonal_update.h"

namespace gr {
namespace {

/// Arrival time at vertex x of the front of cell `c`, extended from x's neighbours in
/// that cell (edge and triangle updates on the final field).
double extendedArrival(const TriMesh& m, const std::vector<double>& P, const std::vector<double>& U,
                       const std::vector<int>& cell, int x, int c) {
  double best = std::numeric_limits<double>::infinity();
  const Vec3& px = m.positions[x];
  for (const int* it = m.cornersBegin(x); it != m.cornersEnd(x); ++it) {
    const int a = m.vertex(TriMesh::next(*it)), b = m.vertex(TriMesh::prev(*it));
    const bool inA = cell[a] == c, inB = cell[b] == c;
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

/// Front `c`'s arrival at x extrapolated from its neighbour w along the front's direction:
/// U(w) + P * g.(x - w), with g the mean unit gradient of U over the faces around w that lie
/// entirely in the cell. +inf if there is no such face.
double extrapolatedArrival(const TriMesh& m, const std::vector<double>& P, const std::vector<double>& U,
                           const std::vector<int>& cell, int w, int x, int c) {
  Vec3 direction = Vec3::Zero();
  for (const int* it = m.cornersBegin(w); it != m.cornersEnd(w); ++it) {
    const Tri& t = m.triangles[TriMesh::face(*it)];
    if (cell[t[0]] != c || cell[t[1]] != c || cell[t[2]] != c) continue;
    const Vec3 e1 = m.positions[t[1]] - m.positions[t[0]], e2 = m.positions[t[2]] - m.positions[t[0]];
    const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2), det = a11 * a22 - a12 * a12;
    if (!(det > 1e-14 * a11 * a22)) continue;
    const double r1 = U[t[1]] - U[t[0]], r2 = U[t[2]] - U[t[0]];
    const Vec3 g = ((r1 * a22 - r2 * a12) / det) * e1 + ((r2 * a11 - r1 * a12) / det) * e2;
    if (g.norm() > 0.0) direction += g.normalized();
  }
  if (direction.norm() == 0.0) return std::numeric_limits<double>::infinity();
  return U[w] + 0.5 * (P[w] + P[x]) * direction.normalized().dot(m.positions[x] - m.positions[w]);
}

}  // namespace

std::vector<VoronoiEdgePoint> voronoiBoundaryPoints(const TriMesh& mesh, const Metric& metric,
                                                    const std::vector<double>& distance, const std::vector<int>& cell) {
  const std::vector<double> P = metric.isUniform() ? std::vector<double>(mesh.vertexCount(), 1.0) : metric.P;
  std::vector<VoronoiEdgePoint> points;
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int v1 = mesh.vertex(TriMesh::next(c)), v2 = mesh.vertex(TriMesh::prev(c));
    const int o = mesh.oppositeCorner[c];
    if (o >= 0 && o < c) continue;  // each interior edge once
    const int a = cell[v1], b = cell[v2];
    if (a < 0 || b < 0 || a == b) continue;
    const double d1a = distance[v1], d2b = distance[v2];
    // Each front continued one vertex past its cell: from the neighbour across the edge when
    // its faces show the front's direction, else from the cell's triangles and edges at the vertex.
    double d1b = extrapolatedArrival(mesh, P, distance, cell, v2, v1, b);
    double d2a = extrapolatedArrival(mesh, P, distance, cell, v1, v2, a);
    if (!std::isfinite(d1b)) d1b = extendedArrival(mesh, P, distance, cell, v1, b);
    if (!std::isfinite(d2a)) d2a = extendedArrival(mesh, P, distance, cell, v2, a);
    const double num = d1b - d1a, den = (d1b - d1a) + (d2a - d2b);
    double lambda = 0.5;
    if (std::isfinite(num) && std::isfinite(den) && den > 0.0) lambda = std::clamp(num / den, 0.0, 1.0);
    points.push_back({v1, v2, a, b, lambda, (1.0 - lambda) * mesh.positions[v1] + lambda * mesh.positions[v2]});
  }
  return points;
}

}  // namespace gr
