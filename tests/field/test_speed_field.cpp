// Speed from a per-vertex field (paper §3.3-3.4): the three mappings against values worked out by
// hand from the formulas in speed_field.h, the robust scale (nearest-rank percentile), the
// fallbacks, and every rejected input with its message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "core/field/speed_field.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

// planeGrid(n) has (n + 1)^2 vertices; planeGrid(3) has 16.
constexpr int kGridVertices = 16;
const TriMesh& grid() {
  static const TriMesh m = test::planeGrid(3);
  return m;
}

/// q = 0, 1, ..., 15: the 95th percentile by nearest rank is the ceil(0.95 * 16) = 16th value, 15;
/// the 50th is the 8th value, 7.
std::vector<double> ramp() {
  std::vector<double> q(kGridVertices);
  for (int v = 0; v < kGridVertices; ++v) q[v] = v;
  return q;
}

TEST(SpeedField, AttractiveIsPaperF2WithRobustScale) {
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Attractive;
  p.strength = 3.0;
  p.percentile = 50.0;
  const auto r = speedFromField(grid(), ramp(), p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->scale, 7.0);
  EXPECT_FALSE(r->usedFallback());
  EXPECT_EQ(r->fieldMin, 0.0);
  EXPECT_EQ(r->fieldMax, 15.0);
  // F = 1 / (1 + 3 q / 7): q = 0 -> 1, q = 7 -> 1/4, q = 14 -> 1/7, q = 15 -> 7/52.
  EXPECT_DOUBLE_EQ(r->speed[0], 1.0);
  EXPECT_DOUBLE_EQ(r->speed[7], 0.25);
  EXPECT_DOUBLE_EQ(r->speed[14], 1.0 / 7.0);
  EXPECT_DOUBLE_EQ(r->speed[15], 7.0 / 52.0);
  EXPECT_DOUBLE_EQ(r->speedMax, 1.0);
  EXPECT_DOUBLE_EQ(r->speedMin, 7.0 / 52.0);
  ASSERT_EQ(r->metric.P.size(), 16u);
  for (int v = 0; v < kGridVertices; ++v) EXPECT_DOUBLE_EQ(r->metric.P[v], 1.0 + 3.0 * v / 7.0) << v;
}

TEST(SpeedField, RepulsiveIsPaperF1) {
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Repulsive;
  p.strength = 2.0;  // default percentile 95 -> scale 15
  const auto r = speedFromField(grid(), ramp(), p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->scale, 15.0);
  // F = 1 + 2 q / 15: q = 0 -> 1, q = 6 -> 1.8, q = 15 -> 3.
  EXPECT_DOUBLE_EQ(r->speed[0], 1.0);
  EXPECT_DOUBLE_EQ(r->speed[6], 1.8);
  EXPECT_DOUBLE_EQ(r->speed[15], 3.0);
  EXPECT_DOUBLE_EQ(r->metric.P[15], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(r->speedMin, 1.0);
  EXPECT_DOUBLE_EQ(r->speedMax, 3.0);
}

TEST(SpeedField, DirectMapsTheRangeOntoOneOverRToOne) {
  // q from -5 to 10 (signed is fine for Direct); percentile 100: plain affine map.
  std::vector<double> q(kGridVertices);
  for (int v = 0; v < kGridVertices; ++v) q[v] = v - 5.0;
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Direct;
  p.strength = 4.0;
  p.percentile = 100.0;
  const auto r = speedFromField(grid(), q, p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->scale, 15.0);
  EXPECT_EQ(r->fieldMin, -5.0);
  EXPECT_EQ(r->fieldMax, 10.0);
  // F = 1/4 + 3/4 (q + 5) / 15.
  EXPECT_DOUBLE_EQ(r->speed[0], 0.25);
  EXPECT_DOUBLE_EQ(r->speed[5], 0.5);
  EXPECT_DOUBLE_EQ(r->speed[10], 0.75);
  EXPECT_DOUBLE_EQ(r->speed[15], 1.0);
  // The ratio of the extreme speeds is r.
  EXPECT_DOUBLE_EQ(r->speedMax / r->speedMin, 4.0);
}

TEST(SpeedField, DirectSaturatesAboveTheRobustScale) {
  // 15 vertices with q - min in 0..14 and one outlier at 1000: the 90th percentile of q - min is
  // the 15th value, 14; the outlier saturates at F = 1 instead of squashing the others.
  std::vector<double> q = ramp();
  q[15] = 1000.0;
  for (double& x : q) x += 2.0;
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Direct;
  p.strength = 2.0;
  p.percentile = 90.0;
  const auto r = speedFromField(grid(), q, p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->scale, 14.0);
  EXPECT_DOUBLE_EQ(r->speed[0], 0.5);
  EXPECT_DOUBLE_EQ(r->speed[7], 0.75);
  EXPECT_DOUBLE_EQ(r->speed[14], 1.0);
  EXPECT_DOUBLE_EQ(r->speed[15], 1.0);
}

TEST(SpeedField, SameStrengthSameSpeedInAnyUnits) {
  // Scaling the field (other units, another mesh size) leaves the speed unchanged.
  std::vector<double> q = ramp(), q1000 = ramp();
  for (double& x : q1000) x *= 1e-3;
  for (SpeedMapping m : {SpeedMapping::Direct, SpeedMapping::Attractive, SpeedMapping::Repulsive}) {
    SpeedFieldParams p;
    p.mapping = m;
    const auto a = speedFromField(grid(), q, p);
    const auto b = speedFromField(grid(), q1000, p);
    ASSERT_TRUE(a && b);
    for (int v = 0; v < kGridVertices; ++v) EXPECT_NEAR(a->speed[v], b->speed[v], 1e-12) << toString(m) << " " << v;
  }
}

TEST(SpeedField, ZeroStrengthIsUniform) {
  for (SpeedMapping m : {SpeedMapping::Attractive, SpeedMapping::Repulsive}) {
    SpeedFieldParams p;
    p.mapping = m;
    p.strength = 0.0;
    const auto r = speedFromField(grid(), ramp(), p);
    ASSERT_TRUE(r) << r.status().message;
    EXPECT_TRUE(r->metric.isUniform());
    EXPECT_EQ(r->speedMin, 1.0);
    EXPECT_EQ(r->speedMax, 1.0);
  }
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Direct;
  p.strength = 1.0;
  const auto r = speedFromField(grid(), ramp(), p);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->metric.isUniform());
}

