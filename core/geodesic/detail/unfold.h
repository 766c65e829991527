// Planar unfolding of a triangle across an edge: the building block of acute splits and of
// the exact initialisation around sources.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace gr {

using Vec2 = Eigen::Vector2d;

inline double cross2(const Vec2& u, const Vec2& v) { return u.x() * v.y() - u.y() * v.x(); }

/// A triangle P0 P1 P2 laid out in its plane from its edge lengths: P0 at the origin, P1 at
/// (l01, 0); returns P2 (above the x axis). A zero l01 puts P2 on the y axis.
inline Vec2 layoutThirdVertex(double l01, double l02, double l12) {
  const double x = l01 > 0.0 ? (l01 * l01 + l02 * l02 - l12 * l12) / (2.0 * l01) : 0.0;
  return Vec2(x, std::sqrt(std::max(0.0, l02 * l02 - x * x)));
}

/// Position of R in the plane, given the edge (p, q) and the lengths |PR|, |QR|, on the side of
/// the line pq opposite to the point t (the third vertex of the triangle already laid out).
inline Vec2 unfold(const Vec2& p, const Vec2& q, const Vec2& t, double lenPR, double lenQR) {
  const Vec2 e = q - p;
  const double len = e.norm();
  const Vec2 dir = e / len;
  const double along = (lenPR * lenPR - lenQR * lenQR + len * len) / (2.0 * len);
  const double h = std::sqrt(std::max(0.0, lenPR * lenPR - along * along));
  Vec2 normal(-dir.y(), dir.x());
  if (cross2(e, t - p) * cross2(e, normal) > 0.0) normal = -normal;  // away from t
  return p + dir * along + normal * h;
}

/// True if the segments [a, b] and [c, d] intersect (touching counts).
inline bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
  const double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
  const double d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
  const double eps = 1e-12 * ((b - a).squaredNorm() + (d - c).squaredNorm());
  return d1 * d2 <= eps && d3 * d4 <= eps;
}

}  // namespace gr
