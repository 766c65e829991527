// A straight line traced across a signpost triangulation (the input surface or an intrinsic
// triangulation of it): from a vertex in a direction of its angular coordinate, or from a point
// of a face in a direction of the face's layout, for a given length (Sharp et al. 2019, §3.2).
//
// Face by face the line is followed in the face's planar layout (signpost_mesh.h) to the edge it
// leaves through, then the neighbour is laid out and turned so that the shared edge coincides
// (unfolding), and the line goes on. A line that runs into a vertex (within 1e-9 of the edge's
// length) continues, if asked, with half the vertex's angle sum on each side (the straightest
// continuation: straight at a flat vertex, Polthier & Schmies 1998) or stops there.
//
//        \  g  /          the point and direction found in f's layout are moved into g's by the
//   ------Q---------      rigid motion that carries the shared edge of f onto that edge in g;
//        /  f  \          the edge entered through is never the next exit (no turning back)
//       P
// Cost: O(faces crossed); bounded by maxFaces (then Failed).
#pragma once

#include "core/geodesic/detail/signpost_mesh.h"

namespace gr {

enum class TraceStop {
  Reached,   ///< the whole length was traced: the end point is (face, bary)
  Boundary,  ///< the line left the surface through boundary halfedge `halfedge`, at (face, bary)
  Vertex,    ///< the line ran into `vertex` (a boundary vertex, or any if not throughVertices)
  Failed,    ///< maxFaces crossed, an isolated vertex, or geometry with no way out (zero area)
};

struct TraceResult {
  TraceStop stop = TraceStop::Failed;
  int face = -1;                  ///< the face the trace ended in (Reached, Boundary, Vertex)
  Vec3 bary = Vec3::Zero();       ///< the end point in that face
  int halfedge = -1;              ///< Boundary: the boundary halfedge it left through
  int vertex = -1;                ///< Vertex: the vertex it ran into
  Vec2 direction = Vec2::Zero();  ///< unit direction of travel at the end, in the layout of `face`
  double remaining = 0.0;         ///< length not traced (0 when Reached)
};

struct TraceOptions {
  bool throughVertices = true;  ///< go on straight through interior vertices, or stop at any vertex
  int maxFaces = 1 << 20;       ///< faces entered (vertex restarts included) before Failed
};

/// From vertex v, leaving in direction `angle` of its angular coordinate, for `length`.
TraceResult traceFromVertex(const SignpostMesh& m, int v, double angle, double length, const TraceOptions& options);

/// From the point `bary` of face f, in the unit direction `direction` of f's layout, for `length`.
/// A point within 1e-9 of a vertex starts from that vertex (its direction turned into the
/// vertex's angular coordinate through the face's corner).
TraceResult traceFromFacePoint(const SignpostMesh& m, int f, const Vec3& bary, const Vec2& direction, double length,
                               const TraceOptions& options);

/// Barycentric coordinates of the point q of the plane in the layout p (clamped to the face).
Vec3 baryInLayout(const std::array<Vec2, 3>& p, const Vec2& q);

}  // namespace gr
