// Per-face geometry shared by several algorithms.
#pragma once

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr {

/// Cross product of the triangle's edges from corner 0, (p1 - p0) x (p2 - p0): its normal (by the
/// right-hand rule over the corner order) times twice its area. Zero on a degenerate triangle.
inline Vec3 areaNormal(const TriMesh& mesh, const Tri& t) {
  return (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
}
inline Vec3 areaNormal(const TriMesh& mesh, int face) { return areaNormal(mesh, mesh.triangles[face]); }

/// Angle at p of the triangle (p, q, r), in radians (atan2: accurate near 0 and 180 degrees).
inline double angleAt(const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 u = q - p, w = r - p;
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

/// Smallest angle of the triangle (p, q, r), in radians (angleAt at each corner).
inline double smallestAngle(const Vec3& p, const Vec3& q, const Vec3& r) {
  return std::min({angleAt(p, q, r), angleAt(q, r, p), angleAt(r, p, q)});
}

/// Per face, its unit normal (zero for a face of no area).
inline std::vector<Vec3> unitFaceNormals(const TriMesh& mesh) {
  std::vector<Vec3> normal(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Vec3 n = areaNormal(mesh, f);
    normal[f] = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
  }
  return normal;
}

/// Barycentric coordinates (of a, b, c) of the point of triangle (a, b, c) nearest to p
/// (Ericson, Real-Time Collision Detection, §5.1.5: the vertex, edge or interior region of p).
inline Vec3 closestPointBarycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return {1.0, 0.0, 0.0};
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return {0.0, 1.0, 0.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return {0.0, 0.0, 1.0};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return {1.0, 0.0, 0.0};  // a degenerate triangle: its first vertex
  return {va / sum, vb / sum, vc / sum};
}

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

/// x rounded to the nearest float, as MeshLab holds texture coordinates. Through a volatile float:
/// GCC 12 folds double(float(x)) away where the result goes straight into an Eigen vector's
/// constructor (measured: no conversion left in the object code, so orientation checks judged
/// unrounded UVs and MeshLab's floats could turn a thin triangle over).
inline double roundedToFloat(double x) {
  volatile float rounded = static_cast<float>(x);
  return rounded;
}

/// Whether the 2D triangle abc is counter-clockwise for certain: the determinant's sign is the
/// exact one (Shewchuk's error bound for orient2d), so any exact judge agrees.
inline bool surelyCounterClockwise(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double left = (a.x() - c.x()) * (b.y() - c.y()), right = (a.y() - c.y()) * (b.x() - c.x());
  const double bound = 3.3306690738754716e-16 * (std::abs(left) + std::abs(right));
  return left - right > bound;
}

}  // namespace gr
