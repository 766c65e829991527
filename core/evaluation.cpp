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

}  // namespace gr
