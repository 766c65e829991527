// Shared test helpers: mesh fixtures built in code, and the path of a real test mesh.
#pragma once

#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr::test {

/// Path of a mesh of the libcgal-demo set fetched by scripts/setup.sh ("fandisk.off").
std::string meshPath(const std::string& name);
/// Loads a real test mesh; fails the current test (ADD_FAILURE) and returns an empty mesh if absent.
TriMesh loadRealMesh(const std::string& name);

/// Regular n x n grid of squares on [0, size]^2 (z = 0), each square split into two triangles.
/// jitter in [0, 0.5): interior vertices moved by up to jitter * spacing, deterministically (seed).
TriMesh planeGrid(int n, double size = 1.0, double jitter = 0.0, unsigned seed = 1);
/// Icosphere of radius r, subdivided `level` times (level 0 = icosahedron).
TriMesh icosphere(int level, double r = 1.0);
/// Two planeGrid(n) meeting at one corner, (1, 1): the second turned by 180 degrees about it.
/// That vertex is non-manifold (two fans of faces); every edge is manifold.
TriMesh gridsMeetingAtACorner(int n);
/// The unit cube [0, 1]^3 in 12 triangles facing out; vertex i is (i & 1, i >> 1 & 1, i >> 2 & 1).
TriMesh unitCube();

}  // namespace gr::test

namespace gr::test {

/// Open cylinder of radius r and height h around the z axis: nTheta x nZ quads, split in two.
TriMesh cylinder(int nTheta, int nZ, double r = 1.0, double h = 2.0);
/// UV (latitude-longitude) sphere of radius r with poles: thin triangles near the poles.
TriMesh uvSphere(int nLat, int nLon, double r = 1.0);
/// Moebius strip: n quads around the unit circle, width 0.6, the ends glued with a half twist
/// (one boundary loop, not orientable).
TriMesh moebiusStrip(int n);

}  // namespace gr::test

namespace gr::test {

/// Topology of a triangle soup, recounted independently of TriMesh (maps, link cycles, union-find),
/// so that tests of TriMesh and of the remeshing do not check TriMesh with itself.
struct Recount {
  bool closedManifoldEdges = true;  ///< every edge in exactly two faces
  bool manifoldEdges = true;        ///< every edge in one or two faces
  int boundaryLoops = 0;            ///< loops of edges with one face (boundary edges joined at shared ends)
  bool simpleBoundary = true;       ///< each boundary vertex starts one boundary half-edge and ends one
  bool oriented = true;             ///< every directed edge once
  bool manifoldVertices = true;     ///< every vertex's link is one cycle or one path
  int components = 0;
  int genusSum = 0;                    ///< sum over components of (2 - chi - loops) / 2
  int isolated = 0;                    ///< vertices in no face
  int boundaryEdges = 0;               ///< edges in one face
  int nonManifoldEdges = 0;            ///< edges in three or more faces
  int inconsistentEdges = 0;           ///< edges in two faces that run the same way in both
  int nonManifoldVertices = 0;         ///< vertices in a face whose link is not one cycle or one path
  int eulerCharacteristic = 0;         ///< V - E + F over the vertices in faces (every edge counted once)
  std::vector<int> componentOfVertex;  ///< per vertex, a component label of this count; -1 if isolated
};
Recount recount(const std::vector<Tri>& tris, int vertexCount);

}  // namespace gr::test

namespace gr::test {

/// The integer just before `words` in a log ("6 added to make" -> 6), or -1000 if `words` is
/// not there.
int numberBefore(const std::string& log, const std::string& words);

}  // namespace gr::test

namespace gr::test {

/// The same surface with very bad triangles: every 12th interior edge (a, b), shared by faces
/// (C, a, b) and (D, b, a), is split at a point m, alternately
///  - near a (m = a + 0.002 (b - a)): needles (C, a, m), (D, m, a) with angles under 1 degree;
///  - at its midpoint, then flipped: (C, a, b) stays and (b, a, m) has zero area, next to
///    (b, m, D) and (m, a, D).
/// New vertices are appended, so original indices and the exact distances there are unchanged.
/// zeroAreaFaces receives the number of zero-area faces made.
TriMesh withBadTriangles(const TriMesh& m, int* zeroAreaFaces);

}  // namespace gr::test

namespace gr::test {

/// Triangle angles recomputed from the positions, independently of gr::angleStatistics:
/// atan2(|u x w|, u . w) at each corner (0 for a zero-length edge).
struct AngleRecount {
  double smallestDegrees = 180.0;  ///< smallest angle of any triangle
  double largestDegrees = 0.0;     ///< largest angle of any triangle
  double shareBelow30 = 0.0;       ///< share of triangles whose smallest angle is under 30 degrees
};
AngleRecount recountAngles(const TriMesh& mesh);

}  // namespace gr::test

namespace gr::test {

/// The mesh files (.off, .ply, .stl, .obj) of the data set fetched by scripts/setup.sh, sorted;
/// prim.off is left out (its header is followed by '#' comment lines, on which vcglib's OFF
/// reader, MeshLab's too, crashes). If none is found, one name that says so, so that a
/// parameterised test fails with that name instead of instantiating nothing.
std::vector<std::string> dataSetMeshFiles();
/// A gtest parameter name for a mesh file ("bunny00.off" -> "bunny00_off").
std::string testNameOfFile(const std::string& file);

/// EXPECTs that `out` is an edge- and vertex-manifold, oriented surface with no isolated vertex
/// and the components, genus and boundary loops of `in`.
void expectValidWithTopologyOf(const Recount& out, const Recount& in);

}  // namespace gr::test
