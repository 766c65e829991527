#include "core/mesh/self_intersection.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

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

/// Twice the signed area of (a, b, c) in the plane of coordinates (i, j).
double orient2(const Vec3& a, const Vec3& b, const Vec3& c, int i, int j) {
  return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
}

/// Whether p lies strictly inside triangle t (counter-clockwise or not) in the plane (i, j).
bool strictlyInside(const Vec3& p, const std::array<Vec3, 3>& t, int i, int j, double eps) {
  const double s0 = orient2(t[0], t[1], p, i, j), s1 = orient2(t[1], t[2], p, i, j), s2 = orient2(t[2], t[0], p, i, j);
  return (s0 > eps && s1 > eps && s2 > eps) || (s0 < -eps && s1 < -eps && s2 < -eps);
}

/// Whether two coplanar triangles overlap with positive area (projected on the plane (i, j) that
/// their normal is most nearly perpendicular to): two edges crossing at interior points, a
/// vertex of one strictly inside the other, or a centroid inside the other (the same wedge at a
/// shared vertex).
bool coplanarOverlap(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b, int i, int j, double eps) {
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      const Vec3 &p = a[k], &q = a[(k + 1) % 3], &r = b[l], &s = b[(l + 1) % 3];
      const double o1 = orient2(p, q, r, i, j), o2 = orient2(p, q, s, i, j);
      const double o3 = orient2(r, s, p, i, j), o4 = orient2(r, s, q, i, j);
      if (((o1 > eps && o2 < -eps) || (o1 < -eps && o2 > eps)) && ((o3 > eps && o4 < -eps) || (o3 < -eps && o4 > eps)))
        return true;
    }
  const Vec3 ca = (a[0] + a[1] + a[2]) / 3.0, cb = (b[0] + b[1] + b[2]) / 3.0;
  if (strictlyInside(ca, b, i, j, eps) || strictlyInside(cb, a, i, j, eps)) return true;
  for (int k = 0; k < 3; ++k)
    if (strictlyInside(a[k], b, i, j, eps) || strictlyInside(b[k], a, i, j, eps)) return true;
  return false;
}

}  // namespace

