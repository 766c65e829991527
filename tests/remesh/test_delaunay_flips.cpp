// Edge flips towards a Delaunay triangulation (delaunay_flips.h). Oracles: the empty-circle
// property checked directly on a planar point set (no fourth point inside any triangle's
// circumcircle, by brute force), invariants (same vertices, faces, topology, orientation), and
// features (a crease is never cut).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "core/base/math.h"
#include "core/measure/evaluation.h"
#include "core/remesh/delaunay_flips.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// Random points in the unit square (corners and a few boundary points included), triangulated
/// badly on purpose: a fan from the first point of each grid-cell strip would need a real
/// triangulator, so use a jittered grid with every diagonal chosen at random.
TriMesh randomDiagonalGrid(int n, double jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Vec3> p;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      p.emplace_back((i + (border ? 0.0 : u(rng))) / n, (j + (border ? 0.0 : u(rng))) / n, 0.0);
    }
  std::vector<Tri> t;
  std::bernoulli_distribution coin(0.5);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      if (coin(rng)) {
        t.push_back({a, b, c});
        t.push_back({a, c, d});
      } else {
        t.push_back({a, b, d});
        t.push_back({b, c, d});
      }
    }
  return buildTriMesh(p, t).value();
}

/// Flips to Delaunay, failing the test if the mesh is refused; the number of flips (-1 if refused).
int flipCount(TriMesh& m, const DelaunayFlipParams& params = {}) {
  const Expected<DelaunayFlipResult> r = flipToDelaunay(m, params);
  EXPECT_TRUE(r) << r.status().message;
  return r ? r->flips : -1;
}

/// Points strictly inside the circumcircle of some triangle (planar, z = 0), by brute force.
int emptyCircleViolations(const TriMesh& m, double relTol) {
  int violations = 0;
  for (const Tri& t : m.triangles) {
    const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    const double d = 2.0 * (a.x() * (b.y() - c.y()) + b.x() * (c.y() - a.y()) + c.x() * (a.y() - b.y()));
    const double ux =
        (a.squaredNorm() * (b.y() - c.y()) + b.squaredNorm() * (c.y() - a.y()) + c.squaredNorm() * (a.y() - b.y())) / d;
    const double uy =
        (a.squaredNorm() * (c.x() - b.x()) + b.squaredNorm() * (a.x() - c.x()) + c.squaredNorm() * (b.x() - a.x())) / d;
    const Vec3 center(ux, uy, 0.0);
    const double r = (a - center).norm();
    for (int v = 0; v < m.vertexCount(); ++v)
      if (v != t[0] && v != t[1] && v != t[2] && (m.positions[v] - center).norm() < r * (1.0 - relTol)) ++violations;
  }
  return violations;
}

TEST(DelaunayFlips, PlanarPointSetBecomesDelaunay) {
  for (unsigned seed : {1u, 2u, 3u}) {
    TriMesh m = randomDiagonalGrid(20, 0.3, seed);
    const Topology before = m.topology;
    const int faces = m.faceCount();
    ASSERT_GT(emptyCircleViolations(m, 1e-9), 0) << "the fixture should start far from Delaunay";
    EXPECT_GT(flipCount(m), 0);
    EXPECT_EQ(emptyCircleViolations(m, 1e-6), 0) << "seed " << seed;
    EXPECT_EQ(m.faceCount(), faces);
    EXPECT_EQ(m.topology.components, before.components);
    EXPECT_EQ(m.topology.boundaryLoops, before.boundaryLoops);
    EXPECT_EQ(m.topology.genus, before.genus);
    EXPECT_EQ(m.topology.inconsistentEdges, 0);
    EXPECT_TRUE(m.topology.isManifold());
    for (const Tri& t : m.triangles) {  // every face still faces up (+z)
      const Vec3 n = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
      EXPECT_GT(n.z(), 0.0);
    }
  }
}

