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

/// X's coordinates in the frame of edge AB: A = (0, 0), B = (lc, 0), X = (xx, xy), xy > 0.
struct TriangleFrame {
  double xx = 0.0, xy = 0.0;
  double lc = 0.0, inv2c = 0.0;  ///< |AB| and 1 / (2 |AB|)
  bool valid = false;            ///< false for a degenerate triangle (edge updates only)
};

/// The frame of triangle XAB from la = |XA|, lb = |XB|, lc = |AB|.
inline TriangleFrame triangleFrame(double la, double lb, double lc) {
  TriangleFrame f;
  if (!(lc > 0.0)) return f;
  f.lc = lc;
  f.inv2c = 0.5 / lc;
  f.xx = (la * la + lc * lc - lb * lb) * f.inv2c;
  const double xy2 = la * la - f.xx * f.xx;
  if (!(xy2 > 0.0)) return f;
  f.xy = std::sqrt(xy2);
  f.valid = true;
  return f;
}

/// |SX| for the virtual source S with |SA| = dA, |SB| = dB on the far side of AB from X, or +inf
/// when no such S exists or the segment SX does not cross AB (no upwind update).
inline double virtualSourceDistance(const TriangleFrame& f, double dA, double dB) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!f.valid) return kInf;
  const double sx = (dA * dA - dB * dB + f.lc * f.lc) * f.inv2c;
  const double sy2 = dA * dA - sx * sx;
  if (sy2 < 0.0) return kInf;  // |dA - dB| > lc: no point at those distances
  const double sy = -std::sqrt(sy2);
  // Upwind: S -> X crosses y = 0 at t = sx + (xx - sx) (-sy) / (xy - sy), t in [0, lc];
  // multiplied through by xy - sy > 0 to avoid the division.
  const double den = f.xy - sy;
  const double tTimesDen = sx * den - (f.xx - sx) * sy;
  if (tTimesDen < 0.0 || tTimesDen > f.lc * den) return kInf;
  return std::sqrt((f.xx - sx) * (f.xx - sx) + den * den);
}

/// The same from the three edge lengths: la = |XA|, lb = |XB|, lc = |AB|.
inline double virtualSourceDistance(double la, double lb, double lc, double dA, double dB) {
  return virtualSourceDistance(triangleFrame(la, lb, lc), dA, dB);
}

}  // namespace gr
