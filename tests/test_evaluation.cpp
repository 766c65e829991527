// Evaluation measures against hand-computed values: angle statistics of known triangles, and
// the distance between parallel planes and between nested spheres.
#include <gtest/gtest.h>

#include <cmath>

#include "core/evaluation.h"
#include "tests/test_support.h"

namespace gr {
namespace {

TEST(AngleStatistics, KnownTriangles) {
  const TriMesh equilateral =
      std::move(buildTriMesh({{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}}, {{0, 1, 2}})).value();
  const AngleStatistics e = angleStatistics(equilateral);
  EXPECT_NEAR(e.stdDegrees, 0.0, 1e-9);
  EXPECT_NEAR(e.minDegrees, 60.0, 1e-9);
  EXPECT_EQ(e.shareMinBelow30, 0.0);
  // Right isosceles: 45, 45, 90 -> std sqrt((15^2 + 15^2 + 30^2) / 3) = sqrt(450).
  const TriMesh right = std::move(buildTriMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}})).value();
  EXPECT_NEAR(angleStatistics(right).stdDegrees, std::sqrt(450.0), 1e-9);
  EXPECT_NEAR(angleStatistics(right).maxDegrees, 90.0, 1e-9);
  // A needle and an equilateral: half the triangles under 30 degrees.
  const TriMesh both = std::move(buildTriMesh({{0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}, {10, 0.1, 0}},
                                              {{0, 1, 2}, {0, 3, 1}}))
                           .value();
  EXPECT_NEAR(angleStatistics(both).shareMinBelow30, 0.5, 1e-12);
}

TEST(SurfaceDistance, ParallelPlanesAndNestedSpheres) {
  TriMesh a = test::planeGrid(10);
  TriMesh b = test::planeGrid(7);
  for (Vec3& p : b.positions) p.z() = 0.1;
  b = std::move(buildTriMesh(b.positions, b.triangles)).value();
  const SurfaceDistance d = surfaceDistance(a, b);
  EXPECT_NEAR(d.max, 0.1, 1e-9);
  EXPECT_NEAR(d.rms, 0.1, 1e-9);
  // The coarse icosphere lies inside the fine one: from the fine vertices (radius 1) to the
  // coarse faces the distance is at most the coarse sagitta, and positive.
  const TriMesh coarse = test::icosphere(2), fine = test::icosphere(4);
  const SurfaceDistance s = surfaceDistance(fine, coarse);
  const double h = coarse.meanEdgeLength();
  EXPECT_GT(s.max, 0.0);
  EXPECT_LT(s.max, h * h);  // sagitta ~ h^2 / (8 r) with r = 1, generous
  EXPECT_NEAR(surfaceDistance(coarse, coarse).max, 0.0, 1e-12);
}

}  // namespace
}  // namespace gr
