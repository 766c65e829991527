#include "core/geodesic/metric.h"

#include <cmath>
#include <string>

namespace gr {
namespace {

/// `count` values, each finite and > 0.
Status checkValues(const std::vector<double>& field, int count, const char* what) {
  if (static_cast<int>(field.size()) != count)
    return invalidInput(std::string(what) + " has " + std::to_string(field.size()) + " values for " +
                        std::to_string(count) + " vertices");
  for (size_t v = 0; v < field.size(); ++v)
    if (!std::isfinite(field[v]) || field[v] <= 0.0)
      return invalidInput(std::string(what) + " must be finite and > 0, but vertex " + std::to_string(v) + " has " +
                          std::to_string(field[v]));
  return Status::ok();
}

Status checkField(const TriMesh& mesh, const std::vector<double>& field, const char* what) {
  return checkValues(field, mesh.vertexCount(), what);
}

}  // namespace

Expected<Metric> Metric::fromSpeed(const TriMesh& mesh, const std::vector<double>& speed) {
  if (Status s = checkField(mesh, speed, "the speed"); !s) return s;
  Metric m;
  m.P.resize(speed.size());
  for (size_t v = 0; v < speed.size(); ++v) m.P[v] = 1.0 / speed[v];
  if (Status s = checkField(mesh, m.P, "the metric 1/speed"); !s) return s;  // catches denormal speeds
  return m;
}

Expected<Metric> Metric::fromCost(const TriMesh& mesh, std::vector<double> cost) {
  if (Status s = checkField(mesh, cost, "the metric"); !s) return s;
  Metric m;
  m.P = std::move(cost);
  return m;
}

Expected<Metric> transferMetric(const Metric& metric, const TriMesh& from, const std::vector<SurfacePoint>& at) {
  if (metric.isUniform()) return metric;
  if (static_cast<int>(metric.P.size()) != from.vertexCount())
    return invalidInput("the metric has " + std::to_string(metric.P.size()) + " values for " +
                        std::to_string(from.vertexCount()) + " vertices");
  std::vector<double> P(at.size());
  for (size_t i = 0; i < at.size(); ++i) {
    const SurfacePoint& p = at[i];
    if (p.vertex >= from.vertexCount() || p.face >= from.faceCount() || (p.vertex < 0 && p.face < 0))
      return invalidInput("point " + std::to_string(i) + " is not on the mesh");
    P[i] = interpolate(from, p, metric.P);
  }
  if (Status s = checkValues(P, static_cast<int>(at.size()), "the metric"); !s) return s;
  Metric m;
  m.P = std::move(P);
  return m;
}

}  // namespace gr
