#include "core/geodesic/geodesic_surface.h"

#include <algorithm>
#include <cmath>
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
  if (sources.empty()) return invalidInput("no source vertices were given");
  for (int s : sources)
    if (s < 0 || s >= mesh.vertexCount())
      return invalidInput("source vertex " + std::to_string(s) + " does not exist (the mesh has " +
                          std::to_string(mesh.vertexCount()) + " vertices)");
  if (std::isnan(params.maxDistance) || params.maxDistance < 0.0)
    return invalidInput("the distance limit must be >= 0, got " + std::to_string(params.maxDistance));
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

}  // namespace

FastMarcher GeodesicSurface::makeMarcher() const {
  if (!refined) {  // boundary seeding only: a few vertices, no measurable cost
    FastMarcher marcher(*input, metric);
    if (input->topology.boundaryEdges > 0) marcher.setSaddleSeeding(true, /*boundaryOnly=*/true);
    marcher.setChordBound(true);
    return marcher;
  }
  FastMarcher marcher(refinement.mesh, refinement.cornerLength, metric);
  marcher.setPathEdges(inputEdges, inputEdgeLength);
  marcher.setSaddleSeeding(true);
  marcher.setChordBound(true);
  return marcher;
}

Expected<GeodesicSurface> prepareGeodesicSurface(const TriMesh& input, const Metric& metric,
                                                 const GeodesicSurfaceParams& params, Progress progress) {
  if (!metric.isUniform() && static_cast<int>(metric.P.size()) != input.vertexCount())
    return invalidInput("the metric has " + std::to_string(metric.P.size()) + " values for " +
                        std::to_string(input.vertexCount()) + " vertices");
  const IntrinsicRefinementParams& ip = params.intrinsic;
  if (!(ip.minAngleDegrees >= 0.0 && ip.minAngleDegrees < 60.0) || !(ip.maxEdgeLength > 0.0) || ip.maxInsertions < -1 ||
      !(params.maxEdgeFraction >= 0.0 && std::isfinite(params.maxEdgeFraction)))
    return invalidInput("refinement parameters out of range: minimum angle " + std::to_string(ip.minAngleDegrees) +
                        " (in [0, 60) degrees), maximum edge length " + std::to_string(ip.maxEdgeLength) +
                        " (> 0), budget " + std::to_string(ip.maxInsertions) + " (>= -1), edge fraction " +
                        std::to_string(params.maxEdgeFraction) + " (>= 0)");
  GeodesicSurface s;
  s.input = &input;
  s.inputQuality = assessTriangulation(input);
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

Expected<GeodesicDistanceResult> geodesicDistance(const TriMesh& mesh, const std::vector<double>& speed,
                                                  const std::vector<int>& sources, const GeodesicDistanceParams& params,
                                                  Progress progress) {
  if (Status s = checkDistanceInput(mesh, sources, params.marching); !s) return s;
  Metric metric = Metric::uniform();
  if (!speed.empty()) {
    Expected<Metric> fromSpeed = Metric::fromSpeed(mesh, speed);
    if (!fromSpeed) return fromSpeed.status();
    metric = std::move(*fromSpeed);
  }
  const GeodesicSurfaceParams& sp = params.surface;
  const bool mayRefine = sp.refinement != SurfaceRefinement::Off;
  Expected<GeodesicSurface> surface =
      prepareGeodesicSurface(mesh, metric, sp, mayRefine ? progress.sub(0.0, 0.5) : Progress());
  if (!surface) return surface.status();
  FastMarcher marcher = surface->makeMarcher();
  for (size_t i = 0; i < sources.size(); ++i)
    if (Status s = marcher.addSource(sources[i], static_cast<int>(i)); !s) return s;
  Progress marching = surface->refined ? progress.sub(0.5, 1.0) : std::move(progress);
  if (Status s = marcher.propagate(params.marching, std::move(marching)); !s) return s;
  GeodesicDistanceResult r;
  r.field = fieldAtInputVertices(marcher, mesh.vertexCount());
  r.refined = surface->refined;
  r.insertedPoints = surface->insertedPoints();
  r.facesBelowMinAngle = surface->refined ? surface->refinement.facesBelowMinAngle : 0;
  r.budgetExhausted = surface->refined && surface->refinement.budgetExhausted;
  r.inputQuality = surface->inputQuality;
  r.refinementSkipped = surface->refinementSkipped;
  return r;
}

}  // namespace gr
