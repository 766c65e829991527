// The distance between a remesh and its input both ways, at the samples of surfaceDistance
// (measure/evaluation.h: the output's vertices, edge midpoints and centroids; the input's
// vertices and centroids), without a spatial search over the whole surface for most samples:
// the remesh knows where each sample lies. Output vertex i sits on the input at origin[i] and owns
// the Voronoi cell of input vertices with cell[v] == i, so
//   - an output vertex is measured against the input face holding its origin (it lies on it); a
//     face's centroid is walked over the input's faces from the input face whose corners lie in
//     its three corners' cells (else from each corner's origin), toward a nearer face while one
//     is found (a local minimum), and the midpoints of its sides from where the centroid's walk
//     ended and from the side's first corner's origin;
//   - an input sample (a vertex v, or the centroid of a face) is measured against the output
//     triangles around its cell's output vertex cell[v] (for a centroid, its corners' cells).
// Each such distance is an upper bound of the distance to the nearest point of the other surface,
// equal to it wherever that point lies in the neighbourhood (nearly every sample on a remesh).
// The largest distance is then made exact: samples are taken largest bound first and measured
// against every triangle of the other surface (skipping the ones whose bounding sphere is farther),
// until the next bound is no larger than the largest exact distance found (all the others are
// below it). If that takes more than kMaxExactQueries samples, the direction is measured by
// surfaceDistance's grid instead.
// So `max` is the one-sided Hausdorff distance at the samples, as surfaceDistance gives it, and
// `rms` is at least surfaceDistance's, where a bound is not exact: by 0.1-3.8% on bunny00, fandisk,
// cheese, femur at 5-30% and the CAD-like meshes at 10%, 8.5% from cheese.off to its remesh at 30%
// (tests/remesh/test_remesh_distance.cpp holds 5% on five of them).
// Cost: O(samples x neighbourhood) + kMaxExactQueries x F, the two directions on two threads;
// bunny00 at 10%: 43-68 ms against 166-196 ms for surfaceDistance both ways one after the other,
// cheese.off 16-25 ms against 133-164 ms.
#pragma once

#include <vector>

#include "core/measure/evaluation.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct RemeshDistances {
  SurfaceDistance toInput;    ///< from the output's samples to the input
  SurfaceDistance fromInput;  ///< from the input's samples to the output
  int exactQueries = 0;       ///< samples measured against every triangle (both directions)
  int gridDirections = 0;     ///< directions that fell back to surfaceDistance's grid (0 to 2)
};

constexpr int kMaxExactQueries = 64;

/// `cell`: per input vertex, its output vertex; `origin`: per output vertex, its point on the
/// input (SurfaceRemeshResult). Both directions run side by side when a second thread is free.
RemeshDistances remeshDistances(const TriMesh& input, const TriMesh& output, const std::vector<int>& cell,
                                const std::vector<SurfacePoint>& origin);

}  // namespace gr
