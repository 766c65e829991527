// Per-face geometry shared by several algorithms.
#pragma once

#include <Eigen/Geometry>

#include "core/mesh/tri_mesh.h"

namespace gr {

/// Cross product of the triangle's edges from corner 0, (p1 - p0) x (p2 - p0): its normal (by the
/// right-hand rule over the corner order) times twice its area. Zero on a degenerate triangle.
inline Vec3 areaNormal(const TriMesh& mesh, const Tri& t) {
  return (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
}
inline Vec3 areaNormal(const TriMesh& mesh, int face) { return areaNormal(mesh, mesh.triangles[face]); }

}  // namespace gr
