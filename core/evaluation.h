// Evaluation measures used the same way everywhere in the project (tests, benchmarks, logs).
#pragma once

#include <vector>

namespace gr {

/// Error of a distance field d against a reference field (e.g. exact geodesics).
struct DistanceError {
  /// Mean of |d - ref| / ref over the vertices whose ref is at least 5% of the largest ref.
  double meanRelative = 0.0;
  /// Largest |d - ref|, divided by the largest ref.
  double maxRelativeToMax = 0.0;
  int comparedVertices = 0;  ///< vertices in the mean
};

/// Vertices where either field is not finite are skipped.
DistanceError distanceError(const std::vector<double>& d, const std::vector<double>& reference);

}  // namespace gr
