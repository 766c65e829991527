// Tangential relaxation on the input surface (surface_relaxation.h). Oracles: invariants of the
// pass (vertices stay on the input surface, the connectivity keeps its topology, recounted
// independently; boundary and crease vertices do not move; in the plane the smallest angle never
// decreases, since moves and Delaunay flips both keep or raise it), and what it is for: better
// angles than the triangulation it starts from.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "core/base/math.h"
#include "core/geodesic/farthest_point_sampling.h"
#include "core/measure/evaluation.h"
#include "core/remesh/geodesic_delaunay.h"
#include "core/remesh/surface_relaxation.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// Smallest angle of a mesh in degrees, recomputed from the positions.
double smallestAngle(const TriMesh& m) { return test::recountAngles(m).smallestDegrees; }

/// The geodesic Delaunay triangulation of `count` farthest-point samples of `input`.
DelaunayResult triangulate(const TriMesh& input, int count) {
  FastMarcher marcher(input, Metric::uniform());
  FpsParams fps;
  fps.targetCount = count;
  const Expected<FpsResult> samples = farthestPointSampling(marcher, fps);
  EXPECT_TRUE(samples);
  Expected<DelaunayResult> r = geodesicDelaunay(marcher, samples->origin);
  EXPECT_TRUE(r) << r.status().message;
  return std::move(*r);
}

void expectSameTopology(const DelaunayResult& before, const TriMesh& after) {
  const test::Recount a = test::recount(before.mesh.triangles, before.mesh.vertexCount());
  const test::Recount b = test::recount(after.triangles, after.vertexCount());
  EXPECT_TRUE(b.manifoldEdges && b.manifoldVertices && b.oriented);
  EXPECT_EQ(b.components, a.components);
  EXPECT_EQ(b.genusSum, a.genusSum);
  EXPECT_EQ(b.boundaryLoops, a.boundaryLoops);
  EXPECT_EQ(after.faceCount(), before.mesh.faceCount());
}

TEST(SurfaceRelaxation, PlaneStaysPlanarKeepsBoundaryAndRaisesTheSmallestAngle) {
  const TriMesh input = test::planeGrid(60, 1.0, 0.3, 7);
  const DelaunayResult d = triangulate(input, 300);
  TriMesh out = d.mesh;
  std::vector<SurfacePoint> points = d.origin;
  const Expected<RelaxationResult> r = relaxOnSurface(out, points, input);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->iterations, RelaxationParams{}.iterations);
  EXPECT_GT(r->moves, 300);
  expectSameTopology(d, out);
  for (int v = 0; v < out.vertexCount(); ++v) {
    EXPECT_EQ(out.positions[v].z(), 0.0);
    EXPECT_LT((points[v].position(input) - out.positions[v]).norm(), 1e-12);
    EXPECT_GE(out.positions[v].x(), 0.0);
    EXPECT_LE(out.positions[v].x(), 1.0);
  }
  // Boundary vertices (an edge with one face) stay on the square's sides; those on its corners
  // stay where they are, the others slide along the sides.
  const auto sides = [](const Vec3& p) {
    int on = 0;
    for (const double x : {p.x(), p.y()}) on += std::abs(x) < 1e-12 || std::abs(x - 1) < 1e-12;
    return on;
  };
  int boundaryVertices = 0, slid = 0;
  for (int c = 0; c < 3 * out.faceCount(); ++c)
    if (out.oppositeCorner[c] < 0) {
      const int v = out.vertex(TriMesh::next(c));
      EXPECT_GE(sides(out.positions[v]), 1) << "vertex " << v << " left the boundary";
      if (sides(d.mesh.positions[v]) == 2) {
        EXPECT_EQ(out.positions[v], d.mesh.positions[v]) << "corner " << v;
      }
      slid += out.positions[v] != d.mesh.positions[v];
      ++boundaryVertices;
    }
  EXPECT_GT(slid, 0);
  EXPECT_LE(r->slidingVertices, boundaryVertices);
  EXPECT_GT(boundaryVertices, 20);
  const double before = smallestAngle(d.mesh), after = smallestAngle(out);
  const AngleStatistics a0 = angleStatistics(d.mesh), a1 = angleStatistics(out);
  std::printf("plane: smallest angle %.1f -> %.1f deg, angle std %.1f -> %.1f deg, under 30: %.2f -> %.2f %%\n", before,
              after, a0.stdDegrees, a1.stdDegrees, 100 * a0.shareMinBelow30, 100 * a1.shareMinBelow30);
  EXPECT_GE(after, before - 1e-9);
  EXPECT_LT(a1.stdDegrees, a0.stdDegrees);
}

TEST(SurfaceRelaxation, SphereVerticesStayOnTheInputSurface) {
  const TriMesh input = test::icosphere(5);  // 10,242 vertices
  const DelaunayResult d = triangulate(input, 1500);
  TriMesh out = d.mesh;
  std::vector<SurfacePoint> points = d.origin;
  const Expected<RelaxationResult> r = relaxOnSurface(out, points, input);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->fixedVertices, 0);  // closed and smooth: every vertex may move
  expectSameTopology(d, out);
  // On a facet of the icosphere: radius between the facets' inradius and 1.
  const double edge = input.meanEdgeLength();
  for (int v = 0; v < out.vertexCount(); ++v) {
    const double radius = out.positions[v].norm();
    EXPECT_LE(radius, 1.0 + 1e-12);
    EXPECT_GE(radius, 1.0 - edge * edge);
    EXPECT_LT((points[v].position(input) - out.positions[v]).norm(), 1e-12);
  }
  EXPECT_GT(angleStatistics(out).minDegrees, angleStatistics(d.mesh).minDegrees);
  EXPECT_GE(angleStatistics(out).minDegrees, 25.0);
}