/// The adjacency the flips keep up to date equals the one built from scratch from the flipped
/// triangles, and the topology is unchanged (recounted from scratch as well).
void expectAdjacencyAsIfRebuilt(const TriMesh& m) {
  const TriMesh fresh = buildTriMesh(m.positions, m.triangles).value();
  EXPECT_EQ(m.oppositeCorner, fresh.oppositeCorner);
  EXPECT_EQ(m.vertexCornerBegin, fresh.vertexCornerBegin);
  EXPECT_EQ(m.vertexCorners, fresh.vertexCorners);
  EXPECT_EQ(m.topology.components, fresh.topology.components);
  EXPECT_EQ(m.topology.genus, fresh.topology.genus);
  EXPECT_EQ(m.topology.boundaryLoops, fresh.topology.boundaryLoops);
  EXPECT_EQ(m.topology.inconsistentEdges, fresh.topology.inconsistentEdges);
  EXPECT_TRUE(fresh.topology.isManifold());
}

TEST(DelaunayFlips, AdjacencyIsThatOfTheFlippedTriangles) {
  TriMesh grid = randomDiagonalGrid(20, 0.3, 5);  // open: boundary fans
  EXPECT_GT(flipCount(grid), 0);
  expectAdjacencyAsIfRebuilt(grid);
  // Closed: a sphere whose vertices are jittered along it, so that many diagonals flip.
  TriMesh sphere = test::icosphere(3);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.04, 0.04);
  for (Vec3& p : sphere.positions) p = (p + Vec3(u(rng), u(rng), u(rng))).normalized();
  sphere = buildTriMesh(sphere.positions, sphere.triangles).value();
  EXPECT_GT(flipCount(sphere), 0);
  expectAdjacencyAsIfRebuilt(sphere);
}

TEST(DelaunayFlips, MinimumAngleDoesNotDecrease) {
  TriMesh m = randomDiagonalGrid(30, 0.35, 7);
  const double before = angleStatistics(m).minDegrees;
  EXPECT_GT(flipCount(m), 0);
  EXPECT_GE(angleStatistics(m).minDegrees, before);  // Delaunay maximises the smallest angle
}

/// A strip folded by 90 degrees along the crease x = z = 0: each crease edge has a skinny
/// triangle on each side whose apex faces it with about 157 degrees, so the planar criterion
/// alone would flip every crease edge (and cut the fold).
TriMesh foldedStrip(int n, double w) {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  for (int i = 0; i <= n; ++i) p.emplace_back(0.0, double(i) / n, 0.0);  // c_i = i
  for (int i = 0; i < n; ++i) p.emplace_back(-w, (i + 0.5) / n, 0.0);    // l_i
  for (int i = 0; i < n; ++i) p.emplace_back(0.0, (i + 0.5) / n, w);     // r_i
  const auto c = [](int i) { return i; };
  const auto l = [&](int i) { return n + 1 + i; };
  const auto r = [&](int i) { return 2 * n + 1 + i; };
  for (int i = 0; i < n; ++i) {
    t.push_back({l(i), c(i), c(i + 1)});
    t.push_back({r(i), c(i + 1), c(i)});
    if (i + 1 < n) {
      t.push_back({l(i), c(i + 1), l(i + 1)});
      t.push_back({r(i), r(i + 1), c(i + 1)});
    }
  }
  return buildTriMesh(p, t).value();
}

int creaseEdgesLeft(const TriMesh& m, int n) {
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    bool found = false;
    for (const Tri& f : m.triangles)
      for (int k = 0; k < 3; ++k) found |= std::minmax(f[k], f[(k + 1) % 3]) == std::minmax(i, i + 1);
    kept += found;
  }
  return kept;
}

TEST(DelaunayFlips, CreaseIsKept) {
  const int n = 10;
  TriMesh m = foldedStrip(n, 0.01);
  EXPECT_GE(flipCount(m), 0);
  EXPECT_EQ(creaseEdgesLeft(m, n), n);
  // The fixture does test something: with the feature check disabled the crease is cut.
  TriMesh unchecked = foldedStrip(n, 0.01);
  DelaunayFlipParams params;
  params.featureAngleDegrees = 180.0;
  EXPECT_GT(flipCount(unchecked, params), 0);
  EXPECT_LT(creaseEdgesLeft(unchecked, n), n);
}

