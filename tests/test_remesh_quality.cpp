// Triangle quality of uniform remeshing (issue acceptance: no angle under 20 degrees, at most 1%
// of triangles with an angle under 30 degrees) on fandisk, bunny00 and armadillo at 10% and 30%,
// with the fronts on the input subdivided (the filter's Refinement): at the input's own
// resolution samples sit on input vertices, and the cells at 10-30% of the vertices are too
// coarse for those bounds (measured: 0.3-20 deg, 2.6-7.8% of triangles; docs/BENCHMARKS.md).
// Two subdivisions suffice everywhere but on armadillo at 30%, which needs three (with two: a
// smallest angle of 16.8 deg, one triangle across a 52-degree fold; with three: 26.8 deg).
// Angles are recomputed here from the positions (independently of angleStatistics).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <tuple>

#include "core/farthest_point_sampling.h"
#include "core/geodesic_delaunay.h"
#include "core/subdivide.h"
#include "tests/test_support.h"

namespace gr {
namespace {

class RemeshQuality : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(RemeshQuality, WellShapedTrianglesWithRefinement) {
  const auto& [name, fraction] = GetParam();
  const TriMesh input = test::loadRealMesh(name);
  const int levels = name == "armadillo.off" && fraction > 0.2 ? 3 : 2;
  const Expected<Subdivision> fine = subdivideMidpoint(input, levels);
  ASSERT_TRUE(fine);
  FastMarcher marcher(fine->mesh, Metric::uniform());
  FpsParams fps;
  fps.targetCount = static_cast<int>(fraction * input.vertexCount());
  const auto samples = farthestPointSampling(marcher, fps);
  ASSERT_TRUE(samples);
  const auto r = geodesicDelaunay(marcher, samples->points);
  ASSERT_TRUE(r) << r.status().message;
  double smallest = 180.0;
  int below30 = 0;
  for (const Tri& t : r->mesh.triangles) {
    double minAngle = 180.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = r->mesh.positions[t[(k + 1) % 3]] - r->mesh.positions[t[k]];
      const Vec3 w = r->mesh.positions[t[(k + 2) % 3]] - r->mesh.positions[t[k]];
      minAngle = std::min(minAngle, std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI);
    }
    smallest = std::min(smallest, minAngle);
    below30 += minAngle < 30.0;
  }
  const double share = double(below30) / r->mesh.faceCount();
  std::printf("%s %.0f%%, %d subdivisions: %d vertices (%d added), smallest angle %.1f deg, %.2f %% of triangles "
              "under 30 deg\n",
              name.c_str(), 100 * fraction, levels, r->mesh.vertexCount(), r->addedSamples, smallest, 100 * share);
  EXPECT_LE(share, 0.01);
  EXPECT_GE(smallest, 20.0);
}

INSTANTIATE_TEST_SUITE_P(Meshes, RemeshQuality,
                         ::testing::Combine(::testing::Values("fandisk.off", "bunny00.off", "armadillo.off"),
                                            ::testing::Values(0.1, 0.3)),
                         [](const ::testing::TestParamInfo<std::tuple<std::string, double>>& p) {
                           const std::string n = std::get<0>(p.param);
                           return n.substr(0, n.find('.')) + "_" + std::to_string(int(100 * std::get<1>(p.param)));
                         });

}  // namespace
}  // namespace gr
