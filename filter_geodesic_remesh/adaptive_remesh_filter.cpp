#include "filter_geodesic_remesh/adaptive_remesh_filter.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "core/field/color_gradient.h"
#include "core/field/curvature.h"
#include "core/field/speed_field.h"
#include "filter_geodesic_remesh/parameter_names.h"
#include "filter_geodesic_remesh/remesh_pipeline.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {
namespace {

enum class Field { VertexQuality = 0, TotalCurvature = 1, ColorGradient = 2 };
const QStringList kFieldNames = {"Vertex quality", "Total curvature", "Color gradient"};
const QStringList kMappingNames = {"Direct", "Attractive", "Repulsive"};

void declareCurvatureRadius(const MeshModel& mesh, RichParameterList& params) {
  const float diag = mesh.cm.bbox.IsNull() ? 1.0f : mesh.cm.bbox.Diag();
  params.addParam(RichAbsPerc(param::kCurvatureRadius, 0.0f, 0.0f, 0.1f * diag, "Curvature radius",
                              "Radius of the neighbourhood the curvature tensor is averaged over (mesh units or % of "
                              "the bounding-box diagonal). 0 = the mean edge length; each vertex uses at least its "
                              "1-ring. Larger radii smooth noise and widen sharp edges (default 0)."));
}

Expected<CurvatureResult> curvatureOf(const TriMesh& mesh, const RichParameterList& params, Progress progress) {
  CurvatureParams curvature;
  curvature.radius = params.getAbsPerc(param::kCurvatureRadius);
  return totalCurvature(mesh, curvature, std::move(progress));
}

/// The 95th percentile (nearest rank) of non-negative values, for a colour ramp.
double percentile95(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(0.95 * values.size()));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

}  // namespace

void declareAdaptiveRemesh(const MeshModel& mesh, RichParameterList& params) {
  declareSampling(mesh, params);
  const SpeedFieldParams defaults;
  params.addParam(RichEnum(param::kField, int(Field::TotalCurvature), kFieldNames, "Field",
                           "The per-vertex field that sets the density: the vertex quality (any filter's output: "
                           "curvature, ambient occlusion, distance, a painted value), the total curvature |k1|+|k2| "
                           "(Cohen-Steiner-Morvan tensor, paper 3.4), or the gradient magnitude of the vertex "
                           "colour's intensity (paper 3.3) (default: Total curvature)."));
  params.addParam(RichEnum(param::kMapping, int(defaults.mapping), kMappingNames, "Mapping",
                           "How the field q becomes the front speed F (sample spacing follows F): Direct: F from 1/r "
                           "to 1 as q grows (sparser where q is large); Attractive: F = 1/(1 + mu q) (paper's F2, "
                           "denser where q is large: vertices gather on features); Repulsive: F = 1 + eps q "
                           "(paper's F1, sparser where q is large). q is first divided by its 95th percentile "
                           "(default: Attractive)."));
  params.addParam(RichFloat(param::kStrength, float(defaults.strength), "Strength",
                            "r for Direct (ratio of the largest to the smallest spacing, >= 1), mu for Attractive, eps "
                            "for Repulsive (>= 0; 0 = uniform). Dimensionless: the same value gives similar results "
                            "on meshes of any size (default 4)."));
  declareCurvatureRadius(mesh, params);
}

