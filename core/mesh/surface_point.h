// SurfacePoint: a point on a triangle mesh, at a vertex or inside a face (barycentric).
#pragma once

#include "core/mesh/tri_mesh.h"

namespace gr {

/// A point on the surface: a vertex, or a point of a face in barycentric coordinates.
struct SurfacePoint {
  int vertex = -1;           ///< >= 0: the point is this vertex
  int face = -1;             ///< >= 0 (with vertex == -1): a point of this face
  Vec3 bary = Vec3::Zero();  ///< barycentric coordinates in `face`, >= 0, summing to 1

  static SurfacePoint atVertex(int v) { return {v, -1, Vec3::Zero()}; }
  static SurfacePoint inFace(int f, const Vec3& b) { return {-1, f, b}; }
  Vec3 position(const TriMesh& mesh) const;
};

/// A per-vertex value at `p`: the vertex's value, or the barycentric blend of the face's three.
template <class T>
T interpolate(const TriMesh& mesh, const SurfacePoint& p, const std::vector<T>& perVertex) {
  if (p.vertex >= 0) return perVertex[p.vertex];
  const Tri& t = mesh.triangles[p.face];
  return p.bary[0] * perVertex[t[0]] + p.bary[1] * perVertex[t[1]] + p.bary[2] * perVertex[t[2]];
}

}  // namespace gr
