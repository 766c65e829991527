#include "core/atlas/chart_packing.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gr {
namespace {

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

/// Andrew's monotone chain: the convex hull, counter-clockwise, without collinear points.
std::vector<Vec2> convexHull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  for (size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(h[k - 2], h[k - 1], p[i]) <= 0.0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

/// Height of the shelves holding the rectangles (sorted by decreasing height, first fit: each goes
/// on the lowest shelf with room left, else on a new shelf on top) at `scale`, or +inf if one is
/// wider than the square. Fills `offset` (indexed like `order`'s entries).
double shelfHeight(const std::vector<ChartRectangle>& r, const std::vector<int>& order, double scale, double gutter,
                   std::vector<Vec2>* offset) {
  struct Shelf {
    double y, height, x;
  };
  std::vector<Shelf> shelves;
  double top = 0.0;
  for (int c : order) {
    const double w = scale * r[c].width + 2.0 * gutter, h = scale * r[c].height + 2.0 * gutter;
    if (w > 1.0) return INFINITY;
    Shelf* shelf = nullptr;
    for (Shelf& s : shelves)
      if (s.x + w <= 1.0) {
        shelf = &s;
        break;
      }
    if (!shelf) {
      shelves.push_back({top, h, 0.0});  // the first on its shelf is the tallest of it
      top += h;
      shelf = &shelves.back();
    }
    if (offset) (*offset)[c] = Vec2(shelf->x + gutter, shelf->y + gutter);
    shelf->x += w;
  }
  return top;
}

}  // namespace

ChartRectangle alignToMinimalRectangle(std::vector<Vec2>& points) {
  if (points.empty()) return {};
  const std::vector<Vec2> hull = convexHull(points);
  double bestArea = INFINITY, bestAngle = 0.0;
  for (size_t i = 0; i < hull.size() && hull.size() >= 2; ++i) {  // one side of the rectangle on each hull edge
    const Vec2 e = hull[(i + 1) % hull.size()] - hull[i];
    if (!(e.norm() > 0.0)) continue;
    const Vec2 u = e / e.norm(), v(-u.y(), u.x());
    double lo0 = INFINITY, hi0 = -INFINITY, lo1 = INFINITY, hi1 = -INFINITY;
    for (const Vec2& q : hull) {
      lo0 = std::min(lo0, q.dot(u));
      hi0 = std::max(hi0, q.dot(u));
      lo1 = std::min(lo1, q.dot(v));
      hi1 = std::max(hi1, q.dot(v));
    }
    if ((hi0 - lo0) * (hi1 - lo1) < bestArea) {
      bestArea = (hi0 - lo0) * (hi1 - lo1);
      bestAngle = std::atan2(u.y(), u.x());
    }
  }
  const double c = std::cos(-bestAngle), s = std::sin(-bestAngle);
  Vec2 lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (Vec2& q : points) {
    q = Vec2(c * q.x() - s * q.y(), s * q.x() + c * q.y());
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const bool turn = hi.y() - lo.y() > hi.x() - lo.x();  // a quarter turn makes it wider than tall
  for (Vec2& q : points) {
    q -= lo;
    if (turn) q = Vec2(hi.y() - lo.y() - q.y(), q.x());
  }
  const Vec2 size = hi - lo;
  return turn ? ChartRectangle{size.y(), size.x()} : ChartRectangle{size.x(), size.y()};
}

Expected<ChartPacking> packCharts(const std::vector<ChartRectangle>& rectangles, double gutter) {
  if (!(gutter >= 0.0) || !std::isfinite(gutter)) return invalidInput("chart packing: the gutter must be >= 0");
  double widest = 0.0;
  for (const ChartRectangle& r : rectangles) {
    if (!(r.width >= 0.0 && r.height >= 0.0) || !std::isfinite(r.width) || !std::isfinite(r.height))
      return invalidInput("chart packing: a chart's rectangle has a negative or non-finite side");
    widest = std::max(widest, r.width);
  }
  std::vector<int> order(rectangles.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return rectangles[a].height > rectangles[b].height; });
  ChartPacking p;
  p.offset.assign(rectangles.size(), Vec2::Zero());
  if (shelfHeight(rectangles, order, 0.0, gutter, nullptr) > 1.0)
    return invalidInput("chart packing: " + std::to_string(rectangles.size()) +
                        " charts do not fit in the texture with this gutter: a larger TextureSize or a smaller "
                        "Gutter is needed");
  // Bisection on the scale: feasible at lo, not at hi.
  double lo = 0.0, hi = widest > 0.0 ? 1.0 / widest : 1.0;
  while (shelfHeight(rectangles, order, hi, gutter, nullptr) <= 1.0) hi *= 2.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (shelfHeight(rectangles, order, mid, gutter, nullptr) <= 1.0 ? lo : hi) = mid;
  }
  p.scale = lo;
  p.heightUsed = shelfHeight(rectangles, order, lo, gutter, &p.offset);
  return p;
}

}  // namespace gr
