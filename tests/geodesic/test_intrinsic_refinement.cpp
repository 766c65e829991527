// Intrinsic Delaunay refinement (intrinsic_refinement.h). Oracles, all computed here from the
// output's TriMesh, corner lengths and origins, not from the refinement's own structures:
//  - flat meshes: every intrinsic edge is a straight segment, so its length equals the 3D
//    distance between its endpoints' origins;
//  - any mesh: the intrinsic faces' areas (Heron) sum to the input's area; each input vertex keeps
//    its angle sum (law of cosines on both sides); inserted points are flat (2 pi inside, pi on the
//    boundary); interior edges are Delaunay; the angle bound holds except on the faces the result
//    reports; every origin is a valid point of the input and the output's positions are theirs;
//    the topology (test::recount) is the input's; input vertices keep their indices;
//  - curved meshes: an edge is at least as long as the chord between its ends and, being a
//    geodesic, at least CGAL's exact geodesic distance between them (close to it: short edges
//    of a Delaunay triangulation are shortest paths).
// Data-set meshes print inserted points and time (not asserted).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "core/base/math.h"
#include "core/geodesic/intrinsic_refinement.h"
#include "core/geodesic/triangulation_quality.h"
#include "core/mesh/vcg_mesh.h"
#include "tests/oracles/geodesic_oracles.h"
#include "tests/support/cad_meshes.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// Angle facing side a (law of cosines; an independent formula from the refinement's).
double angleFacing(double a, double b, double c) {
  if (!(b > 0.0 && c > 0.0)) return 0.0;
  return std::acos(std::clamp((b * b + c * c - a * a) / (2.0 * b * c), -1.0, 1.0));
}

/// Heron's formula in Kahan's stable form.
double heronArea(double a, double b, double c) {
  if (a < b) std::swap(a, b);
  if (a < c) std::swap(a, c);
  if (b < c) std::swap(b, c);
  const double q = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
  return 0.25 * std::sqrt(std::max(0.0, q));
}

/// The input's area and per-vertex angle sums from its 3D edge lengths plus `epsilon` (the
/// mollification the refinement reports; 0 = the 3D surface itself): Heron and the law of cosines.
struct InputGeometry {
  double area = 0.0;
  std::vector<double> angleSum;
};

InputGeometry inputGeometry(const TriMesh& m, double epsilon) {
  InputGeometry g;
  g.angleSum.assign(m.vertexCount(), 0.0);
  for (const Tri& t : m.triangles) {
    double len[3];
    for (int k = 0; k < 3; ++k) len[k] = (m.positions[t[(k + 1) % 3]] - m.positions[t[(k + 2) % 3]]).norm() + epsilon;
    g.area += heronArea(len[0], len[1], len[2]);
    for (int k = 0; k < 3; ++k) g.angleSum[t[k]] += angleFacing(len[k], len[(k + 1) % 3], len[(k + 2) % 3]);
  }
  return g;
}

/// Corner angle of the output at corner c, from the corner lengths.
double outputAngle(const RefinedSurface& r, int c) {
  return angleFacing(r.cornerLength[c], r.cornerLength[TriMesh::next(c)], r.cornerLength[TriMesh::prev(c)]);
}

Expected<RefinedSurface> refineTimed(const std::string& label, const TriMesh& input,
                                     const IntrinsicRefinementParams& params = {}) {
  const auto start = std::chrono::steady_clock::now();
  Expected<RefinedSurface> r = refineIntrinsicDelaunay(input, params);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (r)
    std::printf("%-28s %7d v %7d inserted %8d flips  smallest %6.2f deg  %5d faces below  %9.1f ms%s\n", label.c_str(),
                input.vertexCount(), r->insertedPoints, r->flips, r->smallestAngleDegrees, r->facesBelowMinAngle, ms,
                r->budgetExhausted ? "  (budget exhausted)" : "");
  return r;
}

