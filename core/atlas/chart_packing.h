// Charts laid out in the unit square: each chart turned to its minimal bounding rectangle, then
// all rectangles packed on shelves at one common scale, the largest that fits.
//
//   chart UVs --convex hull, rotating calipers--> rotated so that its minimal-area bounding
//   rectangle is axis-aligned at the origin, wider than tall
//   rectangles --sorted by height, first fit on shelves (each on the lowest shelf with room, else
//   on a new shelf on top), each padded by the gutter on every side--> offsets; the scale is found by bisection (the shelves' height is
//   checked for each trial scale) so that the packing fills [0, 1]^2 as far as shelves allow.
//
// Charts in distinct rectangles never overlap, and the gutter keeps texture filtering of one
// chart from bleeding into another. Cost: O(n log n) per chart (the hull), O(60 C S) to pack C
// charts on S shelves.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/base/status.h"

namespace gr {

using Vec2 = Eigen::Vector2d;

/// Width and height of a chart's bounding rectangle (in the chart's own units).
struct ChartRectangle {
  double width = 0.0, height = 0.0;
};

/// Rotates (and translates) `points` so that their minimal-area bounding rectangle is
/// [0, width] x [0, height] with width >= height; returns that rectangle. Orientation (the sign
/// of areas) is kept: a rotation, never a mirror. Empty input: a 0 x 0 rectangle.
ChartRectangle alignToMinimalRectangle(std::vector<Vec2>& points);

struct ChartPacking {
  double scale = 0.0;        ///< chart units -> unit square
  std::vector<Vec2> offset;  ///< per chart, where its rectangle's origin goes (after scaling)
  double heightUsed = 0.0;   ///< of the unit square's height, by the shelves (<= 1)
};

/// Packs the rectangles, scaled by one common factor, into [0, 1]^2 with `gutter` (in unit-square
/// units, >= 0) of empty space around each one, so that chart c occupies
/// offset[c] + scale * [0, width] x [0, height]. InvalidInput if a rectangle has a negative or
/// non-finite side, the gutter is negative, or the gutters alone do not fit.
Expected<ChartPacking> packCharts(const std::vector<ChartRectangle>& rectangles, double gutter);

}  // namespace gr
