#include "core/evaluation.h"

#include <algorithm>
#include <cmath>

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

}  // namespace gr
