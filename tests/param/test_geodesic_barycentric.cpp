// Heron coordinates (paper §4.1). Oracles: points made from known barycentric coordinates on
// planar triangles (straight distances are the geodesic ones there), the closed-form area of a
// needle triangle, and the symmetry of an octant of the unit sphere (great-circle distances).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/param/geodesic_barycentric.h"

namespace gr {
namespace {

HeronCoordinates fromPoints(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  return heronCoordinates((x - a).norm(), (x - b).norm(), (x - c).norm(), (b - a).norm(), (c - b).norm(),
                          (a - c).norm());
}

TEST(HeronCoordinates, ExactInsidePlanarTriangles) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0), w(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng)), c(u(rng), u(rng), u(rng));
    if ((b - a).cross(c - a).norm() < 0.05) continue;  // well away from degenerate
    Vec3 bary(w(rng), w(rng), w(rng));
    bary /= bary.sum();
    const Vec3 x = bary[0] * a + bary[1] * b + bary[2] * c;
    const HeronCoordinates h = fromPoints(x, a, b, c);
    ASSERT_TRUE(h.valid);
    EXPECT_NEAR(h.excess, 0.0, 1e-9) << trial;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(h.weights[k], bary[k], 1e-7) << trial << " corner " << k;
  }
}

TEST(HeronCoordinates, CornersEdgesAndOutside) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 1, 0);
  const HeronCoordinates atB = fromPoints(b, a, b, c);
  EXPECT_NEAR(atB.weights[1], 1.0, 1e-12);
  EXPECT_NEAR(atB.weights[0] + atB.weights[2], 0.0, 1e-12);
  const HeronCoordinates onBc = fromPoints(0.5 * (b + c), a, b, c);
  EXPECT_NEAR(onBc.weights[0], 0.0, 1e-7);
  EXPECT_NEAR(onBc.weights[1], 0.5, 1e-7);
  EXPECT_NEAR(onBc.weights[2], 0.5, 1e-7);
  // Outside: the unsigned areas sum to more than the triangle's, more the farther out.
  double previous = 0.0;
  for (double t : {1.2, 1.5, 2.0, 4.0}) {
    const HeronCoordinates out = fromPoints(t * Vec3(1.0, 0.5, 0.0), a, b, c);  // beyond the midpoint of bc
    ASSERT_TRUE(out.valid);
    EXPECT_GT(out.excess, previous + 1e-6) << t;
    EXPECT_NEAR(out.weights.sum(), 1.0, 1e-12);
    EXPECT_GE(out.weights.minCoeff(), 0.0);
    previous = out.excess;
  }
}

TEST(HeronCoordinates, StableOnANeedleAndBrokenTriangleInequality) {
  // Sides 1, 1, 1e-9: area = (1e-9 / 4) sqrt(4 - 1e-18), to a few ulps with Kahan's form.
  const double exact = 0.25 * 1e-9 * std::sqrt(4.0 - 1e-18);
  EXPECT_NEAR(heronArea(1.0, 1.0, 1e-9), exact, 1e-15 * exact);
  EXPECT_NEAR(heronArea(1e-9, 1.0, 1.0), exact, 1e-15 * exact);
  EXPECT_EQ(heronArea(1.0, 1.0, 3.0), 0.0);
  EXPECT_TRUE(std::isnan(heronArea(-1.0, 1.0, 1.0)));
  EXPECT_TRUE(std::isnan(heronArea(1.0, NAN, 1.0)));
  // A degenerate base triangle, or bad lengths: no coordinates.
  EXPECT_FALSE(heronCoordinates(0.5, 0.5, 0.5, 1.0, 1.0, 2.0).valid);
  EXPECT_FALSE(heronCoordinates(0.5, -0.5, 0.5, 1.0, 1.0, 1.0).valid);
  EXPECT_FALSE(heronCoordinates(0.5, 0.5, INFINITY, 1.0, 1.0, 1.0).valid);
}

// The octant of the unit sphere between the three axes, with great-circle distances (the geodesic
// ones): its centre (1, 1, 1)/sqrt(3) gets equal weights by symmetry, a side's midpoint no weight
// at the opposite corner, and a point nearer a corner more weight there.
TEST(HeronCoordinates, SphericalOctant) {
  const Vec3 a(1, 0, 0), b(0, 1, 0), c(0, 0, 1);
  const auto arc = [](const Vec3& p, const Vec3& q) { return std::acos(std::clamp(p.dot(q), -1.0, 1.0)); };
  const auto coords = [&](const Vec3& x) {
    const Vec3 n = x.normalized();
    return heronCoordinates(arc(n, a), arc(n, b), arc(n, c), arc(a, b), arc(b, c), arc(c, a));
  };
  const HeronCoordinates centre = coords(Vec3(1, 1, 1));
  ASSERT_TRUE(centre.valid);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(centre.weights[k], 1.0 / 3.0, 1e-12);
  const HeronCoordinates mid = coords(Vec3(0, 1, 1));
  EXPECT_NEAR(mid.weights[0], 0.0, 1e-7);
  EXPECT_NEAR(mid.weights[1], 0.5, 1e-7);
  const HeronCoordinates nearA = coords(Vec3(3, 1, 1));
  EXPECT_GT(nearA.weights[0], 0.5);
  EXPECT_NEAR(nearA.weights[1], nearA.weights[2], 1e-12);
}

}  // namespace
}  // namespace gr