/// Sum over vertices of (valence - 6)^2 (4 on the boundary), valences counted from the triangle
/// list alone (distinct neighbours), independently of TriMesh's adjacency.
int valenceExcess(const TriMesh& m) {
  std::vector<std::vector<int>> neighbours(m.vertexCount());
  std::map<std::pair<int, int>, int> edgeFaces;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbours[t[k]].push_back(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].push_back(t[k]);
      ++edgeFaces[std::minmax(t[k], t[(k + 1) % 3])];
    }
  std::vector<char> boundary(m.vertexCount(), 0);
  for (const auto& [e, faces] : edgeFaces)
    if (faces == 1) boundary[e.first] = boundary[e.second] = 1;
  int sum = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    std::sort(neighbours[v].begin(), neighbours[v].end());
    const int valence =
        static_cast<int>(std::unique(neighbours[v].begin(), neighbours[v].end()) - neighbours[v].begin());
    const int e = valence - (boundary[v] ? 4 : 6);
    sum += e * e;
  }
  return sum;
}

// Flips toward valence 6 on a grid with random diagonals (valences 4 to 8): the valence excess
// falls, the topology is the same (recounted), no angle under the bound appears (the grid's
// triangles have 45 and 90 degrees), and a flat grid stays flat.
TEST(ValenceFlips, EvenTheValencesAndKeepTheMesh) {
  TriMesh m = randomDiagonalGrid(20, 0.0, 3);
  const int before = valenceExcess(m);
  const test::Recount in = test::recount(m.triangles, m.vertexCount());
  const Expected<DelaunayFlipResult> r = flipTowardValenceSix(m);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_GT(r->flips, 0);
  std::printf("valence excess %d -> %d after %d flips\n", before, valenceExcess(m), r->flips);
  EXPECT_LT(valenceExcess(m), before);
  const test::Recount out = test::recount(m.triangles, m.vertexCount());
  EXPECT_TRUE(out.manifoldEdges && out.manifoldVertices && out.oriented);
  EXPECT_EQ(out.components, in.components);
  EXPECT_EQ(out.boundaryLoops, in.boundaryLoops);
  EXPECT_EQ(out.genusSum, in.genusSum);
  EXPECT_EQ(m.faceCount(), 2 * 20 * 20);
  EXPECT_GE(angleStatistics(m).minDegrees, 30.0 - 1e-9);
  expectAdjacencyAsIfRebuilt(m);
}

/// The grid's edges on the line x = 0.5 (both ends there), after folding it there by 90 degrees.
int foldEdges(const TriMesh& m) {
  std::map<std::pair<int, int>, int> seen;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (std::abs(m.positions[a].x() - 0.5) < 1e-12 && std::abs(m.positions[b].x() - 0.5) < 1e-12 &&
          std::abs(m.positions[a].z()) < 1e-12 && std::abs(m.positions[b].z()) < 1e-12)
        seen[std::minmax(a, b)] = 1;
    }
  return static_cast<int>(seen.size());
}

TEST(ValenceFlips, CreaseIsKept) {
  // Seed 4: diagonals for which some edges of the line x = 0.5 are worth flipping when flat.
  const unsigned seed = 4;
  const auto grid = [seed](bool fold) {
    TriMesh m = randomDiagonalGrid(20, 0.0, seed);
    for (Vec3& p : m.positions)
      if (fold && p.x() > 0.5 + 1e-12) p = Vec3(0.5, p.y(), p.x() - 0.5);
    return m;
  };
  ValenceFlipParams anyAngle;  // the angle bound alone would keep those edges (new angles of 27 deg)
  anyAngle.minAngleDegrees = 0.0;
  TriMesh folded = grid(true);
  ASSERT_EQ(foldEdges(folded), 20);
  ASSERT_TRUE(flipTowardValenceSix(folded, anyAngle));
  EXPECT_EQ(foldEdges(folded), 20);
  // The fixture tests something: on the same grid left flat, some of those edges are flipped.
  TriMesh flat = grid(false);
  ASSERT_TRUE(flipTowardValenceSix(flat, anyAngle));
  EXPECT_LT(foldEdges(flat), 20);
}

/// The mesh's edges, each as (smaller, larger) vertex.
std::map<std::pair<int, int>, int> edgesOf(const TriMesh& m) {
  std::map<std::pair<int, int>, int> edges;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) edges[std::minmax(t[k], t[(k + 1) % 3])] = 1;
  return edges;
}

