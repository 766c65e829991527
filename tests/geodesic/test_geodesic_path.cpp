// Geodesic paths by descent on the distance field (paper Fig. 2). Oracles: straight segments on
// planes, great circles on spheres; invariants: U decreases along the path, which ends at a source.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_path.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

void expectDescendsToASource(const GeodesicPath& path, const std::vector<double>& U) {
  ASSERT_GE(path.points.size(), 2u);
  ASSERT_GE(path.endVertex, 0);
  EXPECT_EQ(U[path.endVertex], 0.0);
  for (size_t i = 1; i < path.values.size(); ++i) ASSERT_LT(path.values[i], path.values[i - 1]) << "point " << i;
}

TEST(GeodesicPath, StraightOnPlanes) {
  for (double jitter : {0.0, 0.3}) {
    const TriMesh m = test::planeGrid(50, 1.0, jitter, 3);
    const double h = m.meanEdgeLength();
    const int source = 5 * 51 + 5;
    const auto r = fastMarching(m, Metric::uniform(), {source});
    ASSERT_TRUE(r);
    for (int start : {45 * 51 + 40, 10 * 51 + 48, 48 * 51 + 6, 30 * 51 + 30}) {
      const auto path = geodesicPath(m, r->distance, SurfacePoint::atVertex(start));
      ASSERT_TRUE(path) << path.status().message;
      expectDescendsToASource(*path, r->distance);
      EXPECT_EQ(path->endVertex, source);
      double deviation = 0.0;
      for (const Vec3& p : path->points)
        deviation = std::max(deviation, distanceToSegment(p, m.positions[start], m.positions[source]));
      const double straight = (m.positions[start] - m.positions[source]).norm();
      std::printf("plane jitter %.1f, start %4d: %zu points, deviation %.3f h, length / straight line %.5f\n", jitter,
                  start, path->points.size(), deviation / h, path->length / straight);
      EXPECT_LT(deviation, 0.5 * h);
      EXPECT_LT(path->length, 1.01 * straight);
    }
  }
}

TEST(GeodesicPath, GreatCirclesOnASphere) {
  const TriMesh m = test::icosphere(5);
  const double h = m.meanEdgeLength();
  const auto r = fastMarching(m, Metric::uniform(), {0});
  ASSERT_TRUE(r);
  const Vec3 s = m.positions[0];
  for (int start : {100, 2000, 7000, 9000}) {
    const auto path = geodesicPath(m, r->distance, SurfacePoint::atVertex(start));
    ASSERT_TRUE(path);
    expectDescendsToASource(*path, r->distance);
    const Vec3 normal = s.cross(m.positions[start]).normalized();  // plane of the great circle
    double offPlane = 0.0;
    for (const Vec3& p : path->points) offPlane = std::max(offPlane, std::abs(normal.dot(p)));
    const double arc = std::acos(std::clamp(s.dot(m.positions[start]), -1.0, 1.0));
    std::printf("sphere start %4d: arc %.3f, path length %.4f (%.3f %%), off the great circle %.3f h\n", start, arc,
                path->length, 100 * (path->length / arc - 1), offPlane / h);
    EXPECT_LT(offPlane, 1.0 * h);
    EXPECT_NEAR(path->length, arc, 0.02 * arc);
  }
}

TEST(GeodesicPath, StartsInsideAFaceAndOnRealMeshes) {
  const TriMesh m = test::loadRealMesh("bunny00.off");
  const auto r = fastMarching(m, Metric::uniform(), {0, 20000});
  ASSERT_TRUE(r);
  for (int f : {17, 5000, 40000, 70000}) {
    const auto path = geodesicPath(m, r->distance, SurfacePoint::inFace(f, Vec3(0.3, 0.3, 0.4)));
    ASSERT_TRUE(path) << path.status().message;
    expectDescendsToASource(*path, r->distance);
    // The path is no shorter than the distance it descends, and not much longer.
    EXPECT_GE(path->length, path->values.front() * 0.98);
    EXPECT_LE(path->length, path->values.front() * 1.05);
  }
}

TEST(GeodesicPath, RejectsBadStarts) {
  const TriMesh m = test::loadRealMesh("knot2.off");  // two tori: the second is not reached
  const auto r = fastMarching(m, Metric::uniform(), {0});
  int other = 0;
  while (m.topology.componentOfVertex[other] == m.topology.componentOfVertex[0]) ++other;
  EXPECT_EQ(geodesicPath(m, r->distance, SurfacePoint::atVertex(other)).status().code, StatusCode::InvalidInput);
  EXPECT_EQ(geodesicPath(m, r->distance, SurfacePoint::atVertex(m.vertexCount())).status().code,
            StatusCode::InvalidInput);
  EXPECT_EQ(geodesicPath(m, {1.0, 2.0}, SurfacePoint::atVertex(0)).status().code, StatusCode::InvalidInput);
}

}  // namespace
}  // namespace gr
