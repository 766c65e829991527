// Edge collapses down to the vertex count asked for (issue 20: "the count asked for").
//
// Where the geodesic Delaunay triangulation needs more samples than asked to be valid (thin
// parts and sliver-rich CAD parts at low counts: cow, cactus, dino, femur at 5%), the shortest
// edges of the output are collapsed, each vertex onto a neighbour, so that every vertex stays a
// sample on the input surface. A collapse of u onto v is made only if
//   - it keeps the topology: u and v share exactly the two neighbours of the edge's two faces
//     (the link condition; a boundary vertex goes only along its boundary), and every vertex
//     keeps three neighbours;
//   - no face that moves turns over (its normal stays within 90 degrees of what it was);
//   - no face that moves crosses another (facesCross, against the faces whose boxes overlap in a
//     grid of the faces' boxes), so an output without crossing faces stays so.
// Edges are taken shortest first, their length weighted by the metric (`weight` per vertex: P at
// the vertex, 1 when uniform), so an adaptive density is kept; a pass moves each vertex at most
// once (its neighbourhood is stale after), and passes go on until the count is reached or a pass
// collapses nothing. The input's Voronoi cells follow: the cell of a removed vertex joins the cell
// of the vertex it went onto.
// Cost: O(E log E) per pass plus about 30 face-against-face tests per collapse.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "core/base/math.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct CollapseResult {
  int collapsed = 0;  ///< vertices removed
  int passes = 0;
};

/// Collapses edges of `mesh` (manifold, oriented) until it has `targetCount` vertices or no edge
/// can go. `origin` (per vertex) and `weight` (per vertex, > 0) are compacted with the vertices;
/// `cell` (per input vertex, an index of `mesh`'s vertices or -1) is renumbered. `keep`: empty,
/// or per vertex whether it stays (a neighbour may still go onto it): the remesh keeps the
/// samples it started its sampling from (FpsParams::initialSamples, the corners of the input's
/// feature curves: patch-23 at 5% took 6 vertices for 5, and its shortest edge joined two corners).
CollapseResult collapseToCount(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<double>& weight,
                               std::vector<int>& cell, int targetCount, std::vector<char> keep = {});

/// The pairs of crossing faces of a mesh to be removed, given the cells (per input vertex) of its
/// vertices: selfIntersectingFaces, or those of them away from where the input crosses itself.
using CrossingPairs = std::function<std::vector<std::pair<int, int>>(const TriMesh&, const std::vector<int>& cell)>;

/// Collapses edges of the faces in `pairsOf`'s pairs, with the same checks: each collapse deletes
/// the two faces of its edge, one of them a crossing face, and moves none into a crossing. Up to
/// `rounds` passes, the pairs asked for again before each. For an output whose triangulation
/// crosses itself where the input does not (armadillo, adaptive, at 30%: 6 pairs, 2 collapses).
CollapseResult collapseCrossingFaces(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<double>& weight,
                                     std::vector<int>& cell, const CrossingPairs& pairsOf, int rounds = 3);

/// Flat ears off the output's boundary: a face with two boundary edges, their common vertex m in
/// no other face and its third edge (a, b) interior, is removed with m (m's cell joins the nearer
/// of a and b) when it has an angle under 30 degrees at a or b and m lies within `maxHeight`
/// times |ab| of the line ab. The boundary then runs along ab: the ear's tip, at most that far
/// off, is cut; no other face changes, so no angle falls and nothing new crosses. Components,
/// genus and boundary loops are kept (the loop loses m). Rounds until none is left (ears made
/// by a removal included), kEarRounds at most. Cost: O(F) per round.
/// lion-head at 30%: two ears of 5.8 and 6.2 degrees, tips of 168 degrees on a straight boundary.
constexpr double kEarAngle = 30.0 * kPi / 180.0;  ///< an ear with an angle under this goes
constexpr int kEarRounds = 8;                     ///< rounds of removeFlatEars at most
CollapseResult removeFlatEars(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<int>& cell,
                              double maxHeight);

/// Thin ears off the output's boundary: ears (as above: the tip m in no other face, its third edge
/// interior) with an angle under kEarAngle, at the tip (a spike of the boundary) or at the base
/// (an ear too tall for removeFlatEars), m within `maxDepth` of the line of the third edge; the
/// faces by their smallest angle, thinnest first. Removing one (removeEar) cuts the boundary along
/// the third edge, as deep as the ear is tall, so the remesh judges each by its distance to the
/// input (cutThinEars in remesh_surface.cpp). lion at 10%: the input's own ear, a triangle of 8
/// degrees at a corner of its boundary, made an output ear of 10.5 degrees, 0.32 mean edge
/// lengths tall, the output's smallest angle (the next: 20.2); through MeshLab's float
/// coordinates, that cut leaves an ear of 11.1 degrees at its base, 0.13 of its base tall.
std::vector<int> thinEars(const TriMesh& mesh, double maxDepth);

/// Removes the ear `face` (an ear as removeFlatEars and thinEars take) with its tip, as
/// removeFlatEars does (the tip's cell joins the nearer end of the third edge); false, with
/// nothing changed, if `face` is no ear or the result would not be valid.
bool removeEar(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<int>& cell, int face);

}  // namespace gr