// The caller's accept is asked last and decides: refusing all leaves the grid as it was; allowing
// only edges with both ends left of x = 0.5 flips some, and every edge gone has both ends there.
TEST(ValenceFlips, AcceptDecidesLast) {
  const TriMesh grid = randomDiagonalGrid(20, 0.0, 3);
  ValenceFlipParams none;
  none.accept = [](int) { return false; };
  TriMesh refused = grid;
  ASSERT_TRUE(flipTowardValenceSix(refused, none));
  EXPECT_EQ(refused.triangles, grid.triangles);

  TriMesh left = grid;
  ValenceFlipParams leftOnly;
  int asked = 0;
  leftOnly.accept = [&](int corner) {
    ++asked;
    const int a = left.vertex(TriMesh::next(corner)), b = left.vertex(TriMesh::prev(corner));
    return left.positions[a].x() < 0.5 - 1e-12 && left.positions[b].x() < 0.5 - 1e-12;
  };
  const Expected<DelaunayFlipResult> r = flipTowardValenceSix(left, leftOnly);
  ASSERT_TRUE(r) << r.status().message;
  TriMesh all = grid;
  const Expected<DelaunayFlipResult> unrestricted = flipTowardValenceSix(all);
  ASSERT_TRUE(unrestricted);
  std::printf("%d flips of %d asked (%d without accept)\n", r->flips, asked, unrestricted->flips);
  EXPECT_GT(r->flips, 0);
  EXPECT_LT(r->flips, unrestricted->flips);
  const std::map<std::pair<int, int>, int> after = edgesOf(left);
  for (const auto& [edge, one] : edgesOf(grid))
    if (!after.count(edge)) {
      EXPECT_LT(grid.positions[edge.first].x(), 0.5);
      EXPECT_LT(grid.positions[edge.second].x(), 0.5);
    }
  expectAdjacencyAsIfRebuilt(left);
}

// A cap: x on the segment ab up to a rounding-sized offset out of the plane, as three samples on
// one straight line of the input give after MeshLab's floats (seen on armadillo subdivided three
// times, adaptive remesh to 100k: 204 such faces). Its normal is perpendicular to the plane of
// its neighbours, which used to read as a crease and block the flip; the flip removes the cap.
TEST(DelaunayFlips, CapIsFlippedAway) {
  //        c
  //      /   \    faces (x, b, c) and (a, x, c)
  //     a--x--b    (a, b, x) is the cap; the plane is z = 0, x is lifted
  //      \   /    face (a, y, b)
  //        y
  // Lifted by rounding (1e-6) or by half a degree (0.005: the cap's normal is then well defined,
  // at right angles to its neighbours').
  for (const double lift : {0.0, 1e-6, -1e-6, 0.005, -0.005}) {
    SCOPED_TRACE(lift);
    const std::vector<Vec3> p = {{0, 0, 0}, {2, 0, 0}, {1, 0, lift}, {1, -1, 0}, {1, 1, 0}};
    const int a = 0, b = 1, x = 2, y = 3, c = 4;
    TriMesh m = buildTriMesh(p, {{a, y, b}, {a, b, x}, {x, b, c}, {a, x, c}}).value();
    ASSERT_GT(test::recountAngles(m).largestDegrees, 179.4);
    EXPECT_GE(flipCount(m), 1);
    EXPECT_LT(test::recountAngles(m).largestDegrees, 91.0);
    EXPECT_EQ(m.faceCount(), 4);
    EXPECT_EQ(m.topology.inconsistentEdges, 0);
    EXPECT_EQ(m.topology.boundaryLoops, 1);
  }
}

