#include "filter_geodesic_remesh/fast_marching_filter.h"

#include <chrono>
#include <cmath>
#include <string>

#include "core/geodesic/geodesic_surface.h"
#include "core/geodesic/triangulation_quality.h"
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

/// The refinement's log: one line on the triangulation fronts ran on, then what the refinement
/// could not do (skipped, faces left below the angle bound, budget spent), as warnings.
void logTriangulation(const GeodesicDistanceResult& r, const GeodesicSurfaceParams& surface, FilterContext& ctx) {
  if (r.exact)
    ctx.log("Exact geodesic distances (window propagation, " + std::to_string(r.windows) + " windows); input " +
            describe(r.inputQuality));
  else if (r.exactOverBudget)
    ctx.log("Exact propagation stopped at its budget (" + std::to_string(r.windows) +
            " windows): the fronts ran on the refined surface instead");
  if (r.refined)
    ctx.log("Surface refined for the fronts (intrinsic Delaunay, angles >= " +
            formatNumber(surface.intrinsic.minAngleDegrees) + " deg, edges <= " +
            formatNumber(100.0 * surface.maxEdgeFraction) + "% of the diagonal): " + std::to_string(r.insertedPoints) +
            " points inserted; input " + describe(r.inputQuality));
  else if (surface.refinement == SurfaceRefinement::Off && !r.exact)
    ctx.log("Refinement Off: the fronts ran on the triangulation as it is (" + describe(r.inputQuality) + ")");
  else if (r.refinementSkipped.empty() && !r.exact)
    ctx.log("Triangulation fine as it is (" + describe(r.inputQuality) + "): not refined");
  if (!r.refinementSkipped.empty())
    ctx.warn("the triangulation is poor but could not be refined (" + r.refinementSkipped +
             "); the fronts ran on it as it is and may be less accurate");
  if (r.facesBelowMinAngle > 0)
    ctx.warn(std::to_string(r.facesBelowMinAngle) + " faces of the refined surface stayed below " +
             formatNumber(surface.intrinsic.minAngleDegrees) + " deg");
  if (r.budgetExhausted)
    ctx.warn("the refinement stopped at its budget of inserted points; some triangles stayed poor");
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
  params.addParam(RichEnum(
      param::kSurfaceRefinement, int(GeodesicSurfaceParams{}.refinement),
      QStringList() << "Auto"
                    << "On"
                    << "Off"
                    << "Exact",
      "Refinement",
      "Auto (default): where the triangles are poor (slivers, caps: CAD exports) or the mesh is coarse, exact "
      "geodesic distances by window propagation when that costs about what refining would (CAD parts, small "
      "meshes), else the fronts run on an intrinsic Delaunay refinement of the same surface (every angle >= 25 deg, "
      "edges <= 2% of the bounding-box diagonal), which fast marching needs to be accurate; well-shaped meshes are "
      "used as they are. On / Off: fronts, always / never refined. Exact: exact distances whenever the speed is "
      "constant (slower on large scans). The values are read at the mesh's own vertices: nothing is added to the "
      "mesh."));
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
  GeodesicDistanceParams gdParams;
  FastMarchingParams& fmParams = gdParams.marching;
  if (maxDistance != 0.0) fmParams.maxDistance = maxDistance;  // 0 = no limit; the core checks the rest
  const int colorBy = params.getEnum(param::kColorBy);
  if (colorBy != int(ColorBy::Distance) && colorBy != int(ColorBy::VoronoiCell))
    return invalidInput("ColorBy must be 0 (Distance) or 1 (Voronoi cell), got " + std::to_string(colorBy));
  const int refinement = params.getEnum(param::kSurfaceRefinement);
  constexpr int kExact = 3;  // the enum's fourth entry: ExactPropagation::Always
  if (refinement < int(SurfaceRefinement::Auto) || refinement > kExact)
    return invalidInput("Refinement must be 0 (Auto), 1 (On), 2 (Off) or 3 (Exact), got " + std::to_string(refinement));
  gdParams.surface.refinement = refinement == kExact ? SurfaceRefinement::Auto : SurfaceRefinement(refinement);
  if (refinement == kExact) gdParams.exact = ExactPropagation::Always;

  Expected<GeodesicDistanceResult> computed = geodesicDistance(view.mesh, *speed, sources, gdParams, ctx.progress);
  if (!computed) {
    const Status& failed = computed.status();
    if (failed.code == StatusCode::NonManifold && refinement == int(SurfaceRefinement::On))
      return nonManifold("Refinement is On: " + failed.message +
                         ". Choose Auto or Off to run the fronts on the mesh as it is");
    if (useQuality && failed.code == StatusCode::InvalidInput)
      return invalidInput("vertex quality used as speed: " + failed.message);
    return failed;
  }
  const FastMarchingResult* result = &computed->field;

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
  logTriangulation(*computed, gdParams.surface, ctx);
  if (gdParams.exact == ExactPropagation::Always && !computed->exact)
    ctx.warn(computed->exactOverBudget
                 ? "Refinement Exact: the exact propagation ran out of its window budget; the fronts gave the values"
                 : "Refinement Exact needs a constant speed, a manifold mesh and no edge of zero length; the fronts "
                   "gave the values");
  ctx.log("Time: " + formatDuration(ms));
  return Status::ok();
}

}  // namespace gr::filters
