// Mathematical constants of the project (kPi is not standard C++).
#pragma once

namespace gr {

/// pi, the same double as kPi.
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace gr
