// Triangle quality of the uniform remeshing at its defaults against CGAL's isotropic remeshing
// (issue 20, point 3), over the data set at 10%:
// - on the meshes listed below, the smallest angle and the share of triangles with an angle under
//   30 degrees at least as good as CGAL's with 10 iterations at the same count (CGAL runs here, on
//   the same mesh). These are the meshes where the relaxation that raises the smallest angle,
//   the vertices sliding along boundaries and creases, the angle rescue (remesh_surface.h) and
//   the polish of the final output (polishOnSurface: homer, oblong, retinal, sphere966, blobby_3cc,
//   femur) brought
//   ours from worse to as good; docs/BENCHMARKS.md lists the whole data set, the meshes
//   where ours is still worse and why.
// - no angle under 20 degrees on every closed mesh of the data set whose input has no angle
//   under 1 degree.
// Angles are recounted here from the positions (test::recountAngles), not taken from the result.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "core/mesh/vcg_mesh.h"
#include "core/remesh/remesh_surface.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

Expected<SurfaceRemeshResult> remeshTenPercent(const TriMesh& input) {
  SurfaceRemeshParams params;
  params.sampling.targetCount = input.vertexCount() / 10;
  params.measure = false;
  return remeshSurface(input, params);
}

class RemeshAnglesAgainstCgal : public ::testing::TestWithParam<std::string> {};

TEST_P(RemeshAnglesAgainstCgal, SmallestAngleAndShareUnder30AtLeastAsGood) {
  const TriMesh input = test::loadRealMesh(GetParam());
  const Expected<SurfaceRemeshResult> ours = remeshTenPercent(input);
  ASSERT_TRUE(ours) << ours.status().message;
  test::expectValidWithTopologyOf(test::recount(ours->mesh.triangles, ours->mesh.vertexCount()),
                                  test::recount(input.triangles, input.vertexCount()));

  Expected<std::unique_ptr<oracle::SurfaceMesh>> cgal = oracle::toSurfaceMesh(input);
  ASSERT_TRUE(cgal);
  const oracle::CgalCalibration calibration =
      oracle::calibrateCgalEdgeLength(**cgal, ours->mesh.vertexCount(), 10, 3, 0.02);
  oracle::cgalIsotropicRemeshing(**cgal, calibration.edgeLength, 10);
  const Expected<TriMesh> theirs = oracle::toTriMesh(**cgal);
  ASSERT_TRUE(theirs);

  const test::AngleRecount a = test::recountAngles(ours->mesh), c = test::recountAngles(*theirs);
  std::printf("%s at 10%%: ours %d vertices, smallest %.2f deg, %.2f %% under 30 | CGAL %d, %.2f deg, %.2f %%%s\n",
              GetParam().c_str(), ours->mesh.vertexCount(), a.smallestDegrees, 100 * a.shareBelow30,
              theirs->vertexCount(), c.smallestDegrees, 100 * c.shareBelow30,
              ours->angleRescued ? " (angle rescue)" : "");
  EXPECT_GE(a.smallestDegrees, c.smallestDegrees);
  EXPECT_LE(a.shareBelow30, c.shareBelow30);
}

INSTANTIATE_TEST_SUITE_P(Meshes, RemeshAnglesAgainstCgal,
                         ::testing::Values("bear.off", "bear_bis.off", "blobby.off", "blobby_3cc.off",
                                           "cube-meshed.off", "dragknob.off", "ellipe0.003.off", "ellipsoid.off",
                                           "fandisk.off", "fandisk_large.off", "femur.off", "hand.off", "holes.off",
                                           "homer.off", "knot1.off", "knot2.off", "larger_sphere.off",
                                           "mannequin-devil.off", "mesh_with_border.off", "oblong.off", "part.off",
                                           "retinal.off", "sphere.ply", "sphere966.off", "three_peaks.off"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return test::testNameOfFile(p.param); });

