// The remesh's distance to its input (core/remesh/remesh_distance.h), which the filters log,
// against surfaceDistance (vcglib's grid over the whole surface, the same samples): the one-sided
// Hausdorff distances equal both ways to CGAL's exact ones at those samples (the grid's within
// 2e-4 of them: near cheese's slivers it misses the nearest point by 1.3e-4), the RMS at least the grid's
// and at most 5% above it; the same with the input's centroids and midpoints measured too. On a
// scan (bunny00), a CAD mesh
// (fandisk), a refined sliver mesh (cheese.off), a refined CAD-like mesh whose input faces span
// many cells (the gear plate) and a coarse input (triceratops at 30%).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "core/measure/evaluation.h"
#include "core/remesh/remesh_distance.h"
#include "core/remesh/remesh_surface.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/cad_meshes.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

void expectAsTheGrid(const std::string& name, const TriMesh& input, double fraction) {
  SCOPED_TRACE(name);
  SurfaceRemeshParams params;
  params.sampling.targetCount = static_cast<int>(fraction * input.vertexCount());
  params.measure = false;
  const Expected<SurfaceRemeshResult> r = remeshSurface(input, params);
  ASSERT_TRUE(r) << r.status().message;
  const RemeshDistances d = remeshDistances(input, r->mesh, r->cell, r->origin, r->collapsedVertices == 0);
  const SurfaceDistance to = surfaceDistance(r->mesh, input);
  const SurfaceDistance from = surfaceDistance(input, r->mesh, {}, 0, DistanceSamples::Vertices);
  std::printf(
      "%s at %.0f%%: to the input max %.6g (grid %.6g) rms %.6g (%.6g); from it max %.6g (%.6g) rms %.6g "
      "(%.6g); %d exact queries, %d directions by the grid\n",
      name.c_str(), 100 * fraction, d.toInput.max, to.max, d.toInput.rms, to.rms, d.fromInput.max, from.max,
      d.fromInput.rms, from.rms, d.exactQueries, d.gridDirections);
  ASSERT_GT(to.max, 0.0);
  ASSERT_GT(from.max, 0.0);
  // The largest distances exact, by CGAL at the same samples; vcglib's grid within 2e-4 of them.
  const Expected<double> exactTo = oracle::largestDistanceAtSamples(r->mesh, input, true);
  const Expected<double> exactFrom = oracle::largestDistanceAtSamples(input, r->mesh, false);
  ASSERT_TRUE(exactTo && exactFrom);
  std::printf("  exact by CGAL: to the input %.9g, from it %.9g\n", *exactTo, *exactFrom);
  EXPECT_NEAR(d.toInput.max, *exactTo, 1e-9 * *exactTo);
  EXPECT_NEAR(d.fromInput.max, *exactFrom, 1e-9 * *exactFrom);
  EXPECT_NEAR(to.max, *exactTo, 2e-4 * *exactTo);
  EXPECT_NEAR(from.max, *exactFrom, 2e-4 * *exactFrom);
  EXPECT_GE(d.toInput.rms, to.rms * (1 - 1e-9));
  EXPECT_LE(d.toInput.rms, 1.05 * to.rms);
  EXPECT_GE(d.fromInput.rms, from.rms * (1 - 1e-9));
  EXPECT_LE(d.fromInput.rms, 1.05 * from.rms);

  // The input's centroids and midpoints measured too (DistanceSamples::VerticesMidpointsCentroids):
  // its side as the grid's whole measure, exact by CGAL where no direction fell back to the grid.
  const RemeshDistances all = remeshDistances(input, r->mesh, r->cell, r->origin, r->collapsedVertices == 0,
                                              DistanceSamples::VerticesMidpointsCentroids);
  const SurfaceDistance fromAll = surfaceDistance(input, r->mesh);
  const Expected<double> exactFromAll = oracle::largestDistanceAtSamples(input, r->mesh, true);
  ASSERT_TRUE(exactFromAll);
  std::printf("  with the input's centroids and midpoints: from it max %.9g (grid %.9g, CGAL %.9g) rms %.6g (%.6g)\n",
              all.fromInput.max, fromAll.max, *exactFromAll, all.fromInput.rms, fromAll.rms);
  EXPECT_EQ(all.toInput.max, d.toInput.max);
  EXPECT_GE(all.fromInput.max, d.fromInput.max);
  EXPECT_NEAR(all.fromInput.max, *exactFromAll, (all.gridDirections == 0 ? 1e-9 : 2e-4) * *exactFromAll);
  EXPECT_GE(all.fromInput.rms, fromAll.rms * (1 - 1e-9));
  EXPECT_LE(all.fromInput.rms, 1.05 * fromAll.rms);
}

TEST(RemeshDistance, HausdorffExactAtTheGridsSamplesAndRmsWithinFivePercent) {
  expectAsTheGrid("bunny00", test::loadRealMesh("bunny00.off"), 0.1);
  expectAsTheGrid("fandisk", test::loadRealMesh("fandisk.off"), 0.05);
  expectAsTheGrid("cheese", test::loadRealMesh("cheese.off"), 0.1);
  expectAsTheGrid("cad_gear", test::cadMeshes()[0].mesh, 0.1);
  expectAsTheGrid("cad_hole_plate", test::cadMeshes()[1].mesh, 0.1);
  // A coarse input for its output: its largest distance lies at a face's sample, not a vertex.
  expectAsTheGrid("triceratops", test::loadRealMesh("triceratops.off"), 0.3);
}

// The filters' log reads the same figures: remeshSurface with `measure` fills them from
// remeshDistances.
TEST(RemeshDistance, RemeshSurfaceMeasuresWithIt) {
  const TriMesh input = test::loadRealMesh("fandisk.off");
  SurfaceRemeshParams params;
  params.sampling.targetCount = 323;
  params.measure = true;
  params.measureDistance = true;
  const Expected<SurfaceRemeshResult> r = remeshSurface(input, params);
  ASSERT_TRUE(r) << r.status().message;
  const RemeshDistances d = remeshDistances(input, r->mesh, r->cell, r->origin, r->collapsedVertices == 0);
  EXPECT_EQ(r->measures.toInput.max, d.toInput.max);
  EXPECT_EQ(r->measures.fromInput.max, d.fromInput.max);
  EXPECT_EQ(r->measures.fromInput.rms, d.fromInput.rms);
  EXPECT_DOUBLE_EQ(r->measures.inputDiagonal, input.boundingBoxDiagonal());
  EXPECT_TRUE(r->measures.distances);
  // Off by default (the filters' ReportError): the angles only, the same remesh.
  params.measureDistance = SurfaceRemeshParams{}.measureDistance;
  ASSERT_FALSE(params.measureDistance);
  const Expected<SurfaceRemeshResult> angles = remeshSurface(input, params);
  ASSERT_TRUE(angles) << angles.status().message;
  EXPECT_FALSE(angles->measures.distances);
  EXPECT_EQ(angles->measures.toInput.max, 0.0);
  EXPECT_EQ(angles->measures.angles.minDegrees, r->measures.angles.minDegrees);
  EXPECT_EQ(angles->mesh.triangles, r->mesh.triangles);
}

}  // namespace
}  // namespace gr