/// The other ends of input vertex iv's edges sharper than 60 degrees (or on the boundary), found
/// from the input's face normals.
std::vector<int> sharpNeighbours(const TriMesh& input, int iv) {
  const auto normal = [&](int f) {
    const Tri& t = input.triangles[f];
    return Vec3((input.positions[t[1]] - input.positions[t[0]])
                    .cross(input.positions[t[2]] - input.positions[t[0]])
                    .normalized());
  };
  std::vector<int> ends;
  for (const int* c = input.cornersBegin(iv); c != input.cornersEnd(iv); ++c)
    for (const int e : {TriMesh::prev(*c), TriMesh::next(*c)}) {  // the edges (iv, next) and (iv, prev)
      const int o = input.oppositeCorner[e];
      const int end = input.vertex(e == TriMesh::prev(*c) ? TriMesh::next(*c) : TriMesh::prev(*c));
      if ((o < 0 || normal(*c / 3).dot(normal(o / 3)) < std::cos(60.0 * kPi / 180.0)) &&
          std::find(ends.begin(), ends.end(), end) == ends.end())
        ends.push_back(end);
    }
  return ends;
}

/// Distance from p to the nearest input edge sharper than 60 degrees.
double distanceToCrease(const TriMesh& input, const Vec3& p) {
  double nearest = std::numeric_limits<double>::infinity();
  for (int v = 0; v < input.vertexCount(); ++v)
    for (const int u : sharpNeighbours(input, v)) {
      const Vec3 a = input.positions[v], ab = input.positions[u] - a;
      const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (p - (a + t * ab)).norm());
    }
  return nearest;
}

/// The vertex after iv on its chain of sharp edges coming from `from`, or -1 where the chain
/// ends: not exactly two sharp edges at iv, or a turn sharper than 60 degrees.
int chainNext(const TriMesh& input, int iv, int from) {
  const std::vector<int> ends = sharpNeighbours(input, iv);
  if (ends.size() != 2) return -1;
  const int to = ends[0] == from ? ends[1] : ends[0];
  const Vec3 in = input.positions[iv] - input.positions[from], out = input.positions[to] - input.positions[iv];
  return in.dot(out) > std::cos(60.0 * kPi / 180.0) * in.norm() * out.norm() ? to : -1;
}

/// The length of the chain of sharp edges through input vertex iv (a vertex with two of them and
/// no sharp turn), walked both ways to its ends (once round a closed one).
double chainLength(const TriMesh& input, int iv) {
  const std::vector<int> ends = sharpNeighbours(input, iv);
  double length = 0;
  for (const int first : ends) {
    int from = iv, at = first;
    for (int steps = 0; steps < input.vertexCount() && at != iv; ++steps) {
      length += (input.positions[at] - input.positions[from]).norm();
      const int next = chainNext(input, at, from);
      if (next < 0) break;
      from = at;
      at = next;
    }
    if (at == iv) return length;  // closed: once round
  }
  return length;
}

/// Output vertices of the triangulation at input vertices on fandisk's sharp edges: on a corner
/// (three or more sharp edges, or a turn sharper than 60 degrees), or on a crease.
void creaseAndCornerVertices(const TriMesh& input, const DelaunayResult& d, std::vector<int>& onCorner,
                             std::vector<int>& onCrease) {
  for (int v = 0; v < d.mesh.vertexCount(); ++v) {
    const int iv = d.origin[v].vertex;
    if (iv < 0) continue;
    const std::vector<int> ends = sharpNeighbours(input, iv);
    if (ends.empty()) continue;
    (ends.size() != 2 || chainNext(input, iv, ends[0]) < 0 ? onCorner : onCrease).push_back(v);
  }
}

