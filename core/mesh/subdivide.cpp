#include "core/mesh/subdivide.h"

#include <string>

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
  if (mesh.topology.nonManifoldEdges > 0)
    return nonManifold("midpoint subdivision needs a mesh without non-manifold edges (" +
                       std::to_string(mesh.topology.nonManifoldEdges) + " found)");
  Subdivision s;
  s.mesh = mesh;
  s.origin.resize(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) s.origin[v] = SurfacePoint::atVertex(v);
  std::vector<int> originalFace(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f) originalFace[f] = f;

  for (int level = 0; level < levels; ++level) {
    const TriMesh& m = s.mesh;
    const int nc = 3 * m.faceCount();
    std::vector<Vec3> positions = m.positions;
    std::vector<int> mid(nc, -1);  // per corner: the new vertex on its opposite edge
    for (int c = 0; c < nc; ++c) {
      if (mid[c] >= 0) continue;
      const int a = m.vertex(TriMesh::next(c)), b = m.vertex(TriMesh::prev(c));
      const int of = originalFace[TriMesh::face(c)];
      mid[c] = static_cast<int>(positions.size());
      positions.push_back(0.5 * (m.positions[a] + m.positions[b]));
      s.origin.push_back(
          SurfacePoint::inFace(of, 0.5 * (baryIn(mesh, of, s.origin[a]) + baryIn(mesh, of, s.origin[b]))));
      if (m.oppositeCorner[c] >= 0) mid[m.oppositeCorner[c]] = mid[c];
    }
    std::vector<Tri> triangles;
    std::vector<int> nextOriginal;
    triangles.reserve(4 * static_cast<size_t>(m.faceCount()));
    nextOriginal.reserve(4 * static_cast<size_t>(m.faceCount()));
    for (int f = 0; f < m.faceCount(); ++f) {
      const Tri& t = m.triangles[f];
      const int bc = mid[3 * f], ca = mid[3 * f + 1], ab = mid[3 * f + 2];
      triangles.push_back({t[0], ab, ca});
      triangles.push_back({ab, t[1], bc});
      triangles.push_back({ca, bc, t[2]});
      triangles.push_back({ab, bc, ca});
      for (int k = 0; k < 4; ++k) nextOriginal.push_back(originalFace[f]);
    }
    Expected<TriMesh> built = buildTriMesh(std::move(positions), std::move(triangles));
    if (!built) return built.status();
    s.mesh = std::move(built).value();
    originalFace.swap(nextOriginal);
  }
  s.originalFace = std::move(originalFace);
  return s;
}

SurfacePoint Subdivision::originOf(const TriMesh& original, const SurfacePoint& p) const {
  if (p.vertex >= 0) return origin[p.vertex];
  const int of = originalFace[p.face];
  const Tri& t = mesh.triangles[p.face];
  Vec3 b = Vec3::Zero();
  for (int k = 0; k < 3; ++k) b += p.bary[k] * baryIn(original, of, origin[t[k]]);
  return SurfacePoint::inFace(of, b);
}

}  // namespace gr
