// Issue 17's acceptance of the remeshing on CAD-like solids (tests/support/cad_meshes.h: slivers,
// vertices only on the outlines): `Remeshing: Geodesic Uniform` at its defaults (10% of the
// vertices, SurfaceRemeshParams defaults) keeps the topology (recounted here independently of
// TriMesh), gives a vertex count within 10% of the one asked for, no self-intersecting output
// triangles (CGAL's exact test, tests/oracles), and every output vertex on the input surface
// (the distance to the nearest input triangle, computed here by brute force, and the position of
// the vertex's origin on the input). The figures are printed (count, smallest angle, time).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/remesh/remesh_surface.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/cad_meshes.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// The point of triangle (a, b, c) closest to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

/// The distance from p to the nearest triangle of `mesh`, by brute force.
double distanceToSurface(const Vec3& p, const TriMesh& mesh) {
  double best = std::numeric_limits<double>::infinity();
  for (const Tri& t : mesh.triangles) {
    const Vec3 q = closestOnTriangle(p, mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    best = std::min(best, (p - q).norm());
  }
  return best;
}

class RemeshCad : public ::testing::TestWithParam<int> {};

TEST_P(RemeshCad, DefaultsKeepTopologyCountAndGiveNoSelfIntersections) {
  const test::CadMesh cad = test::cadMeshes()[GetParam()];
  const TriMesh& input = cad.mesh;
  SurfaceRemeshParams params;  // the filter's defaults
  const int target = SurfaceRemeshParams::defaultTargetCount(input.vertexCount());
  params.sampling.targetCount = target;
  params.measure = false;
  const auto start = std::chrono::steady_clock::now();
  const Expected<SurfaceRemeshResult> remeshed = remeshSurface(input, params);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(remeshed) << remeshed.status().message;
  const SurfaceRemeshResult& r = *remeshed;
  const TriMesh& out = r.mesh;
  const test::Recount in = test::recount(input.triangles, input.vertexCount());
  const test::Recount rc = test::recount(out.triangles, out.vertexCount());
  const Expected<std::vector<std::pair<int, int>>> crossing = oracle::selfIntersections(out);
  ASSERT_TRUE(crossing) << crossing.status().message;
  const test::AngleRecount angles = test::recountAngles(out);
  std::printf(
      "%s: %d input vertices, %d asked, %d got (%d samplings, %d asked of the kept one, fewest %d; %d added, %d "
      "dropped), genus %d, %d loops, %d components; %zu "
      "self-intersecting pairs; smallest angle %.2f deg, %.1f %% under 30 deg; %s (%d inserted points); %.3f s "
      "(prepare %.3f)\n",
      cad.name.c_str(), input.vertexCount(), target, out.vertexCount(), r.samplingRounds, r.sampledAsked, r.fewestCount,
      r.addedSamples, r.droppedSamples, rc.genusSum, rc.boundaryLoops, rc.components, crossing->size(),
      angles.smallestDegrees, 100 * angles.shareBelow30, r.refinedSurface ? "refined" : "not refined", r.refinedPoints,
      seconds, r.times.prepare);
  EXPECT_EQ(in.genusSum, cad.genus);
  test::expectValidWithTopologyOf(rc, in);
  // The plate with 20 holes (128 asked) needs about 270 samples for a valid geodesic Delaunay
  // triangulation whatever the request; edge collapses (edge_collapse.h) bring it to the count. The
  // gear (104 asked) and the bracket (4 asked) land on it from the count search.
  EXPECT_LE(std::abs(out.vertexCount() - target), 0.1 * target);
  EXPECT_EQ(crossing->size(), 0u);
  const double diagonal = input.boundingBoxDiagonal();
  for (int v = 0; v < out.vertexCount(); ++v) {
    ASSERT_LT(distanceToSurface(out.positions[v], input), 1e-9 * diagonal) << "vertex " << v;
    ASSERT_LT((r.origin[v].position(input) - out.positions[v]).norm(), 1e-9 * diagonal) << "vertex " << v;
  }
  for (int v = 0; v < input.vertexCount(); ++v) ASSERT_TRUE(r.cell[v] >= 0 && r.cell[v] < out.vertexCount());
}

// Centroidal samples on the thin gear plate: the relaxation moved a vertex over the plate's rim
// and folded faces onto the other side (3 crossing faces at 104 samples, 3 Lloyd iterations,
// returned as they were since the count was met); the relaxation is now cut where it makes faces
// cross. CGAL's exact test is the judge.
TEST(RemeshCadCentroidal, GearAtItsCountWithoutCrossingFaces) {
  const test::CadMesh gear = test::cadMeshes()[0];
  ASSERT_EQ(gear.name, "cad_gear");
  const TriMesh& input = gear.mesh;
  SurfaceRemeshParams params;
  params.sampling.targetCount = SurfaceRemeshParams::defaultTargetCount(input.vertexCount());
  params.centroidalIterations = 3;
  params.measure = false;
  const Expected<SurfaceRemeshResult> r = remeshSurface(input, params);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->mesh.vertexCount(), params.sampling.targetCount);
  const Expected<std::vector<std::pair<int, int>>> crossing = oracle::selfIntersections(r->mesh);
  ASSERT_TRUE(crossing) << crossing.status().message;
  EXPECT_EQ(crossing->size(), 0u);
  test::expectValidWithTopologyOf(test::recount(r->mesh.triangles, r->mesh.vertexCount()),
                                  test::recount(input.triangles, input.vertexCount()));
}

INSTANTIATE_TEST_SUITE_P(Meshes, RemeshCad, ::testing::Range(0, 4),
                         [](const ::testing::TestParamInfo<int>& p) { return test::cadMeshes()[p.param].name; });

}  // namespace
}  // namespace gr
