// Tests of TriMesh: adjacency (opposite corners, vertex -> corner CSR) and topology counts.
//
// Oracles: (1) closed-form values of fixtures built in code (a tetrahedron has chi 2, a torus
// chi 0, a grid n boundary edges 4n); (2) the independent recount of tests/support
// (test::recount: edges kept in std::maps, each vertex's link checked to be one cycle or one path,
// components and boundary loops by union-find of its own); (3) real meshes re-read by a small OFF
// parser of our own. None of these share code with core/mesh/tri_mesh.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/base/math.h"
#include "core/mesh/orientation.h"
#include "core/mesh/tri_mesh.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

using EdgeKey = std::pair<int, int>;
EdgeKey key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

test::Recount recount(const TriMesh& m) { return test::recount(m.triangles, m.vertexCount()); }

/// Components are equal up to renumbering: same partition of the vertices, same isolated ones.
void expectSamePartition(const std::vector<int>& got, const std::vector<int>& ref) {
  ASSERT_EQ(got.size(), ref.size());
  std::map<int, int> refOfGot, gotOfRef;
  for (size_t v = 0; v < got.size(); ++v) {
    ASSERT_EQ(got[v] < 0, ref[v] < 0) << "vertex " << v;
    if (got[v] < 0) continue;
    auto [it, inserted] = refOfGot.emplace(got[v], ref[v]);
    ASSERT_EQ(it->second, ref[v]) << "vertex " << v << ": component " << got[v] << " spans two true components";
    auto [jt, inserted2] = gotOfRef.emplace(ref[v], got[v]);
    ASSERT_EQ(jt->second, got[v]) << "vertex " << v << ": true component " << ref[v] << " is split";
  }
}

/// Compares the code's topology with an independent recount (of the mesh's triangles, or of the
/// file's). Loops and genus only when the recount could define them (the boundary is a union of simple
/// oriented loops).
void expectTopologyMatches(const Topology& t, const test::Recount& r) {
  EXPECT_EQ(t.boundaryEdges, r.boundaryEdges);
  EXPECT_EQ(t.nonManifoldEdges, r.nonManifoldEdges);
  EXPECT_EQ(t.nonManifoldVertices, r.nonManifoldVertices);
  EXPECT_EQ(t.isolatedVertices, r.isolated);
  EXPECT_EQ(t.inconsistentEdges, r.inconsistentEdges);
  EXPECT_EQ(t.components, r.components);
  EXPECT_EQ(t.eulerCharacteristic, r.eulerCharacteristic);
  if (r.simpleBoundary) {
    EXPECT_EQ(t.boundaryLoops, r.boundaryLoops);
    EXPECT_EQ(t.genus, r.genusSum);
  }
  expectSamePartition(t.componentOfVertex, r.componentOfVertex);
  EXPECT_EQ(t.isManifold(), r.nonManifoldEdges == 0 && r.nonManifoldVertices == 0);
}

void expectTopologyMatchesRecount(const TriMesh& m) {
  SCOPED_TRACE("topology vs independent recount");
  expectTopologyMatches(m.topology, recount(m));
}

// ---------------------------------------------------------------------------------------------
// Adjacency invariants, checked against a std::map of edges.

