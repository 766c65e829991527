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
  double smallest = kPi, largest = 0.0;
  int slivers = 0, caps = 0, longFaces = 0;
  for (const Tri& t : mesh.triangles) {
    double lo = kPi, hi = 0.0;
    bool hasLongEdge = false;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]];
      const Vec3 w = mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[k]];
      const double a = std::atan2(u.cross(w).norm(), u.dot(w));
      lo = std::min(lo, a);
      hi = std::max(hi, a);
      hasLongEdge = hasLongEdge || u.squaredNorm() > longEdge2;
    }
    longFaces += hasLongEdge;
    smallest = std::min(smallest, lo);
    largest = std::max(largest, hi);
    slivers += lo < kSliverAngleDegrees * kPi / 180.0;
    caps += hi > kCapAngleDegrees * kPi / 180.0;
  }
  q.smallestAngleDegrees = smallest * 180.0 / kPi;
  q.largestAngleDegrees = largest * 180.0 / kPi;
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
         "%, smallest angle " + formatNumber(q.smallestAngleDegrees, "%.3g") +
         " deg: " + (q.needsRefinement ? "refine" : "fine as it is");
}

}  // namespace gr
