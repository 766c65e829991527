#include "core/geodesic/geodesic_surface.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

namespace gr {
namespace {

bool wantsRefinement(const GeodesicSurfaceParams& params, const TriangulationQuality& quality) {
  switch (params.refinement) {
    case SurfaceRefinement::On: return quality.faces > 0;
    case SurfaceRefinement::Off: return false;
    case SurfaceRefinement::Auto: break;
  }
  return quality.needsRefinement;
}

Status checkDistanceInput(const TriMesh& mesh, const std::vector<int>& sources, const FastMarchingParams& params) {
  if (Status s = checkSourcesAndLimit(mesh, sources, params.maxDistance); !s) return s;
  for (int t : params.targets)
    if (t < 0 || t >= mesh.vertexCount()) return invalidInput("target vertex " + std::to_string(t) + " does not exist");
  return Status::ok();
}

/// The marcher's field restricted to the input's first n vertices.
FastMarchingResult fieldAtInputVertices(const FastMarcher& marcher, int n) {
  FastMarchingResult r;
  r.distance.assign(marcher.distance().begin(), marcher.distance().begin() + n);
  r.cell.assign(marcher.cell().begin(), marcher.cell().begin() + n);
  r.acceptedOrder.reserve(n);
  for (int v : marcher.acceptedOrder())
    if (v < n) r.acceptedOrder.push_back(v);
  for (int v : r.acceptedOrder) r.maxDistance = std::max(r.maxDistance, r.distance[v]);
  return r;
}

Status checkSurfaceParams(const GeodesicSurfaceParams& params) {
  const IntrinsicRefinementParams& ip = params.intrinsic;
  if (!(ip.minAngleDegrees >= 0.0 && ip.minAngleDegrees < 60.0) || !(ip.maxEdgeLength > 0.0) || ip.maxInsertions < -1 ||
      !(params.maxEdgeFraction >= 0.0 && std::isfinite(params.maxEdgeFraction)))
    return invalidInput("refinement parameters out of range: minimum angle " + std::to_string(ip.minAngleDegrees) +
                        " (in [0, 60) degrees), maximum edge length " + std::to_string(ip.maxEdgeLength) +
                        " (> 0), budget " + std::to_string(ip.maxInsertions) + " (>= -1), edge fraction " +
                        std::to_string(params.maxEdgeFraction) + " (>= 0)");
  return Status::ok();
}

/// The constant speed of `speed` (1 when empty), or 0 when it varies.
double constantSpeed(const std::vector<double>& speed) {
  if (speed.empty()) return 1.0;
  for (double f : speed)
    if (f != speed.front()) return 0.0;
  return speed.front();
}

/// Exact window propagation when `params` allows it and it finishes within its budget: the field
/// in `r` (true), or false with `r.windows` / `r.exactOverBudget` telling what was tried.
Expected<bool> tryExact(const TriMesh& mesh, const std::vector<double>& speed, const std::vector<int>& sources,
                        const GeodesicDistanceParams& params, GeodesicDistanceResult& r, Progress progress) {
  if (params.exact == ExactPropagation::Never || params.surface.refinement != SurfaceRefinement::Auto) return false;
  const double f = constantSpeed(speed);
  if (!(f > 0.0) || !params.marching.targets.empty() || params.marching.region != nullptr) return false;
  ExactGeodesicParams ep;
  if (params.exact == ExactPropagation::WhereCheaper) {
    if (!r.inputQuality.needsRefinement) return false;
    ep.maxWindows = exactWindowBudget(r.inputQuality, mesh.vertexCount());
  }
  ep.maxDistance = params.marching.maxDistance * f;
  Expected<ExactGeodesicResult> exact = exactGeodesicDistance(mesh, sources, ep, std::move(progress));
  if (!exact) {  // a non-manifold mesh or a zero-length edge: the fronts do what they can
    if (exact.status().code == StatusCode::Cancelled) return exact.status();
    r.exactOverBudget = exact.status().code == StatusCode::OutOfMemory;
    return false;
  }
  r.windows = exact->windows;
  r.exactOverBudget = exact->budgetExhausted;
  if (exact->budgetExhausted) return false;
  r.exact = true;
  r.field = std::move(exact->field);
  if (f != 1.0) {
    for (double& d : r.field.distance) d /= f;
    r.field.maxDistance /= f;
  }
  return true;
}

}  // namespace

long long exactWindowBudget(const TriangulationQuality& quality, int vertices) {
  const double poor = std::max({quality.sliverShare, quality.capShare, quality.longEdgeShare});
  return 50000 + static_cast<long long>(vertices * (10.0 + 100.0 * poor));
}

namespace {

/// The engine on an unrefined input: boundary seeding only (a few vertices, no measurable cost)
/// and the chord bound.
void setUpForInput(FastMarcher& marcher, const TriMesh& input) {
  if (input.topology.boundaryEdges > 0) marcher.setSaddleSeeding(true, /*boundaryOnly=*/true);
  marcher.setChordBound(true);
}

}  // namespace

FastMarcher GeodesicSurface::makeMarcher() const {
  if (!refined) {
    FastMarcher marcher(*input, metric);
    setUpForInput(marcher, *input);
    return marcher;
  }
  FastMarcher marcher(refinement.mesh, refinement.cornerLength, metric);
  marcher.setPathEdges(inputEdges, inputEdgeLength);
  marcher.setSaddleSeeding(true);
  marcher.setChordBound(true);
  return marcher;
}

namespace {

/// prepareGeodesicSurface with the test's figures already known.
Expected<GeodesicSurface> prepareSurface(const TriMesh& input, const Metric& metric,
                                         const GeodesicSurfaceParams& params, const TriangulationQuality& quality,
                                         Progress progress) {
  if (!metric.isUniform() && static_cast<int>(metric.P.size()) != input.vertexCount())
    return invalidInput("the metric has " + std::to_string(metric.P.size()) + " values for " +
                        std::to_string(input.vertexCount()) + " vertices");
  if (Status st = checkSurfaceParams(params); !st) return st;
  GeodesicSurface s;
  s.input = &input;
  s.inputQuality = quality;
  s.metric = metric;
  if (!wantsRefinement(params, s.inputQuality)) return s;
  IntrinsicRefinementParams intrinsic = params.intrinsic;
  if (params.maxEdgeFraction > 0.0 && s.inputQuality.diagonal > 0.0)
    intrinsic.maxEdgeLength = std::min(intrinsic.maxEdgeLength, params.maxEdgeFraction * s.inputQuality.diagonal);
  Expected<RefinedSurface> refined = refineIntrinsicDelaunay(input, intrinsic, std::move(progress));
  if (!refined) {
    const StatusCode code = refined.status().code;
    // Auto falls back to the input where refinement cannot work (non-manifold, non-orientable;
    // the parameters were checked above).
    const bool fallBack = params.refinement == SurfaceRefinement::Auto &&
                          (code == StatusCode::NonManifold || code == StatusCode::InvalidInput);
    if (!fallBack) return refined.status();
    s.refinementSkipped = refined.status().message;
    return s;
  }
  Expected<Metric> transferred = transferMetric(metric, input, refined->origin);
  if (!transferred) return transferred.status();
  s.refined = true;
  s.refinement = std::move(*refined);
  for (int c = 0; c < 3 * input.faceCount(); ++c) {  // each input edge once
    const int a = input.vertex(TriMesh::next(c)), b = input.vertex(TriMesh::prev(c));
    const int opposite = input.oppositeCorner[c];
    if (opposite >= 0 && opposite < c) continue;
    s.inputEdges.push_back({a, b});
    s.inputEdgeLength.push_back((input.positions[a] - input.positions[b]).norm());
  }
  s.metric = std::move(*transferred);
  return s;
}

}  // namespace

Expected<GeodesicSurface> prepareGeodesicSurface(const TriMesh& input, const Metric& metric,
                                                 const GeodesicSurfaceParams& params, Progress progress) {
  return prepareSurface(input, metric, params, assessTriangulation(input), std::move(progress));
}

Expected<GeodesicDistanceResult> geodesicDistance(const TriMesh& mesh, const std::vector<double>& speed,
                                                  const std::vector<int>& sources, const GeodesicDistanceParams& params,
                                                  Progress progress) {
  if (Status s = checkDistanceInput(mesh, sources, params.marching); !s) return s;
  if (Status s = checkSurfaceParams(params.surface); !s) return s;
  Metric metric = Metric::uniform();
  if (!speed.empty()) {  // checked whichever method runs
    Expected<Metric> fromSpeed = Metric::fromSpeed(mesh, speed);
    if (!fromSpeed) return fromSpeed.status();
    metric = std::move(*fromSpeed);
  }
  GeodesicDistanceResult r;
  // The engine on the input measures the triangulation while it is built: on a good mesh, the
  // common case, the test then costs no second pass over the faces (2.4% of a call on a 1.66M
  // mesh). Refinement On builds it only on the refined surface.
  std::optional<FastMarcher> inputEngine;
  if (params.surface.refinement != SurfaceRefinement::On) inputEngine.emplace(mesh, metric);
  const TriangulationQuality* measured = inputEngine ? inputEngine->triangulationQuality() : nullptr;
  r.inputQuality = measured ? *measured : assessTriangulation(mesh);
  Expected<bool> exact = tryExact(mesh, speed, sources, params, r, progress.sub(0.0, 0.3));
  if (!exact) return exact.status();
  if (*exact) return r;
  const GeodesicSurfaceParams& sp = params.surface;
  const bool mayRefine = sp.refinement != SurfaceRefinement::Off;
  // The progress goes on from where an exact run that ran out of windows left it.
  const double start = r.windows > 0 ? 0.3 : 0.0, middle = start + 0.5 * (1.0 - start);
  Expected<GeodesicSurface> surface =
      prepareSurface(mesh, metric, sp, r.inputQuality, mayRefine ? progress.sub(start, middle) : Progress());
  if (!surface) return surface.status();
  FastMarcher marcher = surface->refined || !inputEngine ? surface->makeMarcher() : std::move(*inputEngine);
  if (!surface->refined && inputEngine) setUpForInput(marcher, mesh);
  for (size_t i = 0; i < sources.size(); ++i)
    if (Status s = marcher.addSource(sources[i], static_cast<int>(i)); !s) return s;
  Progress marching = surface->refined ? progress.sub(middle, 1.0) : progress.sub(start, 1.0);
  if (Status s = marcher.propagate(params.marching, std::move(marching)); !s) return s;
  r.field = fieldAtInputVertices(marcher, mesh.vertexCount());
  r.refined = surface->refined;
  r.insertedPoints = surface->insertedPoints();
  r.facesBelowMinAngle = surface->refined ? surface->refinement.facesBelowMinAngle : 0;
  r.budgetExhausted = surface->refined && surface->refinement.budgetExhausted;
  r.refinementSkipped = surface->refinementSkipped;
  return r;
}

}  // namespace gr
