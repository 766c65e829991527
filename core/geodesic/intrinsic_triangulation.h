// An intrinsic triangulation of a surface mesh with signposts (Sharp, Soliman & Crane 2019,
// "Navigating intrinsic triangulations"): the same surface as the input, described by edge
// lengths only, on which edges are flipped and vertices inserted while each vertex keeps its
// place on the input (its origin, a SurfacePoint).
//
// Edge flip: the two faces of an interior edge, laid out in the plane, give the other diagonal's
// length; its signposts follow from the neighbours' (signpost_mesh.h). Refused on the boundary,
// when both sides are one face, and when a new face would have (nearly) zero or negative area.
//
//        x                x
//       / \              /|\         new length |x y| in the planar layout of the two faces
//      a---b     ->     a | b        (the angles at x and y summing to more than pi makes
//       \ /              \|/         the quad convex, so a non-Delaunay edge always flips)
//        y                y
//
// Vertex insertion: a point of a face (split in 3) or of an edge (split in 4, or in 2 on the
// boundary). The new lengths come from the planar layout of the face (or the edge's two faces);
// the point is found on the input by tracing a straight line over the input (signpost_trace.h)
// from one of its new neighbours along the new edge (a neighbour located at an input vertex
// first, then the shortest edge), and the direction it arrives from fixes how the new vertex's
// angular coordinate sits in the input face. A point on a boundary edge is placed on the input
// boundary edge it lies on by interpolation. If the trace fails, nothing changes.
//
// Input lengths are the 3D edge lengths, plus one small epsilon on every edge only when some face
// has a zero-length edge (coincident vertices) or lengths violating the triangle inequality
// beyond rounding (intrinsic mollification, Sharp & Crane 2020): the least epsilon that gives
// every face a margin of 1e-10 times the mean edge length; the angles of those faces are then the
// mollified (thin, positive-area) triangles'. Flat faces (angles 0, 0, pi) alone get a margin of
// only 1e-14 of the mean length: zero-area faces can glue two parts of a surface along a segment
// that no front crosses by triangle updates, and as thin triangles they are split by the
// refinement like any sliver; the surface bends by about 1e-7 of the mean length there.
//
// Preconditions (checked by refineIntrinsicDelaunay, not here): manifold, faces coherently
// oriented. Cost: a flip O(1) (plus O(valence) for the simplicial check when asked); an insertion
// O(faces of the input crossed by the locating trace).
#pragma once

#include <vector>

#include "core/geodesic/detail/signpost_mesh.h"
#include "core/geodesic/detail/signpost_trace.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

class IntrinsicTriangulation {
 public:
  /// Starts as a copy of `input` (manifold, coherently oriented), with mollified lengths.
  explicit IntrinsicTriangulation(const TriMesh& input);

  const SignpostMesh& input() const { return input_; }
  const SignpostMesh& mesh() const { return mesh_; }
  /// Per vertex: where it lies on the input (vertex i < inputVertexCount() is atVertex(i)).
  const std::vector<SurfacePoint>& origin() const { return origin_; }
  int inputVertexCount() const { return inputVertexCount_; }
  /// The epsilon added to every input length (0 unless a face had a zero-length edge).
  double mollification() const { return mollification_; }
  int flipCount() const { return flips_; }

  /// Whether the edge of h is locally Delaunay: a boundary edge, or angles facing it summing to at
  /// most pi + toleranceRadians.
  bool isDelaunay(int h, double toleranceRadians) const;
  /// Flips the edge of h; false (nothing changed) if it cannot be flipped (see the file comment),
  /// or, with keepSimplicial, if the new edge would join a vertex to itself or to a neighbour.
  bool flip(int h, bool keepSimplicial = false);
  /// Flips non-Delaunay edges (angle tolerance 1e-9 rad) until none is left among the edges of
  /// the faces changed since the last call (all edges at the first call), at most maxFlips.
  /// Returns the number of flips.
  int flipToDelaunay(bool keepSimplicial = false, long maxFlips = -1);
  /// Puts every interior edge on the work list of the next flipToDelaunay (an edge whose flip was
  /// refused may have become flippable without its faces changing). O(halfedges).
  void queueAllEdges();

  /// Inserts a vertex at the point `bary` of face f; returns it, or -1 if the point is within 1e-12
  /// of the face's size of a vertex or could not be located on the input (nothing changed).
  int insertVertex(int f, const Vec3& bary);
  /// Splits the edge of h at t in (0, 1) (from its tail); returns the new vertex, or -1 as above.
  int splitEdge(int h, double t);

  /// Faces created or changed since the last call (with repetitions).
  std::vector<int> takeChangedFaces();
  /// Halfedges of edges that keep the triangulation from being a simplicial complex: one per
  /// self-edge (a vertex joined to itself) and one per extra copy of an edge joining the same two
  /// vertices. Cost O(halfedges).
  std::vector<int> nonSimplicialEdges() const;
  /// Whether the edge of h is a self-edge or one of several edges between its two vertices.
  bool isNonSimplicial(int h) const;

 private:
  /// A straight line on the input from an intrinsic vertex: direction in its angular coordinate.
  struct TracePlan {
    int from = -1;
    double angle = 0.0;
    double length = 0.0;
  };
  /// Where a new vertex lies on the input and the direction it is reached from (input layout).
  struct Located {
    SurfacePoint at;
    Vec2 arrival = Vec2::Zero();
  };
  bool locate(const TracePlan& plan, Located* where) const;
  /// Of several plans for one point, the index of the one to trace: from an input vertex first,
  /// then the shortest.
  static int pickPlan(const std::vector<TracePlan>& plans, int inputVertexCount);
  int addVertex(const SurfacePoint& origin, bool onBoundary);
  /// Sets the new vertex v's offset from the trace arrival (v's halfedge toward the plan's start).
  void alignVertex(int v, int halfedgeToStart, const Located& where);
  void link(int h, int g, double length);
  void touchFace(int f);
  bool joins(int v, int w) const;
  int splitBoundaryEdge(int h, double t);
  SurfacePoint boundaryPoint(int h, double t) const;
  double boundaryParameter(int inputHalfedge, int v) const;

  SignpostMesh input_;
  SignpostMesh mesh_;
  std::vector<SurfacePoint> origin_;
  /// Per vertex not at an input vertex: direction 0 of its angular coordinate is direction
  /// `offset` (radians from the x axis) in the layout of its origin's face.
  std::vector<double> offset_;
  int inputVertexCount_ = 0;
  double mollification_ = 0.0;
  int flips_ = 0;
  std::vector<int> changed_;
  std::vector<int> flipQueue_;
  std::vector<char> queued_;  ///< per halfedge: in flipQueue_
};

}  // namespace gr
