// Tests of fast marching (core/geodesic/fast_marching.h): weighted geodesic distance and nearest source.
//
// Oracles, none taken from the code under test:
//  - analytic: on a plane the geodesic distance is the Euclidean distance; on the unit sphere it
//    is the great-circle arc acos(p . s);
//  - bounds: a Dijkstra over the mesh edges written here is an upper bound (fast marching always
//    tries the edge update), the straight-line distance a lower bound (an unfolded virtual source
//    at distances >= the true ones is never closer than the true source, by Stewart's theorem);
//  - invariants: symmetry, triangle inequality, scaling by a constant metric, the distance limit
//    as a sub-run of the unlimited run, separate single-source runs for the multi-source cells.
// Tolerances are multiples of the mean edge length h of the mesh at hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <queue>
#include <random>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "core/geodesic/fast_marching.h"
#include "core/geodesic/metric.h"
#include "core/mesh/tri_mesh.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

FastMarchingResult run(const TriMesh& m, const std::vector<int>& sources, const Metric& metric = Metric::uniform(),
                       const FastMarchingParams& params = {}) {
  Expected<FastMarchingResult> r = fastMarching(m, metric, sources, params);
  EXPECT_TRUE(r.hasValue()) << r.status().message;
  return r ? std::move(r).value() : FastMarchingResult{};
}

/// Dijkstra over the edges of the mesh, edge weight = mean P of its ends times its length.
std::vector<double> dijkstra(const TriMesh& m, int source, const std::vector<double>& P = {}) {
  const int nv = m.vertexCount();
  std::vector<std::set<int>> nbr(nv);
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      nbr[t[k]].insert(t[(k + 1) % 3]);
      nbr[t[(k + 1) % 3]].insert(t[k]);
    }
  auto cost = [&](int v) { return P.empty() ? 1.0 : P[v]; };
  std::vector<double> d(nv, kInf);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
  d[source] = 0;
  q.push({0.0, source});
  while (!q.empty()) {
    auto [du, u] = q.top();
    q.pop();
    if (du > d[u]) continue;
    for (int w : nbr[u]) {
      const double nd = du + 0.5 * (cost(u) + cost(w)) * (m.positions[u] - m.positions[w]).norm();
      if (nd < d[w]) {
        d[w] = nd;
        q.push({nd, w});
      }
    }
  }
  return d;
}

/// Vertex of the grid nearest the centre of [0, size]^2.
int gridCentre(int n) { return (n / 2) * (n + 1) + n / 2; }

/// Spread-out vertices: greedy farthest points in the Euclidean metric, starting at vertex 0.
std::vector<int> spreadVertices(const TriMesh& m, int count) {
  std::vector<int> picked = {0};
  std::vector<double> d(m.vertexCount(), kInf);
  while (static_cast<int>(picked.size()) < count) {
    for (int v = 0; v < m.vertexCount(); ++v)
      d[v] = std::min(d[v], (m.positions[v] - m.positions[picked.back()]).norm());
    picked.push_back(static_cast<int>(std::max_element(d.begin(), d.end()) - d.begin()));
  }
  return picked;
}

/// True if `msg` names `word n` as a whole number ("vertex 7", not "vertex 71").
bool names(const std::string& msg, const std::string& word, long n) {
  return std::regex_search(msg, std::regex("\\b" + word + " " + std::to_string(n) + "(?![0-9])"));
}

struct ErrorStats {
  double meanRelative = 0;  ///< over vertices with exact >= 5% of the largest exact distance
  double maxAbsolute = 0;
  double minRatio = kInf;  ///< min fast-marching / exact over the same vertices
};

ErrorStats compare(const std::vector<double>& got, const std::vector<double>& exact) {
  ErrorStats s;
  const double far = *std::max_element(exact.begin(), exact.end());
  int n = 0;
  for (size_t v = 0; v < exact.size(); ++v) {
    s.maxAbsolute = std::max(s.maxAbsolute, std::abs(got[v] - exact[v]));
    if (exact[v] < 0.05 * far) continue;
    s.meanRelative += std::abs(got[v] - exact[v]) / exact[v];
    s.minRatio = std::min(s.minRatio, got[v] / exact[v]);
    ++n;
  }
  s.meanRelative /= std::max(n, 1);
  return s;
}

// ---------------------------------------------------------------------------------------------
// Accuracy against analytic distances.

