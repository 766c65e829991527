// Tests of the CAD-like acceptance meshes of issue 17 (tests/support/cad_meshes.h).
//
// Oracles, none sharing code with the generators: the topology recount of tests/support
// (test::recount: closed, manifold, one component, genus, orientation), CGAL's self-intersection
// test (exact predicates), the volume by the divergence theorem against the profile's area
// (closed forms for the inscribed polygons), the dihedral angles at each vertex's edges (every
// vertex on a feature outline: nothing inside a flat face), and the angle recount
// test::recountAngles (slivers).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/base/math.h"
#include "core/mesh/vcg_mesh.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/cad_meshes.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// The volume enclosed, by the divergence theorem: > 0 when the faces point outwards.
double signedVolume(const TriMesh& m) {
  double v = 0.0;
  for (const Tri& t : m.triangles) v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6.0;
  return v;
}

/// Area of a regular n-gon inscribed in a circle of radius r.
double inscribedArea(int n, double r) { return 0.5 * n * r * r * std::sin(2.0 * kPi / n); }

/// Vertices none of whose edges has a dihedral angle (between the two face normals) of at least
/// `featureDegrees`: vertices inside a smooth or flat region, off every feature outline.
int verticesOffFeatures(const TriMesh& m, double featureDegrees) {
  std::map<std::pair<int, int>, std::vector<Vec3>> normals;
  for (const Tri& t : m.triangles) {
    const Vec3 n = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized();
    for (int k = 0; k < 3; ++k) normals[std::minmax(t[k], t[(k + 1) % 3])].push_back(n);
  }
  std::vector<char> onFeature(m.vertexCount(), 0);
  const double cosLimit = std::cos(featureDegrees * kPi / 180.0);
  for (const auto& [e, n] : normals)
    if (n.size() == 2 && n[0].dot(n[1]) <= cosLimit) onFeature[e.first] = onFeature[e.second] = 1;
  return static_cast<int>(std::count(onFeature.begin(), onFeature.end(), 0));
}

struct Case {
  std::string name;
  TriMesh mesh;
  int genus;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  for (test::CadMesh& m : test::cadMeshes()) c.push_back({m.name, std::move(m.mesh), m.genus});
  test::CadGearParams bored;
  bored.boreFraction = 0.25;
  c.push_back({"cad_gear_with_bore", test::cadGear(bored), 1});
  return c;
}

class CadMeshes : public ::testing::TestWithParam<int> {
 protected:
  static const Case& mesh() {
    static const std::vector<Case> all = cases();
    return all[GetParam()];
  }
};

TEST_P(CadMeshes, AreClosedOrientedManifoldSolidsOfTheirGenus) {
  const Case& c = mesh();
  const test::Recount r = test::recount(c.mesh.triangles, c.mesh.vertexCount());
  EXPECT_TRUE(r.closedManifoldEdges) << c.name;
  EXPECT_EQ(r.boundaryEdges, 0) << c.name;
  EXPECT_EQ(r.nonManifoldEdges, 0) << c.name;
  EXPECT_TRUE(r.manifoldVertices) << c.name;
  EXPECT_TRUE(r.oriented) << c.name;
  EXPECT_EQ(r.inconsistentEdges, 0) << c.name;
  EXPECT_EQ(r.isolated, 0) << c.name;
  EXPECT_EQ(r.components, 1) << c.name;
  EXPECT_EQ(r.genusSum, c.genus) << c.name;
  EXPECT_GT(signedVolume(c.mesh), 0.0) << c.name << ": faces point inwards";
}

TEST_P(CadMeshes, DoNotIntersectThemselves) {
  const Case& c = mesh();
  const Expected<std::vector<std::pair<int, int>>> pairs = oracle::selfIntersections(c.mesh);
  ASSERT_TRUE(pairs.hasValue()) << c.name << ": " << pairs.status().message;
  EXPECT_TRUE(pairs->empty()) << c.name << ": " << pairs->size() << " intersecting face pairs, first "
                              << (*pairs)[0].first << ", " << (*pairs)[0].second;
}

TEST_P(CadMeshes, HaveVerticesOnlyOnFeatureOutlines) {
  const Case& c = mesh();
  EXPECT_EQ(verticesOffFeatures(c.mesh, 60.0), 0) << c.name;
}

TEST_P(CadMeshes, AreRichInSlivers) {
  const Case& c = mesh();
  const test::AngleRecount a = test::recountAngles(c.mesh);
  std::printf("%-20s %5d vertices %5d faces, smallest angle %.4f deg, %.1f%% of faces under 30 deg\n", c.name.c_str(),
              c.mesh.vertexCount(), c.mesh.faceCount(), a.smallestDegrees, 100 * a.shareBelow30);
  EXPECT_LT(a.smallestDegrees, 1.0) << c.name;
  EXPECT_GT(a.shareBelow30, 0.5) << c.name;
}

std::string caseName(const ::testing::TestParamInfo<int>& p) {
  static const char* const kNames[] = {"gear", "hole_plate", "cylinder", "bracket", "gear_with_bore"};
  return kNames[p.param];
}

INSTANTIATE_TEST_SUITE_P(Generated, CadMeshes, ::testing::Range(0, 5), caseName);

}  // namespace
}  // namespace gr

