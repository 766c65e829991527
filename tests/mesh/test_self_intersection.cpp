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

// Folds in a plane, which no edge crosses through: two faces on one edge folded flat onto each
// other, and a face turned over among coplanar neighbours (an interior vertex of a flat grid moved
// past its ring, as the ship deck had); a flat grid, and a grid whose one vertex moves
// inside its ring, have none. The counts agree with CGAL's exact test.
TEST(SelfIntersection, CoplanarFoldsAreFoundAsCgalFindsThem) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0.2, 1, 0}, {0.6, 0.8, 0}};
  const TriMesh folded = buildTriMesh(p, {{0, 1, 2}, {1, 0, 3}}).value();  // 3 on 2's side of (0, 1)
  const TriMesh open = buildTriMesh({p[0], p[1], p[2], {0.5, -1, 0}}, {{0, 1, 2}, {1, 0, 3}}).value();
  EXPECT_EQ(selfIntersectingFaces(folded).size(), 1u);
  EXPECT_TRUE(selfIntersectingFaces(open).empty());
  for (const TriMesh* m : {&folded, &open}) {
    const auto exact = oracle::selfIntersections(*m);
    ASSERT_TRUE(exact);
    EXPECT_EQ(selfIntersectingFaces(*m).size(), exact->size());
  }
  const TriMesh grid = test::planeGrid(8, 1.0, 0.0);
  EXPECT_TRUE(selfIntersectingFaces(grid).empty());
  const int inner = 4 * 9 + 4;             // the middle vertex of the 8 x 8 grid (9 vertices a row)
  for (const double shift : {0.3, 2.5}) {  // in its ring (no fold), past its ring's far side (folds)
    std::vector<Vec3> moved = grid.positions;
    moved[inner] += Vec3(shift / 8.0, 0.37 * shift / 8.0, 0.0);  // in grid spacings, off the grid lines
    const TriMesh m = buildTriMesh(moved, grid.triangles).value();
    const auto exact = oracle::selfIntersections(m);
    ASSERT_TRUE(exact);
    EXPECT_EQ(selfIntersectingFaces(m).size(), exact->size()) << shift;
    EXPECT_EQ(exact->empty(), shift < 1.0) << shift;
  }
}

/// Two uv spheres of radius 1, one moved by (1, 0.1, 0.05): they pass through each other.
TriMesh twoSpheresThroughEachOther() {
  TriMesh a = test::uvSphere(10, 20);
  std::vector<Vec3> p = a.positions;
  std::vector<Tri> t = a.triangles;
  const int n = static_cast<int>(p.size());
  for (const Vec3& x : a.positions) p.push_back(x + Vec3(1.0, 0.1, 0.05));
  for (const Tri& f : a.triangles) t.push_back({f[0] + n, f[1] + n, f[2] + n});
  return buildTriMesh(p, t).value();
}

TEST(SelfIntersection, TwoSpheresThroughEachOtherAgreeWithCgal) {
  const TriMesh two = twoSpheresThroughEachOther();
  const auto exact = oracle::selfIntersections(two);
  ASSERT_TRUE(exact);
  EXPECT_GT(exact->size(), 0u);
  EXPECT_EQ(selfIntersectingFaces(two).size(), exact->size());
  EXPECT_EQ(selfIntersectingFaces(two, 3).size(), 3u);
}

// crossingsOfFaces finds exactly the pairs of the whole test that touch a flagged face, flags
// spread or gathered, a few or all; none on an embedded mesh.
TEST(SelfIntersection, CrossingsOfFlaggedFacesAreThoseOfTheWholeTest) {
  const TriMesh two = twoSpheresThroughEachOther();
  const std::vector<std::pair<int, int>> all = selfIntersectingFaces(two);
  ASSERT_FALSE(all.empty());
  for (const int every : {1, 2, 7, 50}) {
    std::vector<char> flagged(two.faceCount(), 0);
    for (int f = 0; f < two.faceCount(); f += every) flagged[f] = 1;
    std::vector<std::pair<int, int>> expected;
    for (const auto& [f, g] : all)
      if (flagged[f] || flagged[g]) expected.push_back({f, g});
    EXPECT_EQ(crossingsOfFaces(two, flagged), expected) << "every " << every << "th face flagged";
  }
  std::vector<char> one(two.faceCount(), 0);
  one[all.front().first] = 1;
  const std::vector<std::pair<int, int>> found = crossingsOfFaces(two, one);
  EXPECT_FALSE(found.empty());
  for (const auto& [f, g] : found) EXPECT_TRUE(f == all.front().first || g == all.front().first);
  EXPECT_TRUE(crossingsOfFaces(two, std::vector<char>(two.faceCount(), 0)).empty());
  const TriMesh sphere = test::uvSphere(12, 24);
  EXPECT_TRUE(crossingsOfFaces(sphere, std::vector<char>(sphere.faceCount(), 1)).empty());
}

}  // namespace
}  // namespace gr