/// Fast marching from the vertex nearest the centre of a plane grid, against Euclidean distance.
ErrorStats planeError(int n, double jitter, unsigned seed, double* h = nullptr) {
  TriMesh m = test::planeGrid(n, 1.0, jitter, seed);
  const int s = gridCentre(n);
  FastMarchingResult r = run(m, {s});
  EXPECT_EQ(r.reachedCount(), m.vertexCount());
  std::vector<double> exact(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) exact[v] = (m.positions[v] - m.positions[s]).norm();
  // The straight line is a lower bound on any mesh; on a flat one it is the exact distance.
  int below = 0;
  for (int v = 0; v < m.vertexCount(); ++v)
    if (r.distance[v] < exact[v] - 1e-9 && ++below <= 3) ADD_FAILURE() << "vertex " << v << " below the straight line";
  const ErrorStats e = compare(r.distance, exact);
  if (h) *h = m.meanEdgeLength();
  std::cout << "[ plane    ] jitter " << jitter << ", seed " << seed << ", n " << std::setw(3) << n << ", h "
            << std::setprecision(4) << m.meanEdgeLength() << ": mean relative error " << e.meanRelative
            << ", max abs error " << e.maxAbsolute << " (" << e.maxAbsolute / m.meanEdgeLength() << " h)\n";
  ::testing::Test::RecordProperty("plane_jitter" + std::to_string(int(jitter * 10 + 0.5)) + "_seed" +
                                      std::to_string(seed) + "_n" + std::to_string(n) + "_mean_rel",
                                  std::to_string(e.meanRelative));
  return e;
}

TEST(FastMarchingAccuracy, RegularPlaneGridIsExactUpToRounding) {
  // Right triangles, point source at a vertex: every accepted value comes from exact neighbours
  // through an upwind triangle, and the unfolded virtual source is then the true source, so the
  // only error is rounding (the refinement order is therefore not measurable here).
  for (int n : {20, 40, 80}) {
    double h = 0;
    const ErrorStats e = planeError(n, 0.0, 1, &h);
    EXPECT_LE(e.maxAbsolute, 1e-9 * h) << "n = " << n;
    EXPECT_LE(e.meanRelative, 1e-9) << "n = " << n;
  }
}

TEST(FastMarchingAccuracy, JitteredPlaneGridConvergesToEuclidean) {
  // Jitter 0.3 makes about half the triangles obtuse. Three seeds, so that the result is not the
  // luck of one vertex layout. A first-order method keeps the max error a small multiple of h
  // and the mean relative error O(h / L), L = 0.5 the typical distance from the centre. Once
  // obtuse angles are split the flat-plane error is mostly rounding plus a few vertices, so the
  // refinement check compares the finer grids with the coarsest, not each step with the last.
  std::vector<double> meanRel;
  for (int n : {20, 40, 80}) {
    double sum = 0;
    for (unsigned seed : {1u, 2u, 3u}) {
      double h = 0;
      const ErrorStats e = planeError(n, 0.3, seed, &h);
      EXPECT_LE(e.maxAbsolute, 2.0 * h) << "n = " << n << ", seed " << seed;
      EXPECT_LE(e.meanRelative, h / 0.5) << "n = " << n << ", seed " << seed;
      EXPECT_GE(e.minRatio, 0.99) << "n = " << n << ", seed " << seed;
      sum += e.meanRelative;
    }
    meanRel.push_back(sum / 3);
    std::cout << "[ plane    ] jitter 0.3, n " << n << ": mean relative error over seeds " << meanRel.back() << "\n";
  }
  EXPECT_LT(meanRel[1], meanRel[0]);
  EXPECT_LT(meanRel[2], meanRel[0]);
}

TEST(FastMarchingAccuracy, JitteredPlaneGridMaxErrorStaysWithinAFewEdgeLengths) {
  // The same bounds on finer grids: with first-order accuracy the max error, measured in edge
  // lengths, does not grow under refinement (without the obtuse-angle treatment it does: edge
  // updates accumulate).
  for (int n : {80, 160, 320}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      double h = 0;
      const ErrorStats e = planeError(n, 0.3, seed, &h);
      EXPECT_LE(e.maxAbsolute, 2.0 * h) << "n = " << n << ", seed " << seed;
      EXPECT_LE(e.meanRelative, h / 0.5) << "n = " << n << ", seed " << seed;
    }
  }
}

TEST(FastMarchingAccuracy, SphereMatchesGreatCircleDistance) {
  std::vector<double> rel;
  for (int level : {4, 5}) {
    TriMesh m = test::icosphere(level, 1.0);
    const double h = m.meanEdgeLength();
    const int s = 0;
    FastMarchingResult r = run(m, {s});
    ASSERT_EQ(r.reachedCount(), m.vertexCount());
    std::vector<double> exact(m.vertexCount());
    for (int v = 0; v < m.vertexCount(); ++v)
      exact[v] = std::acos(std::clamp(m.positions[v].dot(m.positions[s]), -1.0, 1.0));
    const ErrorStats e = compare(r.distance, exact);
    std::cout << "[ sphere   ] level " << level << ", V " << m.vertexCount() << ", h " << std::setprecision(4) << h
              << ": mean relative error " << e.meanRelative << ", max abs error " << e.maxAbsolute << " ("
              << e.maxAbsolute / h << " h), min fm/exact " << e.minRatio << "\n";
    ::testing::Test::RecordProperty("sphere_level" + std::to_string(level) + "_mean_rel",
                                    std::to_string(e.meanRelative));
    EXPECT_LE(e.maxAbsolute, 2.0 * h);
    // The icosphere is inscribed in the sphere: its distances are shorter, by O(h).
    if (level == 5) {
      EXPECT_GE(e.minRatio, 0.99);
    }
    for (int v = 0; v < m.vertexCount(); ++v)
      ASSERT_GE(r.distance[v], (m.positions[v] - m.positions[s]).norm() - 1e-9) << "below the chord, vertex " << v;
    rel.push_back(e.meanRelative);
  }
  EXPECT_LT(rel[1], 0.02);
  EXPECT_LT(rel[1], rel[0]);
}

