// Per-face geometry shared by several algorithms.
#pragma once

#include <Eigen/Geometry>

#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr {

/// Cross product of the triangle's edges from corner 0, (p1 - p0) x (p2 - p0): its normal (by the
/// right-hand rule over the corner order) times twice its area. Zero on a degenerate triangle.
inline Vec3 areaNormal(const TriMesh& mesh, const Tri& t) {
  return (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
}
inline Vec3 areaNormal(const TriMesh& mesh, int face) { return areaNormal(mesh, mesh.triangles[face]); }

/// Edge lengths read per corner: the length of the edge facing corner c, (V(next c), V(prev c)).
/// Measured between the positions, or read from per-corner lengths when a triangulation carries
/// its own (an intrinsic triangulation, whose edges are not the straight chords).
class CornerLengths {
 public:
  explicit CornerLengths(const TriMesh& mesh, const std::vector<double>* given = nullptr)
      : mesh_(mesh), given_(given) {}
  double operator()(int c) const {
    if (given_) return (*given_)[c];
    return (mesh_.positions[mesh_.vertex(TriMesh::next(c))] - mesh_.positions[mesh_.vertex(TriMesh::prev(c))]).norm();
  }
  bool intrinsic() const { return given_ != nullptr; }

 private:
  const TriMesh& mesh_;
  const std::vector<double>* given_;
};

}  // namespace gr