/// The output's shape: sizes, input vertices first with their indices, valid origins whose
/// positions are the output's, and the input's topology.
void expectWellFormed(const TriMesh& input, const RefinedSurface& r) {
  const int n = input.vertexCount();
  ASSERT_EQ(r.inputVertexCount, n);
  ASSERT_EQ(r.mesh.vertexCount(), n + r.insertedPoints);
  ASSERT_EQ(static_cast<int>(r.origin.size()), r.mesh.vertexCount());
  ASSERT_EQ(static_cast<int>(r.cornerLength.size()), 3 * r.mesh.faceCount());
  const double tol = 1e-9 * input.boundingBoxDiagonal();
  for (int v = 0; v < r.mesh.vertexCount(); ++v) {
    const SurfacePoint& o = r.origin[v];
    if (v < n) {
      ASSERT_EQ(o.vertex, v);
    } else {
      ASSERT_EQ(o.vertex, -1) << "inserted point " << v;
      ASSERT_TRUE(o.face >= 0 && o.face < input.faceCount()) << "inserted point " << v;
      ASSERT_GE(o.bary.minCoeff(), -1e-12) << "inserted point " << v;
      ASSERT_NEAR(o.bary.sum(), 1.0, 1e-9) << "inserted point " << v;
    }
    ASSERT_LE((o.position(input) - r.mesh.positions[v]).norm(), tol) << "vertex " << v << " is not at its origin";
  }
  for (double l : r.cornerLength) ASSERT_TRUE(std::isfinite(l) && l > 0.0);
  const test::Recount in = test::recount(input.triangles, n);
  const test::Recount out = test::recount(r.mesh.triangles, r.mesh.vertexCount());
  EXPECT_TRUE(out.manifoldEdges && out.manifoldVertices && out.oriented);
  EXPECT_EQ(out.components, in.components);
  EXPECT_EQ(out.genusSum, in.genusSum);
  EXPECT_EQ(out.boundaryLoops, in.boundaryLoops);
  EXPECT_EQ(out.eulerCharacteristic, in.eulerCharacteristic);
  EXPECT_EQ(out.isolated, in.isolated);
}

/// Intrinsic geometry kept: total area, the input vertices' angle sums, flat inserted points, all
/// against the input's lengths with the reported mollification, and that surface within 1e-6 of
/// the 3D input's area (flat faces: a margin of 1e-14 of the mean length bends them by ~1e-7).
void expectGeometryKept(const TriMesh& input, const RefinedSurface& r) {
  double area = 0.0;
  std::vector<double> sum(r.mesh.vertexCount(), 0.0);
  for (int f = 0; f < r.mesh.faceCount(); ++f) {
    area += heronArea(r.cornerLength[3 * f], r.cornerLength[3 * f + 1], r.cornerLength[3 * f + 2]);
    for (int c = 3 * f; c < 3 * f + 3; ++c) sum[r.mesh.vertex(c)] += outputAngle(r, c);
  }
  const InputGeometry given = inputGeometry(input, r.mollification);
  EXPECT_NEAR(area, given.area, 1e-7 * given.area);
  const double area3d = inputGeometry(input, 0.0).area;
  EXPECT_NEAR(given.area, area3d, 1e-6 * area3d) << "mollification " << r.mollification;
  const std::vector<double>& inputSum = given.angleSum;
  const std::vector<char> boundary = boundaryVertexFlags(r.mesh);
  int worst = -1;
  double worstError = 0.0;
  for (int v = 0; v < r.mesh.vertexCount(); ++v) {
    const double expected = v < input.vertexCount() ? inputSum[v] : (boundary[v] ? kPi : 2.0 * kPi);
    if (std::abs(sum[v] - expected) > worstError) {
      worstError = std::abs(sum[v] - expected);
      worst = v;
    }
  }
  EXPECT_LE(worstError, 1e-6) << "angle sum of vertex " << worst << " (input has " << input.vertexCount() << ")";
}

/// Whether vertices x and y are joined by an edge of the output.
bool joined(const TriMesh& m, int x, int y) {
  for (const int* it = m.cornersBegin(x); it != m.cornersEnd(x); ++it)
    if (m.vertex(TriMesh::next(*it)) == y || m.vertex(TriMesh::prev(*it)) == y) return true;
  return false;
}