Status applyAdaptiveRemesh(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  RemeshRequest request;
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  Expected<FpsParams> sampling = readSampling(params);
  if (!sampling) return sampling.status();
  const TriMesh& mesh = current->view.mesh;
  MeshModel* mm = current->model;

  // The field, per core vertex.
  const int fieldIndex = params.getEnum(param::kField);
  const int mappingIndex = params.getEnum(param::kMapping);
  if (fieldIndex < 0 || fieldIndex >= kFieldNames.size())
    return invalidInput("Field must be 0 to " + std::to_string(kFieldNames.size() - 1) + ", got " + std::to_string(fieldIndex));
  if (mappingIndex < 0 || mappingIndex >= kMappingNames.size())
    return invalidInput("Mapping must be 0 to " + std::to_string(kMappingNames.size() - 1) + ", got " +
                        std::to_string(mappingIndex));
  const Field field = static_cast<Field>(fieldIndex);
  std::vector<double> q;
  std::string fieldInfo;
  if (field == Field::VertexQuality) {
    if (!mm->hasDataMask(MeshModel::MM_VERTQUALITY))
      return invalidInput("the mesh has no vertex quality: compute one first (e.g. Compute Total Curvature, or any "
                          "filter of the Quality Measure and Computations menu), or choose another Field");
    q = adapters::vertexQuality(mm->cm, current->view);
    fieldInfo = "vertex quality";
  } else if (field == Field::TotalCurvature) {
    if (!mesh.topology.isManifold())
      return nonManifold("the mesh has non-manifold edges or vertices; repair them first (Cleaning and Repairing menu)");
    Expected<CurvatureResult> tau = curvatureOf(mesh, params, ctx.progress.sub(0.0, 0.1));
    if (!tau) return tau.status();
    q = tau->tau;
    fieldInfo = "total curvature (radius " + formatNumber(tau->radius, "%.4g") + ")";
  } else {
    if (!mm->hasDataMask(MeshModel::MM_VERTCOLOR))
      return invalidInput("the mesh has no vertex colour: the Color gradient field needs one");
    Expected<GradientResult> g = gradientMagnitude(mesh, adapters::vertexColorIntensity(mm->cm, current->view));
    if (!g) return g.status();
    q = g->magnitude;
    fieldInfo = "colour intensity gradient";
  }

  SpeedFieldParams speedParams;
  speedParams.mapping = static_cast<SpeedMapping>(mappingIndex);
  speedParams.strength = params.getFloat(param::kStrength);
  Expected<SpeedFieldResult> speed = speedFromField(mesh, q, speedParams);
  if (!speed) return speed.status();

  request.sampling = *sampling;
  request.metric = speed->metric;
  request.title = "Geodesic adaptive remeshing";
  request.layerSuffix = " - geodesic adaptive remesh";
  request.start = std::chrono::steady_clock::now();
  const std::string mapping = toString(speedParams.mapping);
  const std::string fieldLine = "Field: " + fieldInfo + " from " + formatNumber(speed->fieldMin, "%.4g") + " to " +
                                formatNumber(speed->fieldMax, "%.4g") + ", scale (95th percentile) " +
                                formatNumber(speed->scale, "%.4g") + "; mapping " + mapping + ", strength " +
                                formatNumber(speedParams.strength, "%.4g") + ": speed from " +
                                formatNumber(speed->speedMin, "%.4g") + " to " + formatNumber(speed->speedMax, "%.4g");
  FilterContext inner = ctx;
  inner.progress = ctx.progress.sub(0.1, 1.0);
  if (Status s = remeshToNewLayer(doc, *current, request, inner); !s) return s;
  ctx.log(fieldLine);
  if (speed->usedFallback()) ctx.warn("Speed field: " + speed->fallback);
  return Status::ok();
}

void declareTotalCurvature(const MeshModel& mesh, RichParameterList& params) { declareCurvatureRadius(mesh, params); }

Status applyTotalCurvature(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  const TriMesh& mesh = current->view.mesh;
  if (!mesh.topology.isManifold())
    return nonManifold("the mesh has " + std::to_string(mesh.topology.nonManifoldEdges) + " non-manifold edges and " +
                       std::to_string(mesh.topology.nonManifoldVertices) +
                       " non-manifold vertices; repair them first (Cleaning and Repairing menu)");
  Expected<CurvatureResult> tau = curvatureOf(mesh, params, ctx.progress);
  if (!tau) return tau.status();
  MeshModel* mm = current->model;
  mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  adapters::writeVertexQuality(mm->cm, current->view, tau->tau, 0.0);
  const double hi = percentile95(tau->tau);
  adapters::colorByRamp(mm->cm, current->view, tau->tau, 0.0, hi > 0.0 ? hi : 1.0);
  const auto [lo, top] = std::minmax_element(tau->tau.begin(), tau->tau.end());
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ctx.log("Total curvature |k1|+|k2| (Cohen-Steiner-Morvan, radius " + formatNumber(tau->radius, "%.4g") + ", " +
          formatNumber(tau->meanNeighbourhoodSize, "%.1f") + " vertices per ball on average) written to vertex quality: "
          "from " + formatNumber(*lo, "%.4g") + " to " + formatNumber(*top, "%.4g") + ", 95th percentile " +
          formatNumber(hi, "%.4g") + " (colour ramp from 0 to it)");
  ctx.log("Time: " + formatDuration(ms));
  return Status::ok();
}

}  // namespace gr::filters
