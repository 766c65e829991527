// Order statistics of a list of values.
#pragma once

#include <vector>

namespace gr {

/// The nearest-rank p-th percentile, p in (0, 100]: the smallest value such that at least p% of
/// the values are <= it (rank ceil(p n / 100), at least 1). 0 for no values. Cost: O(n).
double percentile(std::vector<double> values, double p);

}  // namespace gr
