// Triangle quality of uniform remeshing (issue acceptance: no angle under 20 degrees, at most 1%
// of triangles with an angle under 30 degrees) on fandisk, bunny00 and armadillo at 10% and 30%,
// at the default settings: the whole core pipeline (core/remesh/remesh.h) on the input as it is. The
// geodesic Delaunay triangulation alone does not meet the bounds at this resolution (samples on
// input vertices, cells of 3-10 vertices: 0.5-20.4 deg, 2.6-7.8% of triangles; docs/BENCHMARKS.md);
// the relaxation after it does. Angles are recomputed here from the positions (independently of
// angleStatistics), and the test also checks what the relaxation must not break: the topology
// (recounted independently), and every vertex on the input surface.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/remesh/remesh_surface.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

class RemeshQuality : public ::testing::TestWithParam<std::tuple<std::string, double>> {};

TEST_P(RemeshQuality, WellShapedTrianglesAtDefaultSettings) {
  const auto& [name, fraction] = GetParam();
  const TriMesh input = test::loadRealMesh(name);
  SurfaceRemeshParams params;
  params.sampling.targetCount = static_cast<int>(fraction * input.vertexCount());
  params.measure = false;
  const Expected<SurfaceRemeshResult> remeshed = remeshSurface(input, params);
  ASSERT_TRUE(remeshed) << remeshed.status().message;
  const SurfaceRemeshResult& r = *remeshed;
  // The count search (issue 20) may have redone the sampling with fewer samples than asked.
  EXPECT_EQ(r.countAsked, params.sampling.targetCount);
  EXPECT_EQ(r.mesh.vertexCount(),
            r.sampledAsked + r.addedSamples - r.droppedSamples - r.collapsedVertices - r.removedEars + r.splitVertices);
  const test::Recount in = test::recount(input.triangles, input.vertexCount());
  const test::Recount out = test::recount(r.mesh.triangles, r.mesh.vertexCount());
  EXPECT_TRUE(out.manifoldEdges && out.manifoldVertices && out.oriented);
  EXPECT_EQ(out.components, in.components);
  EXPECT_EQ(out.genusSum, in.genusSum);
  EXPECT_EQ(out.boundaryLoops, in.boundaryLoops);
  for (int v = 0; v < r.mesh.vertexCount(); ++v)
    ASSERT_LT((r.origin[v].position(input) - r.mesh.positions[v]).norm(), 1e-9 * input.boundingBoxDiagonal());
  const test::AngleRecount angles = test::recountAngles(r.mesh);
  const double smallest = angles.smallestDegrees, share = angles.shareBelow30;
  std::printf(
      "%s %.0f%%: %d vertices (%d added), %d relaxation moves, smallest angle %.1f deg, %.2f %% of "
      "triangles under 30 deg\n",
      name.c_str(), 100 * fraction, r.mesh.vertexCount(), r.addedSamples, remeshed->relaxation.moves, smallest,
      100 * share);
  EXPECT_LE(share, 0.01);
  EXPECT_GE(smallest, 20.0);
}

