// The geodesic barycentric parameterisation over a base domain (core/param): each property
// recomputed here from the result's arrays, not read from the code's own counters.
//  - The cut surface is the input: every face lies in its input face (its corners' positions are
//    their barycentric coordinates there) and the areas add up to the input's.
//  - Each piece is a disk (recounted from its faces: one component, one boundary loop, Euler
//    characteristic 1) whose corners sit at its base triangle's corners.
//  - The map is one-to-one: no face of the cut surface has a non-positive area in its base
//    triangle's domain, and the areas of each piece add up to its triangle's: the pieces tile
//    each base triangle, within 1e-6.
//  - Neighbouring pieces agree on their shared side: a vertex on a cut has the same coordinates of
//    the side's two base vertices in both (no crack, no overlap between base triangles).
// On fandisk, bunny00 and armadillo, and on every mesh of the data set: valid or a clean failure.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "core/mesh/vcg_mesh.h"
#include "core/param/geodesic_parameterization.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

double area3(const Vec3& a, const Vec3& b, const Vec3& c) { return 0.5 * (b - a).cross(c - a).norm(); }

double cross2(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// The weight of each base vertex of base triangle t at corner c of the cut surface (u, v = the
/// weights of corners 1 and 2).
std::map<int, double> baseWeights(const Parameterization& p, int c) {
  const Tri& bt = p.base.triangles[p.pieces.triangle[c / 3]];
  const Vec2& uv = p.cornerUv[c];
  return {{bt[0], 1.0 - uv.x() - uv.y()}, {bt[1], uv.x()}, {bt[2], uv.y()}};
}

void expectSurfaceIsTheInput(const TriMesh& input, const Parameterization& p) {
  const TriMesh& cut = p.pieces.mesh;
  const double diagonal = input.boundingBoxDiagonal();
  double inputArea = 0.0, cutArea = 0.0, worst = 0.0;
  for (const Tri& t : input.triangles)
    inputArea += area3(input.positions[t[0]], input.positions[t[1]], input.positions[t[2]]);
  for (int f = 0; f < cut.faceCount(); ++f) {
    const Tri& t = cut.triangles[f];
    cutArea += area3(cut.positions[t[0]], cut.positions[t[1]], cut.positions[t[2]]);
    const Tri& of = input.triangles[p.pieces.originalFace[f]];
    for (int k = 0; k < 3; ++k) {
      Vec3 b = p.pieces.cornerBary[3 * f + k];
      if (p.flipped[p.pieces.originalFace[f]]) std::swap(b[1], b[2]);
      const Vec3 at = b[0] * input.positions[of[0]] + b[1] * input.positions[of[1]] + b[2] * input.positions[of[2]];
      worst = std::max(worst, (at - cut.positions[t[k]]).norm());
    }
  }
  EXPECT_LT(worst, 1e-9 * diagonal) << "a cut vertex is not where its barycentric coordinates put it";
  // cutVertexOrigins (what the filter writes from): each vertex's point on the input as given.
  const std::vector<SurfacePoint> origin = cutVertexOrigins(p);
  double worstOrigin = 0.0;
  for (int v = 0; v < cut.vertexCount(); ++v) {
    const SurfacePoint& o = origin[v];
    Vec3 at = Vec3::Zero();
    if (o.vertex >= 0)
      at = input.positions[o.vertex];
    else
      for (int k = 0; k < 3; ++k) at += o.bary[k] * input.positions[input.triangles[o.face][k]];
    worstOrigin = std::max(worstOrigin, (at - cut.positions[v]).norm());
  }
  EXPECT_LT(worstOrigin, 1e-9 * diagonal) << "an origin is not on its cut vertex";
  EXPECT_NEAR(cutArea, inputArea, 1e-9 * inputArea);
}

void expectDiskPieces(const Parameterization& p) {
  const TriMesh& cut = p.pieces.mesh;
  const int nt = static_cast<int>(p.base.triangles.size());
  std::vector<std::vector<Tri>> faces(nt);
  for (int f = 0; f < cut.faceCount(); ++f) {
    ASSERT_GE(p.pieces.triangle[f], 0);
    ASSERT_LT(p.pieces.triangle[f], nt);
    faces[p.pieces.triangle[f]].push_back(cut.triangles[f]);
  }
  int notDisks = 0;
  for (int t = 0; t < nt; ++t) {
    const test::Recount r = test::recount(faces[t], cut.vertexCount());
    notDisks += !(r.components == 1 && r.boundaryLoops == 1 && r.eulerCharacteristic == 1 && r.manifoldVertices);
  }
  EXPECT_EQ(notDisks, 0) << "pieces that are not disks";
}

void expectOneToOneTiling(const Parameterization& p) {
  const TriMesh& cut = p.pieces.mesh;
  const int nt = static_cast<int>(p.base.triangles.size());
  std::vector<double> area(nt, 0.0);
  int flipped = 0, misplacedCorners = 0;
  for (int f = 0; f < cut.faceCount(); ++f) {
    const double a = cross2(p.cornerUv[3 * f], p.cornerUv[3 * f + 1], p.cornerUv[3 * f + 2]);
    flipped += !(a > 0.0);
    area[p.pieces.triangle[f]] += a;  // twice the area; the reference triangle's is 1
    for (int k = 0; k < 3; ++k) {
      const Tri& bt = p.base.triangles[p.pieces.triangle[f]];
      for (int c = 0; c < 3; ++c)
        if (cut.triangles[f][k] == p.base.baseVertex[bt[c]])
          misplacedCorners += (baseWeights(p, 3 * f + k)[bt[c]] < 1.0 - 1e-12);
    }
  }
  EXPECT_EQ(flipped, 0) << "faces flipped or degenerate in their base triangle";
  EXPECT_EQ(misplacedCorners, 0) << "base vertices not at their triangle's corner";
  double worst = 0.0;
  for (double a : area) worst = std::max(worst, std::abs(a - 1.0));
  EXPECT_LT(worst, 1e-6) << "the pieces do not tile their base triangles";
}

/// A vertex of a cut has, in each piece it is in, weight 0 for the third corner and the same
/// weights of the side's two base vertices.
void expectSidesAgree(const Parameterization& p) {
  const TriMesh& cut = p.pieces.mesh;
  std::vector<std::map<int, double>> seen(cut.vertexCount());
  std::vector<int> seenTriangle(cut.vertexCount(), -1);
  double worst = 0.0;
  int compared = 0;
  for (int c = 0; c < 3 * cut.faceCount(); ++c) {
    const int v = cut.vertex(c), t = p.pieces.triangle[c / 3];
    const std::map<int, double> w = baseWeights(p, c);
    if (seenTriangle[v] < 0) {
      seenTriangle[v] = t;
      seen[v] = w;
      continue;
    }
    if (seenTriangle[v] == t) {  // the same piece: the same point
      for (const auto& [b, x] : w) worst = std::max(worst, std::abs(x - seen[v][b]));
      continue;
    }
    ++compared;  // another piece: the shared base vertices weigh the same, the others 0
    for (const auto& [b, x] : w) {
      const auto it = seen[v].find(b);
      worst = std::max(worst, std::abs(x - (it == seen[v].end() ? 0.0 : it->second)));
    }
  }
  EXPECT_GT(compared, 0);
  EXPECT_LT(worst, 1e-9) << "neighbouring pieces disagree on a shared side";
}

void expectValid(const TriMesh& input, const Parameterization& p) {
  expectSurfaceIsTheInput(input, p);
  expectDiskPieces(p);
  expectOneToOneTiling(p);
  expectSidesAgree(p);
}

class NamedMeshes : public ::testing::TestWithParam<std::pair<std::string, int>> {};

TEST_P(NamedMeshes, PiecesAreDisksThatTileTheirBaseTriangles) {
  const TriMesh input = test::loadRealMesh(GetParam().first);
  ParameterizationParams params;
  params.base.baseVertices = GetParam().second;
  const Expected<Parameterization> p = parameterizeOverBase(input, params);
  ASSERT_TRUE(p) << p.status().message;
  EXPECT_GE(static_cast<int>(p->base.baseVertex.size()), GetParam().second);
  expectValid(input, *p);
  // The base has the input's topology: V - E + F of the base triangles.
  const test::Recount base = test::recount(p->base.triangles, static_cast<int>(p->base.baseVertex.size()));
  EXPECT_EQ(base.genusSum, input.topology.genus);
  EXPECT_EQ(base.boundaryLoops, input.topology.boundaryLoops);
  std::printf("%s: %zu base vertices, pieces: %d Heron, %d smoothed near folds, %d repaired; %d edges split\n",
              GetParam().first.c_str(), p->base.baseVertex.size(), p->heronPieces, p->smoothedPieces, p->repairedPieces,
              p->pieces.splitEdges);
}

INSTANTIATE_TEST_SUITE_P(Meshes, NamedMeshes,
                         ::testing::Values(std::make_pair(std::string("fandisk.off"), 100),
                                           std::make_pair(std::string("bunny00.off"), 500),
                                           std::make_pair(std::string("armadillo.off"), 500),
                                           std::make_pair(std::string("elephant-with-holes.off"), 200),
                                           std::make_pair(std::string("knot2.off"), 200)),
                         [](const auto& p) { return test::testNameOfFile(p.param.first); });

/// On an n x n flat square with 30 base vertices: the mean distance, over the corners of the cut
/// surface whose planar coordinates are all >= 0.15, between their (u, v) and the planar
/// barycentric coordinates of their position in the straight triangle of their base vertices.
double planarError(int n) {
  const TriMesh plane = test::planeGrid(n, 1.0);
  ParameterizationParams params;
  params.base.baseVertices = 30;
  params.base.curvatureStrength = 0.0;
  const Expected<Parameterization> p = parameterizeOverBase(plane, params);
  EXPECT_TRUE(p) << p.status().message;
  if (!p) return 1.0;
  expectValid(plane, *p);
  double sum = 0.0;
  int count = 0;
  for (int c = 0; c < 3 * p->pieces.mesh.faceCount(); ++c) {
    const Tri& bt = p->base.triangles[p->pieces.triangle[c / 3]];
    const Vec3 a = plane.positions[p->base.baseVertex[bt[0]]], b = plane.positions[p->base.baseVertex[bt[1]]],
               d = plane.positions[p->base.baseVertex[bt[2]]], x = p->pieces.mesh.positions[p->pieces.mesh.vertex(c)];
    Eigen::Matrix2d m;
    m << (b - a).x(), (d - a).x(), (b - a).y(), (d - a).y();
    const Vec2 planar = m.inverse() * Vec2((x - a).x(), (x - a).y());
    if (std::min({planar.x(), planar.y(), 1.0 - planar.x() - planar.y()}) < 0.15) continue;
    sum += (planar - p->cornerUv[c]).norm();
    ++count;
  }
  std::printf("flat square %d x %d: pieces %d Heron, %d smoothed near folds, %d repaired; mean |uv - planar| %.4f\n", n,
              n, p->heronPieces, p->smoothedPieces, p->repairedPieces, sum / count);
  EXPECT_GT(count, 100);
  return sum / count;
}

// On a flat square the geodesic distances are straight ones, so a point's coordinates in its base
// triangle are its planar barycentric coordinates in the straight triangle of the base vertices
// (the oracle), up to the fronts' error, at points away from the triangle's sides (the sides are
// paths of edges pinned onto the straight sides: a zig-zag one edge wide moves the points beside
// it). The error falls as the grid is refined (the fronts' error goes with the edge length).
TEST(GeodesicParameterization, FlatSquareGivesPlanarBarycentricCoordinates) {
  const double coarse = planarError(30), fine = planarError(120);
  EXPECT_LT(planarError(60), 0.03);
  EXPECT_LT(fine, 0.6 * coarse);
}

TEST(GeodesicParameterization, SameSeedSameResult) {
  const TriMesh input = test::loadRealMesh("fandisk.off");
  ParameterizationParams params;
  params.base.baseVertices = 80;
  const Expected<Parameterization> a = parameterizeOverBase(input, params), b = parameterizeOverBase(input, params);
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->base.triangles, b->base.triangles);
  EXPECT_EQ(a->pieces.mesh.triangles, b->pieces.mesh.triangles);
  EXPECT_EQ(a->cornerUv, b->cornerUv);
}

