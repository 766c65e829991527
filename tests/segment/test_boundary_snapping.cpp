// Boundary snapping (core/segment/boundary_snapping.h) on meshes where the answer is known: a
// plane folded by 90 degrees along a grid line, two cells whose boundary runs one face column
// beside the fold. Regions are recounted as disks by the independent soup count of tests/support.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/segment/boundary_snapping.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

constexpr int kN = 20;     // grid of kN x kN squares on [0, 1]^2
constexpr int kFold = 10;  // the fold: the grid line x = kFold / kN
constexpr int kCut = 11;   // cells: x <= (kCut - 1) / kN is cell 0

/// The grid, folded up by 90 degrees along x = 0.5 when `folded`.
TriMesh roof(bool folded) {
  TriMesh m = test::planeGrid(kN);
  for (Vec3& p : m.positions)
    if (folded && p.x() > 0.5) p = Vec3(0.5, p.y(), p.x() - 0.5);
  return m;
}

int column(const TriMesh& flat, int v) { return static_cast<int>(std::lround(flat.positions[v].x() * kN)); }

struct Labels {
  std::vector<int> cell, face;
};

/// Cells split at column kCut; each face takes the cell of its vertex with the least column
/// (as fronts from the left would label it): the region boundary lies on the line x = kCut / kN.
Labels labelsOf(const TriMesh& flat) {
  Labels l;
  for (int v = 0; v < flat.vertexCount(); ++v) l.cell.push_back(column(flat, v) < kCut ? 0 : 1);
  for (const Tri& t : flat.triangles) {
    int least = t[0];
    for (int v : t)
      if (column(flat, v) < column(flat, least)) least = v;
    l.face.push_back(l.cell[least]);
  }
  return l;
}

/// Each region recounted as a triangle soup: one component, one boundary loop, genus 0.
void expectDisks(const TriMesh& m, const std::vector<int>& face) {
  for (int r = 0; r < 2; ++r) {
    std::vector<Tri> tris;
    for (int f = 0; f < m.faceCount(); ++f)
      if (face[f] == r) tris.push_back(m.triangles[f]);
    const test::Recount rc = test::recount(tris, m.vertexCount());
    EXPECT_EQ(rc.components, 1) << "region " << r;
    EXPECT_EQ(rc.boundaryLoops, 1) << "region " << r;
    EXPECT_EQ(rc.genusSum, 0) << "region " << r;
    EXPECT_TRUE(rc.manifoldVertices) << "region " << r;
  }
}

/// The columns of the vertices of the edges between the two regions.
std::vector<int> boundaryColumns(const TriMesh& m, const TriMesh& flat, const std::vector<int>& face) {
  std::vector<int> columns;
  for (int c = 0; c < 3 * m.faceCount(); ++c) {
    const int o = m.oppositeCorner[c];
    if (o < c || face[c / 3] == face[o / 3]) continue;  // each edge once
    columns.push_back(column(flat, m.vertex(TriMesh::next(c))));
    columns.push_back(column(flat, m.vertex(TriMesh::prev(c))));
  }
  return columns;
}

TEST(BoundarySnapping, MovesTheBoundaryOntoTheFold) {
  const TriMesh flat = roof(false), folded = roof(true);
  Labels l = labelsOf(flat);
  for (int c : boundaryColumns(folded, flat, l.face)) ASSERT_EQ(c, kCut);
  const int moved = snapBoundariesToSharpEdges(folded, l.cell, l.face, 2);
  // The face column between the fold and the old boundary, two triangles per square.
  EXPECT_EQ(moved, 2 * kN);
  const std::vector<int> columns = boundaryColumns(folded, flat, l.face);
  EXPECT_EQ(static_cast<int>(columns.size()), 2 * kN);  // kN edges, two ends each
  for (int c : columns) EXPECT_EQ(c, kFold);
  expectDisks(folded, l.face);
}

TEST(BoundarySnapping, LeavesAFlatStraightBoundaryWhereItIs) {
  const TriMesh flat = roof(false);
  Labels l = labelsOf(flat);
  const std::vector<int> before = l.face;
  // Every straight line across the band costs the same: nothing is gained by moving.
  EXPECT_EQ(snapBoundariesToSharpEdges(flat, l.cell, l.face, 2), 0);
  EXPECT_EQ(l.face, before);
  expectDisks(flat, l.face);
}

}  // namespace
}  // namespace gr
