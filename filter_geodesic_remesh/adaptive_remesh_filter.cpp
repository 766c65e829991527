#include "filter_geodesic_remesh/adaptive_remesh_filter.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "core/base/format.h"
#include "core/base/statistics.h"
#include "core/field/curvature.h"
#include "core/remesh/remesh_surface.h"
#include "filter_geodesic_remesh/parameter_names.h"
#include "filter_geodesic_remesh/remesh_layer.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {
namespace {

const QStringList kFieldNames = {"Vertex quality", "Total curvature", "Color gradient"};  // AdaptiveField order
const QStringList kMappingNames = {"Direct", "Attractive", "Repulsive"};                  // SpeedMapping order
constexpr double kRampPercentile = 95.0;  ///< the total curvature's colour ramp ends at this percentile

/// `zeroMeans`: what a radius of 0 stands for in this filter.
void declareCurvatureRadius(const MeshModel& mesh, RichParameterList& params, const QString& zeroMeans) {
  const float diag = mesh.cm.bbox.IsNull() ? 1.0f : mesh.cm.bbox.Diag();
  const CurvatureParams defaults;
  params.addParam(RichAbsPerc(param::kCurvatureRadius, float(defaults.radius), 0.0f, 0.1f * diag, "Curvature radius",
                              "Radius of the neighbourhood the curvature tensor is averaged over (mesh units or % of "
                              "the bounding-box diagonal). 0 = " +
                                  zeroMeans +
                                  "; each vertex uses at least its 1-ring. Larger radii smooth noise and widen sharp "
                                  "edges (default " +
                                  QString::number(defaults.radius) + ")."));
}

/// The per-vertex values the field needs from the layer: its quality, or its colour's intensity.
Expected<std::vector<double>> fieldValues(const CurrentMesh& current, AdaptiveField field) {
  const MeshModel* mm = current.model;
  if (field == AdaptiveField::VertexQuality) {
    if (!mm->hasDataMask(MeshModel::MM_VERTQUALITY))
      return invalidInput(
          "the mesh has no vertex quality: compute one first (e.g. Compute Total Curvature, or any "
          "filter of the Quality Measure and Computations menu), or choose another Field");
    return adapters::vertexQuality(mm->cm, current.view);
  }
  if (field == AdaptiveField::ColorGradient) {
    if (!mm->hasDataMask(MeshModel::MM_VERTCOLOR))
      return invalidInput("the mesh has no vertex colour: the Color gradient field needs one");
    return adapters::vertexColorIntensity(mm->cm, current.view);
  }
  return std::vector<double>();
}

/// The log line of the field and its speed.
std::string fieldLine(const AdaptiveRemeshParams& adaptive, const AdaptiveRemeshResult& result) {
  const AdaptiveMetricParams& params = adaptive.metric;
  const AdaptiveMetricResult& metric = result.metric;
  const SpeedFieldResult& speed = metric.speed;
  std::string field = toString(params.field);
  if (params.field == AdaptiveField::TotalCurvature)
    field +=
        " (radius " + formatNumber(metric.curvatureRadius, "%.4g") +
        (result.automaticRadius ? ", automatic: " + formatNumber(adaptive.radiusInSpacings, "%g") + " target spacings"
                                : std::string()) +
        ")";
  return "Field: " + field + " from " + formatNumber(speed.fieldMin, "%.4g") + " to " +
         formatNumber(speed.fieldMax, "%.4g") + ", scale (" + formatNumber(params.speed.percentile, "%g") +
         "th percentile) " + formatNumber(speed.scale, "%.4g") + "; mapping " + toString(params.speed.mapping) +
         ", strength " + formatNumber(params.speed.strength, "%.4g") + ": speed from " +
         formatNumber(speed.speedMin, "%.4g") + " to " + formatNumber(speed.speedMax, "%.4g") +
         (adaptive.gradation > 0.0
              ? " after the gradation (" + formatNumber(adaptive.gradation, "%g") +
                    " per target spacing lowered it at " + std::to_string(result.gradedVertices) + " vertices)"
              : std::string());
}

}  // namespace

void declareAdaptiveRemesh(const MeshModel& mesh, RichParameterList& params) {
  const AdaptiveRemeshParams adaptiveDefaults;
  declareSampling(mesh, params, adaptiveDefaults.remesh);
  const AdaptiveMetricParams defaults;
  params.addParam(RichEnum(param::kField, int(defaults.field), kFieldNames, "Field",
                           "The per-vertex field that sets the density: the vertex quality (any filter's output: "
                           "curvature, ambient occlusion, distance, a painted value), the total curvature |k1|+|k2| "
                           "(Cohen-Steiner-Morvan tensor, paper 3.4), or the gradient magnitude of the vertex "
                           "colour's intensity (paper 3.3) (default: " +
                               kFieldNames[int(defaults.field)] + ")."));
  params.addParam(RichEnum(param::kMapping, int(defaults.speed.mapping), kMappingNames, "Mapping",
                           "How the field q becomes the front speed F (sample spacing follows F): Direct: F from 1/r "
                           "to 1 as q grows (sparser where q is large); Attractive: F = 1/(1 + mu q) (paper's F2, "
                           "denser where q is large: vertices gather on features); Repulsive: F = 1 + eps q "
                           "(paper's F1, sparser where q is large). q is first divided by its " +
                               QString::number(defaults.speed.percentile) +
                               "th percentile (default: " + kMappingNames[int(defaults.speed.mapping)] + ")."));
  params.addParam(RichFloat(param::kStrength, float(defaults.speed.strength), "Strength",
                            "r for Direct (ratio of the largest to the smallest spacing, >= 1), mu for Attractive, eps "
                            "for Repulsive (>= 0; 0 = uniform). Dimensionless: the same value gives similar results "
                            "on meshes of any size (default " +
                                QString::number(defaults.speed.strength) + ")."));
  declareCurvatureRadius(mesh, params,
                         "automatic: " + QString::number(AdaptiveRemeshParams{}.radiusInSpacings) +
                             " times the target spacing (the side of equilateral triangles of the surface's area "
                             "at Target vertices), so sharp edges attract a band about one output edge wide at any "
                             "count");
  params.addParam(RichFloat(param::kGradation, float(adaptiveDefaults.gradation), "Gradation",
                            "How fast the spacing may grow away from where the field packs the vertices: at most "
                            "this many times the distance, in units of the target spacing (0 = off). A spacing "
                            "that jumps, dense on a sharp edge and sparse on the face beside it, leaves thin "
                            "triangles between (default " +
                                QString::number(adaptiveDefaults.gradation) + ")."));
  params.addParam(RichInt(param::kRelaxation, adaptiveDefaults.remesh.relaxation.iterations, "Relaxation",
                          "Rounds of tangential relaxation after the triangulation (0 to " +
                              QString::number(SurfaceRemeshParams::kMaxRelaxationRounds) +
                              "), as in the uniform filter, each vertex moving toward the mean of its neighbours "
                              "weighted by the density so that it stays. Raises the smallest angles (fandisk at 10% "
                              "with 5 rounds: none under 30 degrees) at some cost in surface error on CAD parts "
                              "(default " +
                              QString::number(adaptiveDefaults.remesh.relaxation.iterations) + ")."));
  declareReportError(params);
}

