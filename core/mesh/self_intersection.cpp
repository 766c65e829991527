#include "core/mesh/self_intersection.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace gr {
namespace {

/// Whether the segment p + t (q - p), t in [tMin, tMax], crosses triangle (a, b, c) (Moller-Trumbore).
bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c, double tMin,
                            double tMax) {
  const Vec3 d = q - p, e1 = b - a, e2 = c - a;
  const Vec3 h = d.cross(e2);
  const double det = e1.dot(h);
  const double scale = e1.norm() * e2.norm() * d.norm();
  if (!(std::abs(det) > 1e-12 * scale)) return false;  // parallel (or coplanar): not counted
  const Vec3 s = p - a;
  const double u = s.dot(h) / det;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 k = s.cross(e1);
  const double v = d.dot(k) / det;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = e2.dot(k) / det;
  return t >= tMin && t <= tMax;
}

/// Whether faces f and g cross: an edge of one through the other, away from shared vertices.
bool facesCross(const TriMesh& m, int f, int g) {
  const Tri& A = m.triangles[f];
  const Tri& B = m.triangles[g];
  int shared = 0;
  for (int x : A) shared += x == B[0] || x == B[1] || x == B[2];
  if (shared >= 2) return false;  // neighbours along an edge (or the same face)
  constexpr double kAway = 1e-9;  // an edge end at a shared vertex touches the other face there
  const auto edgesThrough = [&](const Tri& S, const Tri& T) {
    const Vec3 &a = m.positions[T[0]], &b = m.positions[T[1]], &c = m.positions[T[2]];
    for (int k = 0; k < 3; ++k) {
      const int x = S[k], y = S[(k + 1) % 3];
      const bool xShared = x == T[0] || x == T[1] || x == T[2], yShared = y == T[0] || y == T[1] || y == T[2];
      if (segmentCrossesTriangle(m.positions[x], m.positions[y], a, b, c, xShared ? kAway : 0.0,
                                 yShared ? 1.0 - kAway : 1.0))
        return true;
    }
    return false;
  };
  return edgesThrough(A, B) || edgesThrough(B, A);
}

}  // namespace

std::vector<std::pair<int, int>> selfIntersectingFaces(const TriMesh& mesh, int limit) {
  std::vector<std::pair<int, int>> pairs;
  const int faces = mesh.faceCount();
  if (faces < 2) return pairs;
  Vec3 lo = mesh.positions[mesh.triangles[0][0]], hi = lo;
  for (const Tri& t : mesh.triangles)
    for (int v : t) {
      lo = lo.cwiseMin(mesh.positions[v]);
      hi = hi.cwiseMax(mesh.positions[v]);
    }
  const double cell = std::max((hi - lo).maxCoeff() / std::cbrt(static_cast<double>(faces)), 1e-300);
  const auto index = [&](const Vec3& p, int k) { return static_cast<long long>(std::floor((p[k] - lo[k]) / cell)); };
  std::unordered_map<long long, std::vector<int>> grid;
  const long long n = static_cast<long long>(std::ceil((hi - lo).maxCoeff() / cell)) + 2;
  std::vector<std::array<long long, 6>> range(faces);
  for (int f = 0; f < faces; ++f) {
    const Tri& t = mesh.triangles[f];
    const Vec3 a = mesh.positions[t[0]].cwiseMin(mesh.positions[t[1]]).cwiseMin(mesh.positions[t[2]]);
    const Vec3 b = mesh.positions[t[0]].cwiseMax(mesh.positions[t[1]]).cwiseMax(mesh.positions[t[2]]);
    range[f] = {index(a, 0), index(a, 1), index(a, 2), index(b, 0), index(b, 1), index(b, 2)};
    for (long long x = range[f][0]; x <= range[f][3]; ++x)
      for (long long y = range[f][1]; y <= range[f][4]; ++y)
        for (long long z = range[f][2]; z <= range[f][5]; ++z) grid[(x * n + y) * n + z].push_back(f);
  }
  std::vector<int> seen(faces, -1);
  for (int f = 0; f < faces; ++f) {
    for (long long x = range[f][0]; x <= range[f][3]; ++x)
      for (long long y = range[f][1]; y <= range[f][4]; ++y)
        for (long long z = range[f][2]; z <= range[f][5]; ++z)
          for (int g : grid[(x * n + y) * n + z]) {
            if (g <= f || seen[g] == f) continue;
            seen[g] = f;
            if (!facesCross(mesh, f, g)) continue;
            pairs.push_back({f, g});
            if (limit > 0 && static_cast<int>(pairs.size()) >= limit) return pairs;
          }
  }
  return pairs;
}

}  // namespace gr
