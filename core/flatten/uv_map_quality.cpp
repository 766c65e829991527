#include "core/flatten/uv_map_quality.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include <Eigen/Geometry>

#include "core/base/math.h"

namespace gr {
namespace {

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Whether segments pq and rs share a point (orientation tests; collinear overlaps count).
bool segmentsMeet(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s) {
  const double d1 = cross2(q - p, r - p), d2 = cross2(q - p, s - p), d3 = cross2(s - r, p - r),
               d4 = cross2(s - r, q - r);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
  const auto onSegment = [](const Vec2& a, const Vec2& b, const Vec2& c) {  // c on ab, given collinear
    return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
           c.y() <= std::max(a.y(), b.y());
  };
  return (d1 == 0 && onSegment(p, q, r)) || (d2 == 0 && onSegment(p, q, s)) || (d3 == 0 && onSegment(r, s, p)) ||
         (d4 == 0 && onSegment(r, s, q));
}

/// Boundary edges (directed as in their face), each once.
std::vector<std::array<int, 2>> boundaryEdges(const TriMesh& m) {
  std::vector<std::array<int, 2>> e;
  for (int c = 0; c < 3 * m.faceCount(); ++c)
    if (m.oppositeCorner[c] < 0) e.push_back({m.vertex(TriMesh::next(c)), m.vertex(TriMesh::prev(c))});
  return e;
}

/// Distance from c to the segment ab.
double pointSegmentDistance(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((c - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - c).norm();
}

/// Whether segments pq and rs meet or come closer than `clearance`.
bool segmentsTouch(const Vec2& p, const Vec2& q, const Vec2& r, const Vec2& s, double clearance) {
  if (segmentsMeet(p, q, r, s)) return true;
  return clearance > 0.0 && std::min({pointSegmentDistance(r, s, p), pointSegmentDistance(r, s, q),
                                      pointSegmentDistance(p, q, r), pointSegmentDistance(p, q, s)}) < clearance;
}

/// Pairs of boundary edges without a common vertex that meet (or come closer than `clearance`),
/// found through a uniform grid whose cells are about the mean edge length.
int boundaryCrossings(const std::vector<std::array<int, 2>>& edges, const std::vector<Vec2>& uv, double clearance) {
  if (edges.size() < 4) return 0;
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  double length = 0.0;
  for (const auto& e : edges) {
    lo = lo.cwiseMin(uv[e[0]]);
    hi = hi.cwiseMax(uv[e[0]]);
    length += (uv[e[1]] - uv[e[0]]).norm();
  }
  const double cell = std::max(length / edges.size() + clearance, 1e-300);
  const double size = std::max({cell, (hi.x() - lo.x()) / 4096.0, (hi.y() - lo.y()) / 4096.0});
  std::unordered_map<long long, std::vector<int>> grid;
  const auto key = [&](long i, long j) { return static_cast<long long>(i) * 1000003LL + j; };
  int crossings = 0;
  for (int k = 0; k < static_cast<int>(edges.size()); ++k) {
    const Vec2 &p = uv[edges[k][0]], &q = uv[edges[k][1]];
    const long i0 = static_cast<long>(std::floor((std::min(p.x(), q.x()) - clearance - lo.x()) / size)),
               i1 = static_cast<long>(std::floor((std::max(p.x(), q.x()) + clearance - lo.x()) / size)),
               j0 = static_cast<long>(std::floor((std::min(p.y(), q.y()) - clearance - lo.y()) / size)),
               j1 = static_cast<long>(std::floor((std::max(p.y(), q.y()) + clearance - lo.y()) / size));
    std::vector<int> seen;
    for (long i = i0; i <= i1; ++i)
      for (long j = j0; j <= j1; ++j) {
        std::vector<int>& bucket = grid[key(i, j)];
        for (int other : bucket) {
          const auto& o = edges[other];
          if (o[0] == edges[k][0] || o[0] == edges[k][1] || o[1] == edges[k][0] || o[1] == edges[k][1]) continue;
          if (std::find(seen.begin(), seen.end(), other) != seen.end()) continue;
          seen.push_back(other);
          crossings += segmentsTouch(p, q, uv[o[0]], uv[o[1]], clearance);
        }
        bucket.push_back(k);
      }
  }
  return crossings;
}

UvInjectivity checkUv(const TriMesh& patch, const std::vector<Vec2>& uv, bool interiorWindings, double clearance) {
  UvInjectivity r;
  double mean = 0.0;
  std::vector<double> area(patch.faceCount());
  for (int f = 0; f < patch.faceCount(); ++f) {
    const Tri& t = patch.triangles[f];
    area[f] = 0.5 * cross2(uv[t[1]] - uv[t[0]], uv[t[2]] - uv[t[0]]);
    mean += std::abs(area[f]);
  }
  mean /= std::max(patch.faceCount(), 1);
  const std::vector<char> onBoundary = boundaryVertexFlags(patch);
  std::vector<double> angleSum(patch.vertexCount(), 0.0);
  for (int f = 0; f < patch.faceCount(); ++f) {
    if (!(area[f] > 1e-12 * mean)) ++r.nonPositiveFaces;
    for (int k = 0; k < 3; ++k) {
      const Tri& t = patch.triangles[f];
      if (!interiorWindings && !onBoundary[t[k]]) continue;
      const Vec2 a = uv[t[(k + 1) % 3]] - uv[t[k]], b = uv[t[(k + 2) % 3]] - uv[t[k]];
      angleSum[t[k]] += std::atan2(std::abs(cross2(a, b)), a.dot(b));
    }
  }
  for (int v = 0; v < patch.vertexCount(); ++v) {
    if (patch.valence(v) == 0 || (!interiorWindings && !onBoundary[v])) continue;
    const bool bad = onBoundary[v] ? angleSum[v] >= 2.0 * kPi - 1e-9 : std::abs(angleSum[v] - 2.0 * kPi) > 1e-6;
    r.windingVertices += bad;
  }
  r.boundaryCrossings = boundaryCrossings(boundaryEdges(patch), uv, clearance);
  return r;
}

}  // namespace

UvInjectivity checkUvInjectivity(const TriMesh& patch, const std::vector<Vec2>& uv) {
  return checkUv(patch, uv, true, 0.0);
}

UvInjectivity checkUvAlongPositivePath(const TriMesh& patch, const std::vector<Vec2>& uv, double clearance) {
  return checkUv(patch, uv, false, clearance);
}

int boundaryContacts(const TriMesh& patch, const std::vector<Vec2>& uv, double clearance) {
  return boundaryCrossings(boundaryEdges(patch), uv, clearance);
}

UvDistortion measureUvDistortion(const TriMesh& mesh, const std::vector<Vec2>& cornerUv) {
  UvDistortion d;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    d.area3d +=
        0.5 * (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm();
    d.areaUv += 0.5 * std::abs(cross2(cornerUv[3 * f + 1] - cornerUv[3 * f], cornerUv[3 * f + 2] - cornerUv[3 * f]));
  }
  if (!(d.area3d > 0.0) || !(d.areaUv > 0.0)) return d;
  const double scale = std::sqrt(d.area3d / d.areaUv);
  double stretch = 0.0, conformal = 0.0, weight = 0.0;
  d.conformalMax = 1.0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    const Vec3 &q1 = mesh.positions[t[0]], &q2 = mesh.positions[t[1]], &q3 = mesh.positions[t[2]];
    const double area = 0.5 * (q2 - q1).cross(q3 - q1).norm();
    if (!(area > 0.0)) continue;
    const Vec2 p1 = scale * cornerUv[3 * f], p2 = scale * cornerUv[3 * f + 1], p3 = scale * cornerUv[3 * f + 2];
    const double a2 = cross2(p2 - p1, p3 - p1);
    if (a2 == 0.0) return {INFINITY, INFINITY, INFINITY, d.area3d, d.areaUv};
    const Vec3 ss = (q1 * (p2.y() - p3.y()) + q2 * (p3.y() - p1.y()) + q3 * (p1.y() - p2.y())) / a2;
    const Vec3 st = (q1 * (p3.x() - p2.x()) + q2 * (p1.x() - p3.x()) + q3 * (p2.x() - p1.x())) / a2;
    const double a = ss.squaredNorm(), b = ss.dot(st), c = st.squaredNorm();
    const double root = std::sqrt((a - c) * (a - c) + 4.0 * b * b);
    const double big = std::sqrt(0.5 * (a + c + root)), small = std::sqrt(std::max(0.5 * (a + c - root), 0.0));
    const double ratio = small > 0.0 ? big / small : INFINITY;
    stretch += area * 0.5 * (a + c);
    conformal += area * ratio;
    weight += area;
    d.conformalMax = std::max(d.conformalMax, ratio);
  }
  d.stretchL2 = std::sqrt(stretch / weight);
  d.conformalMean = conformal / weight;
  return d;
}

}  // namespace gr