/// Whether flipping the edge facing corner c (o on the other side) would make a face of (nearly)
/// zero or negative area: the two faces laid out from their lengths do not form a strictly convex
/// quadrilateral (x and y are the corners' vertices, a and b the edge's ends).
bool flipWouldDegenerate(const RefinedSurface& r, int c, int o) {
  const double ab = r.cornerLength[c], xa = r.cornerLength[TriMesh::next(c)], bx = r.cornerLength[TriMesh::prev(c)];
  const double ay = r.cornerLength[TriMesh::prev(o)], yb = r.cornerLength[TriMesh::next(o)];
  const auto third = [ab](double fromA, double fromB, double side) {
    const double x = (ab * ab + fromA * fromA - fromB * fromB) / (2.0 * ab);
    return Vec3(x, side * std::sqrt(std::max(0.0, fromA * fromA - x * x)), 0.0);
  };
  const Vec3 a(0, 0, 0), b(ab, 0, 0), x = third(xa, bx, 1.0), y = third(ay, yb, -1.0);
  const double scale = 1e-9 * (x - y).squaredNorm();
  return (a - x).cross(y - x).z() <= scale || (b - y).cross(x - y).z() <= scale;
}

/// Interior edges that are not locally Delaunay: {all, those a TriMesh cannot flip (the flip would
/// join two vertices already joined) or that cannot be flipped (the flip would make a degenerate
/// face): allowed}.
std::pair<int, int> nonDelaunayEdges(const RefinedSurface& r, double toleranceRadians) {
  int bad = 0, blocked = 0;
  for (int c = 0; c < 3 * r.mesh.faceCount(); ++c) {
    const int o = r.mesh.oppositeCorner[c];
    if (o < c) continue;  // boundary, or counted from the other side
    if (outputAngle(r, c) + outputAngle(r, o) <= kPi + toleranceRadians) continue;
    ++bad;
    blocked += joined(r.mesh, r.mesh.vertex(c), r.mesh.vertex(o)) || flipWouldDegenerate(r, c, o);
  }
  return {bad, blocked};
}

/// Faces with an angle below the bound, counted from the corner lengths.
int facesBelow(const RefinedSurface& r, double degrees) {
  int below = 0;
  for (int f = 0; f < r.mesh.faceCount(); ++f) {
    const double a = std::min({outputAngle(r, 3 * f), outputAngle(r, 3 * f + 1), outputAngle(r, 3 * f + 2)});
    if (a < degrees * kPi / 180.0) ++below;
  }
  return below;
}

/// Everything that holds on any mesh.
void expectValidRefinement(const TriMesh& input, const RefinedSurface& r, double minAngleDegrees = 25.0) {
  ASSERT_NO_FATAL_FAILURE(expectWellFormed(input, r));
  expectGeometryKept(input, r);
  const auto [nonDelaunay, blocked] = nonDelaunayEdges(r, 1e-6);
  EXPECT_EQ(nonDelaunay, blocked) << "non-Delaunay edges that could be flipped";
  if (nonDelaunay > 0)
    std::printf("  %d edges not Delaunay: their flip would repeat an edge or make a degenerate face\n", nonDelaunay);
  EXPECT_EQ(facesBelow(r, minAngleDegrees - 1e-6), r.facesBelowMinAngle);
}

/// Flat: each edge as long as the segment between its ends' origins.
void expectFlatLengths(const RefinedSurface& r, double scale) {
  double worst = 0.0;
  for (int c = 0; c < 3 * r.mesh.faceCount(); ++c) {
    const Vec3& a = r.mesh.positions[r.mesh.vertex(TriMesh::next(c))];
    const Vec3& b = r.mesh.positions[r.mesh.vertex(TriMesh::prev(c))];
    worst = std::max(worst, std::abs((a - b).norm() - r.cornerLength[c]));
  }
  EXPECT_LE(worst, 1e-8 * scale);
}

