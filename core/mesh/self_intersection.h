// Pairs of faces of a triangle mesh that cross each other (a mesh that is not embedded): the
// remeshing's count search (remesh_surface.cpp) prefers outputs without any.
//
// Broad phase: the faces' bounding boxes in a uniform grid of about F cells; narrow phase, for two
// faces whose boxes overlap: each edge of one against the other triangle (segment against
// triangle, Moller-Trumbore), where an edge that starts or ends at a vertex the faces share does
// not count as crossing there. Two faces in one plane (to 1e-12 of their size) cross when they
// overlap with positive area, neighbours included: a fold, two faces on one edge folded flat onto
// each other, or a face turned over among coplanar neighbours (CGAL counts these too). Faces
// sharing an edge and not in one plane meet along it only. Floating point, not exact: the tests'
// oracle (CGAL, exact) decides in the tests; this is the core's own cheap check.
// Cost: O(F) for the grid plus O(pairs of overlapping boxes).
#pragma once

#include <utility>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr {

/// Pairs (f, g), f < g, of faces that cross; at most `limit` pairs (0 = all).
std::vector<std::pair<int, int>> selfIntersectingFaces(const TriMesh& mesh, int limit = 0);

/// The pairs of selfIntersectingFaces with at least one face flagged in `flagged` (one flag per
/// face): what a change to those faces may have made cross. The broad phase grids only the
/// flagged faces' boxes, so the cost is O(F) box tests plus the flagged faces' neighbourhoods.
std::vector<std::pair<int, int>> crossingsOfFaces(const TriMesh& mesh, const std::vector<char>& flagged);

/// Whether faces f and g cross (the narrow phase of selfIntersectingFaces): an edge of one through
/// the other away from shared vertices, or, in one plane, an overlap of positive area.
bool facesCross(const TriMesh& mesh, int f, int g);

/// Per vertex, 1 if it is a corner of a face that crosses another (selfIntersectingFaces).
std::vector<char> crossingVertices(const TriMesh& mesh);

}  // namespace gr
