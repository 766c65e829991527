// Geodesic Lloyd: the descent reaches the intrinsic centre of mass (judged with CGAL's exact
// geodesics), the energy never increases and drops well below the farthest-point sampling's.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/geodesic/farthest_point_sampling.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_lloyd.h"
#include "tests/oracles/geodesic_oracles.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// Per-vertex mass recomputed here: one third of the area of each face, from the positions.
std::vector<double> massOf(const TriMesh& m) {
  std::vector<double> mass(m.vertexCount(), 0.0);
  for (const Tri& t : m.triangles) {
    const double a = 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
    for (int v : t) mass[v] += a / 3.0;
  }
  return mass;
}

/// sum_x m_x d(x, w)^2 with d from CGAL's exact geodesics from the surface point w.
double exactEnergy(const TriMesh& m, const std::vector<double>& mass, const SurfacePoint& w) {
  std::vector<SurfacePoint> targets(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) targets[v] = SurfacePoint::atVertex(v);
  const std::vector<double> d = oracle::exactGeodesicBetween(m, w, targets);
  double e = 0.0;
  for (int v = 0; v < m.vertexCount(); ++v) e += mass[v] * d[v] * d[v];
  return e;
}

/// The sum over seeds' cells of m_x U(x)^2, from a multi-source front run here (not Lloyd's own).
double energyOfSeeds(const TriMesh& m, const std::vector<SurfacePoint>& seeds) {
  FastMarcher marcher(m, Metric::uniform());
  for (size_t i = 0; i < seeds.size(); ++i) EXPECT_TRUE(marcher.addSource(seeds[i], static_cast<int>(i)));
  EXPECT_TRUE(marcher.propagate());
  const std::vector<double> mass = massOf(m);
  double e = 0.0;
  for (int v = 0; v < m.vertexCount(); ++v) e += mass[v] * marcher.distance()[v] * marcher.distance()[v];
  return e;
}

/// A spherical cap (the part of an icosphere above z = -0.2, about 1.4k vertices) and a saddle
/// patch z = 0.4 (x^2 - y^2) over a 40 x 40 grid (1.7k vertices): one cell each.
TriMesh sphereCap() {
  const TriMesh s = test::icosphere(4);
  std::vector<int> index(s.vertexCount(), -1);
  std::vector<Vec3> pos;
  std::vector<Tri> tris;
  for (const Tri& t : s.triangles) {
    if (s.positions[t[0]].z() < -0.2 || s.positions[t[1]].z() < -0.2 || s.positions[t[2]].z() < -0.2) continue;
    Tri n;
    for (int k = 0; k < 3; ++k) {
      if (index[t[k]] < 0) {
        index[t[k]] = static_cast<int>(pos.size());
        // Squashed along x so that the centre is not a symmetry point of the icosphere's vertices.
        pos.push_back(Vec3(1.3 * s.positions[t[k]].x(), s.positions[t[k]].y(), s.positions[t[k]].z()));
      }
      n[k] = index[t[k]];
    }
    tris.push_back(n);
  }
  return *buildTriMesh(pos, tris);
}

TriMesh saddlePatch() {
  TriMesh g = test::planeGrid(40, 2.0, 0.3);
  for (Vec3& p : g.positions) {
    p -= Vec3(0.7, 1.0, 0.0);  // off-centre: the cell's centre of mass is not a grid symmetry point
    p.z() = 0.4 * (p.x() * p.x() - p.y() * p.y());
  }
  return *buildTriMesh(g.positions, g.triangles);
}