TEST(GeodesicParameterization, BadInputIsRefused) {
  const TriMesh input = test::loadRealMesh("fandisk.off");
  ParameterizationParams params;
  params.base.baseVertices = 3;
  EXPECT_EQ(parameterizeOverBase(input, params).status().code, StatusCode::InvalidInput);
  params.base.baseVertices = 50;
  params.base.centroidalIterations = -1;
  EXPECT_EQ(parameterizeOverBase(input, params).status().code, StatusCode::InvalidInput);
  params.base.centroidalIterations = 0;
  params.base.curvatureStrength = std::nan("");
  EXPECT_EQ(parameterizeOverBase(input, params).status().code, StatusCode::InvalidInput);
  // Two triangles sharing only a vertex (a non-manifold vertex), and a triangle soup.
  Expected<TriMesh> bowtie = buildTriMesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)},
                                          {{0, 1, 2}, {0, 3, 4}});
  ASSERT_TRUE(bowtie);
  EXPECT_EQ(parameterizeOverBase(*bowtie, {}).status().code, StatusCode::NonManifold);
  std::vector<Vec3> soupPositions;
  std::vector<Tri> soup;
  for (int f = 0; f < 20; ++f) {
    for (int k = 0; k < 3; ++k) soupPositions.push_back(Vec3(f + (k == 1), k == 2, 0.1 * f));
    soup.push_back({3 * f, 3 * f + 1, 3 * f + 2});
  }
  Expected<TriMesh> soupMesh = buildTriMesh(soupPositions, soup);
  ASSERT_TRUE(soupMesh);
  const Status s = parameterizeOverBase(*soupMesh, {}).status();
  EXPECT_EQ(s.code, StatusCode::InvalidInput);
  EXPECT_NE(s.message.find("Merge Close Vertices"), std::string::npos) << s.message;
}

