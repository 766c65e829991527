// Intrinsic Delaunay refinement of a surface mesh: the same surface, triangulated again with
// well-shaped triangles, for algorithms (fast marching) that go wrong on slivers.
//
// Sharp, Soliman & Crane 2019, "Navigating intrinsic triangulations", §4 (after Chew 1993 and
// Ruppert 1995): the input's edges are flipped until the triangulation is intrinsically Delaunay
// (flips change lengths, never the surface); then, largest faces first (faces on the boundary
// before the others), each face with an angle below `minAngleDegrees` or an edge longer than
// `maxEdgeLength` gets its circumcentre inserted, found by tracing a straight line across the
// intrinsic triangles from the face's barycentre, and the triangulation is flipped back to
// Delaunay around it. A trace that reaches the boundary first, or a circumcentre that would lie
// in the diametral disk of a boundary edge of its Delaunay cavity (Ruppert's encroachment: the
// faces whose circumdisk holds it, unfolded around it), splits that boundary edge at its midpoint
// instead. Every vertex stays where it is on the input: input vertices keep their indices, and
// each inserted point is located on an input face (intrinsic_triangulation.h).
//
// Faces left alone (they cannot be improved, or would be refined for ever):
//  - faces with a vertex whose angle sum is below 60 degrees (a needle tip, or a sharp corner of
//    the boundary: every triangle there keeps a small angle) unless an edge is too long;
//  - faces whose circumradius is below 1e-5 times the input's mean edge length;
//  - faces whose circumcentre could not be traced or located (the trace ran into a vertex, or
//    found no way out of a degenerate face).
// A TriMesh cannot hold what intrinsic triangulations allow, self-edges and two edges joining the
// same two vertices (they appear around sharp cones: vertices with a small angle sum). After the
// refinement such edges are split at their midpoints and the triangulation is flipped to Delaunay
// again refusing flips that would recreate one, until there is none (at most 20 rounds); then the
// refinement runs once more under the same rule (the splits may have made small angles), and the
// clean-up once more. So the output is simplicial and Delaunay except for the edges whose flip
// would repeat an edge (or make a degenerate face, on flat folds): cheese.off keeps 6 such edges
// and 6 faces under 25 degrees, next to four cones of angle sum 80 to 90 degrees.
//
// Input: any manifold triangle mesh, with boundaries, several components, zero-area faces and
// faces not oriented coherently (they are oriented internally with orientCoherently; the output
// has the orientation most faces of each component had). Fails with NonManifold (non-manifold
// edges or vertices), InvalidInput (a non-orientable component; parameters out of range),
// Cancelled, or Internal if the output's topology differs from the input's (a bug).
//
// Cost: O(F) for the first flips' queue plus O(flips) (in practice a small multiple of F); per
// inserted point, O(faces crossed by the traces) + O(flips around it) + O(log F) for the queue;
// with the default budget (10 V + 1000 points, plus 2 A / (sqrt(3) L^2 / 4) under a length bound L)
// O((V + points) log V) when traces stay short.
// Memory: O(F + points) (about 120 bytes per intrinsic face).
#pragma once

#include <limits>
#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

struct IntrinsicRefinementParams {
  /// Refine until every angle of the intrinsic triangles is at least this (degrees, in [0, 60);
  /// 0 = no angle bound). Above about 30 degrees the refinement may not end before the budget.
  double minAngleDegrees = 25.0;
  /// And every edge at most this long (mesh units, > 0); +inf (default) = no length bound.
  double maxEdgeLength = kUnbounded;
  /// At most this many inserted points (>= 0); -1 (default) = 10 x the input's vertex count + 1000,
  /// plus, with a length bound L, 2 per equilateral triangle of side L in the surface's area.
  int maxInsertions = -1;
  /// Only flip to Delaunay, insert no circumcentre (points are still inserted where the output
  /// would not be simplicial without them).
  bool flipOnly = false;
};

struct RefinedSurface {
  /// The intrinsic triangulation as a TriMesh: vertices 0..n-1 are the input's vertices, inserted
  /// points after them; positions = the 3D position of each vertex's origin (for display and
  /// chords only: the geometry is `cornerLength`). Faces coherently oriented.
  TriMesh mesh;
  /// Per corner c = 3f + k: the intrinsic length of the edge facing c (includes the input's
  /// mollification epsilon).
  std::vector<double> cornerLength;
  /// The epsilon added to every input length (intrinsic_triangulation.h): 0 unless the input had a
  /// zero-length edge, a triangle-inequality violation or a flat face. The refinement keeps the
  /// geometry of those lengths (area, angle sums) exactly.
  double mollification = 0.0;
  /// Per vertex: where it lies on the input (vertices < n: atVertex(i); inserted points: an input
  /// face and barycentric coordinates in the input's own corner order).
  std::vector<SurfacePoint> origin;
  int inputVertexCount = 0, insertedPoints = 0, flips = 0;
  double smallestAngleDegrees = 0.0;  ///< of the intrinsic triangles
  /// Faces left with an angle below minAngleDegrees (the faces left alone, see the file comment,
  /// and any left when the budget ran out). An addition to the interface the engine consumes: the
  /// log says how many.
  int facesBelowMinAngle = 0;
  bool budgetExhausted = false;  ///< the refinement stopped at maxInsertions
};

/// Intrinsic Delaunay refinement of `input` (see the file comment). progress reports the inserted
/// points over the budget; false from it returns Cancelled.
Expected<RefinedSurface> refineIntrinsicDelaunay(const TriMesh& input, const IntrinsicRefinementParams& params = {},
                                                 Progress progress = {});

}  // namespace gr
