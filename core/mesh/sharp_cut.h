// The surface cut open along its sharp edges: fronts on the cut surface cannot cross them.
//
//        a                     a           Each vertex is split into one copy per sector of
//       / \                   / \          faces between its sharp edges (the sectors are the
//  ----b===c----    -->  ----b   c----     classes of its corners joined across smooth edges);
//       \ /                  b'==c'        a vertex on one sharp edge only (the end of a crease)
//        d                    \ /          keeps one copy, so the crease is a slit there.
//                              d
// The faces keep their numbers and order. The first copy of vertex v keeps the number v; the
// other copies are appended (origin[i] = the input vertex of copy i), so per-vertex fields of
// the cut surface read on its first vertexCount() entries are fields of the input's vertices.
// Cost: O(F) (union-find over corners) and one buildTriMesh.
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Per corner, 1 if the edge facing it is sharp: two faces whose normals differ by more than
/// `degrees` (a dihedral angle of 180 - degrees or less); boundary edges and edges of a face
/// with no normal (zero area) are not.
std::vector<char> sharpEdgeCorners(const TriMesh& mesh, double degrees);

struct CutSurface {
  TriMesh mesh;             ///< the cut surface: the input's faces, vertices split at sharp edges
  std::vector<int> origin;  ///< per vertex of `mesh`, the input vertex it is a copy of
  int sharpEdges = 0;       ///< edges cut open
};

/// `mesh` cut open along the edges marked in `cutCorner` (per corner, as sharpEdgeCorners gives;
/// either corner of an edge may mark it). Fails as buildTriMesh.
Expected<CutSurface> cutAlongEdges(const TriMesh& mesh, const std::vector<char>& cutCorner);

/// `mesh` with each non-manifold vertex split into one copy per fan of faces (cutAlongEdges with
/// no edge cut), as MeshLab's Split Non Manifold Vertices does. Fails as buildTriMesh.
Expected<CutSurface> splitNonManifoldVertices(const TriMesh& mesh);

}  // namespace gr
