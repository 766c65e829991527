// Acute splits of obtuse angles for the fast-marching update (Kimmel & Sethian 1998, §4).
//
// At an obtuse corner X of triangle XAB, a front crossing AB may reach X before B is known, so
// the triangle can never give X its upwind update. Unfolding the triangles beyond AB into the
// plane of XAB, along the bisector of the angle at X, finds a mesh vertex R such that XR splits
// the angle into two acute ones; the updates then come from the virtual triangles XAR and XRB:
//
//                 R   (unfolded beyond AB)
//                /|\    .
//      A -------/-|-\------- B     angle AXR <= 90 deg, angle RXB <= 90 deg
//         `.      |      .'
//            `.   |   .'
//               ` X '   (obtuse corner)
//
// The search follows the bisector for at most `maxUnfoldings` triangles and stops at boundary
// and non-manifold edges; corners without a split keep the plain (monotone) update.
// Cost: O(corners * maxUnfoldings) once per mesh.
#pragma once

#include <vector>

#include "core/geodesic/triangulation_quality.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct AcuteSplit {
  int corner;    ///< the obtuse corner X
  int vertex;    ///< R
  double lenXR;  ///< unfolded lengths
  double lenAR;  ///< A = vertex(next(corner))
  double lenBR;  ///< B = vertex(prev(corner))
  double lenXA;  ///< edge lengths of the corner's triangle
  double lenXB;
};

struct AcuteSplits {
  std::vector<int> splitOfCorner;  ///< per corner: index into `splits`, or -1
  std::vector<AcuteSplit> splits;
  std::vector<int> byVertexBegin;  ///< CSR: the splits whose R is a given vertex
  std::vector<int> byVertex;
  int obtuseCorners = 0;  ///< corners with an angle above 90 degrees
  /// assessTriangulation's figures, measured in the same pass over the faces (positions only: not
  /// for a triangulation with its own lengths, where `quality.faces` stays 0).
  TriangulationQuality quality;
};

/// `cornerLength`, if not null, gives per corner c the length of the edge facing c (an intrinsic
/// triangulation); else lengths are measured between the positions.
AcuteSplits findAcuteSplits(const TriMesh& mesh, const std::vector<double>* cornerLength = nullptr,
                            int maxUnfoldings = 12);

}  // namespace gr
