// Semi-regular remeshing (core/param/semi_regular.h), judged from the output's faces alone:
//  - subdivision connectivity: every vertex that is not a base vertex has 6 neighbours (4 on the
//    boundary), counted from the face list;
//  - a manifold, oriented mesh with the input's components, genus and boundary loops (recounted);
//  - its vertices on the input surface;
//  - accuracy: the two-sided Hausdorff distance (oracle::twoSidedDistance, vcglib's grid over the
//    whole surface) at the level whose count is closest to 10% of the input at most 1.3 times
//    that of our uniform remesh at the same count; smallest angle (recounted) >= 15 degrees at
//    levels 2 and 3 on bunny00 and armadillo;
//  - the same output for the same seed; bad parameters refused before any work.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

#include "core/measure/evaluation.h"
#include "core/mesh/vcg_mesh.h"
#include "core/param/semi_regular.h"
#include "core/remesh/remesh_surface.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// Vertices past the base vertices whose neighbour count is not 6 (4 on a boundary), from the faces.
int irregularVertices(const TriMesh& m, int baseVertices) {
  std::vector<std::set<int>> neighbours(m.vertexCount());
  std::map<std::pair<int, int>, int> edgeFaces;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      neighbours[a].insert(b);
      neighbours[b].insert(a);
      ++edgeFaces[{std::min(a, b), std::max(a, b)}];
    }
  std::vector<char> onBoundary(m.vertexCount(), 0);
  for (const auto& [e, n] : edgeFaces)
    if (n == 1) onBoundary[e.first] = onBoundary[e.second] = 1;
  int irregular = 0;
  for (int v = baseVertices; v < m.vertexCount(); ++v)
    irregular += static_cast<int>(neighbours[v].size()) != (onBoundary[v] ? 4 : 6);
  return irregular;
}

void expectSemiRegular(const TriMesh& input, const SemiRegularResult& r, int levels) {
  EXPECT_EQ(irregularVertices(r.mesh, r.baseVertices), 0);
  EXPECT_EQ(r.mesh.faceCount(), r.baseTriangles * (1 << (2 * levels)));
  test::expectValidWithTopologyOf(test::recount(r.mesh.triangles, r.mesh.vertexCount()),
                                  test::recount(input.triangles, input.vertexCount()));
  const double onSurface = surfaceDistance(r.mesh, input, {}, 0, DistanceSamples::Vertices).max;
  EXPECT_LT(onSurface, 1e-6 * input.boundingBoxDiagonal()) << "an output vertex is off the input";
}

class Accuracy : public ::testing::TestWithParam<std::string> {};

// At the level whose vertex count is closest to 10% of the input (500 base vertices: level 1 on
// both meshes), against our uniform remesh with the same count.
TEST_P(Accuracy, HausdorffWithinAThirdOfTheUniformRemeshAtTenPercent) {
  const TriMesh input = test::loadRealMesh(GetParam());
  SemiRegularParams p;
  const double tenPercent = 0.1 * input.vertexCount();
  int level = 0;
  for (int l = 1; l <= 3; ++l)
    if (std::abs(p.base.baseVertices * std::pow(4.0, l) - tenPercent) <
        std::abs(p.base.baseVertices * std::pow(4.0, level) - tenPercent))
      level = l;
  p.levels = level;
  const Expected<SemiRegularResult> r = semiRegularRemesh(input, p);
  ASSERT_TRUE(r) << r.status().message;
  expectSemiRegular(input, *r, level);
  SurfaceRemeshParams u;
  u.sampling.targetCount = r->mesh.vertexCount();
  const Expected<SurfaceRemeshResult> uniform = remeshSurface(input, u);
  ASSERT_TRUE(uniform) << uniform.status().message;
  const double diagonal = input.boundingBoxDiagonal();
  const double ours = oracle::twoSidedDistance(r->mesh, input).max / diagonal;
  const double theirs = oracle::twoSidedDistance(uniform->mesh, input).max / diagonal;
  std::printf("%s level %d, %d vertices: Hausdorff %.3f%% (uniform remesh, %d vertices: %.3f%%)\n", GetParam().c_str(),
              level, r->mesh.vertexCount(), 100 * ours, uniform->mesh.vertexCount(), 100 * theirs);
  EXPECT_LE(ours, 1.3 * theirs);
}

