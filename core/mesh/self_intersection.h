// Pairs of faces of a triangle mesh that cross each other (a mesh that is not embedded): the
// remeshing's count search (remesh_surface.cpp) prefers outputs without any.
//
// Broad phase: the faces' bounding boxes in a uniform grid of about F cells; narrow phase, for two
// faces whose boxes overlap: each edge of one against the other triangle (segment against
// triangle, Moller-Trumbore), where an edge that starts or ends at a vertex the faces share does
// not count as crossing there. Faces sharing an edge are not tested (they meet along it), nor are
// coplanar overlaps (a fold flat onto itself) found. Floating point, not exact: the tests' oracle
// (CGAL, exact) decides in the tests; this is the core's own cheap check.
// Cost: O(F) for the grid plus O(pairs of overlapping boxes).
#pragma once

#include <utility>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr {

/// Pairs (f, g), f < g, of faces that cross; at most `limit` pairs (0 = all).
std::vector<std::pair<int, int>> selfIntersectingFaces(const TriMesh& mesh, int limit = 0);

}  // namespace gr
