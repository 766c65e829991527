#include "core/base/format.h"

#include <cstdio>

namespace gr {

std::string formatNumber(double x, const char* spec) {
  char buf[64];
  std::snprintf(buf, sizeof buf, spec, x);
  return buf;
}

std::string formatDuration(double milliseconds) {
  // "%.3g" would print 2870 ms as "2.87e+03 ms": seconds from 1,000 ms on.
  return milliseconds < 1000.0 ? formatNumber(milliseconds, "%.3g") + " ms"
                               : formatNumber(milliseconds / 1000.0, "%.3g") + " s";
}

}  // namespace gr