// The centre of mass is right: one cell, Lloyd from a far vertex; the final seed's energy, by
// exact geodesics, within 0.5% of the least energy of any vertex of the cell. The vertices whose
// fast-marching energy is within 3% of the least are the candidates evaluated exactly (the
// others are far above: fast marching is within 1% on these meshes).
void expectCentreOfMass(const TriMesh& m) {
  const std::vector<double> mass = massOf(m);
  // Fast-marching energy of every vertex, to pick the candidates.
  std::vector<std::pair<double, int>> approx;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const Expected<FastMarchingResult> f = fastMarching(m, Metric::uniform(), {v});
    double e = 0.0;
    for (int x = 0; x < m.vertexCount(); ++x) e += mass[x] * f->distance[x] * f->distance[x];
    approx.emplace_back(e, v);
  }
  std::sort(approx.begin(), approx.end());
  double bestExact = kUnreached;
  int evaluated = 0;
  for (const auto& [e, v] : approx) {
    if (e > 1.03 * approx.front().first) break;
    bestExact = std::min(bestExact, exactEnergy(m, mass, SurfacePoint::atVertex(v)));
    ++evaluated;
  }
  EXPECT_GT(evaluated, 0);
  // The default one-step descent and the checked descent (two steps per iteration, each checked
  // by a front over the cell), both from vertex 0 on the boundary.
  for (const int steps : {0, 2}) {
    SCOPED_TRACE(steps);
    FastMarcher marcher(m, Metric::uniform());
    LloydParams params;
    params.iterations = 10;
    params.tolerance = 0.0;
    params.descentSteps = steps;
    const Expected<LloydResult> r = geodesicLloyd(m, Metric::uniform(), marcher, {SurfacePoint::atVertex(0)}, params);
    ASSERT_TRUE(r) << r.status().message;
    ASSERT_EQ(r->seeds.size(), 1u);
    const double ours = exactEnergy(m, mass, r->seeds[0]);
    std::printf("centre of mass, %d descent steps: ours %.6g, best vertex %.6g (%d evaluated exactly), start %.6g\n",
                steps, ours, bestExact, evaluated, exactEnergy(m, mass, SurfacePoint::atVertex(0)));
    EXPECT_LE(ours, 1.005 * bestExact);
  }
}

TEST(GeodesicLloyd, CentreOfMassOfASphereCap) { expectCentreOfMass(sphereCap()); }
TEST(GeodesicLloyd, CentreOfMassOfASaddlePatch) { expectCentreOfMass(saddlePatch()); }

// Energy on bunny00 with 100 and 500 seeds: recomputed from a front of each iterate's seeds (the
// seeds of a run of k iterations), it never increases, and it ends within 4% of the lower bound
// that no N points can beat: L. Fejes Toth's moment theorem (a plane domain of area A cut into N
// cells has a second moment of at least N times the regular hexagon's, 5 sqrt(3) / 54 (A / N)^2;
// on a surface this curved at this sampling, up to a percent or so). Issue 18 asks the energy to
// end at least 10% below the farthest-point samples': out of reach, because the samples are only
// 10.3% (100) and 9.6% (500) above that bound, so 10% below them is below the bound; Lloyd ends at
// 2.5% above it after 40 iterations (92.9% and 93.5% of the samples'). Held at the measured figures
// after 8 iterations (93.7% and 93.6%, with the default descent), so that any change shows.
void expectEnergyFalls(int seedCount) {
  const TriMesh m = test::loadRealMesh("bunny00.off");
  ASSERT_GT(m.vertexCount(), 0);
  FastMarcher marcher(m, Metric::uniform());
  FpsParams fps;
  fps.targetCount = seedCount;
  fps.boundaryPriority = 1.0;
  const Expected<FpsResult> samples = farthestPointSampling(marcher, fps);
  ASSERT_TRUE(samples);
  double previous = energyOfSeeds(m, samples->origin);
  const double start = previous;
  constexpr int kIterations = 8;
  for (int k = 1; k <= kIterations; ++k) {
    LloydParams params;
    params.iterations = k;
    params.tolerance = 0.0;
    const Expected<LloydResult> r = geodesicLloyd(m, Metric::uniform(), marcher, samples->origin, params);
    ASSERT_TRUE(r) << r.status().message;
    ASSERT_EQ(static_cast<int>(r->seeds.size()), seedCount);
    const double e = energyOfSeeds(m, r->seeds);
    std::printf("%d seeds, %d iterations: energy %.6g (%.1f%% of the samples')\n", seedCount, k, e, 100.0 * e / start);
    EXPECT_LE(e, previous * (1.0 + 1e-12)) << "iteration " << k;
    // Every cell kept: each seed is the nearest seed of some vertex.
    std::vector<char> has(seedCount, 0);
    for (int c : r->cell)
      if (c >= 0) has[c] = 1;
    EXPECT_EQ(std::count(has.begin(), has.end(), 1), seedCount);
    previous = e;
  }
  EXPECT_LE(previous, 0.940 * start);
  double area = 0.0;
  for (const Tri& t : m.triangles)
    area += 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
  const double hexagonBound = 5.0 * std::sqrt(3.0) / 54.0 * area * area / seedCount;
  std::printf("%d seeds: samples %.3f x the hexagon bound, after %d iterations %.3f x\n", seedCount,
              start / hexagonBound, kIterations, previous / hexagonBound);
  EXPECT_LE(previous, 1.04 * hexagonBound);
}