// Issue 18, point 5, on the adaptive filter: fandisk at 10% with the main command's script
// (resources/adaptive_curvature_10pct.mlx: the defaults, gradation 0.4 and 10 centroidal
// iterations, plus 5 relaxation rounds): smallest angle >= 20 degrees, <= 2% of the triangles
// with an angle under 30, two-sided Hausdorff (CGAL-free oracle: vcglib's sampling) within 10% of
// the 1.468% the script gave before; and the filter's defaults alone (no relaxation) already
// raise the angles over no gradation and no centroidal iterations.
TEST(RemeshQualityAdaptive, FandiskScriptGivesGoodTrianglesWithinTenPercentOfItsError) {
  const TriMesh input = test::loadRealMesh("fandisk.off");
  const double diagonal = input.boundingBoxDiagonal();
  AdaptiveRemeshParams script;
  script.remesh.sampling.targetCount = 647;
  script.remesh.relaxation.iterations = 5;
  AdaptiveRemeshParams defaults;
  defaults.remesh.sampling.targetCount = 647;
  AdaptiveRemeshParams before = defaults;
  before.gradation = 0.0;
  before.remesh.centroidalIterations = 0;
  const Expected<AdaptiveRemeshResult> s = remeshAdaptive(input, {}, script);
  const Expected<AdaptiveRemeshResult> d = remeshAdaptive(input, {}, defaults);
  const Expected<AdaptiveRemeshResult> b = remeshAdaptive(input, {}, before);
  ASSERT_TRUE(s && d && b);
  const test::AngleRecount as = test::recountAngles(s->remesh.mesh), ad = test::recountAngles(d->remesh.mesh),
                           ab = test::recountAngles(b->remesh.mesh);
  const double hausdorff = oracle::twoSidedDistance(s->remesh.mesh, input).max / diagonal;
  std::printf(
      "fandisk adaptive 10%%: script %.1f deg / %.2f%% under 30 / Hausdorff %.3f%%; defaults %.1f / %.2f%%; "
      "without gradation and centroidal iterations %.1f / %.2f%%\n",
      as.smallestDegrees, 100 * as.shareBelow30, 100 * hausdorff, ad.smallestDegrees, 100 * ad.shareBelow30,
      ab.smallestDegrees, 100 * ab.shareBelow30);
  EXPECT_GE(as.smallestDegrees, 20.0);
  EXPECT_LE(as.shareBelow30, 0.02);
  EXPECT_LE(hausdorff, 1.1 * 0.01468);
  EXPECT_GT(ad.smallestDegrees, ab.smallestDegrees);
  EXPECT_LT(ad.shareBelow30, ab.shareBelow30);
}

// Centroidal relaxation (issue 18, point 5): bunny00 at 10% with 10 geodesic Lloyd iterations on
// the samples and 10 rounds of the relaxation it regularises (valence flips, RelaxationParams::
// regularised): angle standard deviation below CGAL's isotropic remeshing at the same count (10
// iterations, 7.2 degrees in BENCHMARKS), smallest angle >= 30 degrees, two-sided Hausdorff
// distance no more than CGAL's, both measured here by the same oracle (tests/oracles).
TEST(RemeshQualityCentroidal, EvenerAnglesThanCgalIsotropicAtTheSameCount) {
  const TriMesh input = test::loadRealMesh("bunny00.off");
  SurfaceRemeshParams params;
  params.sampling.targetCount = input.vertexCount() / 10;
  params.relaxation.iterations = 10;
  params.countTolerance = 0.0;  // both at the count itself, so that they compare at the same count
  const Expected<SurfaceRemeshResult> plain = remeshSurface(input, params);
  params.centroidalIterations = 10;
  const Expected<SurfaceRemeshResult> centroidal = remeshSurface(input, params);
  ASSERT_TRUE(plain && centroidal);
  EXPECT_EQ(centroidal->mesh.vertexCount(), plain->mesh.vertexCount());

  Expected<std::unique_ptr<oracle::SurfaceMesh>> cgal = oracle::toSurfaceMesh(input);
  ASSERT_TRUE(cgal);
  const oracle::CgalCalibration calibration =
      oracle::calibrateCgalEdgeLength(**cgal, centroidal->mesh.vertexCount(), 10, 4, 0.02);
  oracle::cgalIsotropicRemeshing(**cgal, calibration.edgeLength, 10);
  Expected<TriMesh> cgalMesh = oracle::toTriMesh(**cgal);
  ASSERT_TRUE(cgalMesh);

  const auto stdDegrees = [](const TriMesh& m) {
    double sum = 0.0, sq = 0.0;
    int n = 0;
    for (const Tri& t : m.triangles)
      for (int k = 0; k < 3; ++k) {
        const Vec3 u = m.positions[t[(k + 1) % 3]] - m.positions[t[k]],
                   w = m.positions[t[(k + 2) % 3]] - m.positions[t[k]];
        const double a = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / 3.14159265358979323846;
        sum += a;
        sq += a * a;
        ++n;
      }
    return std::sqrt(sq / n - (sum / n) * (sum / n));
  };
  const double diagonal = input.boundingBoxDiagonal();
  const double ours = oracle::twoSidedDistance(centroidal->mesh, input).max / diagonal;
  const double before = oracle::twoSidedDistance(plain->mesh, input).max / diagonal;
  const double theirs = oracle::twoSidedDistance(*cgalMesh, input).max / diagonal;
  std::printf(
      "bunny00 10%%, 10 relaxation rounds: angle std %.2f -> %.2f deg (CGAL %.2f at %d vertices), Hausdorff %.3f%% -> "
      "%.3f%% (CGAL %.3f%%), smallest %.1f deg\n",
      stdDegrees(plain->mesh), stdDegrees(centroidal->mesh), stdDegrees(*cgalMesh), cgalMesh->vertexCount(),
      100 * before, 100 * ours, 100 * theirs, test::recountAngles(centroidal->mesh).smallestDegrees);
  EXPECT_LT(stdDegrees(centroidal->mesh), stdDegrees(*cgalMesh));
  EXPECT_LT(stdDegrees(centroidal->mesh), 7.2);
  EXPECT_GE(test::recountAngles(centroidal->mesh).smallestDegrees, 30.0);
  EXPECT_LE(ours, theirs);
}