// ---------------------------------------------------------------------------------------------
// Bounds and invariants.

TEST(FastMarchingBounds, BetweenStraightLineAndEdgeDijkstra) {
  struct Case {
    std::string name;
    TriMesh mesh;
  };
  std::vector<Case> cases;
  cases.push_back({"jittered grid", test::planeGrid(40, 1.0, 0.3)});
  cases.push_back({"icosphere 4", test::icosphere(4)});
  cases.push_back({"fandisk", test::loadRealMesh("fandisk.off")});
  cases.push_back({"mech-holes-shark", test::loadRealMesh("mech-holes-shark.off")});
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const TriMesh& m = c.mesh;
    ASSERT_GT(m.vertexCount(), 0);
    for (int s : {0, m.vertexCount() / 2}) {
      FastMarchingResult r = run(m, {s});
      const std::vector<double> dj = dijkstra(m, s);
      int below = 0, above = 0;
      double worstRatio = 1;
      for (int v = 0; v < m.vertexCount(); ++v) {
        if (dj[v] == kInf) {
          EXPECT_EQ(r.distance[v], kInf);
          continue;
        }
        const double line = (m.positions[v] - m.positions[s]).norm();
        if (r.distance[v] > dj[v] + 1e-9 && ++above <= 3)
          ADD_FAILURE() << "vertex " << v << ": fast marching " << r.distance[v] << " > Dijkstra " << dj[v];
        if (r.distance[v] < line - 1e-9 && ++below <= 3)
          ADD_FAILURE() << "vertex " << v << ": fast marching " << r.distance[v] << " < straight line " << line;
        if (dj[v] > 0) worstRatio = std::min(worstRatio, r.distance[v] / dj[v]);
      }
      EXPECT_EQ(above, 0);
      EXPECT_EQ(below, 0);
      // On a jittered grid or a sphere Dijkstra is a clearly longer path: the bound is not slack.
      std::cout << "[ bounds   ] " << c.name << ", source " << s << ": min fm/dijkstra " << worstRatio << "\n";
    }
  }
}

TEST(FastMarchingBounds, WeightedMetricBelowWeightedDijkstra) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.5, 2.0);
  std::vector<double> P(m.vertexCount());
  for (double& p : P) p = u(rng);
  Expected<Metric> metric = Metric::fromCost(m, P);
  ASSERT_TRUE(metric.hasValue()) << metric.status().message;
  const int s = 123;
  FastMarchingResult r = run(m, {s}, *metric);
  const std::vector<double> dj = dijkstra(m, s, P);
  const double pMin = *std::min_element(P.begin(), P.end());
  for (int v = 0; v < m.vertexCount(); ++v) {
    ASSERT_LE(r.distance[v], dj[v] + 1e-9) << "vertex " << v;
    // Every path costs at least pMin times its length, which is at least the straight line.
    ASSERT_GE(r.distance[v], pMin * (m.positions[v] - m.positions[s]).norm() - 1e-9) << "vertex " << v;
  }
  for (size_t i = 1; i < r.acceptedOrder.size(); ++i)
    ASSERT_GE(r.distance[r.acceptedOrder[i]], r.distance[r.acceptedOrder[i - 1]]) << "step " << i;
}

TEST(FastMarchingInvariants, MonotoneAlongAcceptedOrder) {
  std::vector<std::pair<std::string, TriMesh>> meshes;
  for (unsigned seed : {1u, 2u, 3u})
    meshes.push_back({"jittered grid seed " + std::to_string(seed), test::planeGrid(40, 1.0, 0.3, seed)});
  meshes.push_back({"fandisk", test::loadRealMesh("fandisk.off")});
  for (const auto& [name, m] : meshes) {
    SCOPED_TRACE(name);
    ASSERT_GT(m.vertexCount(), 0);
    for (const std::vector<int>& sources :
         {std::vector<int>{7}, std::vector<int>{0, m.vertexCount() / 3, m.vertexCount() - 1}}) {
      FastMarchingResult r = run(m, sources);
      ASSERT_EQ(r.reachedCount(), m.vertexCount());
      for (size_t i = 1; i < r.acceptedOrder.size(); ++i)
        ASSERT_GE(r.distance[r.acceptedOrder[i]], r.distance[r.acceptedOrder[i - 1]]) << "step " << i;
      EXPECT_EQ(r.maxDistance, r.distance[r.acceptedOrder.back()]);
    }
  }
}

