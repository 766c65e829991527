// selfIntersectingFaces (self_intersection.h): none on embedded meshes, the crossing pairs where
// a surface passes through another or through itself, against CGAL's exact test on the CAD meshes.
#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "core/mesh/self_intersection.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/cad_meshes.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

TEST(SelfIntersection, NoneOnEmbeddedMeshes) {
  EXPECT_TRUE(selfIntersectingFaces(test::uvSphere(12, 24)).empty());
  EXPECT_TRUE(selfIntersectingFaces(test::planeGrid(10, 1.0, 0.2)).empty());
  for (const test::CadMesh& cad : test::cadMeshes()) EXPECT_TRUE(selfIntersectingFaces(cad.mesh).empty()) << cad.name;
}

TEST(SelfIntersection, TwoTrianglesThroughEachOther) {
  const std::vector<Vec3> p = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {3, 3, 0}};
  const TriMesh crossing = buildTriMesh(p, {{0, 1, 2}, {3, 4, 5}}).value();
  const std::vector<std::pair<int, int>> pairs = selfIntersectingFaces(crossing);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0], std::make_pair(0, 1));
  // Sharing a vertex and crossing elsewhere: found; touching only at the shared vertex: not.
  const TriMesh fanCrossing = buildTriMesh(p, {{0, 1, 2}, {0, 4, 3}}).value();
  EXPECT_EQ(selfIntersectingFaces(fanCrossing).size(), 1u);
  const std::vector<Vec3> q = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0.5}, {0, -1, 0.5}};
  EXPECT_TRUE(selfIntersectingFaces(buildTriMesh(q, {{0, 1, 2}, {0, 3, 4}}).value()).empty());
}

TEST(SelfIntersection, TwoSpheresThroughEachOtherAgreeWithCgal) {
  TriMesh a = test::uvSphere(10, 20);
  std::vector<Vec3> p = a.positions;
  std::vector<Tri> t = a.triangles;
  const int n = static_cast<int>(p.size());
  for (const Vec3& x : a.positions) p.push_back(x + Vec3(1.0, 0.1, 0.05));
  for (const Tri& f : a.triangles) t.push_back({f[0] + n, f[1] + n, f[2] + n});
  const TriMesh two = buildTriMesh(p, t).value();
  const auto exact = oracle::selfIntersections(two);
  ASSERT_TRUE(exact);
  EXPECT_GT(exact->size(), 0u);
  EXPECT_EQ(selfIntersectingFaces(two).size(), exact->size());
  EXPECT_EQ(selfIntersectingFaces(two, 3).size(), 3u);
}

}  // namespace
}  // namespace gr