// The same pipeline on the same surfaces with needles (angles under 1 degree) and zero-area faces
// (test::withBadTriangles): a valid mesh of the input's topology, every vertex finite and on the
// input, and the same quality bounds.
// The count search's tolerance: by default it stops at an output from the count asked for to 1%
// above it (bunny00 at 10%: the first sampling, 5 samples added), with 0 it goes on to the count
// itself; a negative tolerance is refused.
TEST(RemeshCount, StopsWithinTheToleranceAboveTheCount) {
  const TriMesh input = test::loadRealMesh("bunny00.off");
  SurfaceRemeshParams params;
  params.sampling.targetCount = input.vertexCount() / 10;
  params.measure = false;
  const int target = params.sampling.targetCount;
  const Expected<SurfaceRemeshResult> tolerant = remeshSurface(input, params);
  params.countTolerance = 0.0;
  const Expected<SurfaceRemeshResult> exact = remeshSurface(input, params);
  ASSERT_TRUE(tolerant && exact);
  std::printf("bunny00, %d asked: %d vertices in %d samplings (tolerance 1%%), %d in %d (tolerance 0)\n", target,
              tolerant->mesh.vertexCount(), tolerant->samplingRounds, exact->mesh.vertexCount(), exact->samplingRounds);
  ASSERT_GT(tolerant->addedSamples, 0) << "the case needs a repair that adds samples";
  EXPECT_EQ(tolerant->samplingRounds, 1);
  EXPECT_GE(tolerant->mesh.vertexCount(), target);
  EXPECT_LE(tolerant->mesh.vertexCount(), 1.01 * target);
  EXPECT_GT(exact->samplingRounds, 1);
  EXPECT_LT(std::abs(exact->mesh.vertexCount() - target), tolerant->mesh.vertexCount() - target);
  params.countTolerance = -0.5;
  const Expected<SurfaceRemeshResult> refused = remeshSurface(input, params);
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.status().code, StatusCode::InvalidInput);
}