// Output vertices on a crease of fandisk slide along it; those on its corners (three or more
// sharp edges, or a turn of the crease sharper than 60 degrees) do not move: every crease held
// (minCreaseLength 0; the short ones: below).
TEST(SurfaceRelaxation, CreaseVerticesStayOnTheirCreasesAndCornersDoNotMove) {
  const TriMesh input = test::loadRealMesh("fandisk.off");
  const DelaunayResult d = triangulate(input, 648);
  std::vector<int> onCorner, onCrease;
  creaseAndCornerVertices(input, d, onCorner, onCrease);
  ASSERT_GE(onCorner.size(), 2u);
  ASSERT_GT(onCrease.size(), 30u);
  TriMesh out = d.mesh;
  std::vector<SurfacePoint> points = d.origin;
  RelaxationParams everyCrease;
  everyCrease.minCreaseLength = 0;
  const Expected<RelaxationResult> r = relaxOnSurface(out, points, input, everyCrease);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->fixedVertices, static_cast<int>(onCorner.size()));
  EXPECT_EQ(r->slidingVertices, static_cast<int>(onCrease.size()));
  for (const int v : onCorner) EXPECT_EQ(out.positions[v], d.mesh.positions[v]) << "vertex " << v;
  int slid = 0;
  for (const int v : onCrease) {
    EXPECT_LT(distanceToCrease(input, out.positions[v]), 1e-9) << "vertex " << v << " left its crease";
    slid += out.positions[v] != d.mesh.positions[v];
  }
  EXPECT_GT(slid, 0);
  expectSameTopology(d, out);
  // The surface error stays that of the triangulation (tips and ridges are not smoothed away).
  const double diag = input.boundingBoxDiagonal();
  const double before = std::max(surfaceDistance(d.mesh, input).max, surfaceDistance(input, d.mesh).max) / diag;
  const double after = std::max(surfaceDistance(out, input).max, surfaceDistance(input, out).max) / diag;
  std::printf("fandisk 10%%: two-sided Hausdorff %.3f -> %.3f %% of the diagonal; smallest angle %.1f -> %.1f deg\n",
              100 * before, 100 * after, smallestAngle(d.mesh), smallestAngle(out));
  EXPECT_LE(after, 1.1 * before);
  EXPECT_GE(smallestAngle(out), 25.0);
}

// The corners of the feature curves (featureCorners), against positions read here: a square
// grid's are its four corners, a cube's its eight (three creases of 90 degrees meet there), none
// on a sphere or an open cylinder (its rims turn by 22.5 degrees a vertex), and none on the cube
// once its creases are under the feature angle.
TEST(SurfaceRelaxation, FeatureCornersAreWhereTheCurvesMeetOrTurn) {
  const TriMesh grid = test::planeGrid(8);
  std::vector<int> corners = featureCorners(grid);
  ASSERT_EQ(corners.size(), 4u);
  for (const int v : corners) {
    const Vec3& p = grid.positions[v];
    EXPECT_TRUE((p.x() == 0.0 || p.x() == 1.0) && (p.y() == 0.0 || p.y() == 1.0)) << p.transpose();
  }
  EXPECT_EQ(featureCorners(test::unitCube()).size(), 8u);
  EXPECT_TRUE(featureCorners(test::icosphere(2)).empty());
  EXPECT_TRUE(featureCorners(test::cylinder(16, 4)).empty());
  RelaxationParams blunt;
  blunt.featureAngleDegrees = 100.0;
  EXPECT_TRUE(featureCorners(test::unitCube(), blunt).empty());
  // A side of the square turned by more than the feature angle at its midpoint is a corner too.
  TriMesh bent = test::planeGrid(8);
  for (Vec3& p : bent.positions) p.z() = p.x() > 0.5 ? 2.0 * (p.x() - 0.5) : 0.0;  // a fold of 63.4 degrees
  corners = featureCorners(bent);
  EXPECT_EQ(corners.size(), 6u);  // the square's four, and the fold's two ends on the boundary
}

// At the defaults, crease chains shorter than the output's mean edge length are not creases
// (RelaxationParams::minCreaseLength): on fandisk at 10% the vertices on chains at least that long
// slide along them as above, and only vertices on shorter chains (chain lengths walked here from
// the input's normals) leave their crease; some do.
TEST(SurfaceRelaxation, OnlyVerticesOnShortCreasesLeaveThem) {
  const TriMesh input = test::loadRealMesh("fandisk.off");
  const DelaunayResult d = triangulate(input, 648);
  std::vector<int> onCorner, onCrease;
  creaseAndCornerVertices(input, d, onCorner, onCrease);
  const double shortest = RelaxationParams{}.minCreaseLength * d.mesh.meanEdgeLength();
  std::vector<int> onLong, onShort;
  for (const int v : onCrease) (chainLength(input, d.origin[v].vertex) >= shortest ? onLong : onShort).push_back(v);
  ASSERT_GT(onLong.size(), 30u);
  ASSERT_GE(onShort.size(), 1u);
  TriMesh out = d.mesh;
  std::vector<SurfacePoint> points = d.origin;
  const Expected<RelaxationResult> r = relaxOnSurface(out, points, input);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->slidingVertices, static_cast<int>(onLong.size()));
  for (const int v : onLong)
    EXPECT_LT(distanceToCrease(input, out.positions[v]), 1e-9) << "vertex " << v << " left a long crease";
  int left = 0;
  for (const int v : onShort) left += distanceToCrease(input, out.positions[v]) > 1e-9;
  std::printf(
      "fandisk 10%%: %zu output vertices on crease chains of at least %.4f, %zu on shorter ones, %d of "
      "them left\n",
      onLong.size(), shortest, onShort.size(), left);
  EXPECT_GE(left, 1);
  expectSameTopology(d, out);
}