// Flat ears off the boundary (removeFlatEars): lion-head at 30% had two ears of 5.8 and 6.2
// degrees, their tips at 168 degrees on a straight stretch of its boundary. They go: no angle
// under 20 degrees (5.75 without), the input's topology recounted.
TEST(RemeshAngles, FlatEarsOffTheBoundaryAreRemoved) {
  const Expected<TriMesh> input = loadTriMesh(test::meshPath("lion-head.off"));
  ASSERT_TRUE(input);
  SurfaceRemeshParams params;
  params.sampling.targetCount = input->vertexCount() * 3 / 10;
  params.measure = false;
  const Expected<SurfaceRemeshResult> ours = remeshSurface(*input, params);
  ASSERT_TRUE(ours) << ours.status().message;
  const test::AngleRecount a = test::recountAngles(ours->mesh);
  const test::Recount in = test::recount(input->triangles, input->vertexCount());
  const test::Recount out = test::recount(ours->mesh.triangles, ours->mesh.vertexCount());
  std::printf("lion-head at 30%%: %d ears removed, smallest angle %.2f deg\n", ours->removedEars, a.smallestDegrees);
  EXPECT_GE(ours->removedEars, 1);
  EXPECT_GE(a.smallestDegrees, 20.0);
  EXPECT_EQ(out.components, in.components);
  EXPECT_EQ(out.genusSum, in.genusSum);
  EXPECT_EQ(out.boundaryLoops, in.boundaryLoops);
}

// The polish's flips to fewer faces under 30 degrees (flipToBetterAngles) cross edges of up to
// the input's feature angle: knot2 at 5% is a tube a few vertices round, whose last face under
// 30 degrees (21.7, with the Delaunay flips' 30-degree crease bound) sits on an edge of 53
// degrees. Angles, topology and crossings recounted (CGAL's self-intersection test).
TEST(RemeshAngles, ThinTubeFlipsAcrossItsCoarseEdges) {
  const Expected<TriMesh> input = loadTriMesh(test::meshPath("knot2.off"));
  ASSERT_TRUE(input);
  SurfaceRemeshParams params;
  params.sampling.targetCount = input->vertexCount() / 20;
  params.measure = false;
  const Expected<SurfaceRemeshResult> ours = remeshSurface(*input, params);
  ASSERT_TRUE(ours) << ours.status().message;
  const test::AngleRecount a = test::recountAngles(ours->mesh);
  std::printf("knot2 at 5%%: smallest angle %.2f deg, %.2f %% under 30\n", a.smallestDegrees, 100 * a.shareBelow30);
  EXPECT_GE(a.smallestDegrees, 25.0);
  EXPECT_EQ(a.shareBelow30, 0.0);
  test::expectValidWithTopologyOf(test::recount(ours->mesh.triangles, ours->mesh.vertexCount()),
                                  test::recount(input->triangles, input->vertexCount()));
  const auto crossings = oracle::selfIntersections(ours->mesh);
  ASSERT_TRUE(crossings);
  EXPECT_TRUE(crossings->empty());
}

TEST(RemeshAngles, NoAngleUnder20DegreesOnClosedMeshesWithoutSlivers) {
  int checked = 0;
  for (const std::string& name : test::dataSetMeshFiles()) {
    const Expected<TriMesh> input = loadTriMesh(test::meshPath(name));
    if (!input || input->vertexCount() > 60000 || input->vertexCount() / 10 < 4) continue;
    const test::Recount in = test::recount(input->triangles, input->vertexCount());
    if (!(in.manifoldEdges && in.manifoldVertices && in.oriented) || in.boundaryLoops > 0) continue;
    if (test::recountAngles(*input).smallestDegrees < 1.0) continue;
    SCOPED_TRACE(name);
    const Expected<SurfaceRemeshResult> r = remeshTenPercent(*input);
    ASSERT_TRUE(r) << r.status().message;
    const double smallest = test::recountAngles(r->mesh).smallestDegrees;
    std::printf("%-26s %6d -> %5d vertices: smallest angle %.1f deg%s\n", name.c_str(), input->vertexCount(),
                r->mesh.vertexCount(), smallest, r->angleRescued ? " (angle rescue)" : "");
    EXPECT_GE(smallest, 20.0);
    ++checked;
  }
  EXPECT_GE(checked, 30);  // the data set has 36 such meshes up to 60,000 vertices
}

}  // namespace
}  // namespace gr