// The repair of a locally valid dual that misses a handle refines the cells that are not closed
// balls (a cell around the handle, two cells meeting along two arcs) rather than the tenth of all
// cells with the largest radius: femur.off (genus 2) at 10% came back with 3,479 vertices for 389
// asked (3,090 samples added); the count search now lands within 10% of the count, with the
// topology (recounted here) and no self-intersecting pair (CGAL; the input has none). lion.off
// (genus 0, several components of cells around its mane: 1,096 for 752 before) is held to the same.
TEST(RemeshCount, HandlesAreCapturedWhereTheyAreNotByRefiningEverywhere) {
  for (const char* name : {"femur.off", "lion.off"}) {
    SCOPED_TRACE(name);
    const TriMesh input = test::loadRealMesh(name);
    SurfaceRemeshParams params;
    const int target = SurfaceRemeshParams::defaultTargetCount(input.vertexCount());
    params.sampling.targetCount = target;
    params.measure = false;
    const Expected<SurfaceRemeshResult> r = remeshSurface(input, params);
    ASSERT_TRUE(r) << r.status().message;
    const Expected<std::vector<std::pair<int, int>>> inputCrossing = oracle::selfIntersections(input);
    const Expected<std::vector<std::pair<int, int>>> crossing = oracle::selfIntersections(r->mesh);
    ASSERT_TRUE(inputCrossing && crossing);
    std::printf("%s: %d asked, %d got (%d samplings, %d added), %zu self-intersecting pairs (input %zu)\n", name,
                target, r->mesh.vertexCount(), r->samplingRounds, r->addedSamples, crossing->size(),
                inputCrossing->size());
    test::expectValidWithTopologyOf(test::recount(r->mesh.triangles, r->mesh.vertexCount()),
                                    test::recount(input.triangles, input.vertexCount()));
    EXPECT_LE(std::abs(r->mesh.vertexCount() - target), 0.1 * target);
    if (inputCrossing->empty()) {
      EXPECT_TRUE(crossing->empty());
    }
  }
}

// Issue 20, point 2: the output does not cross itself where the input does not. Cases of the data
// set whose output crossed itself before the repair (CGAL pairs, input none): rotor.off, a thin
// part, at 5% and 10% (24 and 12 pairs: dual triangles through the part), bunny00, fandisk and
// armadillo at 30% (4, 11 and 13 pairs: slivers folding over a neighbour, vertices relaxed over a
// fold). The relaxation refuses the moves that make faces cross (RelaxationGuard), and where the
// triangulation still crosses, its repair adds samples in the cells of crossing triangles; the
// judge is CGAL's exact test.
TEST(RemeshCrossing, OutputsDoNotCrossThemselvesWhereTheInputDoesNot) {
  const std::vector<std::pair<const char*, double>> cases = {
      {"rotor.off", 0.05}, {"rotor.off", 0.1}, {"bunny00.off", 0.3}, {"fandisk.off", 0.3}, {"armadillo.off", 0.3}};
  for (const auto& [name, fraction] : cases) {
    SCOPED_TRACE(std::string(name) + " at " + std::to_string(fraction));
    const TriMesh input = test::loadRealMesh(name);
    const Expected<std::vector<std::pair<int, int>>> inputCrossing = oracle::selfIntersections(input);
    ASSERT_TRUE(inputCrossing);
    ASSERT_TRUE(inputCrossing->empty());
    SurfaceRemeshParams params;
    params.sampling.targetCount = static_cast<int>(fraction * input.vertexCount());
    params.measure = false;
    const Expected<SurfaceRemeshResult> r = remeshSurface(input, params);
    ASSERT_TRUE(r) << r.status().message;
    const Expected<std::vector<std::pair<int, int>>> crossing = oracle::selfIntersections(r->mesh);
    ASSERT_TRUE(crossing);
    std::printf("%s at %.0f%%: %d asked, %d got, %d crossing repair rounds, %d vertices pinned, %zu crossing pairs\n",
                name, 100 * fraction, params.sampling.targetCount, r->mesh.vertexCount(), r->crossingRounds,
                r->relaxation.pinnedVertices, crossing->size());
    test::expectValidWithTopologyOf(test::recount(r->mesh.triangles, r->mesh.vertexCount()),
                                    test::recount(input.triangles, input.vertexCount()));
    EXPECT_TRUE(crossing->empty());
    EXPECT_EQ(r->crossingPairs, 0);
  }
}

