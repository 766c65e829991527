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

TriangulationTally::TriangulationTally(double diagonal) : diagonal_(diagonal) {
  longEdge2_ = kLongEdgeFraction * kLongEdgeFraction * diagonal * diagonal;
  const auto signedSquare = [](double c) { return c < 0.0 ? -c * c : c * c; };
  sliverBound_ = signedSquare(std::cos(kSliverAngleDegrees * kPi / 180.0));
  capBound_ = signedSquare(std::cos(kCapAngleDegrees * kPi / 180.0));
}

TriangulationQuality TriangulationTally::result() const {
  TriangulationQuality q;
  q.faces = faces_;
  if (faces_ == 0) return q;
  q.diagonal = diagonal_;
  const auto angleOf = [](double c2) { return std::acos(c2 < 0.0 ? -std::sqrt(-c2) : std::sqrt(c2)) * 180.0 / kPi; };
  q.smallestAngleDegrees = angleOf(largest_);
  q.largestAngleDegrees = angleOf(smallest_);
  q.sliverShare = static_cast<double>(slivers_) / q.faces;
  q.capShare = static_cast<double>(caps_) / q.faces;
  q.longEdgeShare = static_cast<double>(longFaces_) / q.faces;
  q.needsRefinement =
      q.sliverShare > kSliverShareBound || q.capShare > kCapShareBound || q.longEdgeShare > kLongShareBound;
  return q;
}

TriangulationQuality assessTriangulation(const TriMesh& mesh) {
  if (mesh.faceCount() == 0) return {};
  TriangulationTally tally(boundingBoxDiagonal(mesh));
  for (const Tri& t : mesh.triangles) tally.add(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
  return tally.result();
}

std::string describe(const TriangulationQuality& q) {
  return "slivers " + formatNumber(100.0 * q.sliverShare, "%.2f") + "%, caps " +
         formatNumber(100.0 * q.capShare, "%.2f") + "%, long edges " + formatNumber(100.0 * q.longEdgeShare, "%.2f") +
         "%, smallest angle " + formatNumber(q.smallestAngleDegrees, "%.3g") + " deg";
}

}  // namespace gr
