// The surface cut open along its sharp edges (core/mesh/sharp_cut.h), and the segmentation that
// runs on it: fronts that stop at sharp edges, seeds shared among the pieces by area.
//
// Oracles: fixtures whose pieces are known in closed form (a box cut into its 6 sides, each a
// grid of (n + 1)(m + 1) vertices; a slit in a flat grid), counted by test::recount, which shares
// no code with core/mesh; the sides of a box told apart by their normals.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "core/mesh/face_geometry.h"
#include "core/mesh/sharp_cut.h"
#include "core/segment/geodesic_segmentation.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

/// A closed box [0, a] x [0, b] x [0, c], each side a grid of squares of side `step` split in two
/// triangles, oriented outwards; vertices shared along the box's edges.
TriMesh box(double a, double b, double c, double step) {
  std::map<std::array<long, 3>, int> index;
  std::vector<Vec3> positions;
  std::vector<Tri> triangles;
  const auto vertex = [&](const Vec3& p) {
    const std::array<long, 3> k{std::lround(p.x() / step * 4), std::lround(p.y() / step * 4),
                                std::lround(p.z() / step * 4)};
    auto [it, added] = index.emplace(k, static_cast<int>(positions.size()));
    if (added) positions.push_back(p);
    return it->second;
  };
  const double size[3] = {a, b, c};
  for (int axis = 0; axis < 3; ++axis)
    for (int high = 0; high < 2; ++high) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      const int nu = static_cast<int>(std::lround(size[u] / step)), nw = static_cast<int>(std::lround(size[w] / step));
      const auto at = [&](int i, int j) {
        Vec3 p = Vec3::Zero();
        p[axis] = high ? size[axis] : 0.0;
        p[u] = i * step;
        p[w] = j * step;
        return vertex(p);
      };
      for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nw; ++j) {
          const int p00 = at(i, j), p10 = at(i + 1, j), p01 = at(i, j + 1), p11 = at(i + 1, j + 1);
          if (high) {  // u x w = +axis: counter-clockwise seen from outside
            triangles.push_back({p00, p10, p11});
            triangles.push_back({p00, p11, p01});
          } else {
            triangles.push_back({p00, p11, p10});
            triangles.push_back({p00, p01, p11});
          }
        }
    }
  return *buildTriMesh(positions, triangles);
}

/// The side of the box a face lies on: 0..5 from its outward normal (axis, sign).
int sideOf(const TriMesh& m, int f) {
  const Vec3 n = areaNormal(m, f);
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(n[k]) > std::abs(n[axis])) axis = k;
  return 2 * axis + (n[axis] > 0.0 ? 1 : 0);
}