// An input that crosses itself (boeing.off: 122 components, 142 boundary loops, 10,976 crossing
// pairs by CGAL): the output, uniform or adaptive at 5% and 10%, crosses itself no more than the
// input does. Its topology needs more vertices than the input has at these counts, so the input's
// own triangles are kept (SurfaceRemeshResult::inputKept; the adaptive remesh had 11,622 pairs).
TEST(RemeshCrossing, NoMoreCrossingsThanAnInputThatCrossesItself) {
  const TriMesh input = test::loadRealMesh("boeing.off");
  const Expected<std::vector<std::pair<int, int>>> inputCrossing = oracle::selfIntersections(input);
  ASSERT_TRUE(inputCrossing);
  ASSERT_GT(inputCrossing->size(), 1000u);
  for (const double fraction : {0.05, 0.1})
    for (const bool adaptive : {false, true}) {
      SCOPED_TRACE(std::string(adaptive ? "adaptive" : "uniform") + " at " + std::to_string(fraction));
      SurfaceRemeshParams u;  // the uniform filter's defaults
      u.sampling.targetCount = static_cast<int>(fraction * input.vertexCount());
      u.measure = false;
      AdaptiveRemeshParams a;  // the adaptive filter's
      a.remesh.sampling.targetCount = u.sampling.targetCount;
      a.remesh.measure = false;
      Expected<SurfaceRemeshResult> r = invalidInput("not run");
      if (adaptive) {
        Expected<AdaptiveRemeshResult> ar = remeshAdaptive(input, {}, a);
        ASSERT_TRUE(ar) << ar.status().message;
        r = std::move(ar->remesh);
      } else {
        r = remeshSurface(input, u);
      }
      ASSERT_TRUE(r) << r.status().message;
      const Expected<std::vector<std::pair<int, int>>> crossing = oracle::selfIntersections(r->mesh);
      ASSERT_TRUE(crossing);
      std::printf("boeing %s at %.0f%%: %d vertices%s, %zu crossing pairs (input %zu)\n",
                  adaptive ? "adaptive" : "uniform", 100 * fraction, r->mesh.vertexCount(),
                  r->inputKept ? " (the input kept)" : "", crossing->size(), inputCrossing->size());
      test::expectValidWithTopologyOf(test::recount(r->mesh.triangles, r->mesh.vertexCount()),
                                      test::recount(input.triangles, input.vertexCount()));
      EXPECT_LE(crossing->size(), inputCrossing->size());
    }
}

TEST(RemeshQualityBadTriangles, NeedlesAndZeroAreaFaces) {
  for (const char* name : {"fandisk.off", "bunny00.off"}) {
    SCOPED_TRACE(name);
    int zeroArea = 0;
    const TriMesh input = test::withBadTriangles(test::loadRealMesh(name), &zeroArea);
    ASSERT_GT(zeroArea, 100);
    SurfaceRemeshParams params;
    params.sampling.targetCount = input.vertexCount() / 10;
    params.measure = false;
    const Expected<SurfaceRemeshResult> remeshed = remeshSurface(input, params);
    ASSERT_TRUE(remeshed) << remeshed.status().message;
    const TriMesh& out = remeshed->mesh;
    const test::Recount in = test::recount(input.triangles, input.vertexCount());
    const test::Recount rc = test::recount(out.triangles, out.vertexCount());
    EXPECT_TRUE(rc.manifoldEdges && rc.manifoldVertices && rc.oriented);
    EXPECT_EQ(rc.components, in.components);
    EXPECT_EQ(rc.genusSum, in.genusSum);
    for (int v = 0; v < out.vertexCount(); ++v) {
      ASSERT_TRUE(out.positions[v].allFinite());
      ASSERT_LT((remeshed->origin[v].position(input) - out.positions[v]).norm(), 1e-9);
    }
    const test::AngleRecount angles = test::recountAngles(out);
    std::printf("%s with %d zero-area faces, 10%%: %d vertices, smallest angle %.1f deg, %.2f %% under 30 deg\n", name,
                zeroArea, out.vertexCount(), angles.smallestDegrees, 100.0 * angles.shareBelow30);
    EXPECT_GE(angles.smallestDegrees, 20.0);
    EXPECT_LE(angles.shareBelow30, 0.01);
  }
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