bool facesCross(const TriMesh& m, int f, int g) {
  const Tri& A = m.triangles[f];
  const Tri& B = m.triangles[g];
  int shared = 0;
  for (int x : A) shared += x == B[0] || x == B[1] || x == B[2];
  if (shared == 3) return false;  // the same face (twice)
  const std::array<Vec3, 3> a = {m.positions[A[0]], m.positions[A[1]], m.positions[A[2]]};
  const std::array<Vec3, 3> b = {m.positions[B[0]], m.positions[B[1]], m.positions[B[2]]};
  const Vec3 n = (a[1] - a[0]).cross(a[2] - a[0]);
  double length = 0.0;
  for (int k = 0; k < 3; ++k)
    length = std::max({length, (a[(k + 1) % 3] - a[k]).norm(), (b[(k + 1) % 3] - b[k]).norm()});
  constexpr double kFlat = 1e-12;  // relative off-plane distance taken as coplanar
  const double nn = n.norm();
  bool coplanar = nn > kFlat * length * length;
  for (int k = 0; k < 3 && coplanar; ++k) coplanar = std::abs(n.dot(b[k] - a[0])) <= kFlat * nn * length;
  if (coplanar) {
    int i = 0;
    n.cwiseAbs().maxCoeff(&i);  // drop the normal's largest coordinate
    return coplanarOverlap(a, b, (i + 1) % 3, (i + 2) % 3, kFlat * length * length);
  }
  if (shared == 2) return false;  // neighbours along an edge, not in one plane: they meet along it only
  // The vertices of one face that the other does not share, all strictly on one side of the
  // other's plane: they can meet at a shared vertex at most (most pairs of nearby faces).
  const auto oneSide = [&](const std::array<Vec3, 3>& p, const Tri& P, const std::array<Vec3, 3>& q, const Tri& Q) {
    const Vec3 normal = (q[1] - q[0]).cross(q[2] - q[0]);
    const double eps = 1e-9 * normal.norm() * length;
    int above = 0, below = 0, free = 0;
    for (int k = 0; k < 3; ++k) {
      if (P[k] == Q[0] || P[k] == Q[1] || P[k] == Q[2]) continue;
      const double d = normal.dot(p[k] - q[0]);
      above += d > eps;
      below += d < -eps;
      ++free;
    }
    return above == free || below == free;
  };
  if (oneSide(b, B, a, A) || oneSide(a, A, b, B)) return false;
  constexpr double kAway = 1e-9;  // an edge end at a shared vertex touches the other face there
  const auto edgesThrough = [&](const Tri& S, const Tri& T) {
    const Vec3 &ta = m.positions[T[0]], &tb = m.positions[T[1]], &tc = m.positions[T[2]];
    for (int k = 0; k < 3; ++k) {
      const int x = S[k], y = S[(k + 1) % 3];
      const bool xShared = x == T[0] || x == T[1] || x == T[2], yShared = y == T[0] || y == T[1] || y == T[2];
      if (segmentCrossesTriangle(m.positions[x], m.positions[y], ta, tb, tc, xShared ? kAway : 0.0,
                                 yShared ? 1.0 - kAway : 1.0))
        return true;
    }
    return false;
  };
  return edgesThrough(A, B) || edgesThrough(B, A);
}

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
  // Cells about the size of a face (a surface fills few cells of a grid of F cells over its box:
  // dozens of faces each), but no face over 64 cells across.
  std::vector<Vec3> boxLo(faces), boxHi(faces);
  double meanExtent = 0.0, maxExtent = 0.0;
  for (int f = 0; f < faces; ++f) {
    const Tri& t = mesh.triangles[f];
    boxLo[f] = mesh.positions[t[0]].cwiseMin(mesh.positions[t[1]]).cwiseMin(mesh.positions[t[2]]);
    boxHi[f] = mesh.positions[t[0]].cwiseMax(mesh.positions[t[1]]).cwiseMax(mesh.positions[t[2]]);
    const double extent = (boxHi[f] - boxLo[f]).maxCoeff();
    meanExtent += extent / faces;
    maxExtent = std::max(maxExtent, extent);
  }
  const double cell = std::max({meanExtent, maxExtent / 64.0, (hi - lo).maxCoeff() * 1e-6, 1e-300});
  const auto index = [&](const Vec3& p, int k) { return static_cast<long long>(std::floor((p[k] - lo[k]) / cell)); };
  const long long n = static_cast<long long>(std::ceil((hi - lo).maxCoeff() / cell)) + 2;
  const auto key = [&](const Vec3& p) { return (index(p, 0) * n + index(p, 1)) * n + index(p, 2); };
  std::vector<std::pair<long long, int>> entries;  // (cell, face) for every cell a face's box meets
  entries.reserve(4 * static_cast<size_t>(faces));
  for (int f = 0; f < faces; ++f) {
    const Vec3 &a = boxLo[f], &b = boxHi[f];
    for (long long x = index(a, 0); x <= index(b, 0); ++x)
      for (long long y = index(a, 1); y <= index(b, 1); ++y)
        for (long long z = index(a, 2); z <= index(b, 2); ++z) entries.push_back({(x * n + y) * n + z, f});
  }
  std::sort(entries.begin(), entries.end());
  // Two faces are tested once: in the cell of the low corner of their boxes' intersection.
  for (size_t begin = 0, end = 0; begin < entries.size(); begin = end) {
    while (end < entries.size() && entries[end].first == entries[begin].first) ++end;
    for (size_t i = begin; i < end; ++i)
      for (size_t j = i + 1; j < end; ++j) {
        const int f = entries[i].second, g = entries[j].second;
        const bool boxesMeet =
            (boxLo[f].array() <= boxHi[g].array()).all() && (boxLo[g].array() <= boxHi[f].array()).all();
        if (!boxesMeet || key(boxLo[f].cwiseMax(boxLo[g])) != entries[begin].first) continue;
        if (!facesCross(mesh, std::min(f, g), std::max(f, g))) continue;
        pairs.push_back({std::min(f, g), std::max(f, g)});
        if (limit > 0 && static_cast<int>(pairs.size()) >= limit) return pairs;
      }
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::vector<std::pair<int, int>> crossingsOfFaces(const TriMesh& mesh, const std::vector<char>& flagged) {
  std::vector<std::pair<int, int>> pairs;
  const int faces = mesh.faceCount();
  const auto box = [&](int f, Vec3& lo, Vec3& hi) {
    const Tri& t = mesh.triangles[f];
    lo = mesh.positions[t[0]].cwiseMin(mesh.positions[t[1]]).cwiseMin(mesh.positions[t[2]]);
    hi = mesh.positions[t[0]].cwiseMax(mesh.positions[t[1]]).cwiseMax(mesh.positions[t[2]]);
  };
  std::vector<int> chosen;
  double cell = 0.0;
  Vec3 lo, hi;
  for (int f = 0; f < faces && f < static_cast<int>(flagged.size()); ++f)
    if (flagged[f]) {
      chosen.push_back(f);
      box(f, lo, hi);
      cell = std::max(cell, (hi - lo).maxCoeff());
    }
  if (chosen.empty()) return pairs;
  cell = std::max(cell, 1e-300);  // cells as large as the largest flagged face: each meets at most 8
  const auto index = [&](double x) { return static_cast<long long>(std::floor(x / cell)); };
  const auto key = [](long long x, long long y, long long z) {
    return (static_cast<unsigned long long>(x) * 73856093ULL) ^ (static_cast<unsigned long long>(y) * 19349663ULL) ^
           (static_cast<unsigned long long>(z) * 83492791ULL);
  };
  std::vector<std::pair<unsigned long long, int>> entries;  // (hashed cell, flagged face)
  for (const int f : chosen) {
    box(f, lo, hi);
    for (long long x = index(lo[0]); x <= index(hi[0]); ++x)
      for (long long y = index(lo[1]); y <= index(hi[1]); ++y)
        for (long long z = index(lo[2]); z <= index(hi[2]); ++z) entries.push_back({key(x, y, z), f});
  }
  std::sort(entries.begin(), entries.end());
  std::vector<int> candidates;
  Vec3 flo, fhi;
  for (int g = 0; g < faces; ++g) {
    box(g, lo, hi);
    candidates.clear();
    // A face larger than the cells is looked up at most 4 cells across; past that, against all.
    const bool large = (hi - lo).maxCoeff() > 4 * cell;
    if (large) candidates = chosen;
    for (long long x = index(lo[0]); !large && x <= index(hi[0]); ++x)
      for (long long y = index(lo[1]); y <= index(hi[1]); ++y)
        for (long long z = index(lo[2]); z <= index(hi[2]); ++z) {
          const unsigned long long k = key(x, y, z);
          for (auto it = std::lower_bound(entries.begin(), entries.end(), std::make_pair(k, -1));
               it != entries.end() && it->first == k; ++it)
            candidates.push_back(it->second);
        }
    std::sort(candidates.begin(), candidates.end());
    candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
    for (const int f : candidates) {
      if (f == g || (flagged[g] && g < f)) continue;  // a pair of two flagged faces once
      box(f, flo, fhi);
      if (!((flo.array() <= hi.array()).all() && (lo.array() <= fhi.array()).all())) continue;
      if (facesCross(mesh, std::min(f, g), std::max(f, g))) pairs.push_back({std::min(f, g), std::max(f, g)});
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

std::vector<char> crossingVertices(const TriMesh& mesh) {
  std::vector<char> crossing(mesh.vertexCount(), 0);
  for (const auto& [f, g] : selfIntersectingFaces(mesh))
    for (int face : {f, g})
      for (int v : mesh.triangles[face]) crossing[v] = 1;
  return crossing;
}

}  // namespace gr
