// Greedy farthest-point sampling (paper §3.1). Oracles: a brute-force recomputation (one-shot
// multi-source fast marching from all earlier samples, full scan for the maximum) and the
// properties of a farthest-point net (covering radius <= every insertion distance).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>

#include "core/geodesic/detail/farthest_queue.h"
#include "core/geodesic/farthest_point_sampling.h"
#include "core/geodesic/fast_marching.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

// The bucket queue against a full scan, through a long run of decreasing updates: values over
// many octaves, below the floor, exact ties, zeros (taken samples), and enough updates to
// trigger its compaction several times.
TEST(FarthestQueue, TopIsTheLargestValueLowestIndexFirst) {
  const int n = 2000;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> U(n);
  for (double& u : U) u = std::ldexp(unit(rng), -static_cast<int>(30 * unit(rng)));  // 1 .. 1e-9
  U[17] = U[1234] = 2.0;                                                             // a tie on top
  FarthestQueue queue(U, 1e-6);
  for (int v = 0; v < n; ++v) queue.update(v);
  const auto scan = [&U] {
    int best = 0;
    for (int v = 1; v < static_cast<int>(U.size()); ++v)
      if (U[v] > U[best]) best = v;  // strict: the lowest index among equals
    return best;
  };
  int checked = 0;
  for (int step = 0; step < 60000; ++step) {
    if (step % 7 == 0) {  // take the top, as sampling does: its value drops to 0
      const int top = queue.top();
      ASSERT_EQ(top, scan()) << "step " << step;
      ++checked;
      U[top] = 0.0;
      queue.update(top);
    }
    // A front lowers some value: by a random factor, or to another vertex's value (ties).
    const int v = static_cast<int>(rng() % n);
    U[v] = step % 5 == 0 ? std::min(U[v], U[rng() % n]) : U[v] * unit(rng);
    queue.update(v);
  }
  EXPECT_GT(checked, 8000);
  // All values at 0: the top has U = 0, as sampling sees when every vertex is a sample.
  for (int v = 0; v < n; ++v) {
    U[v] = 0.0;
    queue.update(v);
  }
  const int top = queue.top();
  ASSERT_GE(top, 0);
  EXPECT_EQ(U[top], 0.0);
}

TEST(FarthestPointSampling, EachSampleIsTheFarthestVertexFromTheEarlierOnes) {
  const TriMesh m = test::loadRealMesh("fandisk.off");
  FpsParams params;
  params.targetCount = 40;
  params.seed = 7;
  const auto r = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(r) << r.status().message;
  ASSERT_EQ(r->samples.size(), 40u);
  // The first sample is the farthest vertex from the seeded start.
  const auto fromStart = fastMarching(m, Metric::uniform(), {7});
  EXPECT_EQ(fromStart->distance[r->samples[0]],
            *std::max_element(fromStart->distance.begin(), fromStart->distance.end()));
  for (size_t k = 1; k < r->samples.size(); ++k) {
    const std::vector<int> earlier(r->samples.begin(), r->samples.begin() + k);
    const auto field = fastMarching(m, Metric::uniform(), earlier);
    const double best = *std::max_element(field->distance.begin(), field->distance.end());
    EXPECT_EQ(field->distance[r->samples[k]], best) << "sample " << k << " is not the farthest vertex";
    EXPECT_EQ(r->insertionDistance[k], best) << "sample " << k;
  }
}

// From given initial samples: they come first, in order, and every later sample is the farthest
// vertex from all before it (the same brute-force oracle as above), its insertion distance that
// farthest distance; the field and cells returned are those of one front from all samples.
TEST(FarthestPointSampling, GoesOnGreedilyFromInitialSamples) {
  const TriMesh m = test::loadRealMesh("fandisk.off");
  FpsParams params;
  params.targetCount = 30;
  params.initialSamples = {5, 4000, 100, 2500};
  const auto r = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(r) << r.status().message;
  ASSERT_EQ(r->samples.size(), 30u);
  for (size_t k = 0; k < params.initialSamples.size(); ++k) {
    EXPECT_EQ(r->samples[k], params.initialSamples[k]);
    EXPECT_EQ(r->insertionDistance[k], kUnreached);
  }
  for (size_t k = params.initialSamples.size(); k < r->samples.size(); ++k) {
    const std::vector<int> earlier(r->samples.begin(), r->samples.begin() + k);
    const auto field = fastMarching(m, Metric::uniform(), earlier);
    const double best = *std::max_element(field->distance.begin(), field->distance.end());
    EXPECT_EQ(field->distance[r->samples[k]], best) << "sample " << k << " is not the farthest vertex";
    EXPECT_EQ(r->insertionDistance[k], best) << "sample " << k;
  }
  const auto all = fastMarching(m, Metric::uniform(), r->samples);
  double largest = 0.0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    EXPECT_NEAR(r->distance[v], all->distance[v], 1e-12) << v;
    largest = std::max(largest, all->distance[v]);
  }
  EXPECT_NEAR(r->coveringRadius, largest, 1e-12);
  // As many initial samples as the target: those, and their field.
  params.targetCount = 4;
  const auto only = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(only);
  EXPECT_EQ(only->samples, params.initialSamples);
}