/// A flat unit square triangulated with slivers: a zigzag between 40 points on the bottom side
/// and 40 on the top side (triangles 1/40 wide and 1 high), plus a fan from a corner.
TriMesh sliverSquare() {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  const int n = 40;
  for (int i = 0; i <= n; ++i) p.emplace_back(static_cast<double>(i) / n, 0.0, 0.0);
  for (int i = 0; i <= n; ++i) p.emplace_back((i + 0.5 * (i > 0 && i < n)) / n, 1.0, 0.0);
  for (int i = 0; i < n; ++i) {
    t.push_back({i, i + 1, n + 1 + i + 1});
    t.push_back({i, n + 1 + i + 1, n + 1 + i});
  }
  // A flat fan above the top side from a point just above its middle: angles near 0 at the top
  // side's points, near 180 degrees at the apex.
  p.emplace_back(0.5, 1.0 + 0.05, 0.0);
  const int apex = static_cast<int>(p.size()) - 1;
  for (int i = 0; i < n; ++i) t.push_back({n + 1 + i, n + 1 + i + 1, apex});
  return buildTriMesh(p, t).value();
}

TEST(IntrinsicRefinement, FlatSliverSquareReachesTheAngleBoundWithExactLengths) {
  const TriMesh input = sliverSquare();
  ASSERT_LT(test::recountAngles(input).smallestDegrees, 1.0);
  const Expected<RefinedSurface> r = refineTimed("sliver square", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  expectFlatLengths(*r, 1.0);
  EXPECT_GT(r->insertedPoints, 0);
  EXPECT_FALSE(r->budgetExhausted);
  // No vertex is a needle tip (the fan's apex has an angle sum near 180 degrees): every face
  // reaches the bound.
  EXPECT_GE(r->smallestAngleDegrees, 25.0 - 1e-6) << r->facesBelowMinAngle << " faces below";
}

TEST(IntrinsicRefinement, FlatGridWithNeedlesAndZeroAreaFaces) {
  int zeroArea = 0;
  const TriMesh input = test::withBadTriangles(test::planeGrid(16, 1.0, 0.2, 3), &zeroArea);
  ASSERT_GT(zeroArea, 0);
  const Expected<RefinedSurface> r = refineTimed("grid, needles + zero area", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  expectFlatLengths(*r, 1.0);
  EXPECT_GE(r->smallestAngleDegrees, 25.0 - 1e-6);
}

TEST(IntrinsicRefinement, MaxEdgeLengthIsReached) {
  const TriMesh input = test::planeGrid(4, 1.0);
  IntrinsicRefinementParams params;
  params.maxEdgeLength = 0.1;
  const Expected<RefinedSurface> r = refineTimed("grid 4, edges <= 0.1", input, params);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  expectFlatLengths(*r, 1.0);
  for (double l : r->cornerLength) EXPECT_LE(l, 0.1 * (1.0 + 1e-9));
}

// The default budget follows the length bound, not the vertex count: a square of two triangles
// (4 vertices, 10 V + 1000 = 1,040 points) needs about 3,000 points for edges of 2% of its side.
TEST(IntrinsicRefinement, DefaultBudgetCoversTheLengthBoundOnACoarseMesh) {
  const TriMesh input = test::planeGrid(1, 1.0);
  ASSERT_EQ(input.vertexCount(), 4);
  IntrinsicRefinementParams params;
  params.maxEdgeLength = 0.02;
  const Expected<RefinedSurface> r = refineTimed("square of 2 faces, edges <= 0.02", input, params);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_FALSE(r->budgetExhausted);
  EXPECT_GT(r->insertedPoints, 10 * input.vertexCount() + 1000);
  expectValidRefinement(input, *r);
  expectFlatLengths(*r, 1.0);
  for (double l : r->cornerLength) EXPECT_LE(l, 0.02 * (1.0 + 1e-9));
}

TEST(IntrinsicRefinement, FlipOnlyMakesTheSurfaceDelaunay) {
  const TriMesh input = sliverSquare();
  IntrinsicRefinementParams params;
  params.flipOnly = true;
  const Expected<RefinedSurface> r = refineTimed("sliver square, flips only", input, params);
  ASSERT_TRUE(r) << r.status().message;
  ASSERT_NO_FATAL_FAILURE(expectWellFormed(input, *r));
  expectGeometryKept(input, *r);
  expectFlatLengths(*r, 1.0);
  EXPECT_GT(r->flips, 0);
  EXPECT_EQ(nonDelaunayEdges(*r, 1e-6).first, 0);
}

TEST(IntrinsicRefinement, BudgetStopsTheRefinement) {
  const TriMesh input = sliverSquare();
  IntrinsicRefinementParams params;
  params.maxInsertions = 5;
  const Expected<RefinedSurface> r = refineTimed("sliver square, budget 5", input, params);
  ASSERT_TRUE(r) << r.status().message;
  ASSERT_NO_FATAL_FAILURE(expectWellFormed(input, *r));
  EXPECT_TRUE(r->budgetExhausted);
  EXPECT_GT(r->facesBelowMinAngle, 0);
  EXPECT_EQ(facesBelow(*r, 25.0 - 1e-6), r->facesBelowMinAngle);
}

/// Curved: edges at least their chord and at least (and close to) the exact geodesic distance
/// between their ends, checked on the edges around `sources` vertices: the end of the edge most
/// longer than its chord (a flipped edge over a fold), then inserted points spread over the mesh.
void expectGeodesicLengths(const TriMesh& input, const RefinedSurface& r, int sources) {
  const double chordSlack = 1e-9 * input.boundingBoxDiagonal();
  int bent = 0;
  double mostBent = -1.0;
  for (int c = 0; c < 3 * r.mesh.faceCount(); ++c) {
    const int a = r.mesh.vertex(TriMesh::next(c)), b = r.mesh.vertex(TriMesh::prev(c));
    const double chord = (r.mesh.positions[a] - r.mesh.positions[b]).norm();
    ASSERT_GE(r.cornerLength[c], chord - chordSlack) << "corner " << c;
    if (r.cornerLength[c] - chord > mostBent) {
      mostBent = r.cornerLength[c] - chord;
      bent = a;
    }
  }
  double worst = 0.0;
  int checked = 0;
  for (int s = 0; s < sources; ++s) {
    const int v = s == 0 ? bent : r.mesh.vertexCount() - s * (r.mesh.vertexCount() / sources);
    std::vector<SurfacePoint> targets;
    std::vector<double> lengths;
    for (const int* it = r.mesh.cornersBegin(v); it != r.mesh.cornersEnd(v); ++it) {
      targets.push_back(r.origin[r.mesh.vertex(TriMesh::next(*it))]);
      lengths.push_back(r.cornerLength[TriMesh::prev(*it)]);
    }
    const std::vector<double> exact = oracle::exactGeodesicBetween(input, r.origin[v], targets);
    for (size_t i = 0; i < exact.size(); ++i, ++checked) {
      EXPECT_GE(lengths[i], exact[i] * (1.0 - 1e-7)) << "edge from vertex " << v << " shorter than a shortest path";
      worst = std::max(worst, (lengths[i] - exact[i]) / exact[i]);
    }
  }
  std::printf("  %d edges against CGAL's exact geodesics: largest excess %.2e (relative)\n", checked, worst);
  EXPECT_LE(worst, 1e-6);
}

TEST(IntrinsicRefinement, UvSphereEdgesAreGeodesics) {
  const TriMesh input = test::uvSphere(12, 24);
  const Expected<RefinedSurface> r = refineTimed("uv sphere 12 x 24", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  EXPECT_GT(r->insertedPoints, 0);
  expectGeodesicLengths(input, *r, 12);
}

// CAD meshes: the traces that located ~20k points on slivers put them where the lengths say.
TEST(IntrinsicRefinement, CheeseAndTurbineEdgesAreGeodesics) {
  for (const char* name : {"cheese.off", "turbine.off"}) {
    SCOPED_TRACE(name);
    const TriMesh input = test::loadRealMesh(name);
    ASSERT_GT(input.vertexCount(), 0);
    const Expected<RefinedSurface> r = refineIntrinsicDelaunay(input);
    ASSERT_TRUE(r) << r.status().message;
    expectGeodesicLengths(input, *r, 3);
  }
}

TEST(IntrinsicRefinement, Bunny00EdgesAreGeodesics) {
  const TriMesh input = test::loadRealMesh("bunny00.off");
  ASSERT_GT(input.vertexCount(), 0);
  const Expected<RefinedSurface> r = refineTimed("bunny00.off", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  expectGeodesicLengths(input, *r, 1);  // one source: CGAL's exact geodesics are slow on 37k vertices
}

// Needles and zero-area faces on a curved mesh (test::withBadTriangles): traces that cross a face
// of zero area (its two short edges on the long one's line) leave it through the edge that holds
// the crossing. They used to leave through the other short edge's end, placing points up to an
// edge away from where their lengths say (an edge of 6e-5 between origins 1e-2 apart).
TEST(IntrinsicRefinement, Bunny00WithNeedlesAndZeroAreaFacesEdgesAreGeodesics) {
  int zeroArea = 0;
  const TriMesh input = test::withBadTriangles(test::loadRealMesh("bunny00.off"), &zeroArea);
  ASSERT_GT(zeroArea, 100);
  const Expected<RefinedSurface> r = refineTimed("bunny00.off with needles and zero-area faces", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  expectGeodesicLengths(input, *r, 1);
}

class IntrinsicRefinementDataSet : public ::testing::TestWithParam<std::string> {};

TEST_P(IntrinsicRefinementDataSet, KeepsTheSurfaceAndReachesTheBound) {
  const TriMesh input = test::loadRealMesh(GetParam());
  ASSERT_GT(input.vertexCount(), 0);
  const Expected<RefinedSurface> r = refineTimed(GetParam(), input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  EXPECT_FALSE(r->budgetExhausted);
  EXPECT_LE(r->facesBelowMinAngle, r->mesh.faceCount() / 100) << "more than 1% of the faces left below the bound";
}

INSTANTIATE_TEST_SUITE_P(Meshes, IntrinsicRefinementDataSet,
                         ::testing::Values("cheese.off", "blade.off", "turbine.off", "fandisk.off",
                                           "mech-holes-shark.off", "elephant-with-holes.off"),
                         [](const ::testing::TestParamInfo<std::string>& p) { return test::testNameOfFile(p.param); });

// Issue 17's CAD-like acceptance meshes (tests/support/cad_meshes.h): vertices only on the outlines,
// slivers across every flat face; the gear plate is 2% thick. Inserted points are checked against
// CGAL's exact geodesics around two of them.
TEST(IntrinsicRefinement, CadAcceptanceMeshes) {
  for (const test::CadMesh& cad : test::cadMeshes()) {
    SCOPED_TRACE(cad.name);
    EXPECT_TRUE(assessTriangulation(cad.mesh).needsRefinement);
    const Expected<RefinedSurface> r = refineTimed(cad.name, cad.mesh);
    ASSERT_TRUE(r) << r.status().message;
    expectValidRefinement(cad.mesh, *r);
    EXPECT_FALSE(r->budgetExhausted);
    EXPECT_EQ(r->facesBelowMinAngle, 0);
    expectGeodesicLengths(cad.mesh, *r, 2);
  }
}

/// Several components in one mesh: a sphere, the sliver square moved aside, a cylinder.
TriMesh threeComponents() {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  const auto append = [&](const TriMesh& m, const Vec3& shift) {
    const int base = static_cast<int>(p.size());
    for (const Vec3& q : m.positions) p.push_back(q + shift);
    for (const Tri& f : m.triangles) t.push_back({f[0] + base, f[1] + base, f[2] + base});
  };
  append(test::uvSphere(8, 16), Vec3(0, 0, 0));
  append(sliverSquare(), Vec3(3, 0, 0));
  append(test::cylinder(24, 3, 0.5, 4.0), Vec3(-3, 0, 0));  // long thin triangles
  return buildTriMesh(p, t).value();
}

TEST(IntrinsicRefinement, SeveralComponentsAndBoundaries) {
  const TriMesh input = threeComponents();
  ASSERT_EQ(input.topology.components, 3);
  const Expected<RefinedSurface> r = refineTimed("three components", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  // Each edge joins two points of one input component.
  for (int c = 0; c < 3 * r->mesh.faceCount(); ++c) {
    const auto componentOf = [&](int v) {
      const SurfacePoint& o = r->origin[v];
      return input.topology.componentOfVertex[o.vertex >= 0 ? o.vertex : input.triangles[o.face][0]];
    };
    ASSERT_EQ(componentOf(r->mesh.vertex(c)), componentOf(r->mesh.vertex(TriMesh::next(c))));
  }
}

// Many small components of slivers and zero-area faces, some overlapping in space, some turned
// (the kind of mesh, a scan with 37 components, that made geometry-central's refinement crash).
TEST(IntrinsicRefinement, ThirtySevenComponentsOfSlivers) {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  for (int k = 0; k < 37; ++k) {
    int zeroArea = 0;
    const TriMesh piece =
        k % 2 ? test::withBadTriangles(test::planeGrid(6, 1.0, 0.3, k + 1), &zeroArea) : sliverSquare();
    const int base = static_cast<int>(p.size());
    const double angle = 0.3 * k;  // tilted, so that the pieces do not all lie in one plane
    for (const Vec3& q : piece.positions)
      p.emplace_back(q.x() + 0.5 * k, std::cos(angle) * q.y(), std::sin(angle) * q.y() + 0.1 * q.x());
    for (const Tri& f : piece.triangles)
      t.push_back(k % 3 ? Tri{f[0] + base, f[1] + base, f[2] + base} : Tri{f[0] + base, f[2] + base, f[1] + base});
  }
  const TriMesh input = buildTriMesh(p, t).value();
  ASSERT_EQ(input.topology.components, 37);
  const Expected<RefinedSurface> r = refineTimed("37 components of slivers", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);
  EXPECT_GE(r->smallestAngleDegrees, 25.0 - 1e-6);
}

// Coincident vertices (a zero-length edge) are mollified: the result is still valid and Delaunay.
TEST(IntrinsicRefinement, ZeroLengthEdge) {
  TriMesh grid = test::planeGrid(6);
  std::vector<Vec3> p = grid.positions;
  p[8] = p[9];  // two neighbours of an interior edge at one place
  const TriMesh input = buildTriMesh(p, grid.triangles).value();
  const Expected<RefinedSurface> r = refineTimed("grid with a zero-length edge", input);
  ASSERT_TRUE(r) << r.status().message;
  ASSERT_NO_FATAL_FAILURE(expectWellFormed(input, *r));
  const auto [nonDelaunay, blocked] = nonDelaunayEdges(*r, 1e-6);
  EXPECT_EQ(nonDelaunay, blocked);
  double area = 0.0;
  for (int f = 0; f < r->mesh.faceCount(); ++f)
    area += heronArea(r->cornerLength[3 * f], r->cornerLength[3 * f + 1], r->cornerLength[3 * f + 2]);
  EXPECT_NEAR(area, 1.0, 1e-6);
}

TEST(IntrinsicRefinement, InconsistentlyOrientedFaces) {
  TriMesh good = threeComponents();
  std::vector<Tri> tris = good.triangles;
  std::mt19937 rng(7);
  for (Tri& f : tris)
    if (rng() % 3 == 0) std::swap(f[1], f[2]);
  const TriMesh input = buildTriMesh(good.positions, tris).value();
  ASSERT_GT(input.topology.inconsistentEdges, 0);
  const Expected<RefinedSurface> r = refineTimed("three components, turned", input);
  ASSERT_TRUE(r) << r.status().message;
  expectValidRefinement(input, *r);  // origins are checked against the input's own corner order
}

TEST(IntrinsicRefinement, RefusesWhatItCannotDo) {
  // Three triangles on one edge.
  const TriMesh fin = buildTriMesh({Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)},
                                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}})
                          .value();
  const Expected<RefinedSurface> r = refineIntrinsicDelaunay(fin);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::NonManifold);
  EXPECT_NE(r.status().message.find("1 non-manifold edges"), std::string::npos) << r.status().message;
  const Expected<RefinedSurface> moebius = refineIntrinsicDelaunay(test::moebiusStrip(12));
  ASSERT_FALSE(moebius);
  EXPECT_EQ(moebius.status().code, StatusCode::InvalidInput) << moebius.status().message;
  const TriMesh square = test::planeGrid(2);
  for (const auto& bad :
       {IntrinsicRefinementParams{60.0}, IntrinsicRefinementParams{-1.0}, IntrinsicRefinementParams{25.0, 0.0},
        IntrinsicRefinementParams{25.0, kUnbounded, -2}, IntrinsicRefinementParams{std::nan(""), kUnbounded}}) {
    const Expected<RefinedSurface> e = refineIntrinsicDelaunay(square, bad);
    ASSERT_FALSE(e);
    EXPECT_EQ(e.status().code, StatusCode::InvalidInput) << e.status().message;
  }
}

TEST(IntrinsicRefinement, CancelledByTheProgressCallback) {
  int calls = 0;
  const Expected<RefinedSurface> r =
      refineIntrinsicDelaunay(sliverSquare(), {}, Progress([&](int, const char*) { return ++calls < 3; }));
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::Cancelled);
  EXPECT_EQ(calls, 3);
}

// ------------------------------------------------------------------------------------------------
// assessTriangulation

TEST(TriangulationQuality, GoodMeshesNeedNoRefinementAndCadMeshesDo) {
  for (const char* name : {"bunny00.off", "armadillo.off", "fandisk.off", "cheese.off", "blade.off", "turbine.off"}) {
    const TriMesh m = test::loadRealMesh(name);
    ASSERT_GT(m.vertexCount(), 0);
    const TriangulationQuality q = assessTriangulation(m);
    std::printf("%-16s %s\n", name, describe(q).c_str());
    const std::string n = name;
    if (n == "bunny00.off" || n == "armadillo.off") {
      EXPECT_FALSE(q.needsRefinement) << name;
    } else if (n == "cheese.off" || n == "blade.off" || n == "turbine.off") {
      EXPECT_TRUE(q.needsRefinement) << name;
    }
  }
  EXPECT_TRUE(assessTriangulation(sliverSquare()).needsRefinement);
  EXPECT_FALSE(assessTriangulation(test::icosphere(3)).needsRefinement);
  EXPECT_FALSE(assessTriangulation(test::planeGrid(60)).needsRefinement);
  // Coarse: edges above 5% of the diagonal on more than 1% of the faces (a grid of 10 x 10
  // squares: 7%), however well shaped.
  const TriangulationQuality coarse = assessTriangulation(test::planeGrid(10));
  EXPECT_TRUE(coarse.needsRefinement);
  EXPECT_DOUBLE_EQ(coarse.longEdgeShare, 1.0);
  EXPECT_EQ(coarse.sliverShare, 0.0);
}

}  // namespace
}  // namespace gr