/// The smallest angle (degrees) of the fan of faces (c, ring[k], ring[k+1]) around a closed ring,
/// or -1 if a face is turned over (clockwise in the plane z = 0); `under30` counts its faces with
/// an angle under 30 degrees.
double fanSmallestAngle(const Vec3& c, const std::vector<Vec3>& ring, int* under30 = nullptr) {
  double smallest = 180;
  if (under30) *under30 = 0;
  for (size_t k = 0; k < ring.size(); ++k) {
    const Vec3 tri[3] = {c, ring[k], ring[(k + 1) % ring.size()]};
    if ((tri[1] - tri[0]).cross(tri[2] - tri[0]).z() <= 0) return -1;
    double face = 180;
    for (int i = 0; i < 3; ++i) {
      const Vec3 u = tri[(i + 1) % 3] - tri[i], w = tri[(i + 2) % 3] - tri[i];
      face = std::min(face, std::atan2(u.cross(w).norm(), u.dot(w)) * 180 / kPi);
    }
    smallest = std::min(smallest, face);
    if (under30) *under30 += face < 30;
  }
  return smallest;
}

// The polish climbs to the top: one free vertex inside a fixed, stretched heptagon (an output
// boundary that no input boundary holds) ends where its faces' smallest angle is within 0.05
// degrees of the largest a brute-force search over the plane finds, from a start 0.1 off,
// among the places with no more faces under 30 degrees than the start has (the polish's rule).
TEST(SurfaceRelaxation, PolishReachesTheLargestSmallestAngleOfAFan) {
  const int n = 200;
  const TriMesh input = test::planeGrid(n, 1.0);  // vertex (i, j) at (i, j) / n
  const auto vertexAt = [&](double x, double y) { return int(std::lround(y * n)) * (n + 1) + int(std::lround(x * n)); };
  std::vector<int> ids = {vertexAt(0.6, 0.5)};  // the free vertex, off the centre
  for (int k = 0; k < 7; ++k) {
    const double a = 2 * kPi * k / 7 + 0.2 * std::sin(3.0 * k);
    ids.push_back(vertexAt(0.5 + (0.3 + 0.04 * (k % 3)) * std::cos(a), 0.5 + 0.05 * std::sin(a)));
  }
  std::vector<Vec3> positions;
  std::vector<SurfacePoint> points;
  for (const int id : ids) {
    positions.push_back(input.positions[id]);
    points.push_back(SurfacePoint::atVertex(id));
  }
  std::vector<Tri> faces;
  for (int k = 0; k < 7; ++k) faces.push_back({0, 1 + k, 1 + (k + 1) % 7});
  TriMesh out = buildTriMesh(positions, faces).value();
  const std::vector<Vec3> ring(positions.begin() + 1, positions.end());
  // Brute force: a grid over the heptagon's box, then finer grids around the best point.
  int startUnder30 = 0;
  const double start = fanSmallestAngle(positions[0], ring, &startUnder30);
  Vec3 best = positions[0];
  double top = start, step = 0.002;
  for (int level = 0; level < 4; ++level, step /= 10) {
    const Vec3 centre = best;
    const int half = level == 0 ? 200 : 20;
    for (int i = -half; i <= half; ++i)
      for (int j = -half; j <= half; ++j) {
        const Vec3 c = centre + Vec3(i * step, j * step, 0);
        int under30 = 0;
        const double s = fanSmallestAngle(c, ring, &under30);
        if (s > top && under30 <= startUnder30) top = s, best = c;
      }
  }
  ASSERT_LT(start, top - 3.0) << "the start must be well below the top for the test to say anything";
  ASSERT_LT(top, 30.0) << "under the polish's aim (30 degrees), so that it climbs to the top";
  RelaxationParams params;
  params.iterations = 0;             // the polish is independent of the rounds
  params.flips.maxFlipsPerFace = 0;  // the fan stays a fan
  const Expected<RelaxationResult> r = polishOnSurface(out, points, input, params);
  ASSERT_TRUE(r) << r.status().message;
  const double polished = fanSmallestAngle(out.positions[0], ring);
  int polishedUnder30 = 0;
  fanSmallestAngle(out.positions[0], ring, &polishedUnder30);
  std::printf("fan: start %.3f deg (%d faces under 30), polished %.3f deg (%d), brute force %.3f deg, %d moves\n",
              start, startUnder30, polished, polishedUnder30, top, r->polishMoves);
  EXPECT_LE(polishedUnder30, startUnder30);
  EXPECT_EQ(out.triangles, faces);
  EXPECT_GE(polished, top - 0.05);
  EXPECT_LE(polished, top + 1e-6);
  EXPECT_GT(r->polishMoves, 0);
  EXPECT_EQ(out.positions[0].z(), 0.0);
  EXPECT_LT((points[0].position(input) - out.positions[0]).norm(), 1e-12);
  for (int v = 1; v < 8; ++v) EXPECT_EQ(out.positions[v], positions[v]) << "ring vertex " << v << " moved";
  params.polishMarginDegrees = -1;  // off
  TriMesh again = buildTriMesh(positions, faces).value();
  std::vector<SurfacePoint> samePoints = points;
  ASSERT_TRUE(polishOnSurface(again, samePoints, input, params));
  EXPECT_EQ(again.positions, positions);
}

