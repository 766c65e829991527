// Geodesic barycentric coordinates (Peyré & Cohen 2003; paper §4.1), the parameterisation of the
// input over the remesh: a point x of a base triangle (a, b, c) gets, from its geodesic distances
// to the corners and the triangle's geodesic side lengths, the areas of the triangles (x, b, c),
// (x, c, a) and (x, a, b) by Heron's formula; normalised by their sum they are its barycentric
// coordinates (the weights of a, b, c).
//
//                a
//               / \            weight of a = area(x, b, c) / (sum of the three areas), ...
//              /   \           on a plane with straight distances: the exact barycentric
//             /  x  \          coordinates while x is inside; outside, Heron's areas are
//            /       \         unsigned, their sum exceeds the triangle's area, and
//           b---------c        excess = sum / area(a, b, c) - 1 > 0 says how far out.
//
// The excess tells which of the base triangles around a sample holds x (the least excess). Six
// lengths that are not those of a planar configuration (geodesic distances on a curved surface,
// or their fronts' error) still give weights >= 0 summing to 1: a sub-triangle whose lengths
// break the triangle inequality has area 0. Heron's formula in Kahan's stable form (sides sorted):
// a needle triangle keeps its area to a few ulps where the textbook form loses all of it.
#pragma once

#include "core/mesh/tri_mesh.h"  // Vec3

namespace gr {

/// The area of a triangle of side lengths a, b, c (>= 0): Kahan's stable Heron formula; 0 when
/// the lengths break the triangle inequality, NaN when one is negative or not finite.
double heronArea(double a, double b, double c);

struct HeronCoordinates {
  Vec3 weights{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0};  ///< of a, b, c: >= 0, sum 1
  /// (area(x, b, c) + area(x, c, a) + area(x, a, b)) / area(a, b, c) - 1: 0 inside a planar
  /// triangle, > 0 outside it.
  double excess = 0.0;
  /// False when a length is negative or not finite, or the triangle (a, b, c) has no area: the
  /// weights are then (1/3, 1/3, 1/3) and the excess +inf.
  bool valid = true;
};

/// x's coordinates in the triangle (a, b, c) from its distances xa, xb, xc to the corners and the
/// side lengths ab, bc, ca.
HeronCoordinates heronCoordinates(double xa, double xb, double xc, double ab, double bc, double ca);

}  // namespace gr
