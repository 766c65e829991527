// Total curvature tau = |k1| + |k2| per vertex, from the Cohen-Steiner–Morvan normal-cycle tensor.
//
// Paper §3.4 (Peyré & Cohen 2006): tau drives the curvature-adaptive speed F = 1 / (1 + mu tau)
// ("edge attractive") or F = 1 + eps tau ("edge repulsive"). Cohen-Steiner & Morvan 2003: over a
// neighbourhood B of a vertex,
//
//     T(B) = 1/area(B) * sum over edges e of  beta(e) |e ∩ B| ê êᵀ
//
// where beta(e) is the signed dihedral angle at e (positive where the surface is convex for its
// orientation) and ê the unit edge direction. The eigenvector of T closest to the vertex normal
// (area-weighted face normals) is dropped, as in vcglib; on smooth surfaces and sharp edges it is
// also the eigenvalue of smallest magnitude, Cohen-Steiner & Morvan's rule. The two other
// eigenvalues are the principal curvatures (their eigenvectors are the principal directions
// swapped, which is why they are not returned); k1 is the one of larger magnitude. Boundary and
// non-manifold edges have no dihedral angle and contribute nothing.
//
// How B is discretised (fast, and exactly consistent between numerator and area):
//  - each edge gives half of beta |e| ê êᵀ to each endpoint, each face a third of its area to each
//    vertex: per-vertex "masses" that sum to the whole surface's integral;
//  - B(v) is the Euclidean ball of radius r_v = max(radius, mean distance from v to its
//    neighbours) around v (radius: the mesh's mean edge length unless given), grown over the
//    connectivity from v (a flood fill that only walks through vertices inside the ball): a
//    radius below the 1-ring's gives the 1-ring's ball. Each vertex u enters with the weight
//    w = clamp(1/2 + (r_v - |u - v|) / s_u, 0, 1), s_u = sqrt(area of u's cell): the share of u's
//    cell inside the ball, read along the radius (v itself: w = 1). An edge thus counts by about
//    the fraction of it inside the ball ((w_a + w_b) / 2). Where a long edge meets much smaller
//    triangles, its half sits at its endpoint, so a ball reaching the endpoint sees all of it.
//
//              . - ~ ~ - .               o  vertex with w = 1 (its cell inside the ball)
//          . '   o     o   ' .           x  vertex near the sphere of radius r_v: 0 < w < 1
//        x    o     o     o    x         edges: half of beta |e| to each endpoint, times w
//       :   o    o  v  o    o   :        area:  a third of each face to each vertex, times w
//        x    o     o     o    x
//          ' .   o     o   . '
//              ' - ~ ~ - '
//
// Deviations from the geodesic ball of the paper: the Euclidean distance is shorter than the
// geodesic one by O(r^3 k^2), so B is slightly larger on curved parts; growing over the
// connectivity keeps B from jumping across a thin gap to another sheet of the surface, but it can
// wrap around a thin plate's rim when the radius exceeds the plate's thickness. A Dijkstra ball
// along edges would overestimate distances by up to 15% on a regular triangular grid (more on
// irregular ones) and cost a heap per vertex; the Euclidean ball is exact on planes and costs only
// a queue.
// The tensor is built in 3D: with a radius comparable to 1/|k| the tilted far edges move part of
// the curvature into the dropped normal eigenvalue (about (r k)^2 / 4 of it); keep r k small.
//
// Preconditions: a TriMesh from buildTriMesh (adjacency built). Zero-area faces, boundaries and
// non-manifold edges are accepted (they contribute no curvature). An edge whose two faces disagree
// on orientation has its angle measured from the lower-numbered face, the other one flipped.
// Cost: O(F) for the masses, then O(V * n * valence) for the neighbourhoods, n = vertices per
// ball (about 7 for the 1-ring, 10 for the default r = h, 20-30 for r = 2 h, 40-55 for r = 3 h,
// h = mean edge length), plus closed-form 3x3 eigenvalues per vertex (Eigen's computeDirect:
// where two eigenvalues coincide, e.g. 0 and 0 on a cylinder or a sharp edge, its relative error
// is about 1e-8). Internally the vertices are renumbered in the order the faces first reach them
// (face order is usually spatially coherent, vertex order after subdivision is not), so a ball's
// vertices are near each other in memory, and the balls run on two threads, half the vertices
// each (times: docs/BENCHMARKS.md). Memory: about 300 bytes per vertex, freed on return.
#pragma once

#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Options of the normal-cycle curvature (Cohen-Steiner & Morvan 2003; paper §3.4).
struct CurvatureParams {
  /// Radius of the neighbourhood ball (mesh units); 0 (the default) = the mesh's mean edge length.
  /// Each ball is at least a vertex's 1-ring (radius = mean distance to its neighbours), so any
  /// radius below that, e.g. 1e-9 times the bounding-box diagonal, gives the most local estimate.
  /// A fixed radius makes tau independent of the local triangle size (a sharp edge of dihedral
  /// angle beta gets about 2 beta / (pi r) wherever it is), smooths the noise of irregular meshes,
  /// and spreads a sharp edge over a band about as wide as the ball. Negative, NaN or infinite:
  /// InvalidInput.
  double radius = 0.0;
};

struct CurvatureResult {
  std::vector<double> tau;             ///< per vertex, total curvature |k1| + |k2| (1 / mesh units), >= 0
  std::vector<double> k1;              ///< per vertex, principal curvature of larger magnitude (signed)
  std::vector<double> k2;              ///< per vertex, principal curvature of smaller magnitude (signed)
  double radius = 0.0;                 ///< the radius used (mesh units); each ball is at least its vertex's 1-ring
  double meanNeighbourhoodSize = 0.0;  ///< vertices with w > 0 per ball, on average (v included)
  int oneRingRadius = 0;               ///< vertices whose ball took their 1-ring's radius (not smaller than `radius`)
  /// The mesh's faces that share no edge with another (their vertices get 0: no dihedral angle),
  /// and whether they are a triangle soup (TriMesh::looksLikeTriangleSoup).
  int looseFaces = 0;
  bool looksLikeTriangleSoup = false;
  /// Non-manifold vertices (fans of faces meeting at one vertex): each fan was its own surface,
  /// and such a vertex has its largest fan's curvature.
  int splitVertices = 0;
};

/// Curvature of every vertex. Signs: positive where the surface is convex for its orientation
/// (a sphere with outward-facing triangles has k1, k2 = +1/R). Isolated vertices get 0. Fans of
/// faces meeting at a (non-manifold) vertex are measured apart (CurvatureResult::splitVertices).
/// Fails (InvalidInput) on a mesh without vertices or faces or without adjacency, a negative,
/// NaN or infinite radius; (Cancelled) if the progress callback says so.
Expected<CurvatureResult> totalCurvature(const TriMesh& mesh, const CurvatureParams& params = {},
                                         Progress progress = {});

}  // namespace gr
