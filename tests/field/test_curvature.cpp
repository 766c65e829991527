// Normal-cycle curvature: analytic shapes (sphere 2/R, cylinder 1/R, torus with its saddles,
// plane 0, a hinge computed by hand), sharp edges of a real mesh found independently from face
// normals, a brute-force rewrite of the formula (per edge and per face, global scan for the ball)
// as an oracle for the fast neighbourhood code, invariances, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <utility>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include "core/base/math.h"
#include "core/field/curvature.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// A radius (in mean edge lengths) below every 1-ring of the test meshes: the 1-ring's ball.
constexpr double kOneRing = 1e-9;

CurvatureResult curvatureOf(const TriMesh& m, double radius) {
  CurvatureParams p;
  p.radius = radius;
  Expected<CurvatureResult> r = totalCurvature(m, p);
  EXPECT_TRUE(r) << r.status().message;
  return r ? std::move(r).value() : CurvatureResult{};
}

double maxRelativeError(const std::vector<double>& values, double expected, const std::vector<int>& vertices) {
  double worst = 0.0;
  for (int v : vertices) worst = std::max(worst, std::abs(values[v] - expected) / std::abs(expected));
  return worst;
}

std::vector<int> allVertices(const TriMesh& m) {
  std::vector<int> v(m.vertexCount());
  std::iota(v.begin(), v.end(), 0);
  return v;
}

TriMesh transformed(const TriMesh& m, const Eigen::Matrix3d& linear, const Vec3& shift) {
  std::vector<Vec3> pos;
  for (const Vec3& p : m.positions) pos.push_back(linear * p + shift);
  return std::move(buildTriMesh(std::move(pos), m.triangles)).value();
}

TriMesh reversed(const TriMesh& m) {
  std::vector<Tri> tris;
  for (const Tri& t : m.triangles) tris.push_back({t[0], t[2], t[1]});
  return std::move(buildTriMesh(m.positions, std::move(tris))).value();
}