namespace gr {
namespace {

// Robustness: every mesh of the data set is refined into a valid result or refused with a code
// that says why (NonManifold, InvalidInput for a non-orientable one); never a crash or Internal.
class IntrinsicRefinementSweep : public ::testing::TestWithParam<std::string> {};

TEST_P(IntrinsicRefinementSweep, ValidOrRefused) {
  Expected<TriMesh> loaded = loadTriMesh(test::meshPath(GetParam()));
  if (!loaded) {  // b9.ply, a point cloud: refused by the loader, with the reason
    EXPECT_EQ(loaded.status().code, StatusCode::InvalidInput) << loaded.status().message;
    EXPECT_NE(loaded.status().message.find("no faces"), std::string::npos) << loaded.status().message;
    return;
  }
  const TriMesh& input = *loaded;
  const Expected<RefinedSurface> r = refineTimed(GetParam(), input);
  if (!r) {
    EXPECT_TRUE(r.status().code == StatusCode::NonManifold || r.status().code == StatusCode::InvalidInput)
        << toString(r.status().code) << ": " << r.status().message;
    std::printf("%-28s refused (%s): %s\n", GetParam().c_str(), toString(r.status().code), r.status().message.c_str());
    return;
  }
  expectValidRefinement(input, *r);
}

INSTANTIATE_TEST_SUITE_P(DataSet, IntrinsicRefinementSweep, ::testing::ValuesIn(test::dataSetMeshFiles()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return test::testNameOfFile(p.param); });

}  // namespace
}  // namespace gr
