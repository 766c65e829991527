// Input vertices located in a base triangulation by geodesic barycentric coordinates. Oracle: on a
// plane the geodesic distances are the straight ones, so each vertex's triangle is the one that
// holds it (point in triangle) and its weights are its planar barycentric coordinates; fast
// marching's error is the tolerance.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>

#include "core/param/base_coordinates.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// The base: the grid points (10 i, 10 j) of a 40 x 40 grid, each square split along a diagonal.
struct PlaneBase {
  std::vector<Tri> triangles;
  std::vector<int> vertex;
};

PlaneBase planeBase(int n, int step) {
  PlaneBase b;
  const int m = n / step;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) b.vertex.push_back(j * step * (n + 1) + i * step);
  const auto id = [m](int i, int j) { return j * (m + 1) + i; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      b.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      b.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return b;
}

Vec3 planarBarycentric(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const double whole = (b - a).cross(c - a).z();
  return Vec3((b - x).cross(c - x).z() / whole, (c - x).cross(a - x).z() / whole, (a - x).cross(b - x).z() / whole);
}

class BaseCoordinatesOnAPlane : public ::testing::TestWithParam<double> {};

// A regular grid (its fronts exact: straight lines in the unfoldings) and a jittered one.
TEST_P(BaseCoordinatesOnAPlane, EachVertexInTheTriangleThatHoldsIt) {
  const int n = 40, step = 10;
  const TriMesh plane = test::planeGrid(n, 1.0, GetParam(), 3);
  const PlaneBase base = planeBase(n, step);
  const Expected<BaseCoordinatesResult> r = baseCoordinates(plane, base.triangles, base.vertex);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->unassigned, 0);
  const double h = 1.0 / n;
  int inside = 0, right = 0;
  double worst = 0.0;
  for (int v = 0; v < plane.vertexCount(); ++v) {
    ASSERT_GE(r->triangle[v], 0) << v;
    EXPECT_NEAR(r->weights[v].sum(), 1.0, 1e-12);
    EXPECT_GE(r->weights[v].minCoeff(), 0.0);
    // The triangle that holds v, by the planar coordinates, away from the base edges by 1.5 h.
    for (size_t t = 0; t < base.triangles.size(); ++t) {
      const Tri& tri = base.triangles[t];
      const Vec3 &a = plane.positions[base.vertex[tri[0]]], &b = plane.positions[base.vertex[tri[1]]],
                 &c = plane.positions[base.vertex[tri[2]]];
      const Vec3 exact = planarBarycentric(plane.positions[v], a, b, c);
      // Distance to the edge opposite corner k: its coordinate times the height over that edge.
      const double twiceArea = std::abs((b - a).cross(c - a).z());
      const Vec3 height(twiceArea / (c - b).norm(), twiceArea / (a - c).norm(), twiceArea / (b - a).norm());
      if (exact.cwiseProduct(height).minCoeff() < 1.5 * h) continue;
      ++inside;
      right += r->triangle[v] == static_cast<int>(t);
      if (r->triangle[v] == static_cast<int>(t)) worst = std::max(worst, (r->weights[v] - exact).cwiseAbs().maxCoeff());
    }
  }
  std::printf(
      "plane, jitter %.1f: %d of %d vertices away from the base edges in the right triangle, weights within %.4f\n",
      GetParam(), right, inside, worst);
  EXPECT_GT(inside, 300);
  EXPECT_EQ(right, inside);
  EXPECT_LT(worst, 0.005);  // measured 1e-4 on the jittered grid, 0 on the regular one
  // The base edges' lengths: the grid's steps and diagonals.
  for (size_t t = 0; t < base.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Tri& tri = base.triangles[t];
      const double straight =
          (plane.positions[base.vertex[tri[(k + 1) % 3]]] - plane.positions[base.vertex[tri[(k + 2) % 3]]]).norm();
      EXPECT_NEAR(r->edgeLength[3 * t + k], straight, 0.01 * straight) << t << " " << k;
    }
}

INSTANTIATE_TEST_SUITE_P(Jitter, BaseCoordinatesOnAPlane, ::testing::Values(0.0, 0.2));

TEST(BaseCoordinates, RefusesABadBase) {
  const TriMesh plane = test::planeGrid(4);
  EXPECT_EQ(baseCoordinates(plane, {}, {0, 1, 2}).status().code, StatusCode::InvalidInput);
  EXPECT_EQ(baseCoordinates(plane, {{0, 1, 2}}, {0, 4, 4}).status().code, StatusCode::InvalidInput);
  EXPECT_EQ(baseCoordinates(plane, {{0, 1, 2}}, {0, 4, 99}).status().code, StatusCode::InvalidInput);
  EXPECT_EQ(baseCoordinates(plane, {{0, 1, 3}}, {0, 4, 24}).status().code, StatusCode::InvalidInput);
}

}  // namespace
}  // namespace gr