void expectAdjacencyConsistent(const TriMesh& m) {
  SCOPED_TRACE("adjacency invariants");
  const int nv = m.vertexCount(), nf = m.faceCount(), nc = 3 * nf;

  // Vertex -> corner CSR: exactly the corners at each vertex, each corner once.
  ASSERT_EQ(static_cast<int>(m.vertexCornerBegin.size()), nv + 1);
  ASSERT_EQ(m.vertexCornerBegin.front(), 0);
  ASSERT_EQ(m.vertexCornerBegin.back(), nc);
  ASSERT_EQ(static_cast<int>(m.vertexCorners.size()), nc);
  std::vector<std::vector<int>> expected(nv);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) expected[m.triangles[f][k]].push_back(3 * f + k);
  int mismatched = 0;
  for (int v = 0; v < nv; ++v) {
    ASSERT_LE(m.vertexCornerBegin[v], m.vertexCornerBegin[v + 1]) << "vertex " << v;
    std::vector<int> got(m.cornersBegin(v), m.cornersEnd(v));
    std::sort(got.begin(), got.end());
    if (got != expected[v] && ++mismatched <= 5) ADD_FAILURE() << "corners of vertex " << v << " differ";
    EXPECT_EQ(m.valence(v), static_cast<int>(expected[v].size()));
  }
  EXPECT_EQ(mismatched, 0);

  // Corner helpers.
  for (int c = 0; c < std::min(nc, 30); ++c) {
    EXPECT_EQ(TriMesh::face(c), c / 3);
    EXPECT_EQ(TriMesh::face(TriMesh::next(c)), c / 3);
    EXPECT_EQ(TriMesh::face(TriMesh::prev(c)), c / 3);
    EXPECT_EQ(TriMesh::next(TriMesh::prev(c)), c);
    EXPECT_EQ(TriMesh::next(TriMesh::next(TriMesh::next(c))), c);
    EXPECT_EQ(m.vertex(TriMesh::next(c)), m.triangles[c / 3][(c % 3 + 1) % 3]);
  }

  // Opposite corners vs the number of faces on each edge.
  std::map<EdgeKey, int> faceCount;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++faceCount[key(t[k], t[(k + 1) % 3])];
  ASSERT_EQ(static_cast<int>(m.oppositeCorner.size()), nc);
  int bad = 0;
  for (int c = 0; c < nc && bad < 10; ++c) {
    const int p = m.vertex(TriMesh::next(c)), q = m.vertex(TriMesh::prev(c));
    const int n = faceCount[key(p, q)];
    const int o = m.oppositeCorner[c];
    if (n == 1) {
      if (o != kBoundary) ++bad, ADD_FAILURE() << "corner " << c << ": boundary edge, opposite " << o;
    } else if (n >= 3) {
      if (o != kNonManifold) ++bad, ADD_FAILURE() << "corner " << c << ": edge with " << n << " faces, opposite " << o;
    } else {
      if (o < 0 || o >= nc) {
        ++bad, ADD_FAILURE() << "corner " << c << ": manifold edge, opposite " << o;
        continue;
      }
      if (m.oppositeCorner[o] != c) ++bad, ADD_FAILURE() << "corner " << c << ": opposite is not an involution";
      if (TriMesh::face(o) == TriMesh::face(c)) ++bad, ADD_FAILURE() << "corner " << c << ": opposite in same face";
      if (key(m.vertex(TriMesh::next(o)), m.vertex(TriMesh::prev(o))) != key(p, q))
        ++bad, ADD_FAILURE() << "corner " << c << ": opposite corner faces another edge";
      if (m.vertex(o) == p || m.vertex(o) == q) ++bad, ADD_FAILURE() << "corner " << c << ": opposite on the edge";
    }
  }
  EXPECT_EQ(bad, 0);
}

void expectValid(const TriMesh& m) {
  expectAdjacencyConsistent(m);
  expectTopologyMatchesRecount(m);
}

TriMesh build(std::vector<Vec3> p, std::vector<Tri> t) {
  Expected<TriMesh> m = buildTriMesh(std::move(p), std::move(t));
  EXPECT_TRUE(m.hasValue()) << m.status().message;
  return m ? std::move(m).value() : TriMesh{};
}

// ---------------------------------------------------------------------------------------------
// Fixtures built in code.

std::vector<Vec3> tetraPositions(const Vec3& offset = Vec3::Zero()) {
  return {offset + Vec3(0, 0, 0), offset + Vec3(1, 0, 0), offset + Vec3(0, 1, 0), offset + Vec3(0, 0, 1)};
}
std::vector<Tri> tetraFaces(int o = 0) {
  // Outward-consistent: every edge is used once in each direction.
  return {{o + 0, o + 2, o + 1}, {o + 0, o + 1, o + 3}, {o + 0, o + 3, o + 2}, {o + 1, o + 2, o + 3}};
}

/// Centre vertex 0 and a ring of k vertices; `closed` = the fan goes all the way round.
void fan(int k, bool closed, double apexHeight, std::vector<Vec3>& p, std::vector<Tri>& t, int offset = 0,
         const Vec3& centre = Vec3::Zero()) {
  p.push_back(centre + Vec3(0, 0, apexHeight));
  for (int i = 0; i < k; ++i) {
    const double a = 2 * kPi * i / k;
    p.push_back(centre + Vec3(std::cos(a), std::sin(a), 0));
  }
  const int faces = closed ? k : k - 1;
  for (int i = 0; i < faces; ++i) t.push_back({offset, offset + 1 + i, offset + 1 + (i + 1) % k});
}