TEST(SpeedField, ConstantFieldFallsBackToUniformSpeed) {
  for (SpeedMapping m : {SpeedMapping::Direct, SpeedMapping::Attractive, SpeedMapping::Repulsive}) {
    for (double c : {0.0, 2.5}) {
      SpeedFieldParams p;
      p.mapping = m;
      const auto r = speedFromField(grid(), std::vector<double>(kGridVertices, c), p);
      ASSERT_TRUE(r) << r.status().message;
      EXPECT_TRUE(r->usedFallback());
      EXPECT_NE(r->fallback.find("constant"), std::string::npos) << r->fallback;
      EXPECT_TRUE(r->metric.isUniform());
      ASSERT_EQ(r->speed.size(), 16u);
      for (double F : r->speed) EXPECT_EQ(F, 1.0);
      EXPECT_EQ(r->fieldMin, c);
      EXPECT_EQ(r->fieldMax, c);
    }
  }
}

TEST(SpeedField, ZeroPercentileFallsBackToTheMaximum) {
  // 15 zeros and one 4: the 95th percentile (16th value) is 4, but the 90th (15th value) is 0.
  std::vector<double> q(kGridVertices, 0.0);
  q[9] = 4.0;
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Attractive;
  p.strength = 1.0;
  p.percentile = 90.0;
  const auto r = speedFromField(grid(), q, p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_TRUE(r->usedFallback());
  EXPECT_NE(r->fallback.find("15 of 16"), std::string::npos) << r->fallback;
  EXPECT_EQ(r->scale, 4.0);
  EXPECT_DOUBLE_EQ(r->speed[9], 0.5);
  EXPECT_DOUBLE_EQ(r->speed[0], 1.0);
  // Direct: the same with the zeros shifted to -1 (at the minimum).
  for (double& x : q) x -= 1.0;
  p.mapping = SpeedMapping::Direct;
  p.strength = 2.0;
  const auto d = speedFromField(grid(), q, p);
  ASSERT_TRUE(d) << d.status().message;
  EXPECT_TRUE(d->usedFallback());
  EXPECT_EQ(d->scale, 4.0);
  EXPECT_DOUBLE_EQ(d->speed[9], 1.0);
  EXPECT_DOUBLE_EQ(d->speed[0], 0.5);
  // With the default percentile there is no fallback.
  p.percentile = 95.0;
  EXPECT_FALSE(speedFromField(grid(), q, p)->usedFallback());
}

void expectInvalid(const Expected<SpeedFieldResult>& r, const std::string& fragment) {
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  EXPECT_NE(r.status().message.find(fragment), std::string::npos) << r.status().message;
}

TEST(SpeedField, RejectsNonFiniteValuesNamingTheVertex) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}) {
    for (SpeedMapping m : {SpeedMapping::Direct, SpeedMapping::Attractive, SpeedMapping::Repulsive}) {
      std::vector<double> q = ramp();
      q[11] = bad;
      SpeedFieldParams p;
      p.mapping = m;
      expectInvalid(speedFromField(grid(), q, p), "vertex 11");
    }
  }
}

