#include "core/geodesic/triangulation_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "core/base/format.h"
#include "core/base/math.h"

namespace gr {
namespace {

constexpr double kSliverAngleDegrees = 10.0;
constexpr double kCapAngleDegrees = 150.0;
constexpr double kSliverShareBound = 0.01;
constexpr double kCapShareBound = 0.005;
constexpr double kLongEdgeFraction = 0.05;
constexpr double kLongShareBound = 0.01;

double boundingBoxDiagonal(const TriMesh& mesh) {
  if (mesh.positions.empty()) return 0.0;
  Vec3 lo = mesh.positions[0], hi = lo;
  for (const Vec3& p : mesh.positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

}  // namespace

TriangulationQuality assessTriangulation(const TriMesh& mesh) {
  TriangulationQuality q;
  q.faces = mesh.faceCount();
  if (q.faces == 0) return q;
  q.diagonal = boundingBoxDiagonal(mesh);
  const double longEdge2 = kLongEdgeFraction * kLongEdgeFraction * q.diagonal * q.diagonal;
  // Angles compared through their signed squared cosines, sign(c) c^2 (increasing with c, so
  // decreasing with the angle): no square root or arc cosine per corner. The loop is written out
  // per corner and without branches, since it runs on every call of the geodesic engine.
  const auto signedSquare = [](double c) { return c < 0.0 ? -c * c : c * c; };
  const double sliverBound = signedSquare(std::cos(kSliverAngleDegrees * kPi / 180.0));
  const double capBound = signedSquare(std::cos(kCapAngleDegrees * kPi / 180.0));
  // sign(c) c^2 of the corner between u and v (squared lengths nu, nv); a zero-length side: 1.
  const auto corner = [](const Vec3& u, const Vec3& v, double nu, double nv) {
    const double dot = u.dot(v), len2 = nu * nv;
    const double c2 = (dot < 0.0 ? -dot * dot : dot * dot) / len2;
    return len2 > 0.0 ? std::min(1.0, std::max(-1.0, c2)) : 1.0;
  };
  double largest = -1.0, smallest = 1.0;  // of sign(c) c^2 over all corners
  int slivers = 0, caps = 0, longFaces = 0;
  for (const Tri& t : mesh.triangles) {
    const Vec3& p0 = mesh.positions[t[0]];
    const Vec3& p1 = mesh.positions[t[1]];
    const Vec3& p2 = mesh.positions[t[2]];
    const Vec3 a = p1 - p0, b = p2 - p1, c = p0 - p2;
    const double na = a.squaredNorm(), nb = b.squaredNorm(), nc = c.squaredNorm();
    const double c0 = corner(a, -c, na, nc), c1 = corner(b, -a, nb, na), c2 = corner(c, -b, nc, nb);
    const double hi = std::max(c0, std::max(c1, c2)), lo = std::min(c0, std::min(c1, c2));
    largest = std::max(largest, hi);
    smallest = std::min(smallest, lo);
    slivers += hi > sliverBound;
    caps += lo < capBound;
    longFaces += std::max(na, std::max(nb, nc)) > longEdge2;
  }
  const auto angleOf = [](double c2) { return std::acos(c2 < 0.0 ? -std::sqrt(-c2) : std::sqrt(c2)) * 180.0 / kPi; };
  q.smallestAngleDegrees = angleOf(largest);
  q.largestAngleDegrees = angleOf(smallest);
  q.sliverShare = static_cast<double>(slivers) / q.faces;
  q.capShare = static_cast<double>(caps) / q.faces;
  q.longEdgeShare = static_cast<double>(longFaces) / q.faces;
  q.needsRefinement =
      q.sliverShare > kSliverShareBound || q.capShare > kCapShareBound || q.longEdgeShare > kLongShareBound;
  return q;
}

std::string describe(const TriangulationQuality& q) {
  return "slivers " + formatNumber(100.0 * q.sliverShare, "%.2f") + "%, caps " +
         formatNumber(100.0 * q.capShare, "%.2f") + "%, long edges " + formatNumber(100.0 * q.longEdgeShare, "%.2f") +
         "%, smallest angle " + formatNumber(q.smallestAngleDegrees, "%.3g") + " deg";
}

}  // namespace gr
