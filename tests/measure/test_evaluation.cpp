// Evaluation measures against hand-computed values: angle statistics of known triangles, and
// the distance between parallel planes and between nested spheres.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "core/measure/evaluation.h"
#include "tests/support/test_support.h"

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

/// Distance from p to triangle abc, by brute force: the nearest of the plane's foot (if inside)
/// and the three sides (Ericson's closest-point tests, written out independently of vcglib).
double pointTriangleDistance(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const auto toSegment = [&](const Vec3& s, const Vec3& t) {
    const Vec3 st = t - s;
    const double len2 = st.squaredNorm();
    const double u = len2 > 0.0 ? std::clamp((p - s).dot(st) / len2, 0.0, 1.0) : 0.0;
    return (p - (s + u * st)).norm();
  };
  double best = std::min({toSegment(a, b), toSegment(b, c), toSegment(c, a)});
  const Vec3 n = (b - a).cross(c - a);
  if (n.squaredNorm() > 0.0) {
    const Vec3 foot = p - n * ((p - a).dot(n) / n.squaredNorm());
    const bool inside = (b - a).cross(foot - a).dot(n) >= 0.0 && (c - b).cross(foot - b).dot(n) >= 0.0 &&
                        (a - c).cross(foot - c).dot(n) >= 0.0;
    if (inside) best = std::min(best, (p - foot).norm());
  }
  return best;
}

/// Max and RMS over the samples of `from` (vertices and, if asked, centroids and the sides'
/// midpoints), each measured to every face of `to`.
SurfaceDistance bruteForceDistance(const TriMesh& from, const TriMesh& to, bool faceSamples) {
  double maxBrute = 0.0, sumSq = 0.0;
  long n = 0;
  const auto sample = [&](const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const Tri& t : to.triangles)
      best = std::min(best, pointTriangleDistance(p, to.positions[t[0]], to.positions[t[1]], to.positions[t[2]]));
    maxBrute = std::max(maxBrute, best);
    sumSq += best * best;
    ++n;
  };
  for (const Vec3& p : from.positions) sample(p);
  for (const Tri& t : from.triangles) {
    if (!faceSamples) break;
    const Vec3 &a = from.positions[t[0]], &b = from.positions[t[1]], &c = from.positions[t[2]];
    sample((a + b + c) / 3.0), sample(0.5 * (a + b)), sample(0.5 * (b + c)), sample(0.5 * (c + a));
  }
  SurfaceDistance d;
  d.max = maxBrute;
  d.rms = std::sqrt(sumSq / n);
  return d;
}

// The grid search, on any number of threads, against every sample measured to every face; both
// sample sets.
TEST(SurfaceDistance, MatchesBruteForceOnAnyNumberOfThreads) {
  const TriMesh from = test::loadRealMesh("fandisk.off");
  const TriMesh to = test::icosphere(2, 0.3);  // 320 faces; 58k samples: four blocks
  for (const DistanceSamples samples : {DistanceSamples::VerticesMidpointsCentroids, DistanceSamples::Vertices}) {
    const SurfaceDistance brute = bruteForceDistance(from, to, samples == DistanceSamples::VerticesMidpointsCentroids);
    const SurfaceDistance one = surfaceDistance(from, to, {}, 1, samples);
    EXPECT_NEAR(one.max, brute.max, 1e-9 * brute.max);
    EXPECT_NEAR(one.rms, brute.rms, 1e-9 * brute.rms);
    for (int threads : {2, 3, 8}) {
      const SurfaceDistance many = surfaceDistance(from, to, {}, threads, samples);
      EXPECT_EQ(many.max, one.max) << threads << " threads";
      EXPECT_EQ(many.rms, one.rms) << threads << " threads";
      EXPECT_TRUE(many.complete);
    }
  }
}

TEST(SurfaceDistance, CancelledThroughProgress) {
  const TriMesh from = test::icosphere(5), to = test::icosphere(3);
  int calls = 0;
  const SurfaceDistance d = surfaceDistance(from, to, Progress([&](int, const char*) { return ++calls < 2; }), 2);
  EXPECT_FALSE(d.complete);
  EXPECT_EQ(calls, 2);
}

}  // namespace
}  // namespace gr
