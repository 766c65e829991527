// Geodesic remeshing, the whole core pipeline (paper §3.1-3.2): farthest-point samples, their
// geodesic Delaunay triangulation, then a tangential relaxation on the input surface.
//
//   FastMarcher (mesh, metric) --farthestPointSampling--> samples + Voronoi cells
//                              --geodesicDelaunay-------> valid mesh of the input's topology
//                              --relaxOnSurface---------> same mesh, better angles
//
// The filters and the tests call this; the benchmark calls the three stages itself to time them.
#pragma once

#include "core/geodesic/farthest_point_sampling.h"
#include "core/remesh/geodesic_delaunay.h"
#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/remesh/surface_relaxation.h"

namespace gr {

struct RemeshParams {
  FpsParams sampling;            ///< target count or spacing, seed, sub-vertex placement
  DelaunayParams triangulation;  ///< repair rounds and the final Delaunay flips
  /// Tangential relaxation after the triangulation (3 rounds by default). Its Laplacian evens
  /// out edge lengths, so with a non-uniform metric (adaptive remeshing) set iterations to 0
  /// (measured: a Laplacian weighted by the metric keeps the density, but moves the samples the
  /// metric put on sharp edges: fandisk at 10%, two-sided Hausdorff 1.47% -> 2.93%).
  RelaxationParams relaxation;
};

struct RemeshResult {
  FpsResult sampling;
  DelaunayResult mesh;  ///< the output: mesh.mesh, mesh.origin (after the relaxation), ...
  RelaxationResult relaxation;
};

/// Runs the three stages on `marcher` (which must be fresh or reset). Fails as the stages do.
Expected<RemeshResult> remesh(FastMarcher& marcher, const RemeshParams& params = {}, Progress progress = {});

}  // namespace gr
