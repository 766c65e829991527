// Geodesic path from a surface point back to its nearest source, by descent on the distance
// field (paper §2.1, Fig. 2).
//
// In each face the field is linear; the path follows -grad U across the face to the edge it
// exits through, then continues in the next face. At a vertex it leaves through the face whose
// corner contains -grad U; where no face does (a ridge of the field), it steps along the edge to
// the lowest neighbour. U strictly decreases along the path, which ends at a vertex with U = 0.
//
//          c
//        /   \        the path enters face (a, b, c) at q on edge ab, follows -grad U,
//      /   .   \      and leaves through edge ac or cb
//    a ----q---- b
//
// Cost: O(faces crossed).
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct GeodesicPathParams {
  int maxSteps = 1000000;  ///< safety bound on faces crossed and vertices visited
};

struct GeodesicPath {
  std::vector<Vec3> points;    ///< from the start to the source
  std::vector<double> values;  ///< U (interpolated) at each point; strictly decreasing
  double length = 0.0;         ///< Euclidean length of the polyline
  int endVertex = -1;          ///< the source vertex reached
};

/// Fails (InvalidInput) if the start is not on the mesh or not reached by the field, or (NotConverged)
/// if maxSteps is exceeded.
Expected<GeodesicPath> geodesicPath(const TriMesh& mesh, const std::vector<double>& distance, const SurfacePoint& start,
                                    const GeodesicPathParams& params = {});

}  // namespace gr