// A folded ear on a boundary: (a, b, x) with x at about 173.5 degrees, a few hundredths off the
// line ab toward y and lifted, so that its normal is 135 degrees from its neighbour's (holes.off
// at 10% had one at 174.7 degrees, the smallest angle of the output, 2.1 degrees). Such a cap says
// nothing about a crease; the flip to (x, y) unfolds it.
TEST(DelaunayFlips, FoldedEarIsFlippedAway) {
  //     a---x---b    x a little below the line, toward y, and lifted out of the plane z = 0
  //      \     /
  //        y
  const std::vector<Vec3> p = {{0, 0, 0}, {2, 0, 0}, {1, -0.04, 0.04}, {1, -1, 0}};
  const int a = 0, b = 1, x = 2, y = 3;
  TriMesh m = buildTriMesh(p, {{a, y, b}, {a, b, x}}).value();
  const auto normal = [&](const Tri& t) {
    return Vec3((m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized());
  };
  ASSERT_LT(normal(m.triangles[0]).dot(normal(m.triangles[1])), std::cos(30.0 * kPi / 180.0));  // folded
  const double largest = test::recountAngles(m).largestDegrees;
  ASSERT_TRUE(largest > 170.0 && largest < 179.0) << largest;
  EXPECT_EQ(flipCount(m), 1);
  EXPECT_LT(test::recountAngles(m).largestDegrees, 120.0);
  EXPECT_GT(normal(m.triangles[0]).dot(normal(m.triangles[1])), std::cos(10.0 * kPi / 180.0));  // unfolded
  EXPECT_EQ(m.topology.inconsistentEdges, 0);
  EXPECT_EQ(m.topology.boundaryLoops, 1);
}

/// flipToDelaunay refuses the mesh with `code` and leaves its triangles as they were.
void expectRefused(TriMesh m, StatusCode code) {
  const std::vector<Tri> before = m.triangles;
  const Expected<DelaunayFlipResult> r = flipToDelaunay(m);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, code) << r.status().message;
  EXPECT_EQ(m.triangles, before);
}

TEST(DelaunayFlips, NonManifoldMeshIsRefusedAndLeftAlone) {
  // Three faces on one edge.
  std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  std::vector<Tri> t = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  TriMesh m = buildTriMesh(p, t).value();
  ASSERT_FALSE(m.topology.isManifold());
  expectRefused(m, StatusCode::NonManifold);
}

TEST(DelaunayFlips, InconsistentOrientationIsRefusedAndLeftAlone) {
  // Two faces that both run 0 -> 1 along their shared edge, which is far from Delaunay (facing
  // angles of about 127 degrees each).
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0.5, 0.25, 0}, {0.5, -0.25, 0}};
  TriMesh m = buildTriMesh(p, {{0, 1, 2}, {0, 1, 3}}).value();
  ASSERT_TRUE(m.topology.isManifold());
  ASSERT_GT(m.topology.inconsistentEdges, 0);
  expectRefused(m, StatusCode::InvalidInput);
}

TEST(DelaunayFlips, MeshWithoutFacesIsRefused) { expectRefused(TriMesh(), StatusCode::InvalidInput); }

/// Two faces (x, a, b), (y, b, a) on the edge a = (0, 0, 0), b = (1, 0, 0), with y lifted by z
/// (a crease along (a, b) of 22 degrees at z = 0.2): smallest angles 24.1 and 27.3 degrees in the
/// plane. The other diagonal gives 24.0 and 42.2: one face under 30 degrees instead of two. The
/// facing angles sum to 179.8 degrees, so the Delaunay flips keep (a, b).
TriMesh quadWithTwoFacesUnder30(double z) {
  const std::vector<Vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0.33, 0.3, 0}, {0.03, -0.5, z}};  // a, b, x, y
  return buildTriMesh(positions, {{2, 0, 1}, {3, 1, 0}}).value();
}

int facesUnder30(const TriMesh& m) {
  return static_cast<int>(std::lround(test::recountAngles(m).shareBelow30 * m.faceCount()));
}