TEST(FastMarchingInvariants, CompleteOnAConnectedMesh) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  ASSERT_EQ(m.topology.components, 1);
  const int s = 4321;
  FastMarchingResult r = run(m, {s});
  ASSERT_EQ(r.reachedCount(), m.vertexCount());
  std::vector<int> order = r.acceptedOrder;
  std::sort(order.begin(), order.end());
  for (int v = 0; v < m.vertexCount(); ++v) ASSERT_EQ(order[v], v) << "acceptedOrder is not a permutation";
  EXPECT_EQ(r.acceptedOrder.front(), s);
  EXPECT_EQ(r.distance[s], 0.0);
  double largest = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (v != s) {
      ASSERT_GT(r.distance[v], 0.0) << "vertex " << v;
    }
    ASSERT_TRUE(std::isfinite(r.distance[v])) << "vertex " << v;
    ASSERT_EQ(r.cell[v], 0) << "vertex " << v;
    largest = std::max(largest, r.distance[v]);
  }
  EXPECT_EQ(r.maxDistance, largest);
}

TEST(FastMarchingInvariants, SymmetryAndTriangleInequality) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  const double h = m.meanEdgeLength();
  const std::vector<int> pts = spreadVertices(m, 8);
  const int k = static_cast<int>(pts.size());
  std::vector<std::vector<double>> d(k, std::vector<double>(k));
  for (int i = 0; i < k; ++i) {
    FastMarchingResult r = run(m, {pts[i]});
    for (int j = 0; j < k; ++j) d[i][j] = r.distance[pts[j]];
  }
  double worstAsym = 0, worstTri = 0;
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b) {
      worstAsym = std::max(worstAsym, std::abs(d[a][b] - d[b][a]));
      EXPECT_LE(std::abs(d[a][b] - d[b][a]), 2.0 * h) << "d(" << pts[a] << ", " << pts[b] << ")";
      for (int c = 0; c < k; ++c) {
        worstTri = std::max(worstTri, d[a][c] - d[a][b] - d[b][c]);
        EXPECT_LE(d[a][c], d[a][b] + d[b][c] + 2.0 * h) << pts[a] << " " << pts[b] << " " << pts[c];
      }
    }
  std::cout << "[ fandisk  ] h " << h << ": worst |d(a,b) - d(b,a)| " << worstAsym / h
            << " h, worst triangle-inequality excess " << worstTri / h << " h\n";
}

TEST(FastMarchingInvariants, DistancesToBothSidesOfAnEdgeDifferByAtMostItsLength) {
  // |U(a) - U(b)| <= P |ab| along every edge (the Eikonal equation is 1-Lipschitz for P = 1);
  // fast marching satisfies it up to its error, O(h).
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  const double h = m.meanEdgeLength();
  FastMarchingResult r = run(m, {17});
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ASSERT_LE(std::abs(r.distance[a] - r.distance[b]), (m.positions[a] - m.positions[b]).norm() + 1e-9)
          << "edge " << a << "-" << b << " (h " << h << ")";
    }
}

// ---------------------------------------------------------------------------------------------
// Metric.

TEST(FastMarchingMetric, ConstantCostScalesEveryDistance) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  const std::vector<int> sources = {5, 3000, 6000};
  FastMarchingResult base = run(m, sources);
  for (double c : {1.0, 2.5, 0.3, 1000.0}) {
    SCOPED_TRACE("P = " + std::to_string(c));
    Expected<Metric> metric = Metric::fromCost(m, std::vector<double>(m.vertexCount(), c));
    ASSERT_TRUE(metric.hasValue()) << metric.status().message;
    FastMarchingResult r = run(m, sources, *metric);
    ASSERT_EQ(r.reachedCount(), m.vertexCount());
    int cellDiffs = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
      ASSERT_NEAR(r.distance[v], c * base.distance[v], 1e-9 * c * base.distance[v]) << "vertex " << v;
      cellDiffs += r.cell[v] != base.cell[v];
    }
    EXPECT_EQ(cellDiffs, 0);
    EXPECT_NEAR(r.maxDistance, c * base.maxDistance, 1e-9 * c * base.maxDistance);
  }
  // Speed F = 1 / c gives the same field as cost c.
  Expected<Metric> slow = Metric::fromSpeed(m, std::vector<double>(m.vertexCount(), 0.25));
  ASSERT_TRUE(slow.hasValue()) << slow.status().message;
  FastMarchingResult r = run(m, sources, *slow);
  for (int v = 0; v < m.vertexCount(); ++v)
    ASSERT_NEAR(r.distance[v], 4.0 * base.distance[v], 1e-9 * 4.0 * base.distance[v]) << "vertex " << v;
}

