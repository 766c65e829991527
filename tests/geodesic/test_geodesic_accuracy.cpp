// Accuracy of fast marching on real meshes against CGAL's exact geodesics, side by side with
// Dijkstra along edges, vcglib's tri::Geodesic and CGAL's heat method on the same mesh and source.
// Error measures (core/measure/evaluation.h): mean relative error over vertices at >= 5% of the largest
// exact distance, and the largest absolute error over the largest exact distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_surface.h"
#include "core/measure/evaluation.h"
#include "tests/oracles/geodesic_oracles.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

struct Errors {
  DistanceError fastMarching, dijkstra, vcglib, heat;
};

/// Errors of every method on one mesh from vertex 0, printed as a table.
Errors errorsOn(const std::string& name) {
  const TriMesh mesh = test::loadRealMesh(name);
  const int source = 0;
  const std::vector<double> exact = oracle::exactGeodesic(mesh, source);
  Errors e;
  e.fastMarching = distanceError(fastMarching(mesh, Metric::uniform(), {source})->distance, exact);
  e.dijkstra = distanceError(oracle::dijkstra(mesh, source), exact);
  e.vcglib = distanceError(oracle::vcgGeodesic(mesh, source), exact);
  e.heat = distanceError(oracle::HeatMethod(mesh).query(source), exact);
  std::printf("%-16s %-14s %12s %12s\n", name.c_str(), "method", "mean rel %", "max/max %");
  auto row = [](const char* method, const DistanceError& d) {
    std::printf("%-16s %-14s %12.4f %12.4f\n", "", method, 100 * d.meanRelative, 100 * d.maxRelativeToMax);
  };
  row("fast marching", e.fastMarching);
  row("dijkstra", e.dijkstra);
  row("vcglib", e.vcglib);
  row("heat (CGAL)", e.heat);
  return e;
}

class RealMeshAccuracy : public ::testing::TestWithParam<std::string> {};

// One test per mesh (CGAL's exact geodesics dominate the cost), three targets of issue 4.
TEST_P(RealMeshAccuracy, FastMarchingMeetsTheTargetsAgainstExactGeodesics) {
  const Errors e = errorsOn(GetParam());
  EXPECT_LE(e.fastMarching.meanRelative, 0.01) << "mean relative error above 1%";
  EXPECT_LE(e.fastMarching.meanRelative, e.dijkstra.meanRelative / 5) << "not 5x better than Dijkstra";
  EXPECT_LE(e.fastMarching.meanRelative, e.vcglib.meanRelative) << "less accurate than vcglib's tri::Geodesic";
  EXPECT_LE(e.fastMarching.maxRelativeToMax, e.vcglib.maxRelativeToMax) << "larger worst error than vcglib";
}

INSTANTIATE_TEST_SUITE_P(Meshes, RealMeshAccuracy, ::testing::Values("fandisk.off", "bunny00.off", "armadillo.off"),
                         [](const ::testing::TestParamInfo<std::string>& p) {
                           const std::string& n = p.param;
                           return n.substr(0, n.find('.'));
                         });

}  // namespace
}  // namespace gr

