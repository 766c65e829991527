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
  // decreasing with the angle): no square root or arc cosine per corner.
  const auto signedSquare = [](double c) { return c < 0.0 ? -c * c : c * c; };
  const double sliverBound = signedSquare(std::cos(kSliverAngleDegrees * kPi / 180.0));
  const double capBound = signedSquare(std::cos(kCapAngleDegrees * kPi / 180.0));
  double largest = -1.0, smallest = 1.0;  // of sign(c) c^2 over all corners
  int slivers = 0, caps = 0, longFaces = 0;
  for (const Tri& t : mesh.triangles) {
    const Vec3 e[3] = {mesh.positions[t[1]] - mesh.positions[t[0]], mesh.positions[t[2]] - mesh.positions[t[1]],
                       mesh.positions[t[0]] - mesh.positions[t[2]]};
    const double n2[3] = {e[0].squaredNorm(), e[1].squaredNorm(), e[2].squaredNorm()};
    double hi = -1.0, lo = 1.0;
    for (int k = 0; k < 3; ++k) {  // the corner at t[k], between e[k] and -e[k + 2]
      const double len2 = n2[k] * n2[(k + 2) % 3];
      const double dot = -e[k].dot(e[(k + 2) % 3]);
      const double c2 = len2 > 0.0 ? std::clamp((dot < 0.0 ? -dot * dot : dot * dot) / len2, -1.0, 1.0) : 1.0;
      hi = std::max(hi, c2);  // a zero-length side: angle 0
      lo = std::min(lo, c2);
    }
    largest = std::max(largest, hi);
    smallest = std::min(smallest, lo);
    slivers += hi > sliverBound;
    caps += lo < capBound;
    longFaces += std::max({n2[0], n2[1], n2[2]}) > longEdge2;
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