TEST(FastMarchingMetric, HyperbolicHalfPlaneMatchesClosedForm) {
  // P = 1 / y on the half-plane y > 0 is the Poincare metric, whose distance is known:
  // d(p, q) = acosh(1 + |p - q|^2 / (2 p.y q.y)). Grid on [0, 1] x [1, 2], source at the centre.
  std::vector<double> meanRel;
  for (int n : {20, 40, 80}) {
    TriMesh m = test::planeGrid(n, 1.0, 0.0);
    for (Vec3& p : m.positions) p.y() += 1.0;
    const double h = m.meanEdgeLength();
    std::vector<double> P(m.vertexCount());
    for (int v = 0; v < m.vertexCount(); ++v) P[v] = 1.0 / m.positions[v].y();
    Expected<Metric> metric = Metric::fromCost(m, P);
    ASSERT_TRUE(metric.hasValue()) << metric.status().message;
    const int s = gridCentre(n);
    const Vec3 q = m.positions[s];
    FastMarchingResult r = run(m, {s}, *metric);
    std::vector<double> exact(m.vertexCount());
    for (int v = 0; v < m.vertexCount(); ++v) {
      const Vec3& p = m.positions[v];
      exact[v] = std::acosh(1.0 + (p - q).squaredNorm() / (2.0 * p.y() * q.y()));
    }
    const ErrorStats e = compare(r.distance, exact);
    std::cout << "[ metric   ] P = 1/y, n " << n << ": mean relative error " << e.meanRelative << ", max abs error "
              << e.maxAbsolute << " (" << e.maxAbsolute / h << " h)\n";
    // P <= 1 here, so the weighted length of a mesh path is at most its length: h bounds the error.
    EXPECT_LE(e.maxAbsolute, h) << "n = " << n;
    meanRel.push_back(e.meanRelative);
  }
  // First order: the error about halves with h.
  EXPECT_LT(meanRel[1], 0.7 * meanRel[0]);
  EXPECT_LT(meanRel[2], 0.7 * meanRel[1]);
}

TEST(FastMarchingMetric, SlowRegionIsAvoided) {
  // A strip of high cost across a grid: distances beyond it grow; a field on the near side of
  // the strip does not change (its optimal paths do not cross it).
  const int n = 40;
  TriMesh m = test::planeGrid(n);
  std::vector<double> P(m.vertexCount(), 1.0);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (std::abs(m.positions[v].x() - 0.5) < 0.1) P[v] = 10.0;
  Expected<Metric> metric = Metric::fromCost(m, P);
  ASSERT_TRUE(metric.hasValue());
  const int s = (n / 2) * (n + 1) + 2;  // x = 0.05, middle row
  FastMarchingResult plain = run(m, {s}), weighted = run(m, {s}, *metric);
  // Any path to the far side crosses the band of P = 10 triangles, |x - 0.5| < 0.1 - h, at a cost
  // of 10 instead of 1 per unit length.
  const double h = 1.0 / n;
  const double extra = 9.0 * (0.2 - 2 * h);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const double x = m.positions[v].x();
    if (x < 0.3) {
      EXPECT_DOUBLE_EQ(weighted.distance[v], plain.distance[v]) << "vertex " << v;
    } else if (x > 0.6 + h) {
      EXPECT_GT(weighted.distance[v], plain.distance[v] + extra - 2 * h) << "vertex " << v;
    }
  }
}

TEST(FastMarchingMetric, FromSpeedRejectsBadSpeedsNamingTheVertex) {
  TriMesh m = test::icosphere(1);
  const int bad = 7;
  for (double s : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), kInf, -kInf, 1e-320}) {
    SCOPED_TRACE("speed " + std::to_string(s));
    std::vector<double> speed(m.vertexCount(), 1.0);
    speed[bad] = s;
    Expected<Metric> metric = Metric::fromSpeed(m, speed);
    ASSERT_FALSE(metric.hasValue());
    EXPECT_EQ(metric.status().code, StatusCode::InvalidInput);
    EXPECT_TRUE(names(metric.status().message, "vertex", bad)) << metric.status().message;
  }
  for (double c : {0.0, -2.0, std::numeric_limits<double>::quiet_NaN(), kInf}) {
    std::vector<double> cost(m.vertexCount(), 1.0);
    cost[bad] = c;
    Expected<Metric> metric = Metric::fromCost(m, cost);
    ASSERT_FALSE(metric.hasValue());
    EXPECT_EQ(metric.status().code, StatusCode::InvalidInput);
    EXPECT_TRUE(names(metric.status().message, "vertex", bad)) << metric.status().message;
  }
  Expected<Metric> shortField = Metric::fromSpeed(m, std::vector<double>(m.vertexCount() - 1, 1.0));
  ASSERT_FALSE(shortField.hasValue());
  EXPECT_EQ(shortField.status().code, StatusCode::InvalidInput);
  Expected<Metric> good = Metric::fromSpeed(m, std::vector<double>(m.vertexCount(), 4.0));
  ASSERT_TRUE(good.hasValue());
  for (double p : good->P) EXPECT_EQ(p, 0.25);
}

