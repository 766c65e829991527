#include "core/evaluation.h"

#include <algorithm>
#include <cmath>

#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/index/grid_static_ptr.h>

#include "core/vcg_mesh.h"

namespace gr {

DistanceError distanceError(const std::vector<double>& d, const std::vector<double>& reference) {
  DistanceError e;
  double refMax = 0.0;
  for (size_t v = 0; v < reference.size(); ++v)
    if (std::isfinite(reference[v]) && std::isfinite(d[v])) refMax = std::max(refMax, reference[v]);
  if (refMax <= 0.0) return e;
  double sum = 0.0, maxAbs = 0.0;
  for (size_t v = 0; v < reference.size(); ++v) {
    if (!std::isfinite(reference[v]) || !std::isfinite(d[v])) continue;
    const double err = std::abs(d[v] - reference[v]);
    maxAbs = std::max(maxAbs, err);
    if (reference[v] >= 0.05 * refMax) {
      sum += err / reference[v];
      ++e.comparedVertices;
    }
  }
  e.meanRelative = e.comparedVertices ? sum / e.comparedVertices : 0.0;
  e.maxRelativeToMax = maxAbs / refMax;
  return e;
}

AngleStatistics angleStatistics(const TriMesh& mesh) {
  AngleStatistics a;
  if (mesh.faceCount() == 0) return a;
  double sumSq = 0.0;
  int below30 = 0;
  for (const Tri& t : mesh.triangles) {
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]];
      const Vec3 w = mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[k]];
      const double nu = u.norm(), nw = w.norm();
      double angle = 0.0;
      if (nu > 0.0 && nw > 0.0) angle = std::acos(std::clamp(u.dot(w) / (nu * nw), -1.0, 1.0)) * 180.0 / M_PI;
      else if (nu > 0.0 || nw > 0.0) angle = 0.0;
      sumSq += (angle - 60.0) * (angle - 60.0);
      smallest = std::min(smallest, angle);
      a.maxDegrees = std::max(a.maxDegrees, angle);
    }
    a.minDegrees = std::min(a.minDegrees, smallest);
    below30 += smallest < 30.0;
  }
  a.stdDegrees = std::sqrt(sumSq / (3.0 * mesh.faceCount()));
  a.shareMinBelow30 = double(below30) / mesh.faceCount();
  return a;
}

SurfaceDistance surfaceDistance(const TriMesh& from, const TriMesh& to) {
  SurfaceDistance d;
  if (from.vertexCount() == 0 || to.faceCount() == 0) return d;
  CoreMesh target;
  toCoreMesh(to, target);
  vcg::GridStaticPtr<CoreFace, double> grid;
  grid.Set(target.face.begin(), target.face.end());
  vcg::face::PointDistanceBaseFunctor<double> pointToFace;
  vcg::tri::EmptyTMark<CoreMesh> marker;
  const double searchRadius = 2.0 * (to.boundingBoxDiagonal() + from.boundingBoxDiagonal());
  double sumSq = 0.0;
  long n = 0;
  auto sample = [&](const Vec3& p) {
    double dist = searchRadius;
    vcg::Point3d closest;
    grid.GetClosest(pointToFace, marker, vcg::Point3d(p.x(), p.y(), p.z()), searchRadius, dist, closest);
    d.max = std::max(d.max, dist);
    sumSq += dist * dist;
    ++n;
  };
  for (const Vec3& p : from.positions) sample(p);
  for (const Tri& t : from.triangles) {
    const Vec3 &a = from.positions[t[0]], &b = from.positions[t[1]], &c = from.positions[t[2]];
    sample((a + b + c) / 3.0);
    sample(0.5 * (a + b));
    sample(0.5 * (b + c));
    sample(0.5 * (c + a));
  }
  d.rms = std::sqrt(sumSq / n);
  return d;
}

}  // namespace gr
