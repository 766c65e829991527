// Fast marching on shapes with known geodesics: cylinder (unrolled plane), UV sphere (great
// circles), and a plane with two speeds (Snell's law of refraction).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/base/math.h"
#include "core/geodesic/fast_marching.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

struct MeanMax {
  double meanRelative = 0.0, maxAbs = 0.0;
};

/// Mean relative error over vertices farther than `minDistance`, and the largest absolute error.
template <class Exact>
MeanMax compare(const TriMesh& m, const std::vector<double>& d, Exact exact, double minDistance) {
  MeanMax r;
  int n = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const double e = exact(v);
    r.maxAbs = std::max(r.maxAbs, std::abs(d[v] - e));
    if (e >= minDistance) {
      r.meanRelative += std::abs(d[v] - e) / e;
      ++n;
    }
  }
  r.meanRelative /= std::max(n, 1);
  return r;
}

// A cylinder is developable: the geodesic distance is the Euclidean distance in the unrolled
// strip, sqrt((R dtheta)^2 + dz^2) on the smooth cylinder.
TEST(FastMarchingShapes, CylinderMatchesUnrolledDistance) {
  const double R = 1.0, H = 3.0;
  double previous = 1.0;
  for (int n : {32, 64, 128}) {
    const TriMesh m = test::cylinder(n, n / 2, R, H);
    const int source = (n / 4) * n;  // theta = 0, z = H / 2
    const auto r = fastMarching(m, Metric::uniform(), {source});
    ASSERT_TRUE(r);
    const Vec3 s = m.positions[source];
    const auto exact = [&](int v) {
      const Vec3& p = m.positions[v];
      double dtheta = std::abs(std::atan2(p.y(), p.x()) - std::atan2(s.y(), s.x()));
      dtheta = std::min(dtheta, 2 * kPi - dtheta);
      return std::hypot(R * dtheta, p.z() - s.z());
    };
    const MeanMax e = compare(m, r->distance, exact, 0.05 * kPi * R);
    std::printf("cylinder %3d x %3d: mean relative error %.4f %%, max abs %.4f h\n", n, n / 2, 100 * e.meanRelative,
                e.maxAbs / m.meanEdgeLength());
    EXPECT_LT(e.meanRelative, previous) << "no convergence under refinement";
    previous = e.meanRelative;
    if (n >= 64) {
      EXPECT_LT(e.meanRelative, 0.01);
    }
  }
}

// UV sphere: thin triangles at the poles. Great-circle distance R * acos(p.s / R^2).
TEST(FastMarchingShapes, UvSphereMatchesGreatCircles) {
  double previous = 1.0;
  for (int n : {16, 32, 64}) {
    const TriMesh m = test::uvSphere(n, 2 * n);
    const int source = 1 + (n / 2 - 1) * 2 * n;  // on the equator
    const auto r = fastMarching(m, Metric::uniform(), {source});
    ASSERT_TRUE(r);
    const Vec3 s = m.positions[source];
    const auto exact = [&](int v) { return std::acos(std::clamp(m.positions[v].dot(s), -1.0, 1.0)); };
    const MeanMax e = compare(m, r->distance, exact, 0.05 * kPi);
    std::printf("UV sphere %3d x %3d: mean relative error %.4f %%, max abs %.4f h\n", n, 2 * n, 100 * e.meanRelative,
                e.maxAbs / m.meanEdgeLength());
    EXPECT_LT(e.meanRelative, previous);
    previous = e.meanRelative;
    if (n >= 32) {
      EXPECT_LT(e.meanRelative, 0.01);
    }
  }
}

/// Travel time from s to q (x > 1) across the line x = 1 between speeds 1 (x < 1) and 1/eta:
/// min over the crossing point (1, y) of |s - (1, y)| + eta |(1, y) - q| (Fermat / Snell).
double snellTime(const Vec3& s, const Vec3& q, double eta) {
  auto cost = [&](double y) { return std::hypot(1.0 - s.x(), y - s.y()) + eta * std::hypot(q.x() - 1.0, q.y() - y); };
  double lo = std::min(s.y(), q.y()), hi = std::max(s.y(), q.y());  // convex: golden section
  for (int i = 0; i < 200; ++i) {
    const double a = lo + (hi - lo) * 0.382, b = lo + (hi - lo) * 0.618;
    if (cost(a) < cost(b)) {
      hi = b;
    } else {
      lo = a;
    }
  }
  return cost(0.5 * (lo + hi));
}

