// Geodesic LLE flattening (core/flatten/geodesic_lle.h). Oracles: Sander et al.'s L2 stretch
// (2001), computed here from the 3D and UV triangles, which is 1 exactly for an isometry up to a
// global scale; the UV orientation of every face (signed areas recomputed here); patches whose
// flattening is known (a plane, a cylinder cut open: developable) and a hemisphere (not).
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/flatten/arap_relaxation.h"
#include "core/flatten/geodesic_lle.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

constexpr double kPiValue = 3.14159265358979323846;

/// Sander's L2 stretch of the map UV -> 3D over the whole mesh, after scaling the UVs so that
/// their total area is the 3D area.
double l2Stretch(const TriMesh& m, const std::vector<Vec2>& uv) {
  double area3 = 0.0, area2 = 0.0;
  for (const Tri& t : m.triangles) {
    area3 += 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
    const Vec2 a = uv[t[1]] - uv[t[0]], b = uv[t[2]] - uv[t[0]];
    area2 += 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
  }
  const double scale = std::sqrt(area3 / area2);
  double sum = 0.0;
  for (const Tri& t : m.triangles) {
    const Vec3 &q1 = m.positions[t[0]], &q2 = m.positions[t[1]], &q3 = m.positions[t[2]];
    const Vec2 p1 = scale * uv[t[0]], p2 = scale * uv[t[1]], p3 = scale * uv[t[2]];
    const double a2 = ((p2.x() - p1.x()) * (p3.y() - p1.y()) - (p3.x() - p1.x()) * (p2.y() - p1.y()));
    if (a2 == 0.0) return INFINITY;
    const Vec3 ss = (q1 * (p2.y() - p3.y()) + q2 * (p3.y() - p1.y()) + q3 * (p1.y() - p2.y())) / a2;
    const Vec3 st = (q1 * (p3.x() - p2.x()) + q2 * (p1.x() - p3.x()) + q3 * (p2.x() - p1.x())) / a2;
    const double area = 0.5 * (q2 - q1).cross(q3 - q1).norm();
    sum += area * 0.5 * (ss.squaredNorm() + st.squaredNorm());
  }
  return std::sqrt(sum / area3);
}

/// Faces whose UV orientation differs from the majority's, or whose UV area is 0.
int flippedFaces(const TriMesh& m, const std::vector<Vec2>& uv) {
  int positive = 0, negative = 0, zero = 0;
  for (const Tri& t : m.triangles) {
    const Vec2 a = uv[t[1]] - uv[t[0]], b = uv[t[2]] - uv[t[0]];
    const double cross = a.x() * b.y() - a.y() * b.x();
    positive += cross > 0.0;
    negative += cross < 0.0;
    zero += cross == 0.0;
  }
  return std::min(positive, negative) + zero;
}

/// A grid of (n + 1) x (n + 1) vertices over the parameter square, mapped by `at`.
template <class F>
TriMesh gridSurface(int n, F at) {
  TriMesh flat = test::planeGrid(n);
  for (Vec3& p : flat.positions) p = at(p.x(), p.y());
  return buildTriMesh(flat.positions, flat.triangles).value();
}

TEST(GeodesicLle, PlaneIsFlattenedIsometrically) {
  const TriMesh m = test::planeGrid(70, 2.0, 0.2, 3);  // 5,041 vertices, jittered
  const Expected<LleFlatteningResult> r = flattenGeodesicLle(m);
  ASSERT_TRUE(r) << r.status().message;
  const double stretch = l2Stretch(m, r->uv);
  std::printf("plane: stretch %.4f, folded before repair %d, Tutte %d\n", stretch, r->foldedBeforeRepair, r->tutte);
  EXPECT_FALSE(r->tutte);
  EXPECT_EQ(flippedFaces(m, r->uv), 0);
  EXPECT_LE(stretch, 1.01);
}

