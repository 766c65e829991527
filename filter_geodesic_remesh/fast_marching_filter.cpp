#include "filter_geodesic_remesh/fast_marching_filter.h"

#include <chrono>
#include <cmath>
#include <string>

#include "core/geodesic/fast_marching.h"
#include "filter_geodesic_remesh/filter_support.h"
#include "filter_geodesic_remesh/parameter_names.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {
namespace {

/// The front speed asked for by the parameters: the vertex quality, or none (F = 1).
Expected<std::vector<double>> speedFromParameters(const MeshModel& mm, const adapters::CoreView& view,
                                                  bool useQuality) {
  if (!useQuality) return std::vector<double>();
  if (!mm.hasDataMask(MeshModel::MM_VERTQUALITY))
    return invalidInput(
        "UseQualityAsSpeed is on, but the mesh has no per-vertex quality: compute one first "
        "(any filter of the Quality Measure and Computations menu)");
  return adapters::vertexQuality(mm.cm, view);
}

}  // namespace

void declareFastMarching(const MeshModel& mesh, RichParameterList& params) {
  const float diag = mesh.cm.bbox.IsNull() ? 1.0f : mesh.cm.bbox.Diag();
  params.addParam(RichBool(param::kUseQualityAsSpeed, false, "Use quality as speed",
                           "If true, the per-vertex quality is the front speed F (> 0 everywhere; distances are "
                           "then travel times, integrals of 1/F). If false (default), the speed is 1 and the "
                           "result is the geodesic distance in mesh units."));
  params.addParam(RichAbsPerc(param::kMaxDistance, 0.0f, 0.0f, diag, "Max distance",
                              "Stop the front at this distance (mesh units, or % of the bounding-box diagonal). "
                              "Vertices farther away are not reached and get quality -1. Default 0 = no limit."));
  params.addParam(RichEnum(param::kColorBy, int(ColorBy::Distance),
                           QStringList() << "Distance"
                                         << "Voronoi cell",
                           "Color by",
                           "Distance (default): a red-to-blue ramp over the distance. Voronoi cell: one color per "
                           "source, each vertex colored by its nearest source (geodesic Voronoi diagram)."));
}

Status applyFastMarching(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  // Compute, with no change to the document...
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  MeshModel* mm = current->model;
  CMeshO& m = mm->cm;
  const adapters::CoreView& view = current->view;
  const Topology& topology = view.mesh.topology;
  if (topology.nonManifoldEdges > 0)
    return nonManifold("the mesh has " + std::to_string(topology.nonManifoldEdges) +
                       " non-manifold edges (shared by three or more faces); fast marching needs at most two "
                       "faces per edge. Run 'Repair non Manifold Edges by removing faces' first.");
  const std::vector<int> sources = adapters::selectedVertices(m, view);
  if (sources.empty())
    return invalidInput(
        "no vertex is selected: select the source vertices first (for example with "
        "'Conditional Vertex Selection')");
  const bool useQuality = params.getBool(param::kUseQualityAsSpeed);
  Expected<std::vector<double>> speed = speedFromParameters(*mm, view, useQuality);
  if (!speed) return speed.status();
  const double maxDistance = params.getAbsPerc(param::kMaxDistance);
  FastMarchingParams fmParams;
  if (maxDistance != 0.0) fmParams.maxDistance = maxDistance;  // 0 = no limit; the core checks the rest
  const int colorBy = params.getEnum(param::kColorBy);
  if (colorBy != int(ColorBy::Distance) && colorBy != int(ColorBy::VoronoiCell))
    return invalidInput("ColorBy must be 0 (Distance) or 1 (Voronoi cell), got " + std::to_string(colorBy));

  Expected<FastMarchingResult> result = fastMarchingWithSpeed(view.mesh, *speed, sources, fmParams, ctx.progress);
  if (!result) {
    if (useQuality && result.status().code == StatusCode::InvalidInput)
      return invalidInput("vertex quality used as speed: " + result.status().message);
    return result.status();
  }

  // ...then commit.
  adapters::writeVertexQuality(m, view, result->distance, -1.0);
  if (colorBy == int(ColorBy::Distance))
    adapters::colorByRamp(m, view, result->distance, 0.0, result->maxDistance);
  else
    adapters::colorByLabel(m, view, result->cell, static_cast<int>(sources.size()));
  mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);

  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const int unreached = view.mesh.vertexCount() - result->reachedCount();
  ctx.log("Fast marching from " + std::to_string(sources.size()) + " selected vertices, speed " +
          (useQuality ? "= vertex quality" : "1") +
          (fmParams.maxDistance < kUnreached ? ", max distance " + formatNumber(fmParams.maxDistance) : std::string()));
  ctx.log("Reached " + std::to_string(result->reachedCount()) + " of " + std::to_string(view.mesh.vertexCount()) +
          " vertices; maximum distance " + formatNumber(result->maxDistance));
  if (unreached > 0)
    ctx.warn(std::to_string(unreached) +
             " vertices were not reached (other connected components, or beyond "
             "MaxDistance); their quality is -1");
  if (topology.nonManifoldVertices > 0)
    ctx.warn("the mesh has " + std::to_string(topology.nonManifoldVertices) +
             " non-manifold vertices; fronts cross them through the vertex only");
  ctx.log("Time: " + formatDuration(ms));
  return Status::ok();
}

}  // namespace gr::filters