// flipToBetterAngles flips to fewer faces under 30 degrees where the Delaunay flips do not, never
// below its angle bound nor across a crease sharper than its feature angle. Counts and angles are
// recounted from the positions.
TEST(AngleFlips, FewerFacesUnder30ThanDelaunay) {
  TriMesh delaunay = quadWithTwoFacesUnder30(0.0);
  EXPECT_EQ(flipCount(delaunay), 0);
  EXPECT_EQ(facesUnder30(delaunay), 2);

  TriMesh m = quadWithTwoFacesUnder30(0.0);
  const Expected<DelaunayFlipResult> r = flipToBetterAngles(m);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->flips, 1);
  EXPECT_EQ(facesUnder30(m), 1);
  EXPECT_NEAR(test::recountAngles(m).smallestDegrees, 23.99, 0.01);
  expectAdjacencyAsIfRebuilt(m);

  AngleFlipParams bound;  // the flip would make 23.99 degrees: under this bound, it is refused
  bound.minAngleDegrees = 24.05;
  TriMesh held = quadWithTwoFacesUnder30(0.0);
  EXPECT_EQ(flipToBetterAngles(held, bound).value().flips, 0);
  EXPECT_EQ(held.triangles, delaunay.triangles);

  AngleFlipParams crease;  // the lifted quad: 21.8 degrees between the faces, 24.8 after the flip
  crease.featureAngleDegrees = 20.0;
  TriMesh creased = quadWithTwoFacesUnder30(0.2);
  EXPECT_EQ(flipToBetterAngles(creased, crease).value().flips, 0);
  crease.featureAngleDegrees = 30.0;
  EXPECT_EQ(flipToBetterAngles(creased, crease).value().flips, 1);
  EXPECT_EQ(facesUnder30(creased), 1);
}

// On a jittered grid, the faces under 30 degrees never grow in number and the smallest angle
// never falls under the bound given (the grid's own smallest angle), the topology kept.
TEST(AngleFlips, NeverMoreFacesUnder30NorASmallerAngle) {
  for (unsigned seed : {3u, 5u, 9u}) {
    TriMesh m = randomDiagonalGrid(20, 0.35, seed);
    const int before = facesUnder30(m);
    AngleFlipParams params;
    params.minAngleDegrees = test::recountAngles(m).smallestDegrees;
    const Expected<DelaunayFlipResult> r = flipToBetterAngles(m, params);
    ASSERT_TRUE(r) << r.status().message;
    std::printf("seed %u: %d flips, faces under 30 degrees %d -> %d\n", seed, r->flips, before, facesUnder30(m));
    EXPECT_GT(r->flips, 0);
    EXPECT_LE(facesUnder30(m), before);
    EXPECT_GE(test::recountAngles(m).smallestDegrees, params.minAngleDegrees - 1e-9);
    expectAdjacencyAsIfRebuilt(m);
  }
}

/// The faces of `m` as sorted vertex triples, each rotated to start at its smallest vertex.
std::vector<Tri> canonicalFaces(const TriMesh& m) {
  std::vector<Tri> faces;
  for (Tri t : m.triangles) {
    while (t[0] != std::min({t[0], t[1], t[2]})) t = {t[1], t[2], t[0]};
    faces.push_back(t);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// flipOneEdge flips one interior edge (the adjacency as if rebuilt), the corner it returns flips
// it back to the same faces, and an edge on a crease sharper than the bound stays.
TEST(OneFlip, FlipsAndFlipsBack) {
  TriMesh m = randomDiagonalGrid(6, 0.2, 4);
  const std::vector<Tri> before = canonicalFaces(m);
  int flipped = 0;
  for (int c = 0; c < 3 * m.faceCount(); ++c) {
    if (m.oppositeCorner[c] < 0) continue;
    const int x = m.vertex(c), y = m.vertex(m.oppositeCorner[c]);
    const int back = flipOneEdge(m, c, 30.0);
    if (back < 0) continue;
    ++flipped;
    EXPECT_NE(canonicalFaces(m), before);
    EXPECT_TRUE((m.vertex(TriMesh::next(back)) == x && m.vertex(TriMesh::prev(back)) == y) ||
                (m.vertex(TriMesh::next(back)) == y && m.vertex(TriMesh::prev(back)) == x));
    expectAdjacencyAsIfRebuilt(m);
    ASSERT_GE(flipOneEdge(m, back, -1.0), 0);
    EXPECT_EQ(canonicalFaces(m), before);
    expectAdjacencyAsIfRebuilt(m);
  }
  EXPECT_GT(flipped, 50);  // most of the 85 interior edges of a 6 x 6 grid

  TriMesh creased = quadWithTwoFacesUnder30(0.2);  // 21.8 degrees between the faces
  EXPECT_EQ(flipOneEdge(creased, 0, 20.0), -1);
  EXPECT_GE(flipOneEdge(creased, 0, 30.0), 0);
}

}  // namespace
}  // namespace gr