TEST(GeodesicLle, CylinderCutOpenIsFlattenedIsometrically) {
  const TriMesh m = gridSurface(60, [](double s, double t) {
    const double theta = 4.0 * kPiValue / 3.0 * s;  // 240 degrees of a unit cylinder, height 2
    return Vec3(std::cos(theta), std::sin(theta), 2.0 * t);
  });
  const Expected<LleFlatteningResult> r = flattenGeodesicLle(m);
  ASSERT_TRUE(r) << r.status().message;
  const double stretch = l2Stretch(m, r->uv);
  std::printf("cylinder: stretch %.4f, folded before repair %d, Tutte %d\n", stretch, r->foldedBeforeRepair, r->tutte);
  EXPECT_EQ(flippedFaces(m, r->uv), 0);
  EXPECT_LE(stretch, 1.01);
}

TEST(GeodesicLle, SphericalCapNeedsNoTutte) {
  // A cap of the unit sphere, 60 degrees around the pole, by a square grid pressed onto it (thin
  // triangles at the square's corners): not developable, but close enough for LLE and the local
  // untangling (no Tutte), with about the stretch a cap of this size forces. 2,601 and 10,000
  // vertices.
  for (const int n : {50, 99}) {
    SCOPED_TRACE(n);
    const TriMesh m = gridSurface(n, [](double s, double t) {
      const double x = 2.0 * s - 1.0, y = 2.0 * t - 1.0;  // the square, onto the cap by the angle
      const double r = std::sqrt(x * x + y * y) / std::sqrt(2.0), theta = std::atan2(y, x);
      const double phi = r * kPiValue / 3.0;
      return Vec3(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi));
    });
    const Expected<LleFlatteningResult> r = flattenGeodesicLle(m);
    ASSERT_TRUE(r) << r.status().message;
    const double stretch = l2Stretch(m, r->uv);
    std::printf("spherical cap, %d vertices: stretch %.4f, folded before repair %d, Tutte %d\n", m.vertexCount(),
                stretch, r->foldedBeforeRepair, r->tutte);
    EXPECT_FALSE(r->tutte);
    EXPECT_EQ(flippedFaces(m, r->uv), 0);
    // 2,601 and 10,000 vertices: 1.0014 (the stress majorisation of the bases, the smoothed
    // extension and the ARAP relaxation; without ARAP 1.006 and 1.012, without any of them 1.039
    // and 1.251, 202 folds untangled over rings of vertices).
    EXPECT_LE(stretch, 1.02);
  }
}

// A base one edge inside the border makes the border vertices beside it extrapolate (they see it
// an edge away and the other bases far on one side): on this cap, with its first bases chosen in 3D,
// 4 faces folded before the bases were moved onto the border. No base is left one edge inside, and
// the extension folds nothing, whatever the seed.
TEST(GeodesicLle, NoBaseOneEdgeInsideTheBorderAndNoFoldOnTheCap) {
  const TriMesh m = gridSurface(99, [](double s, double t) {
    const double x = 2.0 * s - 1.0, y = 2.0 * t - 1.0;
    const double r = std::sqrt(x * x + y * y) / std::sqrt(2.0), theta = std::atan2(y, x);
    const double phi = r * kPiValue / 3.0;
    return Vec3(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi));
  });
  std::vector<char> border(m.vertexCount(), 0);
  for (int c = 0; c < 3 * m.faceCount(); ++c)
    if (m.oppositeCorner[c] < 0) border[m.vertex(TriMesh::next(c))] = border[m.vertex(TriMesh::prev(c))] = 1;
  for (unsigned seed = 0; seed < 4; ++seed) {
    SCOPED_TRACE(seed);
    LleFlatteningParams params;
    params.seed = seed;
    const Expected<LleFlatteningResult> r = flattenGeodesicLle(m, params);
    ASSERT_TRUE(r) << r.status().message;
    EXPECT_EQ(r->foldedBeforeRepair, 0);
    std::vector<char> isBase(m.vertexCount(), 0);
    for (int b : r->basePoints) isBase[b] = 1;
    for (int b : r->basePoints) {
      if (border[b]) continue;
      for (const Tri& t : m.triangles) {
        if (t[0] != b && t[1] != b && t[2] != b) continue;
        for (int w : t) EXPECT_FALSE(border[w] && !isBase[w]) << "base " << b << " is one edge inside the border";
      }
    }
  }
}