TEST(FarthestPointSampling, InitialSamplesOnOneComponentLeaveNoneUnsampled) {
  const TriMesh m = test::loadRealMesh("knot2.off");  // two tori
  ASSERT_EQ(m.topology.components, 2);
  int onFirst = -1;
  for (int v = 0; v < m.vertexCount() && onFirst < 0; ++v)
    if (m.topology.componentOfVertex[v] == 0) onFirst = v;
  FpsParams params;
  params.targetCount = 6;
  params.initialSamples = {onFirst};
  const auto r = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(r) << r.status().message;
  std::set<int> components;
  for (int s : r->samples) components.insert(m.topology.componentOfVertex[s]);
  EXPECT_EQ(components.size(), 2u);
  EXPECT_EQ(m.topology.componentOfVertex[r->samples[1]], 1) << "the other component's first sample comes next";
  for (int v = 0; v < m.vertexCount(); ++v) ASSERT_TRUE(std::isfinite(r->distance[v])) << v;
}

// The 3D sampling against a brute-force recomputation: the first vertex is the farthest (in 3D)
// from the seeded start, each next one the farthest from all before it; it stops when every vertex
// is taken.
TEST(FarthestPointSampling, In3dEachVertexIsTheFarthestFromTheEarlierOnes) {
  const TriMesh m = test::loadRealMesh("fandisk.off");
  const std::vector<int> chosen = farthestPointsIn3d(m, 25, 7);
  ASSERT_EQ(chosen.size(), 25u);
  const auto nearest = [&](int v, size_t k) {
    double best = kUnreached;
    for (size_t i = 0; i < k; ++i) best = std::min(best, (m.positions[v] - m.positions[chosen[i]]).norm());
    return k == 0 ? (m.positions[v] - m.positions[7]).norm() : best;
  };
  for (size_t k = 0; k < chosen.size(); ++k) {
    double farthest = 0.0;
    for (int v = 0; v < m.vertexCount(); ++v) farthest = std::max(farthest, nearest(v, k));
    EXPECT_EQ(nearest(chosen[k], k), farthest) << "vertex " << k;
  }
  const TriMesh small = test::planeGrid(2);  // 9 vertices
  EXPECT_EQ(farthestPointsIn3d(small, 20).size(), 9u);
  EXPECT_TRUE(farthestPointsIn3d(small, 0).empty());
}

TEST(FarthestPointSampling, RejectsBadInitialSamples) {
  const TriMesh m = test::planeGrid(4);
  FpsParams p;
  p.targetCount = 5;
  for (const std::vector<int>& bad :
       std::vector<std::vector<int>>{{-1}, {m.vertexCount()}, {3, 7, 3}, {0, 1, 2, 3, 4, 5}}) {
    p.initialSamples = bad;
    const auto r = farthestPointSampling(m, Metric::uniform(), p);
    EXPECT_EQ(r.status().code, StatusCode::InvalidInput) << bad.size();
  }
  // A vertex in no face is no sample.
  TriMesh withLoose = test::planeGrid(4);
  withLoose.positions.push_back(Vec3(5.0, 5.0, 5.0));
  const Expected<TriMesh> loose = buildTriMesh(withLoose.positions, withLoose.triangles);
  ASSERT_TRUE(loose);
  p.initialSamples = {loose->vertexCount() - 1};
  EXPECT_EQ(farthestPointSampling(*loose, Metric::uniform(), p).status().code, StatusCode::InvalidInput);
}

TEST(FarthestPointSampling, FormsANet) {
  const TriMesh m = test::loadRealMesh("bunny00.off");
  FpsParams params;
  params.targetCount = 300;
  const auto r = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(r);
  // Insertion distances never increase, and all are at least the final covering radius.
  for (size_t k = 2; k < r->insertionDistance.size(); ++k)
    EXPECT_LE(r->insertionDistance[k], r->insertionDistance[k - 1]) << k;
  EXPECT_GT(r->coveringRadius, 0.0);
  EXPECT_LE(r->coveringRadius, r->insertionDistance.back());
  // Every vertex is within the covering radius of a sample; regions partition the vertices.
  std::set<int> regions;
  for (int v = 0; v < m.vertexCount(); ++v) {
    ASSERT_LE(r->distance[v], r->coveringRadius) << v;
    ASSERT_GE(r->cell[v], 0);
    regions.insert(r->cell[v]);
  }
  EXPECT_EQ(regions.size(), 300u);
  // Packing: each sample is at least the covering radius away from every other one.
  const std::vector<int> sample10(r->samples.begin(), r->samples.begin() + 10);
  for (size_t i = 0; i < sample10.size(); ++i) {
    const auto d = fastMarching(m, Metric::uniform(), {sample10[i]});
    for (int other : r->samples) {
      if (other != sample10[i]) {
        EXPECT_GE(d->distance[other], 0.99 * r->coveringRadius);
      }
    }
  }
}