/// Torus: an m x n quad grid wrapped in both directions, each quad split into two triangles.
TriMesh torus(int m, int n, double R = 2.0, double r = 0.7) {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) {
      const double u = 2 * kPi * i / m, v = 2 * kPi * j / n;
      p.emplace_back((R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [m, n](int i, int j) { return (j % n) * m + (i % m); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < m; ++i) {
      t.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      t.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return build(std::move(p), std::move(t));
}

// ---------------------------------------------------------------------------------------------
// Fixture tests: closed-form expectations, plus the recount.

TEST(TriMeshFixtures, SingleTriangle) {
  TriMesh m = build({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
  ASSERT_EQ(m.vertexCount(), 3);
  ASSERT_EQ(m.faceCount(), 1);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(m.oppositeCorner[c], kBoundary);
  EXPECT_EQ(m.topology.boundaryEdges, 3);
  EXPECT_EQ(m.topology.boundaryLoops, 1);
  EXPECT_EQ(m.topology.components, 1);
  EXPECT_EQ(m.topology.eulerCharacteristic, 1);
  EXPECT_EQ(m.topology.genus, 0);
  EXPECT_TRUE(m.topology.isManifold());
  for (int v = 0; v < 3; ++v) EXPECT_EQ(m.valence(v), 1);
  EXPECT_NEAR(m.boundingBoxDiagonal(), std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(m.meanEdgeLength(), (2.0 + std::sqrt(2.0)) / 3.0, 1e-15);
  expectValid(m);
}

TEST(TriMeshFixtures, ClosedTetrahedron) {
  TriMesh m = build(tetraPositions(), tetraFaces());
  const Topology& t = m.topology;
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.boundaryEdges, 0);
  EXPECT_EQ(t.boundaryLoops, 0);
  EXPECT_EQ(t.eulerCharacteristic, 2);
  EXPECT_EQ(t.inconsistentEdges, 0);
  EXPECT_TRUE(t.isManifold());
  for (int c = 0; c < 12; ++c) EXPECT_GE(m.oppositeCorner[c], 0) << "corner " << c;
  for (int v = 0; v < 4; ++v) EXPECT_EQ(m.valence(v), 3);
  expectValid(m);
}

TEST(TriMeshFixtures, OneRingFanIsADisk) {
  for (int k : {3, 6, 11}) {
    SCOPED_TRACE("valence " + std::to_string(k));
    std::vector<Vec3> p;
    std::vector<Tri> t;
    fan(k, /*closed=*/true, 0.0, p, t);
    TriMesh m = build(p, t);
    EXPECT_EQ(m.valence(0), k);
    EXPECT_EQ(m.topology.boundaryEdges, k);
    EXPECT_EQ(m.topology.boundaryLoops, 1);
    EXPECT_EQ(m.topology.eulerCharacteristic, 1);
    EXPECT_EQ(m.topology.genus, 0);
    EXPECT_EQ(m.topology.components, 1);
    EXPECT_TRUE(m.topology.isManifold());
    // Spokes are interior edges: the corners facing them (at ring vertices) have an opposite.
    for (const int* c = m.cornersBegin(0); c != m.cornersEnd(0); ++c) {
      EXPECT_EQ(m.oppositeCorner[*c], kBoundary) << "the rim edge facing the centre is a boundary";
      EXPECT_GE(m.oppositeCorner[TriMesh::next(*c)], 0);
      EXPECT_GE(m.oppositeCorner[TriMesh::prev(*c)], 0);
    }
    expectValid(m);
  }
}

TEST(TriMeshFixtures, OpenFanHasItsCentreOnTheBoundary) {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  fan(6, /*closed=*/false, 0.0, p, t);
  TriMesh m = build(p, t);
  EXPECT_EQ(m.topology.boundaryEdges, 5 + 2);
  EXPECT_EQ(m.topology.boundaryLoops, 1);
  EXPECT_EQ(m.topology.eulerCharacteristic, 1);
  EXPECT_EQ(m.topology.nonManifoldVertices, 0);
  expectValid(m);
}

TEST(TriMeshFixtures, OpenCone) {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  fan(8, /*closed=*/true, 1.5, p, t);
  TriMesh m = build(p, t);
  EXPECT_EQ(m.topology.boundaryEdges, 8);
  EXPECT_EQ(m.topology.boundaryLoops, 1);
  EXPECT_EQ(m.topology.genus, 0);
  EXPECT_EQ(m.topology.eulerCharacteristic, 1);
  EXPECT_TRUE(m.topology.isManifold());
  // Slant edge sqrt(1 + 1.5^2) (8 spokes, each in two faces) and rim chord 2 sin(pi/8) (8 edges).
  const double slant = std::sqrt(1 + 1.5 * 1.5), chord = 2 * std::sin(kPi / 8);
  EXPECT_NEAR(m.meanEdgeLength(), (16 * slant + 8 * chord) / 24.0, 1e-12);
  expectValid(m);
}

TEST(TriMeshFixtures, PlaneGridHasOneBoundaryLoop) {
  for (int n : {1, 2, 5, 16}) {
    SCOPED_TRACE("n = " + std::to_string(n));
    TriMesh m = test::planeGrid(n);
    EXPECT_EQ(m.vertexCount(), (n + 1) * (n + 1));
    EXPECT_EQ(m.faceCount(), 2 * n * n);
    EXPECT_EQ(m.topology.boundaryEdges, 4 * n);
    EXPECT_EQ(m.topology.boundaryLoops, 1);
    EXPECT_EQ(m.topology.components, 1);
    EXPECT_EQ(m.topology.eulerCharacteristic, 1);
    EXPECT_EQ(m.topology.genus, 0);
    EXPECT_EQ(m.topology.inconsistentEdges, 0);
    EXPECT_TRUE(m.topology.isManifold());
    EXPECT_NEAR(m.boundingBoxDiagonal(), std::sqrt(2.0), 1e-12);
    expectValid(m);
  }
}

TEST(TriMeshFixtures, IcosphereIsClosedGenusZero) {
  for (int level : {0, 1, 3}) {
    SCOPED_TRACE("level " + std::to_string(level));
    TriMesh m = test::icosphere(level);
    const int f = 20 << (2 * level);
    EXPECT_EQ(m.faceCount(), f);
    EXPECT_EQ(m.vertexCount(), f / 2 + 2);
    EXPECT_EQ(m.topology.boundaryEdges, 0);
    EXPECT_EQ(m.topology.boundaryLoops, 0);
    EXPECT_EQ(m.topology.eulerCharacteristic, 2);
    EXPECT_EQ(m.topology.genus, 0);
    EXPECT_EQ(m.topology.components, 1);
    EXPECT_EQ(m.topology.inconsistentEdges, 0);
    EXPECT_TRUE(m.topology.isManifold());
    expectValid(m);
  }
}

TEST(TriMeshFixtures, TorusHasGenusOne) {
  TriMesh m = torus(12, 7);
  EXPECT_EQ(m.vertexCount(), 84);
  EXPECT_EQ(m.topology.boundaryEdges, 0);
  EXPECT_EQ(m.topology.boundaryLoops, 0);
  EXPECT_EQ(m.topology.eulerCharacteristic, 0);
  EXPECT_EQ(m.topology.genus, 1);
  EXPECT_EQ(m.topology.components, 1);
  EXPECT_EQ(m.topology.inconsistentEdges, 0);
  EXPECT_TRUE(m.topology.isManifold());
  expectValid(m);
}

TEST(TriMeshFixtures, TwoDisjointTetrahedraAreTwoComponents) {
  std::vector<Vec3> p = tetraPositions();
  std::vector<Vec3> p2 = tetraPositions(Vec3(5, 0, 0));
  p.insert(p.end(), p2.begin(), p2.end());
  std::vector<Tri> t = tetraFaces(0), t2 = tetraFaces(4);
  t.insert(t.end(), t2.begin(), t2.end());
  TriMesh m = build(p, t);
  const Topology& top = m.topology;
  EXPECT_EQ(top.components, 2);
  EXPECT_EQ(top.eulerCharacteristic, 4);
  EXPECT_EQ(top.genus, 0);
  ASSERT_EQ(top.componentOfVertex.size(), 8u);
  for (int v = 1; v < 4; ++v) EXPECT_EQ(top.componentOfVertex[v], top.componentOfVertex[0]);
  for (int v = 5; v < 8; ++v) EXPECT_EQ(top.componentOfVertex[v], top.componentOfVertex[4]);
  EXPECT_NE(top.componentOfVertex[0], top.componentOfVertex[4]);
  // facesOfComponent: faces 0..3 in the first, 4..7 in the second.
  EXPECT_EQ(facesOfComponent(m, top.componentOfVertex[0]), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(facesOfComponent(m, top.componentOfVertex[4]), (std::vector<int>{4, 5, 6, 7}));
  expectValid(m);
}

TEST(TriMeshFixtures, ThreeTrianglesOnOneEdgeMakeANonManifoldEdge) {
  // Edge 0-1 shared by three triangles (a "book" with three pages).
  TriMesh m = build({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  EXPECT_EQ(m.topology.nonManifoldEdges, 1);
  EXPECT_EQ(m.topology.boundaryEdges, 6);
  EXPECT_FALSE(m.topology.isManifold());
  EXPECT_EQ(m.topology.components, 1);
  // The corners facing edge 0-1 are those at vertices 2, 3, 4: all kNonManifold.
  for (int c = 0; c < 9; ++c) {
    const int v = m.vertex(c);
    EXPECT_EQ(m.oppositeCorner[c] == kNonManifold, v >= 2) << "corner " << c;
  }
  // V - E + F counts the shared edge once: 5 - 7 + 3.
  EXPECT_EQ(m.topology.eulerCharacteristic, 1);
  expectValid(m);
}

TEST(TriMeshFixtures, TwoTetrahedraJoinedAtOneVertex) {
  // Second tetrahedron shares vertex 3 (its local vertex 0) with the first.
  std::vector<Vec3> p = tetraPositions();
  p.push_back(Vec3(1, 0, 1));
  p.push_back(Vec3(0, 1, 1));
  p.push_back(Vec3(0, 0, 2));
  std::vector<Tri> t = tetraFaces(0);
  for (Tri f : tetraFaces(0)) {
    for (int& v : f) v = v == 0 ? 3 : v + 3;  // local 0 -> 3, 1..3 -> 4..6
    t.push_back(f);
  }
  TriMesh m = build(p, t);
  EXPECT_EQ(m.topology.nonManifoldVertices, 1);
  EXPECT_EQ(m.topology.nonManifoldEdges, 0);
  EXPECT_EQ(m.topology.boundaryEdges, 0);
  EXPECT_EQ(m.topology.components, 1);
  EXPECT_FALSE(m.topology.isManifold());
  EXPECT_EQ(m.topology.eulerCharacteristic, 7 - 12 + 8);
  expectValid(m);
}

TEST(TriMeshFixtures, TwoFansJoinedAtOneVertex) {
  std::vector<Vec3> p;
  std::vector<Tri> t;
  fan(5, true, 0.0, p, t);
  // A second fan whose ring passes through vertex 0 of the first: build it apart, then weld.
  std::vector<Vec3> p2;
  std::vector<Tri> t2;
  fan(5, true, 0.0, p2, t2, 0, Vec3(-1, 0, 0.0));  // its ring vertex at angle 0 is (0,0,0)
  std::vector<int> remap(p2.size());
  for (size_t i = 0; i < p2.size(); ++i) {
    if (i == 1) {
      remap[i] = 0;  // ring vertex at angle 0 == centre of the first fan
    } else {
      remap[i] = static_cast<int>(p.size());
      p.push_back(p2[i] + Vec3(0, 0, 1.0));
    }
  }
  for (Tri f : t2) {
    for (int& v : f) v = remap[v];
    t.push_back(f);
  }
  TriMesh m = build(p, t);
  EXPECT_EQ(m.topology.nonManifoldVertices, 1);
  EXPECT_EQ(m.topology.nonManifoldEdges, 0);
  EXPECT_EQ(m.topology.components, 1);
  EXPECT_EQ(m.topology.boundaryEdges, 10);
  EXPECT_FALSE(m.topology.isManifold());
  EXPECT_EQ(m.topology.eulerCharacteristic, 11 - 20 + 10);
  expectAdjacencyConsistent(m);
  expectTopologyMatchesRecount(m);
}

TEST(TriMeshFixtures, FlippedInteriorFaceGivesInconsistentEdges) {
  TriMesh grid = test::planeGrid(4);
  std::vector<Tri> t = grid.triangles;
  // Face of square (1, 1): all three edges interior.
  const int f = 2 * (1 * 4 + 1);
  std::swap(t[f][1], t[f][2]);
  TriMesh m = build(grid.positions, t);
  EXPECT_EQ(m.topology.inconsistentEdges, 3);
  EXPECT_EQ(m.topology.nonManifoldVertices, 0) << "orientation does not change the fans";
  EXPECT_EQ(m.topology.boundaryLoops, 1);
  EXPECT_EQ(m.topology.genus, 0);
  EXPECT_EQ(m.topology.eulerCharacteristic, 1);
  expectValid(m);
}

TEST(TriMeshFixtures, FlippedFaceAtTheBoundaryKeepsVerticesManifold) {
  TriMesh grid = test::planeGrid(4);
  std::vector<Tri> t = grid.triangles;
  // Second triangle of square (1, 0): vertices (1,0), (2,1), (1,1); edges all interior, but its
  // vertex (1,0) lies on the boundary, where the fan is open.
  const int f = 2 * (0 * 4 + 1) + 1;
  std::swap(t[f][1], t[f][2]);
  TriMesh m = build(grid.positions, t);
  EXPECT_EQ(m.topology.inconsistentEdges, 3);
  EXPECT_EQ(m.topology.nonManifoldVertices, 0) << "orientation does not change the fans";
  EXPECT_TRUE(m.topology.isManifold());
  EXPECT_EQ(m.topology.boundaryLoops, 1);
  expectValid(m);
}

TEST(TriMeshFixtures, IsolatedVertex) {
  std::vector<Vec3> p = tetraPositions();
  p.insert(p.begin() + 2, Vec3(9, 9, 9));  // vertex 2 is in no face
  std::vector<Tri> t = tetraFaces();
  for (Tri& f : t)
    for (int& v : f)
      if (v >= 2) ++v;
  TriMesh m = build(p, t);
  EXPECT_EQ(m.topology.isolatedVertices, 1);
  EXPECT_EQ(m.topology.componentOfVertex[2], -1);
  EXPECT_EQ(m.valence(2), 0);
  EXPECT_EQ(m.topology.components, 1);
  EXPECT_EQ(m.topology.eulerCharacteristic, 2) << "isolated vertices are not counted in chi";
  EXPECT_EQ(m.topology.genus, 0);
  expectValid(m);
}

// ---------------------------------------------------------------------------------------------
// Real meshes: re-read with our own OFF parser, recount, compare.

struct OffData {
  std::vector<Vec3> positions;
  std::vector<Tri> triangles;
  bool ok = false;
};

/// Minimal OFF reader (header "OFF", counts, vertices, faces; '#' comments). Triangles only.
OffData readOff(const std::string& path) {
  OffData d;
  std::ifstream in(path);
  std::stringstream clean;
  std::string line;
  while (std::getline(in, line)) clean << line.substr(0, line.find('#')) << '\n';
  std::string header;
  clean >> header;
  if (header != "OFF") return d;
  long nv = 0, nf = 0, ne = 0;
  clean >> nv >> nf >> ne;
  d.positions.resize(nv);
  for (long i = 0; i < nv; ++i) clean >> d.positions[i].x() >> d.positions[i].y() >> d.positions[i].z();
  for (long i = 0; i < nf; ++i) {
    int k = 0;
    clean >> k;
    if (k != 3) return d;
    Tri t;
    clean >> t[0] >> t[1] >> t[2];
    std::getline(clean, line);  // optional colour
    d.triangles.push_back(t);
  }
  d.ok = static_cast<bool>(clean);
  return d;
}

class RealMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(RealMesh, AdjacencyAndTopologyMatchAnIndependentRecount) {
  const std::string name = GetParam();
  TriMesh m = test::loadRealMesh(name);
  ASSERT_GT(m.vertexCount(), 0);
  OffData off = readOff(test::meshPath(name));
  ASSERT_TRUE(off.ok) << "cannot parse " << name;
  // The loader keeps the file's vertices and faces in order.
  ASSERT_EQ(m.vertexCount(), static_cast<int>(off.positions.size()));
  ASSERT_EQ(m.faceCount(), static_cast<int>(off.triangles.size()));
  const double tol = 1e-6 * m.boundingBoxDiagonal();  // the file is text; vcglib may parse floats
  for (int v = 0; v < m.vertexCount(); ++v)
    ASSERT_LE((m.positions[v] - off.positions[v]).norm(), tol) << "vertex " << v;
  for (int f = 0; f < m.faceCount(); ++f) ASSERT_EQ(m.triangles[f], off.triangles[f]) << "face " << f;

  expectAdjacencyConsistent(m);
  const test::Recount r = test::recount(off.triangles, static_cast<int>(off.positions.size()));
  ASSERT_TRUE(r.simpleBoundary) << name << ": boundary is not a union of simple loops";
  expectTopologyMatches(m.topology, r);
  std::cout << "[ mesh     ] " << name << ": V " << m.vertexCount() << ", F " << m.faceCount() << ", components "
            << r.components << ", chi " << r.eulerCharacteristic << ", boundary loops " << r.boundaryLoops << ", genus "
            << r.genusSum << "\n";
}

INSTANTIATE_TEST_SUITE_P(Meshes, RealMesh,
                         ::testing::Values("fandisk.off", "knot2.off", "mech-holes-shark.off",
                                           "elephant-with-holes.off", "eight.off", "handle.off", "blobby_3cc.off",
                                           "sphere.off"),
                         [](const ::testing::TestParamInfo<const char*>& p) {
                           std::string s = p.param;
                           s = s.substr(0, s.find('.'));
                           std::replace(s.begin(), s.end(), '-', '_');
                           return s;
                         });

TEST(RealMeshTopology, FandiskIsAClosedSphere) {
  TriMesh m = test::loadRealMesh("fandisk.off");
  ASSERT_GT(m.vertexCount(), 0);
  EXPECT_EQ(m.topology.components, 1);
  EXPECT_EQ(m.topology.boundaryEdges, 0);
  EXPECT_EQ(m.topology.eulerCharacteristic, 2);
  EXPECT_EQ(m.topology.genus, 0);
  EXPECT_TRUE(m.topology.isManifold());
}

TEST(RealMeshTopology, Knot2IsTwoTori) {
  TriMesh m = test::loadRealMesh("knot2.off");
  ASSERT_GT(m.vertexCount(), 0);
  EXPECT_EQ(m.topology.components, 2);
  EXPECT_EQ(m.topology.genus, 2);
  EXPECT_EQ(m.topology.eulerCharacteristic, 0);
  EXPECT_EQ(m.topology.boundaryEdges, 0);
  EXPECT_TRUE(m.topology.isManifold());
  // Each component is a torus on its own: chi_i = V_i - E_i + F_i = 0 with E_i = 3 F_i / 2.
  for (int c = 0; c < 2; ++c) {
    const std::vector<int> faces = facesOfComponent(m, c);
    std::set<int> verts;
    for (int f : faces)
      for (int v : m.triangles[f]) {
        verts.insert(v);
        EXPECT_EQ(m.topology.componentOfVertex[v], c);
      }
    EXPECT_EQ(
        static_cast<long>(verts.size()) - 3 * static_cast<long>(faces.size()) / 2 + static_cast<long>(faces.size()), 0)
        << "component " << c;
  }
}

TEST(RealMeshTopology, EightIsADoubleTorus) {
  TriMesh m = test::loadRealMesh("eight.off");
  ASSERT_GT(m.vertexCount(), 0);
  EXPECT_EQ(m.topology.components, 1);
  EXPECT_EQ(m.topology.boundaryLoops, 0);
  EXPECT_EQ(m.topology.genus, 2);
  EXPECT_EQ(m.topology.eulerCharacteristic, -2);
}

TEST(RealMeshTopology, MechHolesSharkHasBoundaries) {
  TriMesh m = test::loadRealMesh("mech-holes-shark.off");
  ASSERT_GT(m.vertexCount(), 0);
  const test::Recount r = recount(m);
  EXPECT_GT(r.boundaryLoops, 0);
  EXPECT_EQ(m.topology.boundaryLoops, r.boundaryLoops);
  EXPECT_EQ(m.topology.boundaryEdges, r.boundaryEdges);
}

// ---------------------------------------------------------------------------------------------
// Bad input: the right code, and a message that names the culprit.

/// True if `msg` contains `word` followed by the number `n` as a whole number ("face 1", not
/// "face 12").
bool names(const std::string& msg, const std::string& word, long n) {
  return std::regex_search(msg, std::regex("\\b" + word + " " + std::to_string(n) + "(?![0-9])"));
}

TEST(TriMeshBadInput, EmptyPositions) {
  Expected<TriMesh> m = buildTriMesh({}, {});
  ASSERT_FALSE(m.hasValue());
  EXPECT_EQ(m.status().code, StatusCode::InvalidInput);
  EXPECT_NE(m.status().message.find("no vertices"), std::string::npos) << m.status().message;
}

TEST(TriMeshBadInput, PointCloudWithoutFaces) {
  Expected<TriMesh> m = buildTriMesh(tetraPositions(), {});
  ASSERT_FALSE(m.hasValue());
  EXPECT_EQ(m.status().code, StatusCode::InvalidInput);
  EXPECT_NE(m.status().message.find("no faces"), std::string::npos) << m.status().message;
}

TEST(TriMeshBadInput, IndexOutOfRange) {
  for (int bad : {4, 17, -1}) {
    std::vector<Tri> t = tetraFaces();
    t[2][1] = bad;
    Expected<TriMesh> m = buildTriMesh(tetraPositions(), t);
    ASSERT_FALSE(m.hasValue());
    EXPECT_EQ(m.status().code, StatusCode::InvalidInput);
    EXPECT_TRUE(names(m.status().message, "face", 2)) << m.status().message;
    EXPECT_NE(m.status().message.find(std::to_string(bad)), std::string::npos) << m.status().message;
  }
}

TEST(TriMeshBadInput, NonFiniteCoordinate) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    std::vector<Vec3> p = tetraPositions();
    p[3].y() = bad;
    Expected<TriMesh> m = buildTriMesh(p, tetraFaces());
    ASSERT_FALSE(m.hasValue());
    EXPECT_EQ(m.status().code, StatusCode::InvalidInput);
    EXPECT_TRUE(names(m.status().message, "vertex", 3)) << m.status().message;
  }
}

// Coordinates so large that squared distances overflow (found by an adversarial run: a vertex
// at 1e308 gave infinite edge lengths, unreached vertices, and a read at cell -1).
TEST(TriMeshBadInput, CoordinatesWhoseSquaredDistancesOverflow) {
  std::vector<Vec3> p = tetraPositions();
  p[2] = Vec3(1e200, 0.0, 0.0);
  Expected<TriMesh> m = buildTriMesh(p, tetraFaces());
  ASSERT_FALSE(m.hasValue());
  EXPECT_EQ(m.status().code, StatusCode::InvalidInput);
  EXPECT_NE(m.status().message.find("too large"), std::string::npos) << m.status().message;
  p[2] = Vec3(1e150, 0.0, 0.0);  // squares up to 1e300: still fine
  EXPECT_TRUE(buildTriMesh(p, tetraFaces()).hasValue());
}

TEST(TriMeshBadInput, FaceRepeatingAVertex) {
  std::vector<Tri> t = tetraFaces();
  t.push_back({1, 3, 1});
  Expected<TriMesh> m = buildTriMesh(tetraPositions(), t);
  ASSERT_FALSE(m.hasValue());
  EXPECT_EQ(m.status().code, StatusCode::Degenerate);
  EXPECT_TRUE(names(m.status().message, "face", 4)) << m.status().message;
  EXPECT_TRUE(names(m.status().message, "vertex", 1)) << m.status().message;

  t.back() = {0, 2, 2};
  m = buildTriMesh(tetraPositions(), t);
  ASSERT_FALSE(m.hasValue());
  EXPECT_EQ(m.status().code, StatusCode::Degenerate);
  EXPECT_TRUE(names(m.status().message, "vertex", 2)) << m.status().message;
}

// orientCoherently: a sphere with a third of its faces flipped gets exactly those faces back,
// two components are oriented each by its own majority, and a Moebius strip is refused.
TEST(OrientCoherently, RestoresTheFlippedFacesOfEachComponent) {
  const TriMesh a = test::icosphere(2), b = test::icosphere(1);
  std::vector<Vec3> pos = a.positions;
  std::vector<Tri> original = a.triangles;
  for (const Vec3& p : b.positions) pos.push_back(p + Vec3(3.0, 0.0, 0.0));
  // The second sphere inside out: its majority orientation is the reversed one, and stays.
  for (const Tri& t : b.triangles)
    original.push_back({t[0] + a.vertexCount(), t[2] + a.vertexCount(), t[1] + a.vertexCount()});
  std::vector<Tri> shuffled = original;
  std::vector<char> expected(shuffled.size(), 0);
  for (size_t f = 0; f < shuffled.size(); f += 3) {
    std::swap(shuffled[f][1], shuffled[f][2]);
    expected[f] = 1;
  }
  const TriMesh m = build(pos, shuffled);
  ASSERT_GT(m.topology.inconsistentEdges, 0);
  std::vector<char> flipped;
  const Expected<TriMesh> o = orientCoherently(m, &flipped);
  ASSERT_TRUE(o) << o.status().message;
  EXPECT_EQ(o->topology.inconsistentEdges, 0);
  EXPECT_EQ(flipped, expected);
  EXPECT_EQ(o->triangles, original);
  EXPECT_EQ(o->topology.components, 2);
  EXPECT_EQ(o->topology.genus, 0);
  // Already coherent: nothing flipped.
  const Expected<TriMesh> again = orientCoherently(*o, &flipped);
  ASSERT_TRUE(again);
  EXPECT_EQ(std::count(flipped.begin(), flipped.end(), 1), 0);
}

TEST(OrientCoherently, RefusesNonManifoldEdgesWithNonManifold) {
  // Edge 0-1 shared by three triangles.
  const TriMesh m =
      build({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  ASSERT_EQ(m.topology.nonManifoldEdges, 1);
  const Expected<TriMesh> o = orientCoherently(m);
  ASSERT_FALSE(o);
  EXPECT_EQ(o.status().code, StatusCode::NonManifold);
}

TEST(OrientCoherently, RefusesAMoebiusStrip) {
  const TriMesh m = test::moebiusStrip(12);
  ASSERT_TRUE(m.topology.isManifold());
  ASSERT_EQ(m.topology.boundaryLoops, 1) << "a Moebius strip has one boundary loop";
  const Expected<TriMesh> o = orientCoherently(m);
  ASSERT_FALSE(o);
  EXPECT_EQ(o.status().code, StatusCode::InvalidInput);
  EXPECT_NE(o.status().message.find("not orientable"), std::string::npos) << o.status().message;
}

}  // namespace
}  // namespace gr