TEST(GeodesicLle, SphereBandCutOpenHasNoFold) {
  const TriMesh m = gridSurface(50, [](double s, double t) {
    const double theta = 2.0 * kPiValue * s, phi = 0.5 * kPiValue * (0.05 + 0.9 * t);  // a band below the pole
    return Vec3(std::cos(theta) * std::cos(phi), std::sin(theta) * std::cos(phi), std::sin(phi));
  });
  const Expected<LleFlatteningResult> r = flattenGeodesicLle(m);
  ASSERT_TRUE(r) << r.status().message;
  std::printf("sphere band cut open: stretch %.4f, folded before repair %d, Tutte %d\n", l2Stretch(m, r->uv),
              r->foldedBeforeRepair, r->tutte);
  EXPECT_EQ(flippedFaces(m, r->uv), 0);
}

TEST(GeodesicLle, CircleBoundaryIsTutteAndHasNoFold) {
  const TriMesh m = test::planeGrid(30, 1.0, 0.3, 5);
  LleFlatteningParams p;
  p.boundary = LleBoundary::Circle;
  const Expected<LleFlatteningResult> r = flattenGeodesicLle(m, p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_TRUE(r->tutte);
  EXPECT_EQ(flippedFaces(m, r->uv), 0);
}

/// Pairs of boundary edges without a shared vertex that cross or touch (brute force: a simple
/// boundary loop has none).
int crossingBoundaryEdges(const TriMesh& m, const std::vector<Vec2>& uv) {
  std::vector<std::array<int, 2>> edges;
  for (int c = 0; c < 3 * m.faceCount(); ++c)
    if (m.oppositeCorner[c] < 0) edges.push_back({m.vertex(TriMesh::next(c)), m.vertex(TriMesh::prev(c))});
  const auto side = [](const Vec2& a, const Vec2& b, const Vec2& c) {
    const double d = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
    return (d > 0) - (d < 0);
  };
  int crossings = 0;
  for (size_t i = 0; i < edges.size(); ++i)
    for (size_t j = i + 1; j < edges.size(); ++j) {
      const auto [a, b] = edges[i];
      const auto [c, d] = edges[j];
      if (a == c || a == d || b == c || b == d) continue;
      crossings += side(uv[a], uv[b], uv[c]) * side(uv[a], uv[b], uv[d]) <= 0 &&
                   side(uv[c], uv[d], uv[a]) * side(uv[c], uv[d], uv[b]) <= 0;
    }
  return crossings;
}

// ARAP from Tutte's circle: a cylinder cut open (developable) comes back to its development, and a
// cap of 150 degrees (far from developable; unconstrained ARAP lets such caps' rims run over
// themselves) stays one-to-one, with less stretch than the circle and a lower energy.
TEST(ArapRelaxation, FromTuttesCircleToTheDevelopmentOneToOne) {
  const TriMesh cylinder = gridSurface(40, [](double s, double t) {
    const double theta = 4.0 * kPiValue / 3.0 * s;
    return Vec3(std::cos(theta), std::sin(theta), 2.0 * t);
  });
  const TriMesh cap = gridSurface(40, [](double s, double t) {
    const double x = 2.0 * s - 1.0, y = 2.0 * t - 1.0;
    const double r = std::sqrt(x * x + y * y) / std::sqrt(2.0), theta = std::atan2(y, x);
    const double phi = r * kPiValue * 150.0 / 180.0;
    return Vec3(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi));
  });
  for (const TriMesh* m : {&cylinder, &cap}) {
    LleFlatteningParams p;
    p.boundary = LleBoundary::Circle;
    const Expected<LleFlatteningResult> circle = flattenGeodesicLle(*m, p);
    ASSERT_TRUE(circle) << circle.status().message;
    std::vector<Vec2> uv = circle->uv;
    ArapParams arap;
    arap.rounds = 40;
    const Expected<ArapResult> r = relaxAsRigidAsPossible(*m, uv, arap);
    ASSERT_TRUE(r) << r.status().message;
    const double before = l2Stretch(*m, circle->uv), after = l2Stretch(*m, uv);
    std::printf("%s: circle stretch %.4f -> ARAP %.4f in %d rounds, energy %.4g -> %.4g\n",
                m == &cylinder ? "cylinder" : "150-degree cap", before, after, r->rounds, r->energyBefore,
                r->energyAfter);
    EXPECT_GT(r->rounds, 0);
    EXPECT_LT(r->energyAfter, r->energyBefore);
    EXPECT_LT(after, before);
    EXPECT_EQ(flippedFaces(*m, uv), 0);
    EXPECT_EQ(crossingBoundaryEdges(*m, uv), 0);
    if (m == &cylinder) {
      EXPECT_LE(after, 1.01);
    }
  }
}

