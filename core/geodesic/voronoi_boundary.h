// Where two geodesic Voronoi cells meet along an edge (paper §2.2).
//
// For an edge (v1, v2) whose vertices have different nearest sources a and b, each front is
// let to overlap one vertex: front a's arrival at v2 (d2a) is extended from v2's neighbours of
// cell a, and front b's arrival at v1 (d1b) likewise. With linear arrival times along the edge
//
//     v1 ---------- x ---------- v2        x = (1 - lambda) v1 + lambda v2,
//     d1a, d1b                  d2a, d2b   lambda = (d1b - d1a) / ((d1b - d1a) + (d2a - d2b))
//
// the fronts meet at x. Cost: O(edges + boundary edges * valence).
#pragma once

#include <vector>

#include "core/geodesic/metric.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct VoronoiEdgePoint {
  int v1, v2;  ///< the edge, v1 in cell cell1, v2 in cell cell2
  int cell1, cell2;
  double lambda;  ///< position along the edge, in [0, 1] from v1
  Vec3 position;
};

/// Boundary points of the Voronoi diagram given by a fast-marching field (distance, cell).
/// Each boundary edge is reported once.
std::vector<VoronoiEdgePoint> voronoiBoundaryPoints(const TriMesh& mesh, const Metric& metric,
                                                    const std::vector<double>& distance, const std::vector<int>& cell);

}  // namespace gr