// The polish never lowers the smallest angle nor adds a face under 30 degrees, keeps the topology
// and the vertices on the input: a relaxed remesh of the plane polished again.
TEST(SurfaceRelaxation, PolishNeverLowersTheSmallestAngleNorAddsFacesUnder30) {
  for (const unsigned seed : {3u, 5u, 7u}) {
    const TriMesh input = test::planeGrid(60, 1.0, 0.3, seed);
    const DelaunayResult d = triangulate(input, 200);
    TriMesh out = d.mesh;
    std::vector<SurfacePoint> points = d.origin;
    RelaxationParams params;
    params.iterations = 1;
    ASSERT_TRUE(relaxOnSurface(out, points, input, params));
    const AngleStatistics before = angleStatistics(out);
    const double smallestBefore = smallestAngle(out);
    const Expected<RelaxationResult> r = polishOnSurface(out, points, input, params);
    ASSERT_TRUE(r) << r.status().message;
    const AngleStatistics after = angleStatistics(out);
    std::printf("seed %u: smallest %.2f -> %.2f deg, under 30: %.2f -> %.2f %%, %d moves\n", seed, smallestBefore,
                smallestAngle(out), 100 * before.shareMinBelow30, 100 * after.shareMinBelow30, r->polishMoves);
    EXPECT_GE(smallestAngle(out), smallestBefore - 1e-9);
    EXPECT_LE(after.shareMinBelow30, before.shareMinBelow30);
    EXPECT_GT(r->polishMoves, 0);
    expectSameTopology(d, out);
    for (int v = 0; v < out.vertexCount(); ++v) {
      EXPECT_EQ(out.positions[v].z(), 0.0);
      EXPECT_LT((points[v].position(input) - out.positions[v]).norm(), 1e-12);
    }
  }
}

/// The point (x, y) of test::planeGrid(n) (the unit square) as a point of its faces: cell (i, j)
/// holds faces 2 (j n + i) (under its diagonal) and 2 (j n + i) + 1 (over it).
SurfacePoint onUnitGrid(int n, double x, double y) {
  const int i = std::min(n - 1, static_cast<int>(x * n)), j = std::min(n - 1, static_cast<int>(y * n));
  const double fx = x * n - i, fy = y * n - j;
  const int cell = 2 * (j * n + i);
  return fx >= fy ? SurfacePoint::inFace(cell, Vec3(1 - fx, fx - fy, fy))
                  : SurfacePoint::inFace(cell + 1, Vec3(1 - fy, fx, fy - fx));
}

// A hole far smaller than the output's edges (a boundary loop of 0.03 mean edges, as the tiny
// holes of ChineseDragon-10kv) is a point at the output's resolution: the faces on its three
// edges are slivers whatever the ring around does. The relaxation and the polish leave them so
// instead of drawing the ring in to widen them, which put 8 to 12 faces under 30 degrees around
// each of those holes. Here: the hole, a ring of six free vertices (off their places) and a fixed
// outer ring, on a plane.
TEST(SurfaceRelaxation, TinyHolesKeepTheirRingAway) {
  const int n = 200;
  const TriMesh input = test::planeGrid(n);
  const double hole = 0.0005, r = 0.1;  // the hole's and the free ring's radii, about (0.5, 0.5)
  std::vector<Vec3> positions;
  const auto at = [&](double radius, double degrees) {
    positions.push_back(
        Vec3(0.5 + radius * std::cos(degrees * kPi / 180), 0.5 + radius * std::sin(degrees * kPi / 180), 0));
  };
  for (int k = 0; k < 3; ++k) at(hole, 120 * k);                                                       // 0-2: the hole
  for (int k = 0; k < 6; ++k) at(r * (1 + 0.15 * std::sin(2.0 * k)), 60 * k + 9 * std::cos(3.0 * k));  // 3-8: free
  for (int k = 0; k < 6; ++k) at(2 * r, 60 * k + 30);                                                  // 9-14: fixed
  const auto m = [](int k) { return 3 + (k + 6) % 6; };
  const auto o = [](int k) { return 9 + (k + 6) % 6; };
  std::vector<Tri> faces = {{0, m(0), m(1)}, {1, m(1), m(2)}, {1, m(2), m(3)}, {2, m(3), m(4)}, {2, m(4), m(5)},
                            {0, m(5), m(0)}, {1, 0, m(1)},    {2, 1, m(3)},    {0, 2, m(5)}};
  for (int k = 0; k < 6; ++k) {
    faces.push_back({m(k), o(k), m(k + 1)});
    faces.push_back({m(k + 1), o(k), o(k + 1)});
  }
  const TriMesh start = buildTriMesh(positions, faces).value();
  struct Relaxed {
    int under30 = 0, slivers = 0;  // faces under 30 degrees, and of them those on the hole's edges
    double nearest = 1;            // the free vertices' nearest distance to the hole's centre
  };
  const auto relaxWith = [&](double tinyLoopLength) {
    TriMesh out = start;
    std::vector<SurfacePoint> points;
    for (const Vec3& p : positions) points.push_back(onUnitGrid(n, p.x(), p.y()));
    RelaxationParams params;
    params.tinyLoopLength = tinyLoopLength;
    EXPECT_TRUE(relaxOnSurface(out, points, input, params));
    EXPECT_TRUE(polishOnSurface(out, points, input, params));
    EXPECT_EQ(test::recount(out.triangles, out.vertexCount()).boundaryLoops, 2);
    EXPECT_EQ(out.faceCount(), start.faceCount());
    Relaxed result;
    for (const Tri& t : out.triangles) {
      const double smallest = test::recountAngles(buildTriMesh(out.positions, {t}).value()).smallestDegrees;
      result.under30 += smallest < 30;
      result.slivers += smallest < 30 && std::count_if(t.begin(), t.end(), [](int v) { return v < 3; }) == 2;
    }
    for (int v = 3; v < 9; ++v)
      result.nearest = std::min(result.nearest, (out.positions[v] - Vec3(0.5, 0.5, 0)).norm());
    for (int v = 0; v < out.vertexCount(); ++v) {
      EXPECT_LT((points[v].position(input) - out.positions[v]).norm(), 1e-12);
      if (v < 3 || v >= 9) {
        EXPECT_EQ(out.positions[v], start.positions[v]) << "boundary vertex " << v << " moved";
      }
    }
    std::printf(
        "tiny loops under %.2f edges: %d faces under 30 degrees (%d on the hole's edges), free ring %.4f "
        "from the hole\n",
        tinyLoopLength, result.under30, result.slivers, result.nearest);
    return result;
  };
  const Relaxed every = relaxWith(0.0), kept = relaxWith(RelaxationParams{}.tinyLoopLength);
  EXPECT_GT(every.under30, 3);  // every angle counted: the ring drawn in
  EXPECT_LT(every.nearest, 0.5 * r);
  EXPECT_EQ(kept.under30, 3);
  EXPECT_EQ(kept.slivers, 3);
  EXPECT_GT(kept.nearest, 0.5 * r);
}