// ---------------------------------------------------------------------------------------------
// Several sources.

TEST(FastMarchingSources, CellsAreTheNearestSource) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  const double h = m.meanEdgeLength();
  const std::vector<int> sources = spreadVertices(m, 6);
  const int k = static_cast<int>(sources.size());
  FastMarchingResult multi = run(m, sources);
  std::vector<FastMarchingResult> single;
  for (int s : sources) single.push_back(run(m, {s}));

  for (int i = 0; i < k; ++i) {
    EXPECT_EQ(multi.distance[sources[i]], 0.0);
    EXPECT_EQ(multi.cell[sources[i]], i);
  }
  const double band = 2.0 * h;  // cells may differ where two sources are within the FM error
  int exact = 0, cellChecked = 0, cellWrong = 0, notArgmin = 0;
  double worstWrongCellGap = 0;
  double worstDiff = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    double best = kInf, second = kInf;
    int arg = -1;
    for (int i = 0; i < k; ++i) {
      const double d = single[i].distance[v];
      if (d < best) {
        second = best;
        best = d;
        arg = i;
      } else if (d < second) {
        second = d;
      }
    }
    ASSERT_GE(multi.cell[v], 0) << "vertex " << v;
    ASSERT_LT(multi.cell[v], k) << "vertex " << v;
    const double diff = std::abs(multi.distance[v] - best);
    worstDiff = std::max(worstDiff, diff);
    EXPECT_LE(diff, h) << "vertex " << v;
    if (diff <= 1e-12 * best) ++exact;
    if (multi.cell[v] != arg) {
      ++notArgmin;
      worstWrongCellGap = std::max(worstWrongCellGap, single[multi.cell[v]].distance[v] - best);
    }
    if (second - best > band) {
      ++cellChecked;
      if (multi.cell[v] != arg && ++cellWrong <= 5)
        ADD_FAILURE() << "vertex " << v << ": cell " << multi.cell[v] << ", nearest source " << arg << " (" << best
                      << " vs " << second << ")";
    }
  }
  std::cout << "[ sources  ] " << k << " sources on fandisk: " << exact << " / " << m.vertexCount()
            << " vertices equal to the min of single-source runs, worst difference " << worstDiff / h << " h; "
            << cellChecked << " cells checked outside the tie band; " << notArgmin
            << " cells not the argmin, worst gap " << worstWrongCellGap / h << " h\n";
  EXPECT_EQ(cellWrong, 0);
  EXPECT_GE(exact, 0.8 * m.vertexCount()) << "away from the region boundaries the runs must agree exactly";
  EXPECT_GE(cellChecked, 0.8 * m.vertexCount());
}

TEST(FastMarchingSources, DuplicateSourceKeepsItsFirstCell) {
  TriMesh m = test::planeGrid(10);
  FastMarchingResult r = run(m, {30, 5, 30});
  EXPECT_EQ(r.cell[30], 0);
  EXPECT_EQ(r.cell[5], 1);
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_NE(r.cell[v], 2) << "vertex " << v;
}

// ---------------------------------------------------------------------------------------------
// Distance limit, components.

TEST(FastMarchingLimit, StopsAtMaxDistanceLikeTheUnlimitedRun) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  for (const std::vector<int>& sources : {std::vector<int>{100}, std::vector<int>{100, 5000}}) {
    FastMarchingResult full = run(m, sources);
    for (double fraction : {0.0, 0.1, 0.45, 0.999}) {
      SCOPED_TRACE("sources " + std::to_string(sources.size()) + ", fraction " + std::to_string(fraction));
      FastMarchingParams params;
      params.maxDistance = fraction * full.maxDistance;
      FastMarchingResult r = run(m, sources, Metric::uniform(), params);
      int expectedReached = 0;
      for (int v = 0; v < m.vertexCount(); ++v) {
        const bool inside = full.distance[v] <= params.maxDistance;
        expectedReached += inside;
        if (inside) {
          ASSERT_EQ(r.distance[v], full.distance[v]) << "vertex " << v;
          ASSERT_EQ(r.cell[v], full.cell[v]) << "vertex " << v;
        } else {
          ASSERT_EQ(r.distance[v], kInf) << "vertex " << v;
          ASSERT_EQ(r.cell[v], -1) << "vertex " << v;
        }
      }
      EXPECT_EQ(r.reachedCount(), expectedReached);
      for (int v : r.acceptedOrder) ASSERT_LE(r.distance[v], params.maxDistance);
      EXPECT_LE(r.maxDistance, params.maxDistance);
      if (fraction == 0.0) {
        EXPECT_EQ(r.reachedCount(), static_cast<int>(sources.size()));
      }
      if (fraction == 0.45) {
        EXPECT_GT(r.reachedCount(), static_cast<int>(sources.size()));
        EXPECT_LT(r.reachedCount(), m.vertexCount());
      }
    }
  }
}