// Plane [0,2] x [0,1], metric P = 1 for x < 1 and P = eta for x > 1: arrival times at probe
// points beyond the interface follow Snell's law; the error falls under refinement.
TEST(FastMarchingShapes, TwoSpeedPlaneRefractsByFermatsPrinciple) {
  const double eta = 1.5;
  double previous = 1.0;
  for (int n : {20, 40, 80}) {
    const TriMesh base = test::planeGrid(2 * n, 2.0);  // spacing 1/n
    std::vector<double> P(base.vertexCount());
    for (int v = 0; v < base.vertexCount(); ++v) {
      const double x = base.positions[v].x();
      P[v] = std::abs(x - 1.0) < 1e-9 ? 0.5 * (1.0 + eta) : (x < 1.0 ? 1.0 : eta);
    }
    const auto metric = Metric::fromCost(base, P);
    ASSERT_TRUE(metric);
    const auto at = [&](double x, double y) {  // the grid vertex at (x, y)
      return int(std::lround(y * n)) * (2 * n + 1) + int(std::lround(x * n));
    };
    const int source = at(0.3, 0.2);
    const auto r = fastMarching(base, *metric, {source});
    ASSERT_TRUE(r);
    double worst = 0.0;
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{{1.5, 0.9}, {1.8, 0.5}, {1.3, 0.8}, {1.9, 0.2}}) {
      const int q = at(x, y);
      const double expected = snellTime(base.positions[source], base.positions[q], eta);
      worst = std::max(worst, std::abs(r->distance[q] - expected) / expected);
    }
    std::printf("two speeds (eta %.1f), h = 1/%d: largest relative error at the probes %.4f %%\n", eta, n, 100 * worst);
    EXPECT_LT(worst, previous);
    previous = worst;
    EXPECT_LT(worst, 0.02);
  }
}

// Strongly jittered grids (angles above 150 degrees, up to nearly 180): the acceptance order
// is monotone and the mean relative error against the Euclidean distance is below 1% at every
// size, 100 x 100 included. The observed order is printed, not asserted: the update is exact on
// planes, so the error comes from rare near-degenerate configurations and has no clean order
// (measured: jitter 0.35 falls 0.12% -> 0.011%, order 1.1; jitter 0.4 and 0.45 stay near 0.1-0.2%).
TEST(FastMarchingShapes, StronglyJitteredGrids) {
  const std::vector<int> sizes = {25, 50, 100, 200};
  for (double jitter : {0.35, 0.4, 0.45}) {
    std::vector<double> errors;
    for (int n : sizes) {
      double sum = 0.0, biggest = 0.0;
      for (unsigned seed : {11u, 12u, 13u}) {
        const TriMesh m = test::planeGrid(n, 1.0, jitter, seed);
        biggest = std::max(biggest, test::recountAngles(m).largestDegrees);
        const int source = (n / 2) * (n + 1) + n / 2;
        const auto r = fastMarching(m, Metric::uniform(), {source});
        ASSERT_TRUE(r);
        for (size_t i = 1; i < r->acceptedOrder.size(); ++i)
          ASSERT_GE(r->distance[r->acceptedOrder[i]], r->distance[r->acceptedOrder[i - 1]]);
        const Vec3 s = m.positions[source];
        sum += compare(
                   m, r->distance, [&](int v) { return (m.positions[v] - s).norm(); }, 0.05)
                   .meanRelative;
      }
      errors.push_back(sum / 3.0);
      std::printf("jitter %.2f, n %3d: largest angle %.1f deg, mean relative error over 3 seeds %.5f %%\n", jitter, n,
                  biggest, 100 * errors.back());
      EXPECT_GT(biggest, 150.0);
      EXPECT_LT(errors.back(), 0.01);
    }
    std::printf("jitter %.2f: observed order n 25 -> 200: %.2f\n", jitter,
                std::log(errors.front() / errors.back()) / std::log(double(sizes.back()) / sizes.front()));
  }
}

}  // namespace
}  // namespace gr
