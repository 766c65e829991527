// The local solver of the Eikonal equation on one triangle, shared by fast marching and the
// Voronoi-boundary localisation.
//
//            S   virtual source, unfolded across AB so that |SA| = dA, |SB| = dB
//            |
//      A ----+-------- B       |SX| if the segment SX crosses AB (upwind), else +inf;
//        \   |      /          the caller then falls back to edge updates.
//          \ |   /
//            X
//
// For a point source in the plane the value is exact; it is monotone in dA and dB.
#pragma once

#include <cmath>
#include <limits>

namespace gr {

/// la = |XA|, lb = |XB|, lc = |AB|; dA, dB: unweighted distances at A and B.
/// Returns |SX|, or +inf when the triangle cannot give an upwind update.
inline double virtualSourceDistance(double la, double lb, double lc, double dA, double dB) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (lc <= 0.0) return kInf;
  const double inv2c = 0.5 / lc;
  // Frame: A = (0, 0), B = (lc, 0), X = (xx, xy) with xy > 0, S = (sx, sy) with sy <= 0.
  const double xx = (la * la + lc * lc - lb * lb) * inv2c;
  const double xy2 = la * la - xx * xx;
  if (!(xy2 > 0.0)) return kInf;  // degenerate triangle: edges only
  const double sx = (dA * dA - dB * dB + lc * lc) * inv2c;
  const double sy2 = dA * dA - sx * sx;
  if (sy2 < 0.0) return kInf;  // |dA - dB| > lc: no point at those distances
  const double xy = std::sqrt(xy2), sy = -std::sqrt(sy2);
  // Upwind: the segment S -> X crosses the line y = 0 inside [0, lc].
  const double t = sx + (xx - sx) * (-sy) / (xy - sy);
  if (t < 0.0 || t > lc) return kInf;
  return std::sqrt((xx - sx) * (xx - sx) + (xy - sy) * (xy - sy));
}

}  // namespace gr