TEST(FastMarchingComponents, ASourceReachesOnlyItsComponent) {
  TriMesh m = test::loadRealMesh("knot2.off");
  ASSERT_GT(m.vertexCount(), 0);
  ASSERT_EQ(m.topology.components, 2);
  const std::vector<int>& comp = m.topology.componentOfVertex;
  for (int s : {0, m.vertexCount() - 1}) {
    FastMarchingResult r = run(m, {s});
    int inComponent = 0;
    for (int v = 0; v < m.vertexCount(); ++v) {
      if (comp[v] == comp[s]) {
        ++inComponent;
        ASSERT_TRUE(std::isfinite(r.distance[v])) << "vertex " << v;
        ASSERT_EQ(r.cell[v], 0);
      } else {
        ASSERT_EQ(r.distance[v], kInf) << "vertex " << v;
        ASSERT_EQ(r.cell[v], -1) << "vertex " << v;
      }
    }
    EXPECT_EQ(r.reachedCount(), inComponent);
    EXPECT_LT(inComponent, m.vertexCount());
    EXPECT_TRUE(std::isfinite(r.maxDistance));
  }
  // One source on each torus reaches everything, each torus the cell of its own source.
  int other = 0;
  while (comp[other] == comp[0]) ++other;
  FastMarchingResult both = run(m, {0, other});
  EXPECT_EQ(both.reachedCount(), m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) ASSERT_EQ(both.cell[v], comp[v] == comp[0] ? 0 : 1);
}

// ---------------------------------------------------------------------------------------------
// Bad input, engine reuse, cancellation.

TEST(FastMarchingBadInput, RejectsBadSourcesAndLimits) {
  TriMesh m = test::planeGrid(5);
  const int nv = m.vertexCount();
  {
    Expected<FastMarchingResult> r = fastMarching(m, Metric::uniform(), {});
    ASSERT_FALSE(r.hasValue());
    EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
    EXPECT_NE(r.status().message.find("source"), std::string::npos) << r.status().message;
  }
  for (int bad : {nv, -1, nv + 100}) {
    Expected<FastMarchingResult> r = fastMarching(m, Metric::uniform(), {0, bad});
    ASSERT_FALSE(r.hasValue());
    EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
    EXPECT_TRUE(names(r.status().message, "vertex", bad)) << r.status().message;
  }
  for (double limit : {std::numeric_limits<double>::quiet_NaN(), -1.0, -kInf}) {
    FastMarchingParams params;
    params.maxDistance = limit;
    Expected<FastMarchingResult> r = fastMarching(m, Metric::uniform(), {0}, params);
    ASSERT_FALSE(r.hasValue()) << "limit " << limit;
    EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  }
  {
    Metric wrongSize;
    wrongSize.P.assign(nv - 1, 1.0);
    Expected<FastMarchingResult> r = fastMarching(m, wrongSize, {0});
    ASSERT_FALSE(r.hasValue());
    EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  }
  {
    FastMarcher marcher(m, Metric::uniform());
    Status s = marcher.addSource(nv, 0);
    EXPECT_EQ(s.code, StatusCode::InvalidInput);
    EXPECT_TRUE(names(s.message, "vertex", nv)) << s.message;
  }
}

TEST(FastMarcherEngine, ResetThenRunEqualsAFreshMarcher) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  FastMarcher reused(m, Metric::uniform());
  // A first run that stops half-way leaves tentative values behind.
  ASSERT_TRUE(reused.addSource(10, 0).isOk());
  FastMarchingParams limited;
  limited.maxDistance = 0.3 * m.boundingBoxDiagonal();
  ASSERT_TRUE(reused.propagate(limited).isOk());
  ASSERT_GT(reused.acceptedOrder().size(), 1u);
  ASSERT_LT(reused.acceptedOrder().size(), static_cast<size_t>(m.vertexCount()));

  for (int round = 0; round < 2; ++round) {
    reused.reset();
    for (int v = 0; v < m.vertexCount(); ++v) {
      ASSERT_EQ(reused.distance()[v], kInf) << "after reset, vertex " << v;
      ASSERT_EQ(reused.cell()[v], -1) << "after reset, vertex " << v;
    }
    EXPECT_TRUE(reused.acceptedOrder().empty());
    const std::vector<int> sources = round == 0 ? std::vector<int>{2000, 6000} : std::vector<int>{10};
    for (size_t i = 0; i < sources.size(); ++i) ASSERT_TRUE(reused.addSource(sources[i], int(i)).isOk());
    ASSERT_TRUE(reused.propagate().isOk());

    FastMarcher fresh(m, Metric::uniform());
    for (size_t i = 0; i < sources.size(); ++i) ASSERT_TRUE(fresh.addSource(sources[i], int(i)).isOk());
    ASSERT_TRUE(fresh.propagate().isOk());
    EXPECT_EQ(reused.distance(), fresh.distance());
    EXPECT_EQ(reused.cell(), fresh.cell());
    EXPECT_EQ(reused.acceptedOrder(), fresh.acceptedOrder());
  }
  // The one-shot function gives the same field too.
  FastMarchingResult once = run(m, {10});
  EXPECT_EQ(reused.distance(), once.distance);
}

