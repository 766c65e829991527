#include "core/param/geodesic_barycentric.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gr {

double heronArea(double a, double b, double c) {
  if (!(a >= 0.0) || !(b >= 0.0) || !(c >= 0.0) || !std::isfinite(a + b + c))
    return std::numeric_limits<double>::quiet_NaN();
  // Kahan, "Miscalculating area and angles of a needle-like triangle": a >= b >= c, and the
  // parentheses as written.
  if (a < b) std::swap(a, b);
  if (a < c) std::swap(a, c);
  if (b < c) std::swap(b, c);
  const double product = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return product > 0.0 ? 0.25 * std::sqrt(product) : 0.0;
}

HeronCoordinates heronCoordinates(double xa, double xb, double xc, double ab, double bc, double ca) {
  HeronCoordinates r;
  const double whole = heronArea(ab, bc, ca);
  const Vec3 part(heronArea(xb, xc, bc), heronArea(xc, xa, ca), heronArea(xa, xb, ab));
  const double sum = part.sum();
  if (!(whole > 0.0) || !std::isfinite(sum)) {
    r.valid = false;
    r.excess = std::numeric_limits<double>::infinity();
    return r;
  }
  r.excess = sum / whole - 1.0;
  // For planar lengths sum >= whole > 0; lengths that fit no planar x can make all three parts
  // vanish (excess -1), and x then keeps the triangle's centre.
  if (sum > 0.0) r.weights = part / sum;
  return r;
}

}  // namespace gr