Status applyAdaptiveRemesh(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  AdaptiveRemeshParams adaptive;
  adaptive.remesh.sampling = readSampling(params);
  adaptive.remesh.centroidalIterations = params.getInt(param::kCentroidalIterations);
  adaptive.remesh.relaxation.iterations = params.getInt(param::kRelaxation);
  adaptive.remesh.measureDistance = readReportError(params);
  adaptive.gradation = params.getFloat(param::kGradation);
  adaptive.metric.field = static_cast<AdaptiveField>(params.getEnum(param::kField));
  adaptive.metric.speed.mapping = static_cast<SpeedMapping>(params.getEnum(param::kMapping));
  adaptive.metric.speed.strength = params.getFloat(param::kStrength);
  adaptive.metric.curvature.radius = params.getAbsPerc(param::kCurvatureRadius);
  Expected<std::vector<double>> values = fieldValues(*current, adaptive.metric.field);
  if (!values) return values.status();
  RemeshCommit commit;
  Expected<AdaptiveRemeshResult> result = remeshAdaptive(current->view.mesh, *values, adaptive, ctx.progress);
  if (!result) return result.status();
  commit.title = "Geodesic adaptive remeshing";
  commit.layerSuffix = " - geodesic adaptive remesh";
  commit.weighted = !result->metric.speed.metric.isUniform();
  commitRemesh(doc, *current, result->remesh, commit, ctx);
  ctx.log(fieldLine(adaptive, *result));
  if (result->metric.speed.usedFallback()) ctx.warn("Speed field: " + result->metric.speed.fallback);
  return Status::ok();
}

void declareTotalCurvature(const MeshModel& mesh, RichParameterList& params) {
  declareCurvatureRadius(mesh, params, "the mean edge length");
}

Status applyTotalCurvature(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  const TriMesh& mesh = current->view.mesh;
  if (mesh.topology.nonManifoldEdges > 0)
    return nonManifold("the mesh has " + std::to_string(mesh.topology.nonManifoldEdges) + " non-manifold edges and " +
                       std::to_string(mesh.topology.nonManifoldVertices) +
                       " non-manifold vertices; repair them first (Cleaning and Repairing menu)");
  CurvatureParams curvature;
  curvature.radius = params.getAbsPerc(param::kCurvatureRadius);
  Expected<CurvatureResult> tau = totalCurvature(mesh, curvature, ctx.progress);
  if (!tau) return tau.status();
  MeshModel* mm = current->model;
  mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  adapters::writeVertexQuality(mm->cm, current->view, tau->tau, 0.0);
  const double hi = percentile(tau->tau, kRampPercentile);
  adapters::colorByRamp(mm->cm, current->view, tau->tau, 0.0, hi > 0.0 ? hi : 1.0);
  const auto [lo, top] = std::minmax_element(tau->tau.begin(), tau->tau.end());
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ctx.log("Total curvature |k1|+|k2| (Cohen-Steiner-Morvan, radius " + formatNumber(tau->radius, "%.4g") + ", " +
          formatNumber(tau->meanNeighbourhoodSize, "%.1f") +
          " vertices per ball on average) written to vertex quality: "
          "from " +
          formatNumber(*lo, "%.4g") + " to " + formatNumber(*top, "%.4g") + ", " + formatNumber(kRampPercentile, "%g") +
          "th percentile " + formatNumber(hi, "%.4g") + " (colour ramp from 0 to it)");
  if (tau->splitVertices > 0)
    ctx.log(std::to_string(tau->splitVertices) +
            " non-manifold vertices (fans of faces meeting at one vertex): each fan measured on its own, such a "
            "vertex given its largest fan's curvature");
  if (tau->looksLikeTriangleSoup)
    ctx.warn(std::to_string(tau->looseFaces) + " of the " + std::to_string(mesh.faceCount()) +
             " faces share no edge with another face (separate triangles, as an STL file read without merging its "
             "vertices gives): their vertices have no neighbours to bend against and get 0. Run 'Cleaning and "
             "Repairing > Merge Close Vertices' first.");
  ctx.log("Time: " + formatDuration(ms));
  return Status::ok();
}

}  // namespace gr::filters