// An intrinsic triangulation gives the engine its edge lengths: the engine must read those and
// never the positions. A flat jittered grid (obtuse corners, so acute splits and their unfoldings
// are exercised) and a copy with the same faces but random positions, given the flat grid's
// lengths, yield the same fields up to rounding (the angles come from a dot product of positions
// in one, the law of cosines in the other): from a vertex, from a point inside a face (the
// unfolded seeding), uniform and with a varying metric. Any position read would show as an error
// of the order of the scrambled coordinates.
TEST(FastMarcherEngine, GivenLengthsAreTheOnlyGeometryRead) {
  const TriMesh flat = test::planeGrid(30, 1.0, 0.45, 7);
  std::vector<double> lengths(3 * flat.faceCount());
  for (int c = 0; c < 3 * flat.faceCount(); ++c)
    lengths[c] = (flat.positions[flat.vertex(TriMesh::next(c))] - flat.positions[flat.vertex(TriMesh::prev(c))]).norm();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
  std::vector<Vec3> scrambled(flat.vertexCount());
  for (Vec3& p : scrambled) p = Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
  Expected<TriMesh> crumpled = buildTriMesh(scrambled, flat.triangles);
  ASSERT_TRUE(crumpled);

  std::vector<double> cost(flat.vertexCount());
  for (int v = 0; v < flat.vertexCount(); ++v) cost[v] = 1.0 + flat.positions[v].x();
  Expected<Metric> varying = Metric::fromCost(flat, cost);
  ASSERT_TRUE(varying);
  int obtuse = 0;
  for (int c = 0; c < 3 * flat.faceCount(); ++c) {
    const double a = lengths[TriMesh::prev(c)], b = lengths[TriMesh::next(c)], opposite = lengths[c];
    obtuse += a * a + b * b < opposite * opposite;
  }
  ASSERT_GT(obtuse, 50) << "the grid must have obtuse corners";
  for (const Metric& metric : {Metric::uniform(), *varying}) {
    for (const SurfacePoint& source : {SurfacePoint::atVertex(465), SurfacePoint::inFace(700, Vec3(0.2, 0.3, 0.5))}) {
      FastMarcher fromPositions(flat, metric), fromLengths(*crumpled, lengths, metric);
      ASSERT_TRUE(fromPositions.addSource(source, 0).isOk());
      ASSERT_TRUE(fromLengths.addSource(source, 0).isOk());
      ASSERT_TRUE(fromPositions.propagate().isOk());
      ASSERT_TRUE(fromLengths.propagate().isOk());
      ASSERT_EQ(static_cast<int>(fromLengths.acceptedOrder().size()), flat.vertexCount());
      double worst = 0.0;
      for (int v = 0; v < flat.vertexCount(); ++v)
        worst = std::max(worst, std::abs(fromPositions.distance()[v] - fromLengths.distance()[v]));
      EXPECT_LT(worst, 1e-12) << "source in face " << source.face;
    }
  }
}

TEST(FastMarcherEngine, ProgressCanCancel) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 4096) << "the marcher reports every 4096 accepted vertices";
  int calls = 0;
  Expected<FastMarchingResult> r =
      fastMarching(m, Metric::uniform(), {0}, {}, Progress([&](int, const char*) { return ++calls, false; }));
  ASSERT_FALSE(r.hasValue());
  EXPECT_EQ(r.status().code, StatusCode::Cancelled);
  EXPECT_EQ(calls, 1);

  std::vector<int> percents;
  Expected<FastMarchingResult> ok = fastMarching(
      m, Metric::uniform(), {0}, {}, Progress([&](int p, const char*) { return percents.push_back(p), true; }));
  ASSERT_TRUE(ok.hasValue());
  EXPECT_FALSE(percents.empty());
  EXPECT_TRUE(std::is_sorted(percents.begin(), percents.end()));
  EXPECT_EQ(ok->distance, run(m, {0}).distance);
}

}  // namespace
}  // namespace gr
