// Greedy farthest-point sampling of a surface (paper §3.1).
//
// The first sample is the vertex farthest from a start vertex chosen by `seed`; each next sample
// is the vertex farthest from all samples so far, where the geodesic distance U_n is largest.
// U_{n+1} = min(U_n, U_x) is updated incrementally: the new front only enters the vertices it
// improves (FastMarcher). The maximum is tracked in a bucket queue (farthest_queue.h) fed with
// the vertices each step changed, so no step scans all vertices. A component with no sample yet is infinitely far: each
// other component gets its lowest-numbered vertex as first sample before any component gets a
// second one. On a mesh with boundaries, boundary vertices take precedence (boundaryPriority),
// so each loop is sampled before the interior near it.
// Sub-vertex placement (paper §3.1, last paragraph): the farthest vertex is only within an edge
// length of the farthest point, which lies where three fronts meet, usually inside a face. With
// `subVertexPlacement` the new sample moves to the point of the faces near that vertex where a
// local model of the fronts is largest: each front L is U at its nearest vertex w plus the
// change of the straight distance to its sample, |p - s_L| - |w - s_L|, and the fronts' minimum
// is maximised over a barycentric lattice of those faces. Boundary samples stay on vertices.
// Cost: O(sum of improved regions * log) - about O(V log V log n) for n samples (paper Table 2).
#pragma once

#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/metric.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Options of greedy farthest-point sampling (Peyré & Cohen 2006, §3.1).
struct FpsParams {
  int targetCount = 1000;   ///< stop after this many samples (>= 1); 0 = stop on spacing only
  double minSpacing = 0.0;  ///< also stop when the farthest distance is below this (mesh units); 0 = off
  unsigned seed = 0;        ///< picks the start vertex: the same seed gives the same samples
  /// Boundary vertices count as this much farther than they are (>= 1), so boundary loops are
  /// sampled first and about 1/boundaryPriority times the interior spacing apart; 1 = no priority.
  double boundaryPriority = 1.5;
  /// Place interior samples where the fronts meet, inside faces, rather than at the farthest
  /// vertex: samples closer to a net of the surface, better shaped triangles at high densities.
  bool subVertexPlacement = false;
  /// Samples to start from (vertices in faces, each once), chosen by a cheaper rule: one
  /// multi-source front gives their field, and the greedy sampling goes on from it (they count
  /// towards targetCount; their insertionDistance is +inf). Empty: the first sample is the vertex
  /// farthest from a start vertex chosen by `seed`. Why: the first samples' fronts are the dearest
  /// (each of the first few covers a large share of the surface: on a 10k-vertex square the first
  /// 10 of 100 samples cost two thirds of the sampling), and a surface's extremities are found
  /// about as well in 3D (geodesic LLE's base points, farthest_point_sampling.h's callers there).
  std::vector<int> initialSamples;
};

struct FpsResult {
  std::vector<int> samples;          ///< the farthest vertex at each step, in the order they were chosen
  std::vector<SurfacePoint> origin;  ///< where the samples lie: samples[i], or a point near it (subVertexPlacement)
  std::vector<double> distance;      ///< per vertex, U to the nearest sample
  std::vector<int> cell;             ///< per vertex, its geodesic Voronoi cell: an index into `samples`
  double coveringRadius = 0.0;       ///< largest U at the end (the next sample's distance)
  std::vector<double> insertionDistance;  ///< U_n at each sample when it was chosen (inf for the first of a component)
};

/// Fails (InvalidInput) on targetCount < 0, both stopping rules off, a negative or NaN spacing,
/// or more samples than vertices in faces; (Cancelled) if the progress callback says so.
Expected<FpsResult> farthestPointSampling(const TriMesh& mesh, const Metric& metric, const FpsParams& params = {},
                                          Progress progress = {});

/// The same on a caller's engine (reset first). On return the engine holds the field of the
/// samples, each the source of its own cell (its index), so the next stage (geodesicDelaunay) can go on from it.
Expected<FpsResult> farthestPointSampling(FastMarcher& marcher, const FpsParams& params = {}, Progress progress = {});

/// At most `count` vertices in faces by greedy farthest-point sampling in the straight 3D distance
/// (O(count V)), the first the farthest from a start vertex chosen by `seed`; fewer when every vertex
/// is taken. Initial samples for farthestPointSampling (FpsParams::initialSamples): a surface's
/// extremities are found as well in 3D, and the geodesic sampling fills what a 3D one leaves where
/// the surface curls back on itself.
std::vector<int> farthestPointsIn3d(const TriMesh& mesh, int count, unsigned seed = 0);

/// The sampling of `count` samples (1 <= count <= longer.samples.size()) with the parameters that
/// gave `longer` on the same engine, without sampling again: greedy sampling chooses each sample
/// from the ones before it alone, so its first `count` samples are that sampling. One
/// multi-source front (the engine is reset) gives their field and cells, left in the engine as
/// farthestPointSampling leaves it (cells the same but at ties on their borders, where the fronts
/// arrive together); the covering radius is the field's largest finite value. Cost: one
/// front, O(V log V), where sampling again costs about log(count) of them.
Expected<FpsResult> samplingPrefix(FastMarcher& marcher, const FpsResult& longer, int count);

}  // namespace gr
