// Gradient magnitude of a per-vertex field: linear fields on a plane and on curved surfaces
// against the analytic tangential gradient |a - (a.n) n|, constant fields, a step, the intensity
// weights, bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "core/field/color_gradient.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

std::vector<double> linearField(const TriMesh& m, const Vec3& a) {
  std::vector<double> f;
  for (const Vec3& p : m.positions) f.push_back(a.dot(p));
  return f;
}

GradientResult gradientOf(const TriMesh& m, const std::vector<double>& field) {
  Expected<GradientResult> g = gradientMagnitude(m, field);
  EXPECT_TRUE(g) << g.status().message;
  return g ? std::move(g).value() : GradientResult{};
}

TEST(ColorGradient, LinearFieldOnAPlaneIsExact) {
  // Any plane position: the piecewise-linear interpolant of a linear field is the field itself.
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.9, Vec3(2, -1, 1).normalized()).toRotationMatrix();
  std::vector<Vec3> pos = test::planeGrid(30, 2.0, 0.35, 3).positions;
  for (Vec3& p : pos) p = rotation * p + Vec3(1, 2, 3);
  const TriMesh m = std::move(buildTriMesh(pos, test::planeGrid(30, 2.0, 0.35, 3).triangles)).value();
  const Vec3 normal = rotation * Vec3::UnitZ();
  const Vec3 a(0.3, -0.7, 2.0);
  const double expected = (a - a.dot(normal) * normal).norm();
  const GradientResult g = gradientOf(m, linearField(m, a));
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_NEAR(g.magnitude[v], expected, 1e-12 * a.norm());
  EXPECT_NEAR(g.maxMagnitude, expected, 1e-12 * a.norm());
  EXPECT_EQ(g.zeroAreaFaces, 0);
}

/// Largest |computed - |a projected on the tangent plane|| / |a| over the vertices, n(v) given.
template <class NormalAt>
double worstTangentialError(const TriMesh& m, const Vec3& a, NormalAt normalAt) {
  const GradientResult g = gradientOf(m, linearField(m, a));
  double worst = 0.0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const Vec3 n = normalAt(m.positions[v]);
    worst = std::max(worst, std::abs(g.magnitude[v] - (a - a.dot(n) * n).norm()) / a.norm());
  }
  return worst;
}

TEST(ColorGradient, LinearFieldOnCurvedSurfacesIsTheTangentialPartOfItsGradient) {
  // Each face sees a's projection on its own plane; its normal is off the vertex normal by about
  // h / (2 R), so the error is O(h / R). Checked: at most h / R, and halving h halves it at least.
  const Vec3 a(1.0, -2.0, 0.5);
  const double R = 1.7;
  double previous = 0.0;
  for (int level : {3, 4, 5}) {
    const TriMesh m = test::icosphere(level, R);
    const double h = m.meanEdgeLength();
    const double err = worstTangentialError(m, a, [](const Vec3& p) { return Vec3(p.normalized()); });
    std::printf("sphere R=%.1f, %d vertices, h/R = %.4f: max error / |a| = %.2e\n", R, m.vertexCount(), h / R, err);
    EXPECT_LT(err, h / R);
    if (previous > 0.0) {
      EXPECT_LT(err, 0.6 * previous);
    }
    previous = err;
  }
  const TriMesh cyl = test::cylinder(96, 40, R, 4.0);
  const double h = cyl.meanEdgeLength();
  const double err =
      worstTangentialError(cyl, a, [](const Vec3& p) { return Vec3(Vec3(p.x(), p.y(), 0.0).normalized()); });
  std::printf("cylinder R=%.1f, h/R = %.4f: max error / |a| = %.2e (rims included)\n", R, h / R, err);
  EXPECT_LT(err, h / R);
}

TEST(ColorGradient, ConstantFieldHasNoGradient) {
  for (const TriMesh& m : {test::icosphere(3, 2.0), test::planeGrid(10, 1.0, 0.3), test::loadRealMesh("fandisk.off")}) {
    const GradientResult g = gradientOf(m, std::vector<double>(m.vertexCount(), 0.731));
    EXPECT_EQ(g.maxMagnitude, 0.0);
  }
}

