#include "core/mesh/sharp_cut.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/base/math.h"
#include "core/mesh/face_geometry.h"

namespace gr {
namespace {

int findRoot(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

std::vector<char> sharpEdgeCorners(const TriMesh& mesh, double degrees) {
  const std::vector<Vec3> normal = unitFaceNormals(mesh);
  const double cosine = std::cos(degrees * kPi / 180.0);
  std::vector<char> sharp(3 * mesh.faceCount(), 0);
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int o = mesh.oppositeCorner[c];
    if (o < 0 || normal[c / 3].isZero() || normal[o / 3].isZero()) continue;
    sharp[c] = normal[c / 3].dot(normal[o / 3]) < cosine;
  }
  return sharp;
}

Expected<CutSurface> cutAlongEdges(const TriMesh& mesh, const std::vector<char>& cutCorner) {
  const int corners = 3 * mesh.faceCount();
  // The corners at a vertex joined across each edge that stays: corner c's edge joins next(c)
  // with the corner of the other face at the same vertex (prev(o) if the faces agree on their
  // orientation, else next(o)), and prev(c) with the other.
  std::vector<int> parent(corners);
  std::iota(parent.begin(), parent.end(), 0);
  CutSurface out;
  for (int c = 0; c < corners; ++c) {
    const int o = mesh.oppositeCorner[c];
    if (o < c) continue;  // a boundary edge, or seen from o
    if (cutCorner[c] || cutCorner[o]) {
      ++out.sharpEdges;
      continue;
    }
    const bool agree = mesh.vertex(TriMesh::prev(o)) == mesh.vertex(TriMesh::next(c));
    const int atNext = agree ? TriMesh::prev(o) : TriMesh::next(o),
              atPrev = agree ? TriMesh::next(o) : TriMesh::prev(o);
    parent[findRoot(parent, TriMesh::next(c))] = findRoot(parent, atNext);
    parent[findRoot(parent, TriMesh::prev(c))] = findRoot(parent, atPrev);
  }
  // The first class met at vertex v keeps v; the others get new numbers.
  std::vector<int> copyOfClass(corners, -1);
  std::vector<char> taken(mesh.vertexCount(), 0);
  std::vector<Vec3> positions = mesh.positions;
  out.origin.resize(mesh.vertexCount());
  std::iota(out.origin.begin(), out.origin.end(), 0);
  std::vector<Tri> triangles = mesh.triangles;
  for (int c = 0; c < corners; ++c) {
    const int root = findRoot(parent, c), v = mesh.vertex(c);
    if (copyOfClass[root] < 0) {
      if (!taken[v]) {
        taken[v] = 1;
        copyOfClass[root] = v;
      } else {
        copyOfClass[root] = static_cast<int>(positions.size());
        positions.push_back(mesh.positions[v]);
        out.origin.push_back(v);
      }
    }
    triangles[c / 3][c % 3] = copyOfClass[root];
  }
  Expected<TriMesh> cut = buildTriMesh(std::move(positions), std::move(triangles));
  if (!cut) return cut.status();
  out.mesh = std::move(*cut);
  return out;
}

Expected<CutSurface> splitNonManifoldVertices(const TriMesh& mesh) {
  return cutAlongEdges(mesh, std::vector<char>(3 * mesh.faceCount(), 0));
}

}  // namespace gr
