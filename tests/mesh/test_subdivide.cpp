// Midpoint subdivision: same surface, same topology, 4x faces per level, and every vertex's
// recorded origin on the original mesh reproduces its position.
#include <gtest/gtest.h>

#include "core/mesh/subdivide.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

TEST(Subdivide, KeepsTopologyAndKnowsWhereEachVertexLies) {
  for (const char* name : {"fandisk.off", "knot2.off", "mech-holes-shark.off"}) {
    SCOPED_TRACE(name);
    const TriMesh m = test::loadRealMesh(name);
    for (int levels : {0, 1, 2}) {
      const auto s = subdivideMidpoint(m, levels);
      ASSERT_TRUE(s);
      EXPECT_EQ(s->mesh.faceCount(), m.faceCount() << (2 * levels));
      EXPECT_EQ(s->mesh.topology.components, m.topology.components);
      EXPECT_EQ(s->mesh.topology.genus, m.topology.genus);
      EXPECT_EQ(s->mesh.topology.boundaryLoops, m.topology.boundaryLoops);
      EXPECT_TRUE(s->mesh.topology.isManifold());
      EXPECT_EQ(s->mesh.topology.inconsistentEdges, m.topology.inconsistentEdges);
      ASSERT_EQ(s->origin.size(), static_cast<size_t>(s->mesh.vertexCount()));
      double worst = 0.0;
      for (int v = 0; v < s->mesh.vertexCount(); ++v) {
        const SurfacePoint& o = s->origin[v];
        if (v < m.vertexCount()) {
          EXPECT_EQ(o.vertex, v);
        }
        if (o.vertex < 0) {
          EXPECT_NEAR(o.bary.sum(), 1.0, 1e-12);
          EXPECT_GE(o.bary.minCoeff(), -1e-12);
        }
        worst = std::max(worst, (o.position(m) - s->mesh.positions[v]).norm());
      }
      EXPECT_LT(worst, 1e-12 * m.boundingBoxDiagonal());
    }
  }
  EXPECT_EQ(subdivideMidpoint(test::planeGrid(2), -1).status().code, StatusCode::InvalidInput);
}

TEST(Subdivide, RefusesNonManifoldEdgesWithNonManifold) {
  // Edge 0-1 shared by three triangles (a book with three pages).
  const auto m =
      buildTriMesh({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  ASSERT_TRUE(m) << m.status().message;
  ASSERT_EQ(m->topology.nonManifoldEdges, 1);
  for (int levels : {0, 1}) EXPECT_EQ(subdivideMidpoint(*m, levels).status().code, StatusCode::NonManifold);
}

}  // namespace
}  // namespace gr