TEST(GeodesicLloyd, EnergyNeverRisesAndEndsNearTheHexagonBoundBunny100) { expectEnergyFalls(100); }
TEST(GeodesicLloyd, EnergyNeverRisesAndEndsNearTheHexagonBoundBunny500) { expectEnergyFalls(500); }

// The first cells read from the sampling's field (LloydParams::marcherHoldsSeedsField) are those
// of a front from the samples: the same energies and cells as a run that starts with that front.
TEST(GeodesicLloyd, StartsFromTheSamplingsFieldAsFromItsOwnFront) {
  const TriMesh m = test::loadRealMesh("bunny00.off");
  FastMarcher marcher(m, Metric::uniform());
  FpsParams fps;
  fps.targetCount = 200;
  const Expected<FpsResult> samples = farthestPointSampling(marcher, fps);
  ASSERT_TRUE(samples);
  LloydParams params;
  params.iterations = 4;
  params.tolerance = 0.0;
  params.marcherHoldsSeedsField = true;
  const Expected<LloydResult> fromSampling = geodesicLloyd(m, Metric::uniform(), marcher, samples->origin, params);
  params.marcherHoldsSeedsField = false;
  FastMarcher fresh(m, Metric::uniform());
  const Expected<LloydResult> fromFront = geodesicLloyd(m, Metric::uniform(), fresh, samples->origin, params);
  ASSERT_TRUE(fromSampling && fromFront);
  ASSERT_EQ(fromSampling->energy.size(), fromFront->energy.size());
  for (size_t k = 0; k < fromFront->energy.size(); ++k)
    EXPECT_NEAR(fromSampling->energy[k], fromFront->energy[k], 1e-12 * fromFront->energy[k]) << "iteration " << k;
  int differ = 0;
  for (int v = 0; v < m.vertexCount(); ++v) differ += fromSampling->cell[v] != fromFront->cell[v];
  EXPECT_LE(differ, m.vertexCount() / 1000);
}

TEST(GeodesicLloyd, RefusesBadInput) {
  const TriMesh m = test::planeGrid(4);
  FastMarcher marcher(m, Metric::uniform());
  EXPECT_EQ(geodesicLloyd(m, Metric::uniform(), marcher, {}).status().code, StatusCode::InvalidInput);
  EXPECT_EQ(geodesicLloyd(m, Metric::uniform(), marcher, {SurfacePoint::atVertex(1000)}).status().code,
            StatusCode::InvalidInput);
  LloydParams bad;
  bad.iterations = -1;
  EXPECT_EQ(geodesicLloyd(m, Metric::uniform(), marcher, {SurfacePoint::atVertex(0)}, bad).status().code,
            StatusCode::InvalidInput);
}

}  // namespace
}  // namespace gr
