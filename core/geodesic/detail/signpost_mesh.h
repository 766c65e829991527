// A triangulation described by its edge lengths alone, with signposts (Sharp, Soliman & Crane
// 2019, "Navigating intrinsic triangulations", §3): the storage of an intrinsic triangulation and
// of the input surface it lies on, and the per-face planar layouts both are walked through.
//
// Halfedge h = 3f + k runs from tri[f][k] to tri[f][(k+1) % 3], its face on its left; faces are
// counter-clockwise. The boundary has no halfedges of its own: a boundary halfedge has twin -1.
//
//                tri[f][2]
//                /     \          halfedge 3f+1 : tri[f][1] -> tri[f][2]
//       3f+2    /   f   \  3f+1   corner at tri[f][k]: between halfedge 3f+k and the
//              /         \        reverse of 3f+(k+2)%3, facing halfedge 3f+(k+1)%3
//       tri[f][0] ------- tri[f][1]
//                  3f+0
//
// Each vertex has an angular coordinate: its corner angles summed counter-clockwise around it,
// from 0 to its angle sum (2 pi on a flat interior point, less at a cone, more at a saddle). A
// boundary vertex's coordinate runs from its outgoing boundary halfedge (0) across its fan to
// the reverse of its incoming boundary halfedge (its angle sum). The signpost of a halfedge is
// its direction at its tail in that coordinate. Vertices are assumed manifold (one fan each).
#pragma once

#include <array>
#include <vector>

#include "core/geodesic/detail/unfold.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct SignpostHalfedge {
  int twin = -1;           ///< the halfedge running the other way in the neighbouring face; -1 = boundary
  double length = 0.0;     ///< intrinsic length of the edge (equal on both halfedges)
  double signpost = 0.0;   ///< direction at the tail, in [0, angle sum) ([0, angle sum] on the boundary)
  int inputHalfedge = -1;  ///< a boundary halfedge of an intrinsic triangulation: the input boundary
                           ///< halfedge it runs along (intrinsic boundary edges are pieces of input ones)
};

struct SignpostVertex {
  double angleSum = 0.0;  ///< sum of the corner angles around the vertex
  int halfedge = -1;      ///< an outgoing halfedge; on the boundary the one with no twin; -1 isolated
  bool onBoundary = false;
};

struct SignpostMesh {
  std::vector<Tri> tri;
  std::vector<SignpostHalfedge> he;
  std::vector<SignpostVertex> vert;

  static int face(int h) { return h / 3; }
  static int next(int h) { return h - h % 3 + (h + 1) % 3; }
  static int prev(int h) { return h - h % 3 + (h + 2) % 3; }
  int tail(int h) const { return tri[h / 3][h % 3]; }
  int tip(int h) const { return tri[h / 3][(h + 1) % 3]; }
  int faceCount() const { return static_cast<int>(tri.size()); }
  int vertexCount() const { return static_cast<int>(vert.size()); }
  double length(int h) const { return he[h].length; }

  /// Angle at the tail of h in its face (between h and the reverse of prev(h)), from the lengths.
  double cornerAngle(int h) const;
  /// tan^2 of half of cornerAngle(h): increasing with it, cheaper (no arc tangent).
  double cornerTanHalfSquared(int h) const;
  /// The face laid out in the plane: vertex k at point k, tri[f][0] at the origin, tri[f][1] on
  /// the positive x axis, tri[f][2] above it.
  std::array<Vec2, 3> layout(int f) const;
  /// `angle` brought into the angular coordinate range of vertex v (modulo its angle sum inside,
  /// clamped to [0, angle sum] on the boundary).
  double standardAngle(int v, double angle) const;
  /// Sets the signpost of h from its clockwise neighbour around its tail, next(twin(h)), plus the
  /// corner angle between them; 0 when h is the outgoing boundary halfedge (no twin).
  void updateSignpostFromClockwise(int h);
  /// After the faces holding h changed: records h as its tail's outgoing halfedge (on the
  /// boundary only the halfedge without a twin qualifies).
  void claimVertexHalfedge(int h);
  /// Next outgoing halfedge counter-clockwise around tail(h), or -1 past the end of a boundary fan.
  int nextAround(int h) const { return he[prev(h)].twin; }
};

/// Moves the halfedge records at `from` to the slots `to` (of faces being rewritten), keeping
/// twin links right also when two moved halfedges are twins of each other.
template <size_t N>
inline void moveHalfedges(std::vector<SignpostHalfedge>& he, const std::array<int, N>& from,
                          const std::array<int, N>& to) {
  std::array<SignpostHalfedge, N> rec;
  std::array<bool, N> internal{};
  for (size_t i = 0; i < N; ++i) rec[i] = he[from[i]];
  for (size_t i = 0; i < N; ++i)
    for (size_t j = 0; j < N; ++j)
      if (rec[i].twin == from[j]) {
        rec[i].twin = to[j];
        internal[i] = true;
        break;
      }
  for (size_t i = 0; i < N; ++i) {
    he[to[i]] = rec[i];
    if (!internal[i] && rec[i].twin >= 0) he[rec[i].twin].twin = to[i];
  }
}

/// The fourth vertex of two faces sharing an edge a -> b laid out with a at the origin and b on
/// the positive x axis: below the axis, at distances lenA from a and lenB from b.
inline Vec2 layoutBelow(double lab, double lenA, double lenB) {
  const Vec2 q = layoutThirdVertex(lab, lenA, lenB);
  return Vec2(q.x(), -q.y());
}

/// Angle facing side `a` of a triangle with sides a, b, c (half-angle formula, stable for
/// slivers); pi when a >= b + c, 0 when a side is zero or a <= |b - c|.
double angleFromLengths(double a, double b, double c);
/// tan^2 of half the angle angleFromLengths gives (+inf for an angle of pi): the same order as the
/// angle, with no arc tangent (the refinement's hot comparisons).
double tanHalfSquaredFromLengths(double a, double b, double c);

/// Angle from u to w counter-clockwise, in (-pi, pi].
double angleBetween(const Vec2& u, const Vec2& w);

/// The signpost triangulation of a manifold, coherently oriented mesh with the given length per
/// corner (the length of the edge facing corner c = 3f+k, i.e. of halfedge 3f+(k+1)%3): twins,
/// lengths, angle sums and signposts; each boundary halfedge's inputHalfedge is itself.
SignpostMesh buildSignpostMesh(const TriMesh& mesh, const std::vector<double>& cornerLength);

}  // namespace gr
