#include "core/field/speed_field.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "core/base/format.h"
#include "core/base/statistics.h"

namespace gr {
namespace {

std::string num(double x) { return formatNumber(x, "%.6g"); }

}  // namespace

const char* toString(SpeedMapping mapping) {
  switch (mapping) {
    case SpeedMapping::Direct: return "Direct";
    case SpeedMapping::Attractive: return "Attractive";
    case SpeedMapping::Repulsive: return "Repulsive";
  }
  return "Unknown";
}

Expected<SpeedFieldResult> speedFromField(const TriMesh& mesh, const std::vector<double>& field,
                                          const SpeedFieldParams& params) {
  const bool direct = params.mapping == SpeedMapping::Direct;
  const std::string name = toString(params.mapping);
  if (!(params.percentile > 0.0 && params.percentile <= 100.0))
    return invalidInput("the scale percentile must be in (0, 100], not " + num(params.percentile));
  if (!std::isfinite(params.strength))
    return invalidInput("the " + name + " strength must be finite, not " + num(params.strength));
  if (direct && params.strength < 1.0)
    return invalidInput("the Direct strength is the speed ratio r and must be >= 1, not " + num(params.strength));
  if (!direct && params.strength < 0.0)
    return invalidInput("the " + name + " strength must be >= 0, not " + num(params.strength));
  const int nv = mesh.vertexCount();
  if (nv == 0) return invalidInput("the mesh has no vertices");
  if (static_cast<int>(field.size()) != nv)
    return invalidInput("the field has " + std::to_string(field.size()) + " values for " + std::to_string(nv) +
                        " vertices");
  for (int v = 0; v < nv; ++v)
    if (!std::isfinite(field[v]))
      return invalidInput("the field is not finite at vertex " + std::to_string(v) + " (q = " + num(field[v]) + ")");

  SpeedFieldResult r;
  const auto [lo, hi] = std::minmax_element(field.begin(), field.end());
  r.fieldMin = *lo;
  r.fieldMax = *hi;
  if (!direct && r.fieldMin < 0.0) {
    const int first = static_cast<int>(lo - field.begin());
    const auto negatives = std::count_if(field.begin(), field.end(), [](double q) { return q < 0.0; });
    return invalidInput("the " + name + " mapping needs a field >= 0, but vertex " + std::to_string(first) +
                        " has q = " + num(r.fieldMin) + " (" + std::to_string(negatives) +
                        " negative vertices); use Direct, or make the field non-negative");
  }
  if (r.fieldMin == r.fieldMax) {
    r.speed.assign(nv, 1.0);
    r.fallback = "the field is constant (q = " + num(r.fieldMin) + " at every vertex): uniform speed F = 1";
    return r;
  }

  // Scale: a percentile of q (Attractive, Repulsive) or of q - qmin (Direct); its maximum if zero.
  std::vector<double> values(field);
  if (direct)
    for (double& q : values) q -= r.fieldMin;
  r.scale = percentile(values, params.percentile);
  if (!(r.scale > 0.0)) {
    const double largest = *std::max_element(values.begin(), values.end());
    const auto atZero = std::count(values.begin(), values.end(), 0.0);
    r.fallback = "the " + num(params.percentile) + "th percentile of " + (direct ? "q - min q" : "q") + " is 0 (" +
                 std::to_string(atZero) + " of " + std::to_string(nv) + " vertices at " +
                 (direct ? "the minimum" : "0") + "): scale = the largest value, " + num(largest);
    r.scale = largest;
  }

  r.speed.resize(nv);
  const double k = params.strength;
  for (int v = 0; v < nv; ++v) {
    const double x = values[v] / r.scale;
    double F = 1.0;
    switch (params.mapping) {
      case SpeedMapping::Direct: F = 1.0 / k + (1.0 - 1.0 / k) * std::min(x, 1.0); break;
      case SpeedMapping::Attractive: F = 1.0 / (1.0 + k * x); break;
      case SpeedMapping::Repulsive: F = 1.0 + k * x; break;
    }
    if (!(std::isfinite(F) && F > 0.0 && std::isfinite(1.0 / F)))
      return invalidInput("the speed at vertex " + std::to_string(v) + " is not representable (q = " + num(field[v]) +
                          ", scale " + num(r.scale) + ", F = " + num(F) + "): the field's range is too wide");
    r.speed[v] = F;
  }
  const auto [fLo, fHi] = std::minmax_element(r.speed.begin(), r.speed.end());
  r.speedMin = *fLo;
  r.speedMax = *fHi;
  if (r.speedMin == r.speedMax) return r;  // strength 0 (or r = 1): uniform metric
  auto metric = Metric::fromSpeed(mesh, r.speed);
  if (!metric) return metric.status();
  r.metric = std::move(*metric);
  return r;
}

int limitSpeedGrowth(const TriMesh& mesh, double growth, SpeedFieldResult& speed) {
  std::vector<double>& F = speed.speed;
  const int nv = mesh.vertexCount();
  if (!(growth > 0.0) || speed.metric.isUniform() || static_cast<int>(F.size()) != nv) return 0;
  using Item = std::pair<double, int>;  // (F, vertex), smallest first
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  for (int v = 0; v < nv; ++v) heap.push({F[v], v});
  std::vector<char> done(nv, 0), lowered(nv, 0);
  while (!heap.empty()) {
    const auto [fv, v] = heap.top();
    heap.pop();
    if (done[v] || fv > F[v]) continue;
    done[v] = 1;
    for (const int* c = mesh.cornersBegin(v); c != mesh.cornersEnd(v); ++c)
      for (const int w : {mesh.vertex(TriMesh::next(*c)), mesh.vertex(TriMesh::prev(*c))}) {
        const double lower = fv + growth * (mesh.positions[w] - mesh.positions[v]).norm();
        if (lower < F[w]) {
          F[w] = lower;
          lowered[w] = 1;
          heap.push({lower, w});
        }
      }
  }
  speed.speedMax = *std::max_element(F.begin(), F.end());
  for (int v = 0; v < nv; ++v) speed.metric.P[v] = 1.0 / F[v];
  return static_cast<int>(std::count(lowered.begin(), lowered.end(), 1));
}

}  // namespace gr