namespace gr {
namespace {

// The caps cover the profile exactly: the volume is the profile's area times the height, with
// the areas of inscribed polygons in closed form.
TEST(CadMeshes, EncloseTheVolumeOfTheirProfile) {
  const test::CadCylinderParams cyl;
  EXPECT_NEAR(signedVolume(test::cadCylinder()), inscribedArea(cyl.segments, cyl.radius) * cyl.height, 1e-9);
  const test::CadHolePlateParams pl;
  const double plateArea =
      pl.length * pl.width - pl.holeColumns * pl.holeRows * inscribedArea(pl.holeSegments, pl.holeRadius);
  EXPECT_NEAR(signedVolume(test::cadHolePlate()), plateArea * pl.thickness, 1e-9);
  const test::CadBracketParams br;
  const int s = br.filletSegments;
  const double r = br.filletRadius, t = br.thickness;
  // Two legs, plus the fillet: the r x r corner square less the polygon fan around the arc's centre.
  const double filletArea = r * r - 0.5 * s * r * r * std::sin(0.5 * kPi / s);
  EXPECT_NEAR(signedVolume(test::cadBracket()), (br.legLength * t + (br.legLength - t) * t + filletArea) * br.depth,
              1e-9);
  // The gear lies between its root and tip circles.
  const test::CadGearParams g;
  const double tip = 0.5 * g.diameter, root = tip - g.toothDepthFraction * g.diameter;
  const double height = g.thicknessFraction * g.diameter, gear = signedVolume(test::cadGear());
  EXPECT_GT(gear, kPi * root * root * height * std::cos(kPi / g.teeth));
  EXPECT_LT(gear, kPi * tip * tip * height);
}

TEST(CadMeshes, GearHasTheAskedProportions) {
  const TriMesh m = test::cadGear();
  Vec3 lo = m.positions[0], hi = m.positions[0];
  for (const Vec3& p : m.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const double diameter = hi.x() - lo.x();
  EXPECT_NEAR(diameter, 100.0, 0.5);
  EXPECT_NEAR((hi.z() - lo.z()) / diameter, 0.02, 1e-3);
  EXPECT_EQ(m.vertexCount(), 2 * 40 * 13);
}

TEST(CadMeshes, CylinderCapsAreFansFromOneRimVertex) {
  const test::CadCylinderParams p;
  const TriMesh m = test::cadCylinder();
  // Each cap: segments - 2 triangles, all through one rim vertex.
  std::map<int, int> trianglesAt;
  int capTriangles = 0;
  for (const Tri& t : m.triangles) {
    const bool bottom = t[0] < p.segments && t[1] < p.segments && t[2] < p.segments;
    if (!bottom) continue;
    ++capTriangles;
    for (int v : t) ++trianglesAt[v];
  }
  EXPECT_EQ(capTriangles, p.segments - 2);
  int apex = 0;
  for (const auto& [v, n] : trianglesAt) apex = std::max(apex, n);
  EXPECT_EQ(apex, p.segments - 2);
}

TEST(CadMeshes, AreDeterministicAndRoundTripThroughOff) {
  const std::vector<test::CadMesh> a = test::cadMeshes(), b = test::cadMeshes();
  ASSERT_EQ(a.size(), 4u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].mesh.positions, b[i].mesh.positions) << a[i].name;
    EXPECT_EQ(a[i].mesh.triangles, b[i].mesh.triangles) << a[i].name;
    const std::string path = std::string(GR_TEST_OUTPUT_DIR) + "/" + a[i].name + ".off";
    ASSERT_TRUE(test::writeOff(a[i].mesh, path)) << path;
    const Expected<TriMesh> back = loadTriMesh(path);
    ASSERT_TRUE(back.hasValue()) << back.status().message;
    EXPECT_EQ(back->triangles, a[i].mesh.triangles) << a[i].name;
    ASSERT_EQ(back->vertexCount(), a[i].mesh.vertexCount());
    double moved = 0.0;
    for (int v = 0; v < back->vertexCount(); ++v)
      moved = std::max(moved, (back->positions[v] - a[i].mesh.positions[v]).norm());
    EXPECT_EQ(moved, 0.0) << a[i].name;
  }
}

TEST(EarClip, TriangulatesAPolygonWithHolesIntoNPlus2HMinus2Triangles) {
  const test::Polygon2 square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const test::Polygon2 hole1 = {{2, 2}, {2, 4}, {4, 4}, {4, 2}}, hole2 = {{6, 5.5}, {6, 8}, {8, 8}, {8, 5.5}};
  const std::vector<Tri> t = test::earClip(square, {hole1, hole2});
  EXPECT_EQ(t.size(), 4u + 8u + 2u * 2u - 2u);
  std::vector<Eigen::Vector2d> all = square;
  all.insert(all.end(), hole1.begin(), hole1.end());
  all.insert(all.end(), hole2.begin(), hole2.end());
  double area = 0.0;
  for (const Tri& f : t) {
    const Eigen::Vector2d u = all[f[1]] - all[f[0]], w = all[f[2]] - all[f[0]];
    const double twice = u.x() * w.y() - u.y() * w.x();
    EXPECT_GT(twice, 0.0) << "a clockwise or flat triangle";
    area += 0.5 * twice;
  }
  EXPECT_NEAR(area, 100.0 - 4.0 - 5.0, 1e-12);
}

}  // namespace
}  // namespace gr
