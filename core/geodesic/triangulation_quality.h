// Whether a mesh's triangles are poor enough for distances on it to need an intrinsic Delaunay
// refinement first (intrinsic_refinement.h): a cheap test on the input's angles.
//
// Fast marching is accurate on well-shaped triangles and goes wrong, silently, on slivers
// (a tiny angle: a long thin triangle across a flat CAD face) and caps (an angle near 180
// degrees: a vertex almost on the opposite edge), the common case of CAD exports. The test
// counts both and says yes when either is more than a small share of the faces:
//  - slivers: faces with an angle below 10 degrees, more than 1% of the faces;
//  - caps: faces with an angle above 150 degrees, more than 0.5% of the faces;
//  - a coarse mesh: faces with an edge longer than 5% of the bounding-box diagonal, more than 1%
//    of the faces (a cube of 12 triangles, a CAD part of a few dozen: fronts there are first-order
//    in the edge length, 2% off on a cube against 0% once refined).
// On the data set: the scans bunny00 and armadillo (0% and 0.11% slivers, 0% and 0.12% caps)
// and fandisk (0%, 0%) say no; cheese (74% slivers), blade (100%) and turbine (6.4%, 1.8%
// caps) say yes. Vertices with an angle sum far from 2 pi next to long edges (vertices only on
// feature outlines) come with slivers on every mesh tried, so they are not counted separately.
// Cost: O(F), one pass over the corners.
#pragma once

#include <algorithm>
#include <string>

#include "core/mesh/tri_mesh.h"

namespace gr {

struct TriangulationQuality {
  int faces = 0;
  double smallestAngleDegrees = 0.0;  ///< smallest corner angle (0 with no faces)
  double largestAngleDegrees = 0.0;   ///< largest corner angle
  double sliverShare = 0.0;           ///< share of faces with an angle below 10 degrees
  double capShare = 0.0;              ///< share of faces with an angle above 150 degrees
  double longEdgeShare = 0.0;         ///< share of faces with an edge above 5% of the diagonal
  double diagonal = 0.0;              ///< of the bounding box
  bool needsRefinement = false;       ///< sliverShare > 1%, capShare > 0.5% or longEdgeShare > 1%
};

/// The figures above, from the 3D positions (a zero-length edge gives its corners angle 0).
TriangulationQuality assessTriangulation(const TriMesh& mesh);

/// The test's pass over the faces, for a caller that reads every face anyway (the engine's set-up,
/// FastMarcher::triangulationQuality: one pass instead of two on the good meshes, where the test
/// is all geodesicDistance adds). add() each face once, then result(): the same figures as
/// assessTriangulation.
class TriangulationTally {
 public:
  explicit TriangulationTally(double diagonal);
  void add(const Vec3& p0, const Vec3& p1, const Vec3& p2) {
    const Vec3 a = p1 - p0, b = p2 - p1, c = p0 - p2;
    const double na = a.squaredNorm(), nb = b.squaredNorm(), nc = c.squaredNorm();
    const double c0 = corner(a, -c, na, nc), c1 = corner(b, -a, nb, na), c2 = corner(c, -b, nc, nb);
    const double hi = std::max(c0, std::max(c1, c2)), lo = std::min(c0, std::min(c1, c2));
    largest_ = std::max(largest_, hi);
    smallest_ = std::min(smallest_, lo);
    slivers_ += hi > sliverBound_;
    caps_ += lo < capBound_;
    longFaces_ += std::max(na, std::max(nb, nc)) > longEdge2_;
    ++faces_;
  }
  TriangulationQuality result() const;

 private:
  /// sign(c) c^2 of the corner between u and v (squared lengths nu, nv); a zero-length side: 1.
  /// Angles are compared through it (increasing with c, so decreasing with the angle): no square
  /// root or arc cosine per corner, and no branch (the loop runs on every call of the engine).
  static double corner(const Vec3& u, const Vec3& v, double nu, double nv) {
    const double dot = u.dot(v), len2 = nu * nv;
    const double c2 = (dot < 0.0 ? -dot * dot : dot * dot) / len2;
    return len2 > 0.0 ? std::min(1.0, std::max(-1.0, c2)) : 1.0;
  }
  double diagonal_, longEdge2_, sliverBound_, capBound_;
  double largest_ = -1.0, smallest_ = 1.0;  // of sign(c) c^2 over all corners
  int faces_ = 0, slivers_ = 0, caps_ = 0, longFaces_ = 0;
};

/// The figures for a log: "slivers 74.00%, caps 2.90%, long edges 0.00%, smallest angle 0.22 deg".
std::string describe(const TriangulationQuality& quality);

}  // namespace gr
