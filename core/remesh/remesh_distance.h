// The distance between a remesh and its input both ways, at the samples of surfaceDistance
// (measure/evaluation.h): the output's vertices, edge midpoints and face centroids; the input's
// vertices (DistanceSamples::Vertices: the input is the finer surface, its vertices its densest
// samples; its centroids tripled the cost and moved the figures by under 0.2% on bunny00), without
// a spatial search over the whole surface for most samples: the remesh knows where each sample
// lies. Output vertex i sits on the input at origin[i] and owns the Voronoi cell of input vertices
// with cell[v] == i, so
//   - an output vertex is measured against the input face holding its origin (it lies on it); a
//     face's centroid is walked over the input's faces from the input face whose corners lie in
//     its three corners' cells (else from each corner's origin), toward a nearer face while one
//     is found (a local minimum), and the midpoint of each side (once per edge, counted for both
//     faces as surfaceDistance counts it) from where the centroid's walk ended and from the side's
//     first corner's origin;
//   - an input vertex v is measured against the output triangles around its cell's output vertex
//     cell[v], then walked over the output's faces from the nearest of them (a local minimum).
// Each such distance is an upper bound of the distance to the nearest point of the other surface,
// equal to it wherever that point lies in the neighbourhood (nearly every sample on a remesh).
// The largest distance is then made exact: samples are taken largest bound first and measured
// against every triangle of the other surface (skipping the ones whose bounding sphere or plane is
// farther), until the next bound is no larger than the largest exact distance found (all the
// others are below it). If that takes more than kMaxExactQueries samples, the direction is
// measured by surfaceDistance's grid instead.
// So `max` is the one-sided Hausdorff distance at the samples, as surfaceDistance gives it (CGAL's
// exact distances agree to 1e-9; vcglib's grid is off by up to 1.3e-4 of it near slivers), and
// `rms` is at least surfaceDistance's, where a bound is not exact
// (tests/remesh/test_remesh_distance.cpp holds 5% on five meshes).
// Cost: O(samples x neighbourhood) + kMaxExactQueries x F on two threads (the input's vertices on
// one, then both share the output's faces); bunny00 at 10%: 11-15 ms (25 ms with the input's
// centroids, the two directions on one thread each; 166-196 ms for surfaceDistance's grid).
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
/// `voronoiCells` false: the cells are no longer Voronoi cells of the output's vertices (edge
/// collapses merged them, edge_collapse.h) and the input's side is measured by surfaceDistance's
/// grid (a merged cell of a coarse output over a thin plate left its RMS 7% above the grid's).
/// `inputSamples`: the input's vertices alone (above), or VerticesMidpointsCentroids, the samples
/// of the project's measure both ways (each face's centroid from its corners' cells, each side's
/// midpoint from its ends'): where the input is coarse for the output, its largest distance may
/// lie there (triceratops at 30%, 849 of 2,832 vertices: 1.282% of the diagonal at a face's
/// samples, 1.162% at its vertices).
RemeshDistances remeshDistances(const TriMesh& input, const TriMesh& output, const std::vector<int>& cell,
                                const std::vector<SurfacePoint>& origin, bool voronoiCells = true,
                                DistanceSamples inputSamples = DistanceSamples::Vertices);

}  // namespace gr