TEST(SurfaceRelaxation, ZeroIterationsChangeNothing) {
  const TriMesh input = test::planeGrid(30, 1.0, 0.3, 3);
  const DelaunayResult d = triangulate(input, 80);
  TriMesh out = d.mesh;
  std::vector<SurfacePoint> points = d.origin;
  RelaxationParams params;
  params.iterations = 0;
  const Expected<RelaxationResult> r = relaxOnSurface(out, points, input, params);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->moves, 0);
  EXPECT_EQ(out.positions, d.mesh.positions);
  EXPECT_EQ(out.triangles, d.mesh.triangles);
}

// Pinned vertices stay where they are, as the boundary does, while the others move; a pin vector
// of the wrong size is refused.
TEST(SurfaceRelaxation, PinnedVerticesDoNotMove) {
  const TriMesh input = test::planeGrid(40, 1.0, 0.3, 5);
  const DelaunayResult d = triangulate(input, 150);
  std::vector<char> pinned(d.mesh.vertexCount(), 0);
  for (int v = 0; v < d.mesh.vertexCount(); v += 3) pinned[v] = 1;
  TriMesh out = d.mesh;
  std::vector<SurfacePoint> points = d.origin;
  const Expected<RelaxationResult> r =
      relaxOnSurface(out, points, input, RelaxationParams{}, RelaxationGuard{pinned, {}});
  ASSERT_TRUE(r) << r.status().message;
  int moved = 0;
  for (int v = 0; v < out.vertexCount(); ++v) {
    if (pinned[v]) {
      EXPECT_EQ(out.positions[v], d.mesh.positions[v]) << v;
    } else {
      moved += out.positions[v] != d.mesh.positions[v];
    }
  }
  EXPECT_GT(moved, 30);
  pinned.pop_back();
  out = d.mesh;
  points = d.origin;
  const Expected<RelaxationResult> refused =
      relaxOnSurface(out, points, input, RelaxationParams{}, RelaxationGuard{pinned, {}});
  ASSERT_FALSE(refused);
  EXPECT_EQ(refused.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(out.positions, d.mesh.positions);
}

TEST(SurfaceRelaxation, BadInputIsReportedAndChangesNothing) {
  const TriMesh input = test::planeGrid(30, 1.0, 0.3, 3);
  const DelaunayResult d = triangulate(input, 80);
  TriMesh out = d.mesh;
  std::vector<SurfacePoint> points = d.origin;
  points.pop_back();  // one point short
  Expected<RelaxationResult> r = relaxOnSurface(out, points, input);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(out.positions, d.mesh.positions);

  points = d.origin;
  points[5] = SurfacePoint::inFace(input.faceCount(), Vec3(1, 0, 0));  // a face out of range
  r = relaxOnSurface(out, points, input);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(out.positions, d.mesh.positions);

  points = d.origin;
  const std::vector<double> density(input.vertexCount() - 1, 1.0);  // one value short
  RelaxationParams params;
  params.density = &density;
  r = relaxOnSurface(out, points, input, params);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(out.positions, d.mesh.positions);
}

/// Three faces on the edge (0, 1): a mesh that is not manifold.
TriMesh threeFacesOnOneEdge() {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  return buildTriMesh(p, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}).value();
}

/// Output vertex i on input vertex i, for the first `count` vertices.
std::vector<SurfacePoint> onFirstVertices(int count) {
  std::vector<SurfacePoint> points;
  for (int v = 0; v < count; ++v) points.push_back(SurfacePoint::atVertex(v));
  return points;
}