TEST(ColorGradient, StepAcrossOneColumnOfFaces) {
  // I = 0 up to the column x = 0.5, 1 from the column x = 0.5 + s on, on a regular grid of
  // spacing s: the strip of faces between those two columns carries |grad I| = 1 / s (a unit jump
  // over one spacing, along x), every other face 0. A vertex of either column away from the
  // border has 3 of its 6 equal-area faces in the strip: 0.5 / s; all other vertices 0.
  const int n = 10;
  const double s = 1.0 / n;
  const TriMesh m = test::planeGrid(n, 1.0);
  std::vector<double> field;
  for (const Vec3& p : m.positions) field.push_back(p.x() > 0.5 + 1e-9 ? 1.0 : 0.0);
  const GradientResult g = gradientOf(m, field);
  for (int v = 0; v < m.vertexCount(); ++v) {
    const Vec3& p = m.positions[v];
    const bool onStrip = std::abs(p.x() - 0.5) < 1e-9 || std::abs(p.x() - 0.5 - s) < 1e-9;
    const bool border = p.y() < 1e-9 || p.y() > 1.0 - 1e-9;
    if (!onStrip) {
      EXPECT_EQ(g.magnitude[v], 0.0) << "vertex " << v;
    } else if (!border) {
      EXPECT_NEAR(g.magnitude[v], 0.5 / s, 1e-9) << "vertex " << v;
    } else {
      EXPECT_GT(g.magnitude[v], 0.0) << "vertex " << v;
      EXPECT_LE(g.magnitude[v], 1.0 / s + 1e-9) << "vertex " << v;
    }
  }
}

TEST(ColorGradient, IntensityWeights) {
  EXPECT_DOUBLE_EQ(rgbIntensity(0, 0, 0), 0.0);
  EXPECT_NEAR(rgbIntensity(255, 255, 255), 255.0, 1e-12);
  EXPECT_NEAR(rgbIntensity(1, 1, 1), 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(rgbIntensity(1, 0, 0), 0.299);
  EXPECT_DOUBLE_EQ(rgbIntensity(0, 1, 0), 0.587);
  EXPECT_DOUBLE_EQ(rgbIntensity(0, 0, 1), 0.114);
  EXPECT_GT(rgbIntensity(0, 1, 0), rgbIntensity(1, 0, 0));  // green looks brightest, blue darkest
  EXPECT_GT(rgbIntensity(1, 0, 0), rgbIntensity(0, 0, 1));
}

TEST(ColorGradient, ZeroAreaFacesAreSkipped) {
  // A flat fan plus a zero-area face (three collinear vertices): that face adds no gradient.
  const std::vector<Vec3> pos = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  const TriMesh m = std::move(buildTriMesh(pos, {{0, 1, 2}, {0, 3, 1}})).value();
  const GradientResult g = gradientOf(m, {0.0, 1.0, 0.0, 2.0});
  EXPECT_EQ(g.zeroAreaFaces, 1);
  EXPECT_NEAR(g.magnitude[0], 1.0, 1e-12);  // I = x on face 0
  EXPECT_EQ(g.magnitude[3], 0.0);           // only in the zero-area face
}

TEST(ColorGradient, RejectsBadInput) {
  const TriMesh m = test::icosphere(1);
  const Expected<GradientResult> shortField = gradientMagnitude(m, std::vector<double>(m.vertexCount() - 1, 0.0));
  ASSERT_FALSE(shortField);
  EXPECT_EQ(shortField.status().code, StatusCode::InvalidInput);
  // The message names the culprit counts.
  const std::string counts =
      std::to_string(m.vertexCount() - 1) + " values for " + std::to_string(m.vertexCount()) + " vertices";
  EXPECT_NE(shortField.status().message.find(counts), std::string::npos) << shortField.status().message;
  std::vector<double> withNan(m.vertexCount(), 1.0);
  withNan[7] = std::numeric_limits<double>::quiet_NaN();
  const Expected<GradientResult> nan = gradientMagnitude(m, withNan);
  ASSERT_FALSE(nan);
  EXPECT_EQ(nan.status().code, StatusCode::InvalidInput);
  EXPECT_NE(nan.status().message.find("vertex 7"), std::string::npos) << nan.status().message;
  const Expected<GradientResult> empty = gradientMagnitude(TriMesh{}, {});
  ASSERT_FALSE(empty);
  EXPECT_EQ(empty.status().code, StatusCode::InvalidInput);
}

}  // namespace
}  // namespace gr
