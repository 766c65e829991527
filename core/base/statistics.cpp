#include "core/base/statistics.h"

#include <algorithm>
#include <cmath>

namespace gr {

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  const double n = static_cast<double>(values.size());
  size_t rank = static_cast<size_t>(std::ceil(p * n / 100.0));  // p * n first: exact for integer p
  rank = std::clamp<size_t>(rank, 1, values.size());
  std::nth_element(values.begin(), values.begin() + (rank - 1), values.end());
  return values[rank - 1];
}

}  // namespace gr
