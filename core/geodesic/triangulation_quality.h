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

/// The figures for a log: "slivers 74.00%, caps 2.90%, long edges 0.00%, smallest angle 0.22 deg".
std::string describe(const TriangulationQuality& quality);

}  // namespace gr