// samplingPrefix: the first k samples of a longer sampling, with their field, are the sampling
// of k itself (a separate run), on a closed mesh, on two components, on one with boundaries, and
// with sub-vertex placement.
void expectPrefixesAreSamplings(const TriMesh& m, FpsParams params, const std::vector<int>& counts) {
  FastMarcher marcher(m, Metric::uniform());
  const auto longer = farthestPointSampling(marcher, params);
  ASSERT_TRUE(longer) << longer.status().message;
  for (int k : counts) {
    params.targetCount = k;
    const auto direct = farthestPointSampling(m, Metric::uniform(), params);
    const auto prefix = samplingPrefix(marcher, *longer, k);
    ASSERT_TRUE(direct && prefix) << k;
    EXPECT_EQ(prefix->samples, direct->samples) << k;
    ASSERT_EQ(prefix->origin.size(), direct->origin.size());
    for (size_t i = 0; i < direct->origin.size(); ++i) {
      EXPECT_EQ(prefix->origin[i].vertex, direct->origin[i].vertex) << k << " sample " << i;
      EXPECT_EQ(prefix->origin[i].position(m), direct->origin[i].position(m)) << k << " sample " << i;
    }
    EXPECT_EQ(prefix->coveringRadius, direct->coveringRadius) << k;
    // Cells: the same but at a few vertices on the cells' borders, where two fronts bring the same
    // value in another order (0-3 vertices here): the other label is the cell of a neighbour.
    int differ = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
      if (prefix->cell[v] == direct->cell[v]) continue;
      ++differ;
      bool neighbourHasIt = false;
      for (const int* c = m.cornersBegin(v); c != m.cornersEnd(v); ++c)
        for (int w : {m.vertex(TriMesh::next(*c)), m.vertex(TriMesh::prev(*c))})
          neighbourHasIt = neighbourHasIt || direct->cell[w] == prefix->cell[v];
      EXPECT_TRUE(neighbourHasIt) << k << " vertex " << v << " is in cell " << prefix->cell[v] << ", not on its border";
    }
    EXPECT_LE(differ, 3 + m.vertexCount() / 1000) << k;
    EXPECT_EQ(marcher.cell(), prefix->cell) << k << ": the engine holds the prefix's cells";
    for (int v = 0; v < m.vertexCount(); ++v) {
      if (std::isinf(direct->distance[v])) {
        ASSERT_EQ(prefix->distance[v], direct->distance[v]) << k << " vertex " << v;
        continue;
      }
      ASSERT_NEAR(prefix->distance[v], direct->distance[v], 1e-12 * m.boundingBoxDiagonal()) << k << " vertex " << v;
    }
  }
  EXPECT_FALSE(samplingPrefix(marcher, *longer, 0));
  EXPECT_FALSE(samplingPrefix(marcher, *longer, static_cast<int>(longer->samples.size()) + 1));
}

TEST(FarthestPointSampling, APrefixIsTheShorterSampling) {
  FpsParams params;
  params.targetCount = 300;
  params.seed = 5;
  expectPrefixesAreSamplings(test::loadRealMesh("fandisk.off"), params, {1, 2, 37, 299, 300});
  params.targetCount = 120;
  const TriMesh twoTori = test::loadRealMesh("knot2.off");
  expectPrefixesAreSamplings(twoTori, params, {1, 2, 3, 64});
  const TriMesh holes = test::loadRealMesh("elephant-with-holes.off");
  ASSERT_GT(holes.topology.boundaryLoops, 0);
  expectPrefixesAreSamplings(holes, params, {5, 100});
  params.subVertexPlacement = true;
  expectPrefixesAreSamplings(test::planeGrid(30, 1.0, 0.3), params, {10, 80});
}

TEST(FarthestPointSampling, DeterministicForASeed) {
  const TriMesh m = test::loadRealMesh("fandisk.off");
  FpsParams params;
  params.targetCount = 25;
  params.seed = 3;
  const auto a = farthestPointSampling(m, Metric::uniform(), params);
  const auto b = farthestPointSampling(m, Metric::uniform(), params);
  EXPECT_EQ(a->samples, b->samples);
  params.seed = 4000;
  const auto c = farthestPointSampling(m, Metric::uniform(), params);
  EXPECT_NE(a->samples, c->samples);
}

