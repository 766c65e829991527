// Incremental fast marching (paper §3.1: U_{n+1} = min(U_n, U_x)), target stops and sources
// inside faces. Oracles: the one-shot multi-source run, the unlimited run, Euclidean distance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/geodesic/fast_marching.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

int argmaxFinite(const std::vector<double>& d) {
  int best = 0;
  for (int v = 0; v < static_cast<int>(d.size()); ++v)
    if (std::isfinite(d[v]) && d[v] > d[best]) best = v;
  return best;
}

class Incremental : public ::testing::TestWithParam<std::string> {};

// Sources added one at a time (each at the farthest vertex, as greedy sampling does) give the
// same field and cells as one run with all of them, and each step accepts exactly the vertices
// whose distance decreased.
TEST_P(Incremental, EqualsMultiSourceRunAndVisitsOnlyImprovedVertices) {
  const TriMesh m = test::loadRealMesh(GetParam());
  FastMarcher marcher(m, Metric::uniform());
  std::vector<int> sources = {0};
  ASSERT_TRUE(marcher.addSource(0, 0));
  ASSERT_TRUE(marcher.propagate());
  EXPECT_EQ(static_cast<int>(marcher.acceptedOrder().size()), m.vertexCount());
  long visited = 0;
  for (int k = 1; k < 60; ++k) {
    const std::vector<double> before = marcher.distance();
    const int next = argmaxFinite(before);
    sources.push_back(next);
    ASSERT_TRUE(marcher.addSource(next, k));
    ASSERT_TRUE(marcher.propagate());
    const std::vector<double>& after = marcher.distance();
    std::set<int> accepted(marcher.acceptedOrder().begin(), marcher.acceptedOrder().end());
    EXPECT_EQ(accepted.size(), marcher.acceptedOrder().size()) << "a vertex accepted twice in one run";
    for (int v = 0; v < m.vertexCount(); ++v) {
      ASSERT_LE(after[v], before[v]) << "step " << k << ": vertex " << v << " got farther";
      ASSERT_EQ(accepted.count(v) == 1, after[v] < before[v]) << "step " << k << ", vertex " << v;
    }
    visited += static_cast<long>(accepted.size());
  }
  const auto oneShot = fastMarching(m, Metric::uniform(), sources);
  ASSERT_TRUE(oneShot);
  int differ = 0;
  double worst = 0.0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const double diff = std::abs(marcher.distance()[v] - oneShot->distance[v]);
    worst = std::max(worst, diff);
    if (diff > 1e-12 * (1.0 + oneShot->distance[v])) ++differ;
    if (diff == 0.0) {
      EXPECT_EQ(marcher.cell()[v], oneShot->cell[v]) << "vertex " << v;
    }
  }
  std::printf(
      "%s: 59 incremental steps visited %ld vertices (%.2f x V); %d of %d differ from the one-shot run "
      "(largest %.3g, h = %.3g)\n",
      GetParam().c_str(), visited, double(visited) / m.vertexCount(), differ, m.vertexCount(), worst,
      m.meanEdgeLength());
  EXPECT_EQ(differ, 0) << "the incremental field differs from the multi-source run";
  EXPECT_LT(visited, 59L * m.vertexCount() / 4) << "incremental steps visit far more than the improved region";
}

INSTANTIATE_TEST_SUITE_P(Meshes, Incremental, ::testing::Values("fandisk.off", "bunny00.off"),
                         [](const ::testing::TestParamInfo<std::string>& p) {
                           return p.param.substr(0, p.param.find('.'));
                         });

TEST(FastMarchingTargets, StopsOnceTargetsAreAcceptedWithTheirFinalValues) {
  const TriMesh m = test::loadRealMesh("fandisk.off");
  const auto full = fastMarching(m, Metric::uniform(), {0});
  ASSERT_TRUE(full);
  FastMarchingParams params;
  params.targets = {full->acceptedOrder[100], full->acceptedOrder[2000], full->acceptedOrder[50]};
  const auto r = fastMarching(m, Metric::uniform(), {0}, params);
  ASSERT_TRUE(r);
  for (int t : params.targets) EXPECT_EQ(r->distance[t], full->distance[t]);
  EXPECT_EQ(r->reachedCount(), 2001) << "stops right after the last target";
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (std::isfinite(r->distance[v])) {
      EXPECT_EQ(r->distance[v], full->distance[v]) << v;
    }
  }
}

TEST(FastMarchingTargets, RejectsMissingTargets) {
  const TriMesh m = test::planeGrid(4);
  FastMarchingParams params;
  params.targets = {999};
  EXPECT_EQ(fastMarching(m, Metric::uniform(), {0}, params).status().code, StatusCode::InvalidInput);
}

// A source inside a face of a plane: the distance is the Euclidean distance from that point.
TEST(FastMarchingFaceSource, PlaneDistanceFromAPointInsideAFace) {
  for (double jitter : {0.0, 0.3}) {
    const TriMesh m = test::planeGrid(40, 1.0, jitter, 7);
    const double h = m.meanEdgeLength();
    const SurfacePoint s = SurfacePoint::inFace(1234, Vec3(0.2, 0.5, 0.3));
    const Vec3 p = s.position(m);
    FastMarcher marcher(m, Metric::uniform());
    ASSERT_TRUE(marcher.addSource(s, 0));
    ASSERT_TRUE(marcher.propagate());
    double sumRel = 0.0, maxAbs = 0.0;
    int n = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
      const double exact = (m.positions[v] - p).norm();
      const double err = std::abs(marcher.distance()[v] - exact);
      maxAbs = std::max(maxAbs, err);
      if (exact > 0.05) {
        sumRel += err / exact;
        ++n;
      }
      ASSERT_GE(marcher.distance()[v], exact - 1e-12);
    }
    std::printf("face source, jitter %.1f: mean relative error %.3g, max %.3g h\n", jitter, sumRel / n, maxAbs / h);
    EXPECT_LT(sumRel / n, 1e-3);
    EXPECT_LT(maxAbs, 0.5 * h);
  }
}

TEST(FastMarchingFaceSource, RejectsBadPoints) {
  const TriMesh m = test::planeGrid(4);
  FastMarcher marcher(m, Metric::uniform());
  EXPECT_EQ(marcher.addSource(SurfacePoint::inFace(99, Vec3(1, 0, 0)), 0).code, StatusCode::InvalidInput);
  EXPECT_EQ(marcher.addSource(SurfacePoint::inFace(0, Vec3(0.5, 0.6, 0)), 0).code, StatusCode::InvalidInput);
  EXPECT_EQ(marcher.addSource(SurfacePoint::inFace(0, Vec3(-0.5, 1.5, 0)), 0).code, StatusCode::InvalidInput);
}

}  // namespace
}  // namespace gr
