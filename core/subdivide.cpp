#include "core/subdivide.h"

#include <string>
#include <unordered_map>

namespace gr {
namespace {

/// Barycentric coordinates, in original face `face`, of a vertex whose origin is `o`.
Vec3 baryIn(const TriMesh& original, int face, const SurfacePoint& o) {
  const Tri& t = original.triangles[face];
  Vec3 b = Vec3::Zero();
  if (o.vertex >= 0) {
    for (int k = 0; k < 3; ++k)
      if (t[k] == o.vertex) b[k] = 1.0;
    return b;
  }
  if (o.face == face) return o.bary;
  // A point on an edge shared with another face: move its coordinates by vertex.
  const Tri& g = original.triangles[o.face];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      if (t[k] == g[i]) b[k] += o.bary[i];
  return b;
}

}  // namespace

Expected<Subdivision> subdivideMidpoint(const TriMesh& mesh, int levels) {
  if (levels < 0) return invalidInput("the number of subdivision levels must be >= 0, got " + std::to_string(levels));
  Subdivision s;
  std::vector<Vec3> positions = mesh.positions;
  std::vector<Tri> triangles = mesh.triangles;
  std::vector<int> originalFace(triangles.size());
  for (size_t f = 0; f < triangles.size(); ++f) originalFace[f] = static_cast<int>(f);
  s.origin.resize(positions.size());
  for (int v = 0; v < mesh.vertexCount(); ++v) s.origin[v] = SurfacePoint::atVertex(v);

  for (int level = 0; level < levels; ++level) {
    std::unordered_map<long long, int> midpointOf;
    std::vector<Tri> next;
    std::vector<int> nextOriginal;
    next.reserve(4 * triangles.size());
    nextOriginal.reserve(4 * triangles.size());
    const long long n = static_cast<long long>(positions.size()) + 3 * static_cast<long long>(triangles.size());
    for (size_t f = 0; f < triangles.size(); ++f) {
      const Tri& t = triangles[f];
      const int of = originalFace[f];
      int m[3];
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        const long long key = std::min(a, b) * n + std::max(a, b);
        auto it = midpointOf.find(key);
        if (it == midpointOf.end()) {
          positions.push_back(0.5 * (positions[a] + positions[b]));
          s.origin.push_back(SurfacePoint::inFace(of, 0.5 * (baryIn(mesh, of, s.origin[a]) + baryIn(mesh, of, s.origin[b]))));
          it = midpointOf.emplace(key, static_cast<int>(positions.size()) - 1).first;
        }
        m[k] = it->second;
      }
      next.push_back({t[0], m[0], m[2]});
      next.push_back({t[1], m[1], m[0]});
      next.push_back({t[2], m[2], m[1]});
      next.push_back({m[0], m[1], m[2]});
      for (int k = 0; k < 4; ++k) nextOriginal.push_back(of);
    }
    triangles.swap(next);
    originalFace.swap(nextOriginal);
  }
  Expected<TriMesh> built = buildTriMesh(std::move(positions), std::move(triangles));
  if (!built) return built.status();
  s.mesh = std::move(built).value();
  return s;
}

}  // namespace gr
