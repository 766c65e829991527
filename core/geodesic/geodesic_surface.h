// The surface fronts run on: the input itself, or, where its triangles are poor, its intrinsic
// Delaunay refinement; and geodesicDistance(), the distance field every caller reads through it.
//
// Fast marching is accurate on well-shaped triangles and wrong, silently, on slivers and caps
// (CAD exports: long thin triangles across flat faces, vertices only on the outlines). So:
//
//   input --assessTriangulation--> refine? (Auto: slivers or caps; On; Off)
//         --refineIntrinsicDelaunay--> the same surface, every angle >= 25 deg, input vertices
//                                      first, inserted points located on input faces
//         --transferMetric----------> P at the inserted points (interpolated on their input face)
//         --FastMarcher on the intrinsic lengths, saddle seeding, the input's edges as path
//           edges (exact along them), the chord bound
//         --> values at the input's vertices (and at the inserted points, for callers that use them)
//
// On a well-shaped mesh (Auto) nothing is built and nothing is paid but the O(F) test: the
// engine runs on the input as before, with seeding at boundary vertices only and the chord bound.
// Saddle seeding at every saddle (FastMarcher::setSaddleSeeding) is turned on only on refined
// surfaces, where the front has many more vertices to go round saddles and holes.
//
// geodesicDistance() (one field, the Fast marching filter's call) can do better on a poor mesh:
// exact window propagation (exact_geodesic.h) gives the polyhedral distance itself, and on CAD
// meshes it is cheaper than the refinement (the CAD gear: 3.4 ms against 17.7 ms). It is tried
// first where the refinement would be, within a window budget that keeps its cost near the
// refinement's (exactWindowBudget); a run over budget hands over to the refinement.
//
// Cost: the test O(F); the refinement (intrinsic_refinement.h) O((V + points) log V); the
// propagation O(V' log V') on the V' = V + points vertices. Memory: the refined mesh, its corner
// lengths and origins, O(V' + F').
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/geodesic/exact_geodesic.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/intrinsic_refinement.h"
#include "core/geodesic/metric.h"
#include "core/geodesic/triangulation_quality.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Whether fronts run on an intrinsic Delaunay refinement of the input.
enum class SurfaceRefinement {
  Auto = 0,  ///< when assessTriangulation says the triangles are poor (default)
  On = 1,    ///< always
  Off = 2,   ///< never: the input as it is
};

struct GeodesicSurfaceParams {
  SurfaceRefinement refinement = SurfaceRefinement::Auto;
  /// The refinement's bound (25 degrees) and budget (10 V + 1000 points, plus 2 per equilateral
  /// triangle of side maxEdgeFraction x diagonal in the surface's area).
  IntrinsicRefinementParams intrinsic;
  /// A refined surface also has no edge longer than this share of the input's bounding-box
  /// diagonal (the smaller of this and intrinsic.maxEdgeLength; 0 = no such bound): cheese.off
  /// 1.03% -> 0.93% mean error against exact geodesics (0.87% with the path edges), a cube 1.9% -> 0%.
  double maxEdgeFraction = 0.02;
};

/// The triangulation fronts run on. Vertices 0..inputVertexCount-1 are the input's, in its order;
/// a refined surface has its inserted points after them. Keep it in place while a FastMarcher
/// made by makeMarcher() lives: the marcher reads its mesh, lengths and metric.
struct GeodesicSurface {
  const TriMesh* input = nullptr;
  TriangulationQuality inputQuality;  ///< the test's figures (also when refinement is On or Off)
  bool refined = false;
  /// When refinement was asked (Auto said yes, or On) but could not be done (a non-manifold
  /// input): why, for the log; the surface is then the input.
  std::string refinementSkipped;
  RefinedSurface refinement;  ///< filled when `refined`
  /// When refined: the input's edges (vertex pairs, the same numbers in mesh()) and their 3D
  /// lengths, the marcher's path edges (FastMarcher::setPathEdges).
  std::vector<std::array<int, 2>> inputEdges;
  std::vector<double> inputEdgeLength;
  Metric metric;  ///< on mesh()'s vertices

