#include "core/param/base_coordinates.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/geodesic/fast_marching.h"
#include "core/param/geodesic_barycentric.h"

namespace gr {
namespace {

/// A base vertex's front runs to this many times its longest straight base edge. A point of a flat
/// triangle is within the longest edge of every corner; twice as far leaves room for geodesics
/// longer than the straight edges and for the neighbouring triangles a vertex is compared in.
constexpr double kReach = 2.0;

Status checkBase(const TriMesh& input, const std::vector<Tri>& base, const std::vector<int>& baseVertex) {
  if (base.empty() || baseVertex.empty()) return invalidInput("base coordinates: the base has no triangle");
  std::vector<char> taken(input.vertexCount(), 0);
  for (int v : baseVertex) {
    if (v < 0 || v >= input.vertexCount() || input.valence(v) == 0)
      return invalidInput("base coordinates: a base vertex (" + std::to_string(v) +
                          ") is not an input vertex in a face");
    if (taken[v]++)
      return invalidInput("base coordinates: input vertex " + std::to_string(v) + " is two base vertices");
  }
  for (const Tri& t : base)
    for (int i : t)
      if (i < 0 || i >= static_cast<int>(baseVertex.size()))
        return invalidInput("base coordinates: a base corner (" + std::to_string(i) + ") is no base vertex");
  return Status::ok();
}

/// Per base vertex, its front up to its reach: (input vertex, distance) pairs, and per base corner
/// the length of the opposite edge (from the fronts of its two ends, the smaller).
struct Fronts {
  std::vector<std::vector<std::pair<int, double>>> reached;  // per base vertex
  std::vector<double> edgeLength;                            // per base corner
};

Expected<Fronts> runFronts(const TriMesh& input, const std::vector<Tri>& base, const std::vector<int>& baseVertex) {
  const int nb = static_cast<int>(baseVertex.size());
  std::vector<double> straight(nb, 0.0);  // the longest straight base edge at each base vertex
  for (const Tri& t : base)
    for (int k = 0; k < 3; ++k) {
      const double l = (input.positions[baseVertex[t[k]]] - input.positions[baseVertex[t[(k + 1) % 3]]]).norm();
      straight[t[k]] = std::max(straight[t[k]], l);
      straight[t[(k + 1) % 3]] = std::max(straight[t[(k + 1) % 3]], l);
    }
  Fronts f;
  f.reached.resize(nb);
  FastMarcher marcher(input, Metric::uniform());
  f.edgeLength.assign(3 * base.size(), kUnreached);
  for (int i = 0; i < nb; ++i) {
    marcher.reset();
    if (Status s = marcher.addSource(baseVertex[i], 0); !s) return s;
    FastMarchingParams limit;
    limit.maxDistance = kReach * straight[i];
    if (Status s = marcher.propagate(limit); !s) return s;
    for (int v : marcher.acceptedOrder()) f.reached[i].emplace_back(v, marcher.distance()[v]);
  }
  // Edge lengths: base vertex j's value in base vertex i's front, the smaller of the two ways.
  std::vector<std::vector<std::pair<int, double>>> byBase(nb);  // per base vertex: (other base vertex, d)
  std::vector<int> baseOf(input.vertexCount(), -1);
  for (int i = 0; i < nb; ++i) baseOf[baseVertex[i]] = i;
  for (int i = 0; i < nb; ++i)
    for (const auto& [v, d] : f.reached[i])
      if (baseOf[v] >= 0) byBase[i].emplace_back(baseOf[v], d);
  for (size_t t = 0; t < base.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = base[t][(k + 1) % 3], b = base[t][(k + 2) % 3];
      for (const auto& [j, d] : byBase[a])
        if (j == b) f.edgeLength[3 * t + k] = std::min(f.edgeLength[3 * t + k], d);
      for (const auto& [j, d] : byBase[b])
        if (j == a) f.edgeLength[3 * t + k] = std::min(f.edgeLength[3 * t + k], d);
    }
  return f;
}

}  // namespace

Expected<BaseCoordinatesResult> baseCoordinates(const TriMesh& input, const std::vector<Tri>& base,
                                                const std::vector<int>& baseVertex) {
  if (Status s = checkBase(input, base, baseVertex); !s) return s;
  Expected<Fronts> fronts = runFronts(input, base, baseVertex);
  if (!fronts) return fronts.status();
  const int n = input.vertexCount(), nb = static_cast<int>(baseVertex.size());
  // Per input vertex, the base vertices whose fronts reached it (CSR) and their distances.
  std::vector<int> begin(n + 1, 0);
  for (const auto& front : fronts->reached)
    for (const auto& [v, d] : front) ++begin[v + 1];
  for (int v = 0; v < n; ++v) begin[v + 1] += begin[v];
  std::vector<std::pair<int, double>> seen(begin[n]);
  std::vector<int> fill(begin.begin(), begin.end() - 1);
  for (int i = 0; i < nb; ++i)
    for (const auto& [v, d] : fronts->reached[i]) seen[fill[v]++] = {i, d};
  // Per base vertex, its triangles.
  std::vector<std::vector<int>> trianglesAt(nb);
  for (size_t t = 0; t < base.size(); ++t)
    for (int i : base[t]) trianglesAt[i].push_back(static_cast<int>(t));
  BaseCoordinatesResult r;
  r.triangle.assign(n, -1);
  r.weights.assign(n, Vec3::Constant(1.0 / 3.0));
  r.excess.assign(n, kUnreached);
  r.edgeLength = fronts->edgeLength;
  std::vector<double> dist(nb, kUnreached);
  std::vector<int> triedFor(base.size(), -1);  // the input vertex a triangle was last evaluated for
  for (int v = 0; v < n; ++v) {
    for (int k = begin[v]; k < begin[v + 1]; ++k) dist[seen[k].first] = seen[k].second;
    for (int k = begin[v]; k < begin[v + 1]; ++k)
      for (int t : trianglesAt[seen[k].first]) {
        if (triedFor[t] == v) continue;  // reached through another of its corners
        triedFor[t] = v;
        const Tri& tri = base[t];
        const double* side = r.edgeLength.data() + 3 * t;  // opposite corners 0, 1, 2: bc, ca, ab
        const HeronCoordinates h =
            heronCoordinates(dist[tri[0]], dist[tri[1]], dist[tri[2]], side[2], side[0], side[1]);
        if (h.valid && h.excess < r.excess[v]) {
          r.excess[v] = h.excess;
          r.triangle[v] = t;
          r.weights[v] = h.weights;
        }
      }
    for (int k = begin[v]; k < begin[v + 1]; ++k) dist[seen[k].first] = kUnreached;
    r.unassigned += r.triangle[v] < 0 && input.valence(v) > 0;
  }
  return r;
}

}  // namespace gr