TEST(SharpCut, ABoxFallsIntoItsSixSides) {
  const double step = 0.25;
  const TriMesh m = box(1.0, 1.0, 2.0, step);
  ASSERT_EQ(m.topology.genus, 0);
  ASSERT_EQ(m.topology.boundaryEdges, 0);
  // Sharp: exactly the box's 12 edges, (4 + 4 + 8 + 8 ...) segments of `step`.
  const std::vector<char> sharp = sharpEdgeCorners(m, 60.0);
  double sharpLength = 0.0;
  for (int c = 0; c < 3 * m.faceCount(); ++c)
    if (sharp[c])
      sharpLength += (m.positions[m.vertex(TriMesh::next(c))] - m.positions[m.vertex(TriMesh::prev(c))]).norm();
  EXPECT_NEAR(sharpLength, 2.0 * (4 * 1.0 + 4 * 1.0 + 4 * 2.0), 1e-9);  // each edge from both sides
  const Expected<CutSurface> cut = cutAlongEdges(m, sharp);
  ASSERT_TRUE(cut) << cut.status().message;
  EXPECT_EQ(cut->sharpEdges, static_cast<int>(std::lround((4 * 1.0 + 4 * 1.0 + 4 * 2.0) / step)));
  // Six grids: two of 5 x 5 vertices, four of 5 x 9.
  EXPECT_EQ(cut->mesh.vertexCount(), 2 * 25 + 4 * 45);
  const test::Recount rc = test::recount(cut->mesh.triangles, cut->mesh.vertexCount());
  EXPECT_EQ(rc.components, 6);
  EXPECT_EQ(rc.boundaryLoops, 6);
  EXPECT_TRUE(rc.manifoldVertices && rc.manifoldEdges && rc.oriented);
  // The same faces in the same order; each copy at its origin's place; the first copies keep
  // their numbers.
  ASSERT_EQ(cut->mesh.faceCount(), m.faceCount());
  ASSERT_EQ(static_cast<int>(cut->origin.size()), cut->mesh.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_EQ(cut->origin[v], v);
  for (int f = 0; f < m.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(cut->origin[cut->mesh.triangles[f][k]], m.triangles[f][k]);
      EXPECT_EQ(cut->mesh.positions[cut->mesh.triangles[f][k]], m.positions[m.triangles[f][k]]);
    }
  // A smooth closed surface has no sharp edge.
  const TriMesh sphere = test::icosphere(3);
  const std::vector<char> none = sharpEdgeCorners(sphere, 60.0);
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
}

TEST(SharpCut, AnEdgeChainThatEndsInsideIsASlit) {
  const int n = 8;
  const TriMesh grid = test::planeGrid(n);
  // Mark the edges on the line y = 1/2 from x = 0 to x = 1/2: a chain from the boundary inward.
  std::vector<char> cutCorner(3 * grid.faceCount(), 0);
  int marked = 0;
  for (int c = 0; c < 3 * grid.faceCount(); ++c) {
    const Vec3 a = grid.positions[grid.vertex(TriMesh::next(c))], b = grid.positions[grid.vertex(TriMesh::prev(c))];
    if (std::abs(a.y() - 0.5) < 1e-9 && std::abs(b.y() - 0.5) < 1e-9 && std::max(a.x(), b.x()) < 0.5 + 1e-9) {
      cutCorner[c] = 1;
      ++marked;
    }
  }
  ASSERT_EQ(marked, 2 * n / 2);  // n/2 interior edges, each seen from its two faces
  const Expected<CutSurface> cut = cutAlongEdges(grid, cutCorner);
  ASSERT_TRUE(cut) << cut.status().message;
  // The chain's vertices but its inner end split in two: n/2 new vertices (the boundary one too).
  EXPECT_EQ(cut->mesh.vertexCount(), grid.vertexCount() + n / 2);
  const test::Recount in = test::recount(grid.triangles, grid.vertexCount());
  const test::Recount rc = test::recount(cut->mesh.triangles, cut->mesh.vertexCount());
  EXPECT_EQ(rc.components, 1);
  EXPECT_EQ(rc.boundaryLoops, 1);  // the slit opens the outer loop, it does not make a new one
  EXPECT_EQ(rc.boundaryEdges, in.boundaryEdges + 2 * (n / 2));
  EXPECT_EQ(rc.eulerCharacteristic, 1);
}

// Seeds shared by area among the sides of a 1 x 1 x 4 box: 18 regions are 4 on each long side and
// 1 on each end (the centroidal energy's best split), and no region crosses a box edge.
TEST(SharpCut, SegmentationSharesSeedsAmongPiecesByArea) {
  const TriMesh m = box(1.0, 1.0, 4.0, 0.125);
  SegmentationParams p;
  p.regions = 18;
  p.featureAlignment = 0.0;  // the cut alone
  const Expected<SegmentationResult> r = segmentSurface(m, {}, p);
  ASSERT_TRUE(r) << r.status().message;
  EXPECT_EQ(r->regions, 18);
  EXPECT_EQ(r->surfacePieces, 6);
  std::vector<int> sideOfRegion(r->regions, -1);
  std::vector<double> area(r->regions, 0.0);
  for (int f = 0; f < m.faceCount(); ++f) {
    const int region = r->faceRegion[f], side = sideOf(m, f);
    if (sideOfRegion[region] < 0) sideOfRegion[region] = side;
    EXPECT_EQ(sideOfRegion[region], side) << "region " << region << " crosses a box edge";
    area[region] += 0.5 * areaNormal(m, f).norm();
  }
  std::array<int, 6> perSide{};
  for (int s : sideOfRegion) ++perSide[s];
  for (int s = 0; s < 6; ++s) EXPECT_EQ(perSide[s], s / 2 == 2 ? 1 : 4) << "side " << s;
  // Even areas: the ends' squares are the long sides' quarters.
  for (double a : area) EXPECT_NEAR(a, 1.0, 0.25);
}

// A speck: one vertex of a flat grid pulled up into a spike, its faces cut off by sharp edges.
// Cut off, it would be a region of its own inside another (a ring around it), so below a quarter
// of the mean region area it is left joined; above, it is a piece and gets its own region.
TEST(SharpCut, SegmentationLeavesSpecksJoined) {
  TriMesh grid = test::planeGrid(20);
  int centre = 0;
  for (int v = 0; v < grid.vertexCount(); ++v)
    if ((grid.positions[v] - Vec3(0.5, 0.5, 0.0)).norm() < (grid.positions[centre] - Vec3(0.5, 0.5, 0.0)).norm())
      centre = v;
  grid.positions[centre].z() = 0.15;
  const TriMesh spike = *buildTriMesh(grid.positions, grid.triangles);
  const Expected<CutSurface> cut = cutAlongEdges(spike, sharpEdgeCorners(spike, 60.0));
  ASSERT_TRUE(cut);
  const int pieces = cut->mesh.topology.components;
  ASSERT_GE(pieces, 2) << "the spike's faces are cut off the rest";
  double speck = 0.0, total = 0.0;
  for (int f = 0; f < spike.faceCount(); ++f) {
    const double a = 0.5 * areaNormal(spike, f).norm();
    total += a;
    if (cut->mesh.topology.componentOfVertex[cut->mesh.triangles[f][0]] !=
        cut->mesh.topology.componentOfVertex[cut->mesh.triangles[0][0]])
      speck += a;
  }
  const auto segment = [&](int regions) {
    SegmentationParams p;
    p.featureAlignment = 0.0;
    p.regions = regions;
    return segmentSurface(spike, {}, p);
  };
  ASSERT_LT(speck, 0.25 * total / 4);
  const Expected<SegmentationResult> few = segment(4);
  ASSERT_TRUE(few) << few.status().message;
  EXPECT_EQ(few->surfacePieces, 1);
  EXPECT_EQ(few->regions, 4);
  ASSERT_GT(speck, 0.25 * total / 100);
  const Expected<SegmentationResult> many = segment(100);
  ASSERT_TRUE(many) << many.status().message;
  EXPECT_GT(many->surfacePieces, 1);
  EXPECT_GT(many->sharpEdges, 0);
}

}  // namespace
}  // namespace gr