TEST(SurfaceRelaxation, NonManifoldMeshesAreRefused) {
  const TriMesh grid = test::planeGrid(4, 1.0, 0.3, 3);
  // A non-manifold output on a manifold input.
  TriMesh out = threeFacesOnOneEdge();
  ASSERT_FALSE(out.topology.isManifold());
  std::vector<SurfacePoint> points = onFirstVertices(out.vertexCount());
  Expected<RelaxationResult> r = relaxOnSurface(out, points, grid);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::NonManifold);
  EXPECT_EQ(out.positions, threeFacesOnOneEdge().positions);
  // A manifold output on a non-manifold input.
  const TriMesh input = threeFacesOnOneEdge();
  TriMesh triangle = buildTriMesh({input.positions[0], input.positions[1], input.positions[2]}, {{0, 1, 2}}).value();
  points = onFirstVertices(3);
  r = relaxOnSurface(triangle, points, input);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::NonManifold);
}

TEST(SurfaceRelaxation, OutputNotOrientedCoherentlyIsRefused) {
  const TriMesh input = test::planeGrid(30, 1.0, 0.3, 3);
  const DelaunayResult d = triangulate(input, 80);
  std::vector<Tri> t = d.mesh.triangles;
  for (size_t f = 0; f < t.size(); f += 2) std::swap(t[f][1], t[f][2]);  // every other face turned over
  TriMesh out = buildTriMesh(d.mesh.positions, t).value();
  ASSERT_TRUE(out.topology.isManifold());
  ASSERT_GT(out.topology.inconsistentEdges, 0);
  std::vector<SurfacePoint> points = d.origin;
  const Expected<RelaxationResult> r = relaxOnSurface(out, points, input);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(out.positions, d.mesh.positions);
  EXPECT_EQ(out.triangles, t);
}

// splitWideFaces on a flat mesh that is its own input, every vertex on itself: two pairs of faces
// on a long edge, each with a wide angle facing it (146.6 degrees: smallest 16.7; 157.4: 11.3), a
// face under 30 degrees whose widest angle is 85.7 (not wide) with a neighbour, and a wide face
// alone (its long edge on the boundary). Split first: the worse pair (unless skipped), then the
// other; never the narrow face nor the boundary edge. The new vertex is on the edge (the input, flat, is the
// plane), where its four faces' smallest angle is largest of the points tried, and its surface
// point is where it is; faces keep facing up; components, genus and boundary loops are kept,
// recounted.
TEST(SurfaceRelaxation, SplitsTheEdgeFacingTheWideAngleOfFacesUnder30) {
  const std::vector<Vec3> p = {{0, 0, 0},  {2, 0, 0},   {1, 0.3, 0},  {1, -1, 0},     // 0-3: pair, 16.7 deg
                               {4, 0, 0},  {6, 0, 0},   {5, 0.2, 0},  {5, -1, 0},     // 4-7: pair, 11.3 deg
                               {8, 0, 0},  {8.3, 0, 0}, {8.15, 2, 0}, {8.15, -2, 0},  // 8-11: narrow
                               {10, 0, 0}, {12, 0, 0},  {11, 0.3, 0}};                // 12-14: alone
  const std::vector<Tri> t = {{0, 1, 2}, {1, 0, 3}, {4, 5, 6}, {5, 4, 7}, {8, 9, 10}, {9, 8, 11}, {12, 13, 14}};
  const TriMesh input = buildTriMesh(p, t).value();
  const test::Recount before = test::recount(input.triangles, input.vertexCount());

  TriMesh none = input;
  std::vector<SurfacePoint> nonePoints = onFirstVertices(input.vertexCount());
  EXPECT_EQ(splitWideFaces(none, nonePoints, input, RelaxationParams{}, 0).value(), 0);
  EXPECT_EQ(none.triangles, input.triangles);

  TriMesh one = input;
  std::vector<SurfacePoint> onePoints = onFirstVertices(input.vertexCount());
  ASSERT_EQ(splitWideFaces(one, onePoints, input, RelaxationParams{}, 1).value(), 1);
  ASSERT_EQ(one.vertexCount(), input.vertexCount() + 1);
  EXPECT_NEAR(one.positions.back().y(), 0.0, 1e-12);  // on the edge (4, 5), the worse pair's
  EXPECT_GT(one.positions.back().x(), 4.5);
  EXPECT_LT(one.positions.back().x(), 5.5);
  for (int f : {0, 1, 4, 5, 6}) EXPECT_EQ(one.triangles[f], input.triangles[f]);

  // Faces a caller skips are not split: the other pair goes first.
  std::vector<char> skip(input.faceCount(), 0);
  skip[2] = 1;
  TriMesh skipped = input;
  std::vector<SurfacePoint> skippedPoints = onFirstVertices(input.vertexCount());
  ASSERT_EQ(splitWideFaces(skipped, skippedPoints, input, RelaxationParams{}, 1, skip).value(), 1);
  EXPECT_NEAR(skipped.positions.back().x(), 1.0, 1e-12);
  for (int f : {2, 3, 4, 5, 6}) EXPECT_EQ(skipped.triangles[f], input.triangles[f]);

  TriMesh out = input;
  std::vector<SurfacePoint> points = onFirstVertices(input.vertexCount());
  const int n = input.vertexCount();
  ASSERT_EQ(splitWideFaces(out, points, input, RelaxationParams{}, 10).value(), 2);
  ASSERT_EQ(out.vertexCount(), n + 2);
  ASSERT_EQ(out.faceCount(), input.faceCount() + 4);
  ASSERT_EQ(points.size(), size_t(n + 2));
  for (const int f : {4, 5, 6}) EXPECT_EQ(out.triangles[f], input.triangles[f]);         // narrow, alone
  const std::array<std::pair<int, int>, 2> edges = {std::pair<int, int>{4, 5}, {0, 1}};  // worse pair first
  for (int k = 0; k < 2; ++k) {
    const Vec3 &a = p[edges[k].first], &b = p[edges[k].second], &m = out.positions[n + k];
    EXPECT_NEAR((m - a).cross(b - a).norm(), 0.0, 1e-12);
    const double along = (m - a).dot(b - a) / (b - a).squaredNorm();
    EXPECT_GE(along, 0.3 - 1e-12);
    EXPECT_LE(along, 0.7 + 1e-12);
    const SurfacePoint& q = points[n + k];
    ASSERT_GE(q.face, 0);
    const Tri& on = input.triangles[q.face];
    const Vec3 there = q.bary[0] * p[on[0]] + q.bary[1] * p[on[1]] + q.bary[2] * p[on[2]];
    EXPECT_NEAR((there - m).norm(), 0.0, 1e-12);
    // Of the points tried, the one whose four faces have the largest smallest angle: here (the
    // pairs are symmetric about x = middle) the middle.
    EXPECT_NEAR(along, 0.5, 1e-12);
  }
  for (const Tri& f : out.triangles)
    EXPECT_GT((out.positions[f[1]] - out.positions[f[0]]).cross(out.positions[f[2]] - out.positions[f[0]]).z(), 0);
  test::expectValidWithTopologyOf(test::recount(out.triangles, out.vertexCount()), before);
}