namespace gr {
namespace {

/// Smallest angle of any face, in degrees.
double smallestAngleDegrees(const TriMesh& m) { return test::recountAngles(m).smallestDegrees; }

void expectFiniteMonotoneComplete(const TriMesh& m, const FastMarchingResult& r) {
  ASSERT_EQ(m.topology.components, 1);
  EXPECT_EQ(r.reachedCount(), m.vertexCount()) << "not every vertex reached";
  for (double d : r.distance) ASSERT_TRUE(std::isfinite(d));
  for (size_t i = 1; i < r.acceptedOrder.size(); ++i)
    ASSERT_GE(r.distance[r.acceptedOrder[i]], r.distance[r.acceptedOrder[i - 1]]) << "not monotone at " << i;
}

// Very bad triangles (needles under 1 degree, zero-area faces) on the surfaces of the good
// meshes: the field stays finite, monotone and complete, and its error against the exact
// geodesics of the same surface stays within 2x of the error on the original triangulation.
TEST(BadTriangles, NeedlesAndZeroAreaFacesStayWithinTwiceTheGoodError) {
  for (const char* name : {"fandisk.off", "bunny00.off", "armadillo.off"}) {
    SCOPED_TRACE(name);
    const TriMesh good = test::loadRealMesh(name);
    int zeroArea = 0;
    const TriMesh bad = test::withBadTriangles(good, &zeroArea);
    ASSERT_GT(zeroArea, 100);
    ASSERT_LT(smallestAngleDegrees(bad), 1.0);
    const std::vector<double> exact = oracle::exactGeodesic(good, 0);
    const DistanceError eGood = distanceError(fastMarching(good, Metric::uniform(), {0})->distance, exact);
    const auto r = fastMarching(bad, Metric::uniform(), {0});
    ASSERT_TRUE(r);
    expectFiniteMonotoneComplete(bad, *r);
    const std::vector<double> atOriginal(r->distance.begin(), r->distance.begin() + good.vertexCount());
    const DistanceError eBad = distanceError(atOriginal, exact);
    std::printf(
        "%-14s good: mean %.4f %% max %.4f %% | %d needles/zero-area faces, smallest angle %.4f deg: mean %.4f %% max "
        "%.4f %%\n",
        name, 100 * eGood.meanRelative, 100 * eGood.maxRelativeToMax, 2 * zeroArea, smallestAngleDegrees(bad),
        100 * eBad.meanRelative, 100 * eBad.maxRelativeToMax);
    EXPECT_LE(eBad.meanRelative, 2.0 * eGood.meanRelative);
  }
}

// Meshes of the data set that come with slivers (angles down to 0.03 degree) and angles above
// 150 degrees, through geodesicDistance: finite, monotone and complete at the input's vertices;
// mean error within 2x of the mean error on the good meshes (fandisk, bunny00, armadillo), well
// ahead of Dijkstra and no worse than vcglib, cheese.off included (genus 133, holes in flat faces
// with vertices only on their rims: 4.98% on the input; by default exact, issue 17). The fronts
// alone (ExactPropagation::Never: what the remeshing runs; Auto refines each of these meshes) are
// held to the same bounds, except cheese's 2x (0.87%: within issue 17's 1%).
TEST(BadTriangles, DataSetSliverMeshes) {
  double goodSum = 0.0;
  for (const char* name : {"fandisk.off", "bunny00.off", "armadillo.off"}) {
    const TriMesh m = test::loadRealMesh(name);
    goodSum +=
        distanceError(fastMarching(m, Metric::uniform(), {0})->distance, oracle::exactGeodesic(m, 0)).meanRelative;
  }
  const double good = goodSum / 3.0;
  for (const char* name : {"blade.off", "mannequin-devil.off", "turbine.off", "cheese.off"}) {
    SCOPED_TRACE(name);
    const TriMesh m = test::loadRealMesh(name);
    const std::vector<double> exact = oracle::exactGeodesic(m, 0);
    const DistanceError eDijkstra = distanceError(oracle::dijkstra(m, 0), exact);
    const DistanceError eVcg = distanceError(oracle::vcgGeodesic(m, 0), exact);
    const auto r = geodesicDistance(m, {}, {0});
    ASSERT_TRUE(r);
    expectFiniteMonotoneComplete(m, r->field);
    const DistanceError e = distanceError(r->field.distance, exact);
    GeodesicDistanceParams frontsOnly;
    frontsOnly.exact = ExactPropagation::Never;
    const auto fronts = geodesicDistance(m, {}, {0}, frontsOnly);
    ASSERT_TRUE(fronts);
    EXPECT_TRUE(fronts->refined);
    expectFiniteMonotoneComplete(m, fronts->field);
    const DistanceError eFronts = distanceError(fronts->field.distance, exact);
    std::printf(
        "%-20s smallest angle %.3f deg: default (%s) %.4f %%, fronts (%d points inserted) %.4f %%, vcglib %.4f %%, "
        "Dijkstra %.4f %% (2x the good meshes: %.4f %%)\n",
        name, smallestAngleDegrees(m), r->exact ? "exact" : "refined", 100 * e.meanRelative, fronts->insertedPoints,
        100 * eFronts.meanRelative, 100 * eVcg.meanRelative, 100 * eDijkstra.meanRelative, 200 * good);
    EXPECT_LE(e.meanRelative, 2.0 * good);
    EXPECT_LE(e.meanRelative, eDijkstra.meanRelative / 3);
    EXPECT_LE(e.meanRelative, eVcg.meanRelative);
    EXPECT_LE(eFronts.meanRelative, 0.01);
    EXPECT_LE(eFronts.meanRelative, eVcg.meanRelative);
    EXPECT_LE(eFronts.meanRelative, eDijkstra.meanRelative / 3);
    // cheese.off's fronts: 0.87%, under issue 17's 1% but above twice the scans' mean (0.65%).
    if (std::string(name) != "cheese.off") {
      EXPECT_LE(eFronts.meanRelative, 2.0 * good);
    }
  }
}

}  // namespace
}  // namespace gr
