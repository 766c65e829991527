#include "core/geodesic/metric.h"

#include <cmath>
#include <string>

namespace gr {
namespace {

Status checkField(const TriMesh& mesh, const std::vector<double>& field, const char* what) {
  if (static_cast<int>(field.size()) != mesh.vertexCount())
    return invalidInput(std::string(what) + " has " + std::to_string(field.size()) + " values for " +
                        std::to_string(mesh.vertexCount()) + " vertices");
  for (size_t v = 0; v < field.size(); ++v)
    if (!std::isfinite(field[v]) || field[v] <= 0.0)
      return invalidInput(std::string(what) + " must be finite and > 0, but vertex " + std::to_string(v) +
                          " has " + std::to_string(field[v]));
  return Status::ok();
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

}  // namespace gr