// Boundary edges (SplitEdges::Boundary): a face of 16.7 degrees whose 146.6-degree angle faces
// an edge of the output's boundary, over an input whose boundary bulges away from that edge (a
// polyline of four input edges). The new vertex lies on the input's boundary, not on the chord:
// a point of a boundary edge of the input, evaluating to its position; the face becomes two, both
// facing up; the topology is recounted the same. Inner edges only (the default) split nothing here.
TEST(SurfaceRelaxation, SplitsABoundaryEdgeOnTheInputsBoundary) {
  std::vector<Vec3> p;
  for (int i = 0; i <= 4; ++i) {
    const double x = 10 + 0.5 * i;
    p.push_back({x, -0.1 * (1 - (x - 11) * (x - 11)), 0});  // the arc, 0 at its ends, -0.1 at x = 11
  }
  p.push_back({11, 0.3, 0});  // 5: the apex
  const std::vector<Tri> fan = {{0, 1, 5}, {1, 2, 5}, {2, 3, 5}, {3, 4, 5}};
  const TriMesh input = buildTriMesh(p, fan).value();
  const TriMesh face = buildTriMesh({p[0], p[4], p[5]}, {{0, 1, 2}}).value();
  const std::vector<SurfacePoint> on = {SurfacePoint::atVertex(0), SurfacePoint::atVertex(4),
                                        SurfacePoint::atVertex(5)};
  const test::Recount before = test::recount(face.triangles, face.vertexCount());

  TriMesh inner = face;
  std::vector<SurfacePoint> innerPoints = on;
  EXPECT_EQ(splitWideFaces(inner, innerPoints, input, RelaxationParams{}, 10).value(), 0);
  EXPECT_EQ(inner.triangles, face.triangles);

  TriMesh out = face;
  std::vector<SurfacePoint> points = on;
  ASSERT_EQ(splitWideFaces(out, points, input, RelaxationParams{}, 10, {}, SplitEdges::Boundary).value(), 1);
  ASSERT_EQ(out.vertexCount(), 4);
  ASSERT_EQ(out.faceCount(), 2);
  ASSERT_EQ(points.size(), size_t(4));
  const Vec3& m = out.positions[3];
  const SurfacePoint& q = points[3];
  ASSERT_GE(q.face, 0);
  const int zeros = (q.bary[0] == 0) + (q.bary[1] == 0) + (q.bary[2] == 0);
  ASSERT_GE(zeros, 1);
  const int k = q.bary[0] == 0 ? 0 : q.bary[1] == 0 ? 1 : 2;
  EXPECT_LT(input.oppositeCorner[3 * q.face + k], 0);  // the edge it lies on is a boundary edge
  const Tri& t = input.triangles[q.face];
  EXPECT_NEAR((q.bary[0] * p[t[0]] + q.bary[1] * p[t[1]] + q.bary[2] * p[t[2]] - m).norm(), 0.0, 1e-12);
  EXPECT_LT(m.y(), -0.05);  // on the bulge, off the chord y = 0
  EXPECT_GT(m.x(), 10.5);
  EXPECT_LT(m.x(), 11.5);
  for (const Tri& f : out.triangles)
    EXPECT_GT((out.positions[f[1]] - out.positions[f[0]]).cross(out.positions[f[2]] - out.positions[f[0]]).z(), 0);
  test::expectValidWithTopologyOf(test::recount(out.triangles, out.vertexCount()), before);
}

}  // namespace
}  // namespace gr