TEST(ArapRelaxation, RefusesAFoldedMapAndLeavesItAlone) {
  const TriMesh m = test::planeGrid(10);
  std::vector<Vec2> uv(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) uv[v] = Vec2(m.positions[v].x(), m.positions[v].y());
  std::swap(uv[12], uv[13]);  // two neighbours exchanged: their faces turn over
  const std::vector<Vec2> given = uv;
  const Expected<ArapResult> r = relaxAsRigidAsPossible(m, uv);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(uv, given);
  std::vector<Vec2> few(3, Vec2::Zero());
  EXPECT_EQ(relaxAsRigidAsPossible(m, few).status().code, StatusCode::InvalidInput);
}

LleFlatteningParams params(int basePoints, int neighbours) {
  LleFlatteningParams p;
  p.basePoints = basePoints;
  p.neighbours = neighbours;
  return p;
}

TEST(GeodesicLle, RefusesWhatIsNotADiskAndBadCounts) {
  const auto refused = [](const TriMesh& m, LleFlatteningParams p) {
    const Expected<LleFlatteningResult> r = flattenGeodesicLle(m, p);
    EXPECT_FALSE(r);
    if (!r) std::printf("refused: %s\n", r.status().message.c_str());
    return !r && (r.status().code == StatusCode::InvalidInput || r.status().code == StatusCode::NonManifold);
  };
  EXPECT_TRUE(refused(test::icosphere(2), {}));     // closed: no boundary loop
  EXPECT_TRUE(refused(test::cylinder(16, 4), {}));  // two boundary loops
  {                                                 // a planar rectangle with a square hole cut out
    const TriMesh full = test::planeGrid(20);
    std::vector<Tri> kept;
    for (int f = 0; f < full.faceCount(); ++f) {
      const Vec3 c = (full.positions[full.triangles[f][0]] + full.positions[full.triangles[f][1]] +
                      full.positions[full.triangles[f][2]]) /
                     3.0;
      if (std::abs(c.x() - 0.5) > 0.15 || std::abs(c.y() - 0.5) > 0.15) kept.push_back(full.triangles[f]);
    }
    EXPECT_TRUE(refused(*buildTriMesh(full.positions, kept), {}));
  }
  const TriMesh grid = test::planeGrid(10);    // 121 vertices
  EXPECT_TRUE(refused(grid, params(200, 8)));  // B > V
  EXPECT_TRUE(refused(grid, params(20, 2)));   // K < 3
  EXPECT_TRUE(refused(grid, params(20, 20)));  // K >= B
  TriMesh nan = grid;
  nan.positions[5].x() = NAN;
  EXPECT_TRUE(refused(nan, {}));
}

}  // namespace
}  // namespace gr
