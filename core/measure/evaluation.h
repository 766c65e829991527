// Evaluation measures used the same way everywhere in the project (tests, benchmarks, logs).
#pragma once

#include <vector>

#include "core/base/progress.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Error of a distance field d against a reference field (e.g. exact geodesics).
struct DistanceError {
  /// Mean of |d - ref| / ref over the vertices whose ref is at least 5% of the largest ref.
  double meanRelative = 0.0;
  /// Largest |d - ref|, divided by the largest ref.
  double maxRelativeToMax = 0.0;
  int comparedVertices = 0;  ///< vertices in the mean
};

/// Vertices where either field is not finite are skipped.
DistanceError distanceError(const std::vector<double>& d, const std::vector<double>& reference);

/// Triangle quality as the project measures it (the mean angle is always 60 degrees, so it is
/// not reported): spread of all angles, the smallest angle, and the share of triangles whose
/// smallest angle is under 30 degrees. Zero-area faces count with angles 0, 0, 180.
struct AngleStatistics {
  double stdDegrees = 0.0;       ///< standard deviation of all triangle angles
  double minDegrees = 180.0;     ///< smallest angle of any triangle
  double maxDegrees = 0.0;       ///< largest angle of any triangle
  double shareMinBelow30 = 0.0;  ///< fraction of triangles with an angle under 30 degrees
};

AngleStatistics angleStatistics(const TriMesh& mesh);

/// Which points of `from` surfaceDistance measures.
enum class DistanceSamples {
  /// Every vertex, face centroid and midpoint of each face's sides: the project's measure (tests,
  /// benchmarks, docs).
  VerticesMidpointsCentroids,
  /// Every vertex alone: 7 times fewer queries on a closed mesh. The side of the filters' logs that
  /// measures a fine input against its remesh (issue 20: the log's figures must cost little of the
  /// filter's time; remesh_distance.h).
  Vertices,
};

struct SurfaceDistance {
  double max = 0.0;      ///< one-sided Hausdorff distance
  double rms = 0.0;      ///< root mean square over the samples
  bool complete = true;  ///< false if cancelled through the progress callback
};

/// Distance from the surface `from` to the surface `to`, sampled at the vertices, edge midpoints
/// and face centroids of `from` (or its vertices only: `samples`), each to its nearest
/// point of `to`, found with vcglib's grid.
/// The samples are measured in fixed blocks on all hardware threads (up to `maxThreads`; 0 = as
/// many as the machine has) and the blocks combined in order, so the result does not depend on
/// the thread count. Cost: O(V + F) nearest-point queries on a grid of 16 cells per face of `to`
/// (times: docs/BENCHMARKS.md). `progress` is reported from the calling thread only; if it
/// cancels, the result is marked incomplete.
SurfaceDistance surfaceDistance(const TriMesh& from, const TriMesh& to, Progress progress = {}, int maxThreads = 0,
                                DistanceSamples samples = DistanceSamples::VerticesMidpointsCentroids);

}  // namespace gr