TEST(SpeedField, RejectsNegativeValuesWhereTheMappingNeedsThem) {
  std::vector<double> q = ramp();
  q[4] = -0.5;
  q[6] = -0.25;
  for (SpeedMapping m : {SpeedMapping::Attractive, SpeedMapping::Repulsive}) {
    SpeedFieldParams p;
    p.mapping = m;
    const auto r = speedFromField(grid(), q, p);
    expectInvalid(r, "vertex 4 has q = -0.5 (2 negative vertices)");
    expectInvalid(r, toString(m));
  }
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Direct;
  const auto r = speedFromField(grid(), q, p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->fieldMin, -0.5);
  for (double F : r->speed) EXPECT_TRUE(F >= 1.0 / p.strength && F <= 1.0) << F;
}

TEST(SpeedField, RejectsBadParameters) {
  const std::vector<double> q = ramp();
  SpeedFieldParams p;
  for (double s : {-1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    for (SpeedMapping m : {SpeedMapping::Direct, SpeedMapping::Attractive, SpeedMapping::Repulsive}) {
      p.mapping = m;
      p.strength = s;
      expectInvalid(speedFromField(grid(), q, p), "strength");
    }
  }
  p.mapping = SpeedMapping::Direct;
  p.strength = 0.5;
  expectInvalid(speedFromField(grid(), q, p), "r and must be >= 1");
  p.strength = 2.0;
  for (double pc : {0.0, -5.0, 100.5, std::nan("")}) {
    p.percentile = pc;
    expectInvalid(speedFromField(grid(), q, p), "percentile");
  }
  p.percentile = 95.0;
  expectInvalid(speedFromField(grid(), std::vector<double>(5, 1.0), p), "5 values for 16 vertices");
  expectInvalid(speedFromField(TriMesh{}, {}, p), "no vertices");
}

TEST(SpeedField, RejectsARangeTooWideForTheSpeed) {
  // q / scale overflows: the 90th percentile (15th of 16 values) is the smallest normal double,
  // the largest value 1e300.
  std::vector<double> q(kGridVertices, std::numeric_limits<double>::min());
  q[0] = 0.0;
  q[3] = 1e300;
  SpeedFieldParams p;
  p.mapping = SpeedMapping::Repulsive;
  p.percentile = 90.0;
  expectInvalid(speedFromField(grid(), q, p), "vertex 3 is not representable");
  p.mapping = SpeedMapping::Attractive;
  expectInvalid(speedFromField(grid(), q, p), "vertex 3 is not representable");
}

}  // namespace
}  // namespace gr

namespace gr {
namespace {

// Gradation (limitSpeedGrowth): on a regular grid of the unit square, F = 0.1 on the column
// x = 0.5 and 1 elsewhere. Lowered to min over y of F(y) + g d(x, y) along edges, F becomes
// min(1, 0.1 + g |x - 0.5|) exactly on the grid's rows (the shortest edge path to the column runs
// along the row), the metric P = 1/F follows, speedMax and the count of lowered vertices are those
// of that closed form; growth 0 and a uniform metric change nothing.
TEST(SpeedFieldGradation, GrowthFromASlowColumnIsTheClosedForm) {
  constexpr int kN = 40;  // planeGrid(40): 41 x 41 vertices, spacing 1/40
  const TriMesh m = test::planeGrid(kN);
  SpeedFieldResult speed;
  speed.speed.assign(m.vertexCount(), 1.0);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (std::abs(m.positions[v].x() - 0.5) < 1e-9) speed.speed[v] = 0.1;
  speed.metric = Metric::fromSpeed(m, speed.speed).value();
  speed.speedMin = 0.1;
  const double g = 2.0;
  const int lowered = limitSpeedGrowth(m, g, speed);
  int expectLowered = 0;
  double largest = 0.0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const double expected = std::min(1.0, 0.1 + g * std::abs(m.positions[v].x() - 0.5));
    EXPECT_NEAR(speed.speed[v], expected, 1e-12) << "vertex " << v;
    EXPECT_NEAR(speed.metric.P[v], 1.0 / expected, 1e-9) << "vertex " << v;
    expectLowered += expected < 1.0 && std::abs(m.positions[v].x() - 0.5) > 1e-9;
    largest = std::max(largest, expected);
  }
  EXPECT_EQ(lowered, expectLowered);
  EXPECT_DOUBLE_EQ(speed.speedMax, largest);

  const std::vector<double> before = speed.speed;
  EXPECT_EQ(limitSpeedGrowth(m, 0.0, speed), 0);
  EXPECT_EQ(speed.speed, before);
  SpeedFieldResult uniform;
  uniform.speed.assign(m.vertexCount(), 1.0);
  EXPECT_EQ(limitSpeedGrowth(m, g, uniform), 0);
}

}  // namespace
}  // namespace gr