TEST(FarthestPointSampling, SpacingStop) {
  const TriMesh m = test::planeGrid(60);
  FpsParams params;
  params.targetCount = 0;
  params.minSpacing = 0.1;
  const auto r = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(r);
  EXPECT_LT(r->coveringRadius, 0.1);
  EXPECT_GE(r->insertionDistance.back(), 0.1);
  // A unit square covered by discs of radius 0.1 needs at least 1 / (pi 0.01) ~ 32 of them.
  EXPECT_GT(r->samples.size(), 31u);
  EXPECT_LT(r->samples.size(), 200u);
}

TEST(FarthestPointSampling, EveryComponentGetsSamples) {
  const TriMesh m = test::loadRealMesh("knot2.off");  // two tori
  ASSERT_EQ(m.topology.components, 2);
  FpsParams params;
  params.targetCount = 10;
  const auto r = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(r);
  std::set<int> components;
  for (int s : r->samples) components.insert(m.topology.componentOfVertex[s]);
  EXPECT_EQ(components.size(), 2u);
  for (int v = 0; v < m.vertexCount(); ++v) ASSERT_TRUE(std::isfinite(r->distance[v])) << v;
}

TEST(FarthestPointSampling, RejectsImpossibleParameters) {
  const TriMesh m = test::planeGrid(4);
  FpsParams p;
  p.targetCount = 1000;
  EXPECT_EQ(farthestPointSampling(m, Metric::uniform(), p).status().code, StatusCode::InvalidInput);
  p.targetCount = -1;
  EXPECT_EQ(farthestPointSampling(m, Metric::uniform(), p).status().code, StatusCode::InvalidInput);
  p.targetCount = 0;
  p.minSpacing = 0.0;
  EXPECT_EQ(farthestPointSampling(m, Metric::uniform(), p).status().code, StatusCode::InvalidInput);
  p.minSpacing = std::nan("");
  EXPECT_EQ(farthestPointSampling(m, Metric::uniform(), p).status().code, StatusCode::InvalidInput);
}

/// On a plane, the net property measured with Euclidean geometry, independently of the code:
/// the smallest distance between two samples over the true covering radius (the largest
/// distance from a point of the square to its nearest sample, by brute force on a fine lattice).
/// A perfect farthest-point net has a ratio >= 1.
double netRatio(const TriMesh& m, const FpsResult& r) {
  std::vector<Vec3> p;
  for (const SurfacePoint& s : r.origin) p.push_back(s.position(m));
  double closest = kUnreached;
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) closest = std::min(closest, (p[i] - p[j]).norm());
  double covering = 0.0;
  const int n = 400;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const Vec3 q(double(i) / n, double(j) / n, 0.0);
      double nearest = kUnreached;
      for (const Vec3& s : p) nearest = std::min(nearest, (q - s).norm());
      covering = std::max(covering, nearest);
    }
  return closest / covering;
}

TEST(FarthestPointSampling, SubVertexPlacementGivesABetterNet) {
  const TriMesh m = test::planeGrid(24, 1.0, 0.3);
  FpsParams params;
  params.targetCount = 80;
  params.boundaryPriority = 1.0;
  const auto atVertices = farthestPointSampling(m, Metric::uniform(), params);
  params.subVertexPlacement = true;
  const auto inFaces = farthestPointSampling(m, Metric::uniform(), params);
  ASSERT_TRUE(atVertices && inFaces);
  int moved = 0;
  for (size_t i = 0; i < inFaces->origin.size(); ++i) {
    const SurfacePoint& s = inFaces->origin[i];
    if (s.vertex >= 0) {
      EXPECT_EQ(s.vertex, inFaces->samples[i]);
      continue;
    }
    ++moved;
    EXPECT_GE(s.bary.minCoeff(), 0.0);
    EXPECT_NEAR(s.bary.sum(), 1.0, 1e-12);
    // Near the farthest vertex it replaces: in a face within two rings of it.
    EXPECT_LT((s.position(m) - m.positions[inFaces->samples[i]]).norm(), 2.5 * m.meanEdgeLength());
  }
  EXPECT_GT(moved, 40);
  const double vertexRatio = netRatio(m, *atVertices), faceRatio = netRatio(m, *inFaces);
  std::printf("net ratio (closest pair / true covering radius): at vertices %.3f, sub-vertex %.3f\n", vertexRatio,
              faceRatio);
  // Both are nets up to the discretisation (the heap ranks vertices, so a hole inside faces can
  // stay up to an edge length deeper than the farthest vertex); placing samples where the fronts
  // meet gives the better one (measured: 0.793 at vertices, 0.812 sub-vertex).
  EXPECT_GT(vertexRatio, 0.75);
  EXPECT_GT(faceRatio, vertexRatio);
}

}  // namespace
}  // namespace gr