/// Torus around the z axis, major radius `big`, tube radius `small`, nU x nV quads split in two,
/// triangles facing outwards. Vertex (i, j) sits at angles u = 2 pi i / nU, v = 2 pi j / nV.
TriMesh torus(int nU, int nV, double big, double small) {
  std::vector<Vec3> pos;
  std::vector<Tri> tris;
  for (int j = 0; j < nV; ++j)
    for (int i = 0; i < nU; ++i) {
      const double u = 2 * kPi * i / nU, v = 2 * kPi * j / nV;
      pos.emplace_back((big + small * std::cos(v)) * std::cos(u), (big + small * std::cos(v)) * std::sin(u),
                       small * std::sin(v));
    }
  auto id = [&](int i, int j) { return (j % nV) * nU + (i % nU); };
  for (int j = 0; j < nV; ++j)
    for (int i = 0; i < nU; ++i) {
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return std::move(buildTriMesh(std::move(pos), std::move(tris))).value();
}

// ------------------------------------------------------------------------------------------------
// Analytic surfaces

TEST(Curvature, SphereHasTotalCurvatureTwoOverR) {
  const double R = 2.5;
  // Radii in mean edge lengths h (kOneRing: the 1-ring's ball; 1 = the default), kept to
  // r <= 0.3 R (the header's tilt bias is (r/R)^2 / 4).
  for (auto [level, radii] : {std::pair{3, std::vector<double>{kOneRing, 1.0, 2.0}},
                              std::pair{4, std::vector<double>{kOneRing, 1.0, 2.0, 3.0}}}) {
    const TriMesh m = test::icosphere(level, R);
    const double h = m.meanEdgeLength();
    for (double radiusInEdges : radii) {
      SCOPED_TRACE("level " + std::to_string(level) + ", radius " + std::to_string(radiusInEdges) + " h");
      const CurvatureResult c = curvatureOf(m, radiusInEdges * h);
      const double err = maxRelativeError(c.tau, 2.0 / R, allVertices(m));
      std::printf(
          "sphere R=%.1f, %d vertices, r = %.3g h = %.3f R: max |tau - 2/R| / (2/R) = %.4f, "
          "ball %.1f vertices\n",
          R, m.vertexCount(), radiusInEdges, radiusInEdges * h / R, err, c.meanNeighbourhoodSize);
      EXPECT_LT(err, 0.05);
      // Both principal curvatures are +1/R (outward-facing triangles: convex is positive).
      EXPECT_LT(maxRelativeError(c.k1, 1.0 / R, allVertices(m)), 0.05);
      EXPECT_LT(maxRelativeError(c.k2, 1.0 / R, allVertices(m)), 0.05);
    }
  }
}

TEST(Curvature, CylinderHasTotalCurvatureOneOverRAwayFromItsRims) {
  const double R = 1.5, height = 4.0;
  const int nTheta = 64;
  const int nZ = static_cast<int>(std::lround(height / (2 * kPi * R / nTheta)));
  const TriMesh m = test::cylinder(nTheta, nZ, R, height);
  const double h = m.meanEdgeLength();
  for (double radiusInEdges : {kOneRing, 1.0, 2.0, 3.0}) {
    SCOPED_TRACE("radius " + std::to_string(radiusInEdges) + " h");
    const CurvatureResult c = curvatureOf(m, radiusInEdges * h);
    // Away from the rims: farther than the ball (and the 1-ring) from both.
    const double margin = std::max(radiusInEdges, 1.0) * h + 2.0 * h;
    std::vector<int> inner;
    for (int v = 0; v < m.vertexCount(); ++v)
      if (m.positions[v].z() > margin && m.positions[v].z() < height - margin) inner.push_back(v);
    ASSERT_GT(inner.size(), m.vertexCount() / 2u);
    const double err = maxRelativeError(c.tau, 1.0 / R, inner);
    std::printf("cylinder R=%.1f, r = %.3g h: max |tau - 1/R| / (1/R) = %.4f over %zu inner vertices\n", R,
                radiusInEdges, err, inner.size());
    EXPECT_LT(err, 0.05);
    double worstK2 = 0.0;
    for (int v : inner) worstK2 = std::max(worstK2, std::abs(c.k2[v]) * R);
    EXPECT_LT(worstK2, 0.05) << "the curvature along the axis is 0";
    EXPECT_LT(maxRelativeError(c.k1, 1.0 / R, inner), 0.05);
  }
}

TEST(Curvature, TorusSaddlesHaveSignedCurvatures) {
  // k across the tube = 1/a; k along the tube = cos v / (b + a cos v), negative on the inner side.
  const double b = 3.0, a = 1.0;
  const int nV = 40, nU = 120;
  const TriMesh m = torus(nU, nV, b, a);
  const double h = m.meanEdgeLength();
  for (double radiusInEdges : {kOneRing, 1.0, 2.0}) {
    SCOPED_TRACE("radius " + std::to_string(radiusInEdges) + " h");
    const CurvatureResult c = curvatureOf(m, radiusInEdges * h);
    double worstTau = 0.0, worstK1 = 0.0, worstK2 = 0.0;
    for (int v = 0; v < m.vertexCount(); ++v) {
      const double angle = 2 * kPi * (v / nU) / nV;
      const double across = 1.0 / a, along = std::cos(angle) / (b + a * std::cos(angle));
      const double tau = std::abs(across) + std::abs(along);
      worstTau = std::max(worstTau, std::abs(c.tau[v] - tau) / tau);
      worstK1 = std::max(worstK1, std::abs(c.k1[v] - across) / tau);
      worstK2 = std::max(worstK2, std::abs(c.k2[v] - along) / tau);
    }
    std::printf("torus %d vertices, r = %.3g h: max relative error tau %.4f, k1 %.4f, k2 %.4f (of tau)\n",
                m.vertexCount(), radiusInEdges, worstTau, worstK1, worstK2);
    EXPECT_LT(worstTau, 0.05);
    EXPECT_LT(worstK1, 0.05);
    EXPECT_LT(worstK2, 0.05);
  }
}

TEST(Curvature, JitteredPlaneInAnyPositionIsFlat) {
  const TriMesh flat = test::planeGrid(40, 3.0, 0.3, 7);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const TriMesh m = transformed(flat, rotation, Vec3(5, -2, 1));
  const double h = m.meanEdgeLength();
  for (double radiusInEdges : {kOneRing, 1.0, 3.0}) {
    const CurvatureResult c = curvatureOf(m, radiusInEdges * h);
    const double worst = *std::max_element(c.tau.begin(), c.tau.end());
    std::printf("rotated jittered plane, r = %.3g h: max tau * h = %.3g\n", radiusInEdges, worst * h);
    EXPECT_LT(worst * h, 1e-12);
  }
}

TEST(Curvature, HingeByHand) {
  // Two triangles meeting at a right angle along the edge a-b; the four other edges are boundary
  // edges and carry no curvature. A ball holding everything: T = beta |ab| x xᵀ / (area1 + area2)
  // at every vertex, so tau = (pi / 2) * 2 / 2.5 and the other principal curvature is 0.
  //   a = 0, b = 1 on the x axis; c = 2 in the plane z = 0; d = 3 in the plane y = 0.
  const std::vector<Vec3> pos = {{0, 0, 0}, {2, 0, 0}, {0.5, 1, 0}, {1.5, 0, 1.5}};
  const TriMesh m = std::move(buildTriMesh(pos, {{0, 1, 2}, {1, 0, 3}})).value();
  const double expected = (kPi / 2) * 2.0 / (1.0 + 1.5);
  const CurvatureResult c = curvatureOf(m, 10.0);
  for (int v = 0; v < 4; ++v) {
    EXPECT_NEAR(c.tau[v], expected, 1e-7 * expected);  // closed-form eigenvalues: ~1e-8 (header)
    EXPECT_NEAR(c.k2[v], 0.0, 1e-7 * expected);
  }
  // Face 0's normal is -z, face 1's is +y: walking from face 0 across a-b the surface folds away
  // from face 0's normal, a concave fold for this orientation.
  EXPECT_LT(c.k1[0], 0.0);
  EXPECT_EQ(c.oneRingRadius, 0);
  EXPECT_DOUBLE_EQ(c.meanNeighbourhoodSize, 4.0);
}

// ------------------------------------------------------------------------------------------------
// The real mesh: sharp edges

/// Vertices of edges whose dihedral angle (between the two face normals) exceeds `degrees`,
/// found from a map of vertex pairs and face normals, without the mesh's adjacency.
std::set<int> sharpEdgeVertices(const TriMesh& m, double degrees, int* edgeCount) {
  std::map<std::pair<int, int>, std::vector<int>> facesOfEdge;
  for (int f = 0; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
      facesOfEdge[{std::min(a, b), std::max(a, b)}].push_back(f);
    }
  auto normal = [&](int f) {
    const Tri& t = m.triangles[f];
    return Vec3((m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized());
  };
  std::set<int> vertices;
  *edgeCount = 0;
  const double cosLimit = std::cos(degrees * kPi / 180.0);
  for (const auto& [edge, faces] : facesOfEdge) {
    if (faces.size() != 2) continue;
    if (normal(faces[0]).dot(normal(faces[1])) < cosLimit) {
      ++*edgeCount;
      vertices.insert(edge.first);
      vertices.insert(edge.second);
    }
  }
  return vertices;
}

TEST(Curvature, FandiskTopFivePercentLieOnSharpEdges) {
  const TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  int sharpEdges = 0;
  const std::set<int> sharp = sharpEdgeVertices(m, 60.0, &sharpEdges);
  const int top = static_cast<int>(std::ceil(0.05 * m.vertexCount()));
  std::printf("fandisk: %d vertices, %d sharp edges (> 60 deg), %zu of their vertices; top 5%% = %d vertices\n",
              m.vertexCount(), sharpEdges, sharp.size(), top);
  const double h = m.meanEdgeLength();
  // Distance from each vertex to the nearest sharp-edge vertex (brute force).
  std::vector<double> toSharp(m.vertexCount(), std::numeric_limits<double>::infinity());
  for (int v = 0; v < m.vertexCount(); ++v)
    for (int s : sharp) toSharp[v] = std::min(toSharp[v], (m.positions[v] - m.positions[s]).norm());
  for (double radiusInEdges : {0.0, kOneRing, 2.0}) {  // 0: the default radius (h)
    SCOPED_TRACE("radius " + std::to_string(radiusInEdges) + " h");
    const CurvatureResult c = curvatureOf(m, radiusInEdges * h);
    std::vector<int> order = allVertices(m);
    std::partial_sort(order.begin(), order.begin() + top, order.end(),
                      [&](int x, int y) { return c.tau[x] > c.tau[y]; });
    int onSharp = 0;
    double farthest = 0.0;
    for (int i = 0; i < top; ++i) {
      onSharp += sharp.count(order[i]) ? 1 : 0;
      farthest = std::max(farthest, toSharp[order[i]]);
    }
    std::printf(
        "  r = %s: %d of the top %d on sharp edges (%.1f%%), the others at most %.2f h from one; "
        "tau threshold %.3g (1/h = %.3g)\n",
        radiusInEdges == 0.0        ? "default (h)"
        : radiusInEdges == kOneRing ? "1-ring"
                                    : "2 h",
        onSharp, top, 100.0 * onSharp / top, farthest / h, c.tau[order[top - 1]], 1.0 / h);
    if (radiusInEdges == 0.0) {
      EXPECT_DOUBLE_EQ(c.radius, h);
      EXPECT_EQ(onSharp, top) << "the default radius puts every top-5% vertex on a sharp edge";
    } else {
      // A sharp edge spreads over a band as wide as the ball. The 1-ring's ball also sees a sharp
      // edge from a vertex closer to it than its own neighbours (fandisk: 2 vertices of 324,
      // 0.28 h and 0.53 h from a sharp vertex whose sharp edges are 1.5-3x longer than theirs).
      EXPECT_LE(farthest, std::max(radiusInEdges, 1.0) * h);
      EXPECT_GE(onSharp, radiusInEdges == kOneRing ? 0.99 * top : 0.75 * top);
    }
  }
}

// ------------------------------------------------------------------------------------------------
// Oracle: the formula written out per edge and per face, the ball by a scan of all vertices

/// tau of vertex v by the header's definition, computed the slow way.
double bruteForceTau(const TriMesh& m, int v, double radius) {
  const int n = m.vertexCount();
  std::vector<Vec3> faceCross(m.faceCount());
  std::vector<double> cellArea(n, 0.0);
  Vec3 vertexNormal = Vec3::Zero();
  std::map<std::pair<int, int>, std::vector<int>> facesOfEdge;
  for (int f = 0; f < m.faceCount(); ++f) {
    const Tri& t = m.triangles[f];
    faceCross[f] = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    for (int k = 0; k < 3; ++k) {
      cellArea[t[k]] += faceCross[f].norm() / 6.0;
      facesOfEdge[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}].push_back(f);
      if (t[k] == v) vertexNormal += faceCross[f];
    }
  }
  // The ball's radius: at least the mean distance to the neighbours.
  double ring = 0.0;
  int neighbours = 0;
  for (const auto& [edge, faces] : facesOfEdge)
    if (edge.first == v || edge.second == v) {
      ring += (m.positions[edge.first] - m.positions[edge.second]).norm();
      ++neighbours;
    }
  radius = std::max(radius, ring / neighbours);
  std::vector<double> w(n, 0.0);
  for (int u = 0; u < n; ++u) {
    const double d = (m.positions[u] - m.positions[v]).norm();
    w[u] = std::clamp(0.5 + (radius - d) / std::sqrt(cellArea[u]), 0.0, 1.0);
  }
  w[v] = 1.0;
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  for (const auto& [edge, faces] : facesOfEdge) {
    if (faces.size() != 2) continue;
    // Orient the edge as it runs in the first face.
    const Tri& t = m.triangles[faces[0]];
    int a = edge.first, b = edge.second;
    for (int k = 0; k < 3; ++k)
      if (t[k] == b && t[(k + 1) % 3] == a) std::swap(a, b);
    const Vec3 e = m.positions[b] - m.positions[a];
    const Vec3 n1 = faceCross[faces[0]].normalized(), n2 = faceCross[faces[1]].normalized();
    const double beta = std::atan2(n1.cross(n2).dot(e.normalized()), n1.dot(n2));
    tensor += 0.5 * (w[a] + w[b]) * beta * e.norm() * e.normalized() * e.normalized().transpose();
  }
  double area = 0.0;
  for (int f = 0; f < m.faceCount(); ++f) {
    const Tri& t = m.triangles[f];
    area += faceCross[f].norm() / 2.0 * (w[t[0]] + w[t[1]] + w[t[2]]) / 3.0;
  }
  tensor /= area;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(tensor);  // iterative, not closed form
  int dropped = 0;
  (solver.eigenvectors().transpose() * vertexNormal.normalized()).cwiseAbs().maxCoeff(&dropped);
  return std::abs(solver.eigenvalues()[(dropped + 1) % 3]) + std::abs(solver.eigenvalues()[(dropped + 2) % 3]);
}

TEST(Curvature, FastNeighbourhoodsMatchTheFormulaWrittenOut) {
  // A bumpy sphere (saddles and mixed signs) and the torus; radii where the Euclidean ball is
  // connected on the surface, so the flood fill and the global scan find the same ball.
  std::vector<Vec3> bumpy = test::icosphere(3, 2.0).positions;
  for (Vec3& p : bumpy) p *= 1.0 + 0.08 * std::sin(3 * p.x()) * std::cos(2 * p.y() + p.z());
  const TriMesh bumpySphere = std::move(buildTriMesh(bumpy, test::icosphere(3, 2.0).triangles)).value();
  for (const TriMesh* m : {&bumpySphere}) {
    const double h = m->meanEdgeLength();
    for (double radiusInEdges : {kOneRing, 1.0, 1.5, 2.5}) {
      const CurvatureResult c = curvatureOf(*m, radiusInEdges * h);
      double worst = 0.0;
      for (int v = 0; v < m->vertexCount(); v += 7)
        worst = std::max(worst, std::abs(c.tau[v] - bruteForceTau(*m, v, radiusInEdges * h)) / c.tau[v]);
      EXPECT_LT(worst, 1e-7) << "radius " << radiusInEdges << " h";  // closed-form eigenvalues: ~1e-8
    }
  }
}

// ------------------------------------------------------------------------------------------------
// Invariances and parameters

TEST(Curvature, ScalesAsOneOverLengthAndIgnoresRigidMotion) {
  const TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  const double h = m.meanEdgeLength();
  const CurvatureResult base = curvatureOf(m, 2.0 * h);
  const double s = 3.5;
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(1.1, Vec3(-1, 0.5, 2).normalized()).toRotationMatrix();
  const CurvatureResult moved = curvatureOf(transformed(m, s * rotation, Vec3(1, 2, 3)), 2.0 * h * s);
  const CurvatureResult flipped = curvatureOf(reversed(m), 2.0 * h);
  double worstMoved = 0.0, worstFlipped = 0.0;
  const double scale = *std::max_element(base.tau.begin(), base.tau.end());
  for (int v = 0; v < m.vertexCount(); ++v) {
    worstMoved = std::max(worstMoved, std::abs(moved.tau[v] * s - base.tau[v]) / scale);
    worstFlipped =
        std::max({worstFlipped, std::abs(flipped.tau[v] - base.tau[v]) / scale,
                  std::abs(flipped.k1[v] + base.k1[v]) / scale, std::abs(flipped.k2[v] + base.k2[v]) / scale});
  }
  // Closed-form eigenvalues: relative error about 1e-8 where two coincide (header).
  EXPECT_LT(worstMoved, 1e-7);
  EXPECT_LT(worstFlipped, 1e-7) << "reversing the orientation negates k1 and k2";
}

TEST(Curvature, RadiusBelowTheOneRingUsesTheOneRing) {
  const TriMesh m = test::icosphere(3, 2.0);
  const double h = m.meanEdgeLength();
  const CurvatureResult ring = curvatureOf(m, kOneRing);
  const CurvatureResult small = curvatureOf(m, 0.2 * h);
  EXPECT_EQ(ring.tau, small.tau);
  EXPECT_EQ(ring.oneRingRadius, m.vertexCount());
  EXPECT_EQ(small.oneRingRadius, m.vertexCount());
  EXPECT_DOUBLE_EQ(small.radius, 0.2 * h);
  // The 1-ring's ball: v and its 5 or 6 neighbours, no farther vertex on this regular mesh.
  EXPECT_GT(ring.meanNeighbourhoodSize, 6.5);
  EXPECT_LE(ring.meanNeighbourhoodSize, 7.0);
  const CurvatureResult wide = curvatureOf(m, 3.0 * h);
  EXPECT_EQ(wide.oneRingRadius, 0);
  EXPECT_GT(wide.meanNeighbourhoodSize, 4.0 * ring.meanNeighbourhoodSize);
  // The default is the mean edge length.
  const CurvatureResult byDefault = curvatureOf(m, 0.0);
  EXPECT_DOUBLE_EQ(byDefault.radius, h);
  EXPECT_EQ(byDefault.tau, curvatureOf(m, h).tau);
}

// Two spheres touching at one vertex (a non-manifold vertex: two fans of faces): each fan is
// measured on its own surface, so every vertex has the value it has on a lone sphere (no ball
// reaches through the shared vertex into the other sphere), and 2 / R within the lone sphere's
// bound.
TEST(Curvature, FansAtOneVertexAreMeasuredApart) {
  const double R = 2.0;
  const TriMesh lone = test::icosphere(3, R);
  const int n = lone.vertexCount(), touch = 0;
  int antipode = -1;  // the icosphere is centrally symmetric
  for (int v = 0; v < n && antipode < 0; ++v)
    if ((lone.positions[v] + lone.positions[touch]).norm() < 1e-9) antipode = v;
  ASSERT_GE(antipode, 0);
  std::vector<Vec3> positions = lone.positions;
  for (const Vec3& p : lone.positions) positions.push_back(p + 2.0 * lone.positions[touch]);
  std::vector<Tri> triangles = lone.triangles;
  const auto second = [&](int v) { return v == antipode ? touch : v + n; };
  for (const Tri& t : lone.triangles) triangles.push_back({second(t[0]), second(t[1]), second(t[2])});
  const TriMesh touching = std::move(buildTriMesh(positions, triangles)).value();
  ASSERT_EQ(touching.topology.nonManifoldVertices, 1);
  const double radius = 2.0 * lone.meanEdgeLength();
  const CurvatureResult one = curvatureOf(lone, radius), two = curvatureOf(touching, radius);
  ASSERT_EQ(two.splitVertices, 1);
  double worst = 0.0;
  for (int v = 0; v < n; ++v) {
    worst = std::max(worst, std::abs(two.tau[v] - one.tau[v]));
    if (v != antipode) worst = std::max(worst, std::abs(two.tau[second(v)] - one.tau[v]));
  }
  std::printf("two spheres touching: largest difference from a lone sphere %.2e\n", worst);
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(maxRelativeError(two.tau, 2.0 / R, std::vector<int>{touch}), 0.05);
}

TEST(Curvature, AcceptsOddMeshesAndKeepsTheirEffectLocal) {
  // One face of a sphere turned over (3 edges whose faces disagree on orientation), a fourth face
  // on one edge (non-manifold), a zero-area face and an isolated vertex: every tau is finite, the
  // isolated vertex gets 0, and vertices whose balls do not reach the odd places keep the tau of
  // the clean sphere.
  const TriMesh clean = test::icosphere(3, 2.0);
  const double h = clean.meanEdgeLength();
  std::vector<Vec3> pos = clean.positions;
  std::vector<Tri> tris = clean.triangles;
  std::swap(tris[0][1], tris[0][2]);  // turned over
  const Tri& t5 = clean.triangles[5];
  pos.push_back(1.2 * pos[t5[0]]);  // a fin on edge t5[0]-t5[1]
  tris.push_back({t5[1], t5[0], static_cast<int>(pos.size()) - 1});
  const Tri& t9 = clean.triangles[9];
  pos.push_back(0.5 * (pos[t9[0]] + pos[t9[1]]));  // zero-area face on edge t9[0]-t9[1]
  tris.push_back({t9[0], t9[1], static_cast<int>(pos.size()) - 1});
  pos.push_back(Vec3(9, 9, 9));  // isolated
  const TriMesh m = std::move(buildTriMesh(pos, tris)).value();
  ASSERT_GT(m.topology.inconsistentEdges, 0);
  ASSERT_GT(m.topology.nonManifoldEdges, 0);
  const CurvatureResult odd = curvatureOf(m, 2.0 * h);
  const CurvatureResult reference = curvatureOf(clean, 2.0 * h);
  EXPECT_EQ(odd.tau.back(), 0.0);
  std::vector<Vec3> oddPlaces;
  for (int f : {0, 5, 9})
    for (int k = 0; k < 3; ++k) oddPlaces.push_back(clean.positions[clean.triangles[f][k]]);
  int far = 0;
  for (int v = 0; v < clean.vertexCount(); ++v) {
    ASSERT_TRUE(std::isfinite(odd.tau[v])) << "vertex " << v;
    double nearest = std::numeric_limits<double>::infinity();
    for (const Vec3& p : oddPlaces) nearest = std::min(nearest, (clean.positions[v] - p).norm());
    if (nearest < 4.0 * h) continue;  // ball 2 h plus the neighbours' cells and normals
    ++far;
    EXPECT_NEAR(odd.tau[v], reference.tau[v], 1e-9 * reference.tau[v]) << "vertex " << v;
  }
  EXPECT_GT(far, clean.vertexCount() / 2);
}

TEST(Curvature, RejectsBadInput) {
  const TriMesh m = test::icosphere(1);
  for (double radius : {-1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    CurvatureParams p;
    p.radius = radius;
    const Expected<CurvatureResult> r = totalCurvature(m, p);
    ASSERT_FALSE(r);
    EXPECT_EQ(r.status().code, StatusCode::InvalidInput);
    EXPECT_NE(r.status().message.find("radius"), std::string::npos) << r.status().message;
  }
  const Expected<CurvatureResult> empty = totalCurvature(TriMesh{});
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.status().code, StatusCode::InvalidInput);
  const Expected<CurvatureResult> stopped = totalCurvature(m, {}, Progress([](int, const char*) { return false; }));
  ASSERT_FALSE(stopped);
  EXPECT_EQ(stopped.status().code, StatusCode::Cancelled);
}

}  // namespace
}  // namespace gr