  const TriMesh& mesh() const { return refined ? refinement.mesh : *input; }
  int inputVertexCount() const { return input->vertexCount(); }
  int insertedPoints() const { return refined ? refinement.insertedPoints : 0; }
  /// Where vertex v of mesh() lies on the input.
  SurfacePoint origin(int v) const { return refined ? refinement.origin[v] : SurfacePoint::atVertex(v); }
  /// A fast-marching engine on this surface (the intrinsic lengths when refined, with saddle
  /// seeding). O(V' + F').
  FastMarcher makeMarcher() const;
};

/// Prepares the surface: the test, the refinement when asked, the metric at the inserted points.
/// `metric` is uniform or has one P per input vertex. Fails with InvalidInput (a metric of the
/// wrong size, refinement parameters out of range), NonManifold (refinement On on a
/// non-manifold mesh; Auto then uses the input and says why in `refinementSkipped`), Cancelled.
Expected<GeodesicSurface> prepareGeodesicSurface(const TriMesh& input, const Metric& metric,
                                                 const GeodesicSurfaceParams& params = {}, Progress progress = {});

/// Whether geodesicDistance may use exact window propagation (exact_geodesic.h) instead of fronts.
enum class ExactPropagation {
  /// Where the surface would be refined (surface.refinement Auto and the test says so), exact
  /// when its windows stay within exactWindowBudget(): CAD meshes and small meshes; the refinement
  /// when they do not (default).
  WhereCheaper = 0,
  Always = 1,  ///< exact whenever it applies, with the window budget of ExactGeodesicParams
  Never = 2,   ///< fast marching only (on the surface `surface` says)
};

struct GeodesicDistanceParams {
  GeodesicSurfaceParams surface;
  FastMarchingParams marching;  ///< distance limit; targets are input vertices
  /// Exact propagation applies with a uniform (or constant) speed, no targets and no region, on a
  /// manifold mesh with no zero-length edge; elsewhere, and when its budget runs out, the fronts
  /// run as `surface` says. surface.refinement On or Off means fronts (Never).
  ExactPropagation exact = ExactPropagation::WhereCheaper;
};

struct GeodesicDistanceResult {
  /// Per input vertex: distance, cell (index into the sources), accepted order (input vertices
  /// only) and the largest finite distance among them.
  FastMarchingResult field;
  bool refined = false;
  int insertedPoints = 0;
  int facesBelowMinAngle = 0;    ///< of the refinement (faces it had to leave alone)
  bool budgetExhausted = false;  ///< the refinement stopped at its point budget (maxInsertions)
  TriangulationQuality inputQuality;
  std::string refinementSkipped;  ///< see GeodesicSurface
  bool exact = false;             ///< the field is exact window propagation's
  long long windows = 0;          ///< windows it created (also when it ran out and fronts took over)
  bool exactOverBudget = false;   ///< it was tried and ran out of windows (or memory): the fronts gave the field
};

/// The windows exact propagation may create on `mesh` under ExactPropagation::WhereCheaper before
/// the refinement takes over: 50,000 + V x (10 + 100 x the share of poor faces (the largest of
/// the sliver, cap and long-edge shares)). Measured over the data set: a window costs about
/// 0.24 us, the refinement about 3-4 us per inserted point; CAD meshes need 10-80 windows per
/// vertex and insert 2-30 points per vertex, scans with a few slivers need 50-600 windows per
/// vertex and insert fewer than 1. So exact runs where it costs about what the refinement would,
/// and a run that runs out wastes at most that much.
long long exactWindowBudget(const TriangulationQuality& quality, int vertices);

/// Multi-source geodesic distance on `mesh` under the speed F (one value per vertex, > 0; empty =
/// F = 1), from the given vertices: exact (window propagation) where `params.exact` allows it,
/// else fronts on the surface prepareGeodesicSurface chooses. Fails as fastMarchingWithSpeed and
/// prepareGeodesicSurface. Progress: the exact run's share is its first third, the refinement's
/// its points over the budget, then the propagation.
Expected<GeodesicDistanceResult> geodesicDistance(const TriMesh& mesh, const std::vector<double>& speed,
                                                  const std::vector<int>& sources,
                                                  const GeodesicDistanceParams& params = {}, Progress progress = {});

}  // namespace gr
