// Numbers and durations as text, for messages and logs.
#pragma once

#include <string>

namespace gr {

/// printf-style formatting of one number ("%.4g").
std::string formatNumber(double x, const char* spec = "%.6g");
/// A duration: "87.7 ms" under ten seconds, "23.5 s" from there on.
std::string formatDuration(double milliseconds);

}  // namespace gr