// Every mesh of the data set: valid, or a clean failure (a refusal of bad input, a cut that found
// no way, a degenerate piece).
class DataSetParameterization : public ::testing::TestWithParam<std::string> {};

TEST_P(DataSetParameterization, ValidOrCleanFailure) {
  Expected<TriMesh> loaded = loadTriMesh(test::meshPath(GetParam()));
  if (!loaded) {
    EXPECT_EQ(loaded.status().code, StatusCode::InvalidInput);
    return;
  }
  ParameterizationParams params;
  params.base.baseVertices = std::clamp(loaded->vertexCount() / 10, 4, 200);
  const Expected<Parameterization> p = parameterizeOverBase(*loaded, params);
  if (!p) {
    std::printf("%s: %s\n", GetParam().c_str(), p.status().message.c_str());
    const StatusCode code = p.status().code;
    EXPECT_TRUE(code == StatusCode::InvalidInput || code == StatusCode::NonManifold ||
                code == StatusCode::NotConverged || code == StatusCode::Degenerate)
        << toString(code);
    return;
  }
  expectValid(*loaded, *p);
}

INSTANTIATE_TEST_SUITE_P(Meshes, DataSetParameterization, ::testing::ValuesIn(test::dataSetMeshFiles()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return test::testNameOfFile(p.param); });

}  // namespace
}  // namespace gr