TEST_P(Accuracy, SmallestAngleAtLeast15DegreesAtLevelsTwoAndThree) {
  const TriMesh input = test::loadRealMesh(GetParam());
  for (int level : {2, 3}) {
    SemiRegularParams p;
    p.levels = level;
    p.measureDistance = false;
    const Expected<SemiRegularResult> r = semiRegularRemesh(input, p);
    ASSERT_TRUE(r) << r.status().message;
    expectSemiRegular(input, *r, level);
    const double smallest = test::recountAngles(r->mesh).smallestDegrees;
    std::printf("%s level %d: smallest angle %.1f degrees\n", GetParam().c_str(), level, smallest);
    EXPECT_GE(smallest, 15.0) << "level " << level;
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, Accuracy, ::testing::Values("bunny00.off", "armadillo.off"),
                         [](const auto& p) { return test::testNameOfFile(p.param); });

TEST(SemiRegular, SameSeedSameOutput) {
  const TriMesh input = test::loadRealMesh("fandisk.off");
  SemiRegularParams p;
  p.base.baseVertices = 60;
  p.levels = 2;
  const Expected<SemiRegularResult> a = semiRegularRemesh(input, p), b = semiRegularRemesh(input, p);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->mesh.triangles, b->mesh.triangles);
  EXPECT_EQ(a->mesh.positions, b->mesh.positions);
}

TEST(SemiRegular, BoundaryVerticesHaveFourNeighbours) {
  const TriMesh input = test::loadRealMesh("elephant-with-holes.off");
  SemiRegularParams p;
  p.base.baseVertices = 200;
  p.levels = 2;
  const Expected<SemiRegularResult> r = semiRegularRemesh(input, p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_GT(r->mesh.topology.boundaryLoops, 0);
  expectSemiRegular(input, *r, 2);
}

// Levels out of 0..6 and outputs over 50 million faces are refused before any work: on a
// non-manifold mesh the answer is about the parameters, not the mesh.
TEST(SemiRegular, BadParametersRefusedBeforeAnyWork) {
  Expected<TriMesh> bowtie = buildTriMesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)},
                                          {{0, 1, 2}, {0, 3, 4}});
  ASSERT_TRUE(bowtie);
  SemiRegularParams p;
  p.levels = 7;
  Status s = semiRegularRemesh(*bowtie, p).status();
  EXPECT_EQ(s.code, StatusCode::InvalidInput);
  EXPECT_NE(s.message.find("Levels"), std::string::npos) << s.message;
  p.levels = -1;
  EXPECT_EQ(semiRegularRemesh(*bowtie, p).status().code, StatusCode::InvalidInput);
  p.levels = 6;
  p.base.baseVertices = 100000;  // 2 x 100,000 x 4^6 = 819 million faces
  s = semiRegularRemesh(*bowtie, p).status();
  EXPECT_EQ(s.code, StatusCode::InvalidInput);
  EXPECT_NE(s.message.find("50 million"), std::string::npos) << s.message;
  p.levels = 1;
  p.base.baseVertices = 10;
  EXPECT_EQ(semiRegularRemesh(*bowtie, p).status().code, StatusCode::NonManifold);
}

// Every mesh of the data set, one level: semi-regular with the input's topology, or a clean failure.
class DataSetSemiRegular : public ::testing::TestWithParam<std::string> {};

TEST_P(DataSetSemiRegular, SemiRegularOrCleanFailure) {
  Expected<TriMesh> loaded = loadTriMesh(test::meshPath(GetParam()));
  if (!loaded) {
    EXPECT_EQ(loaded.status().code, StatusCode::InvalidInput);
    return;
  }
  SemiRegularParams p;
  p.base.baseVertices = std::clamp(loaded->vertexCount() / 20, 4, 200);
  p.levels = 1;
  p.measureDistance = false;
  const Expected<SemiRegularResult> r = semiRegularRemesh(*loaded, p);
  if (!r) {
    const StatusCode code = r.status().code;
    EXPECT_TRUE(code == StatusCode::InvalidInput || code == StatusCode::NonManifold ||
                code == StatusCode::NotConverged || code == StatusCode::Degenerate)
        << toString(code);
    return;
  }
  expectSemiRegular(*loaded, *r, 1);
}

INSTANTIATE_TEST_SUITE_P(Meshes, DataSetSemiRegular, ::testing::ValuesIn(test::dataSetMeshFiles()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return test::testNameOfFile(p.param); });

}  // namespace
}  // namespace gr
