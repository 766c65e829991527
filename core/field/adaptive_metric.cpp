#include "core/field/adaptive_metric.h"

#include <string>
#include <utility>

#include "core/field/color_gradient.h"

namespace gr {
namespace {

/// The field q per vertex; `radius` receives the curvature ball's radius.
Expected<std::vector<double>> fieldOf(const TriMesh& mesh, const std::vector<double>& values,
                                      const AdaptiveMetricParams& params, Progress progress, double& radius) {
  switch (params.field) {
    case AdaptiveField::VertexQuality: return values;
    case AdaptiveField::TotalCurvature: {
      if (!mesh.topology.isManifold())
        return nonManifold("the mesh has " + mesh.topology.nonManifoldCounts() +
                           "; repair them first (Cleaning and Repairing menu)");
      Expected<CurvatureResult> tau = totalCurvature(mesh, params.curvature, std::move(progress));
      if (!tau) return tau.status();
      radius = tau->radius;
      return std::move(tau->tau);
    }
    case AdaptiveField::ColorGradient: {
      Expected<GradientResult> g = gradientMagnitude(mesh, values);
      if (!g) return g.status();
      return std::move(g->magnitude);
    }
  }
  return values;  // not reached: adaptiveMetric checks the field first
}

}  // namespace

const char* toString(AdaptiveField field) {
  static const char* const kNames[kAdaptiveFieldCount] = {"vertex quality", "total curvature",
                                                          "colour intensity gradient"};
  const int i = static_cast<int>(field);
  return i >= 0 && i < kAdaptiveFieldCount ? kNames[i] : "unknown field";
}

Expected<AdaptiveMetricResult> adaptiveMetric(const TriMesh& mesh, const std::vector<double>& values,
                                              const AdaptiveMetricParams& params, Progress progress) {
  const int field = static_cast<int>(params.field), mapping = static_cast<int>(params.speed.mapping);
  if (field < 0 || field >= kAdaptiveFieldCount)
    return invalidInput("Field must be 0 to " + std::to_string(kAdaptiveFieldCount - 1) + ", got " +
                        std::to_string(field));
  if (mapping < 0 || mapping >= kSpeedMappingCount)
    return invalidInput("Mapping must be 0 to " + std::to_string(kSpeedMappingCount - 1) + ", got " +
                        std::to_string(mapping));
  AdaptiveMetricResult r;
  Expected<std::vector<double>> q = fieldOf(mesh, values, params, std::move(progress), r.curvatureRadius);
  if (!q) return q.status();
  Expected<SpeedFieldResult> speed = speedFromField(mesh, *q, params.speed);
  if (!speed) return speed.status();
  r.speed = std::move(*speed);
  return r;
}

}  // namespace gr
