#include "core/flatten/arap_relaxation.h"

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "core/flatten/uv_map_quality.h"

namespace gr {
namespace {

/// A face of at most this share of the mean 3D face area carries no weight (its angles are noise).
constexpr double kNegligibleArea = 1e-8;
/// Proximal weight, relative to the mean diagonal of the Laplacian: keeps the system definite
/// (translation, vertices of weightless faces) without moving the solution measurably.
constexpr double kProximal = 1e-8;
/// The line search stops this far short of the first face turning over.
constexpr double kStepMargin = 0.8;
/// Halvings of the step before a round that cannot stay one-to-one ends the relaxation.
constexpr int kHalvings = 6;
/// Boundary edges must keep this share of the mean edge length apart: a boundary that nearly
/// touches itself crosses once the atlas rounds its UVs to float.
constexpr double kBoundaryClearance = 1e-3;

/// A face in its own plane: the half cotangent weight of each edge (the edge opposite corner k)
/// and the edge vectors x_i - x_j in an isometric 2D frame.
struct FlatFace {
  std::array<double, 3> weight{};                                         // of the edge (k+1, k+2)
  std::array<Vec2, 3> edge = {Vec2::Zero(), Vec2::Zero(), Vec2::Zero()};  // x_{k+1} - x_{k+2}
};

double faceArea(const TriMesh& patch, int f) {
  const Tri& t = patch.triangles[f];
  return 0.5 *
         (patch.positions[t[1]] - patch.positions[t[0]]).cross(patch.positions[t[2]] - patch.positions[t[0]]).norm();
}

std::vector<FlatFace> flatFaces(const TriMesh& patch) {
  std::vector<FlatFace> faces(patch.faceCount());
  double meanArea = 0.0;
  for (int f = 0; f < patch.faceCount(); ++f) meanArea += faceArea(patch, f);
  meanArea /= std::max(1, patch.faceCount());
  for (int f = 0; f < patch.faceCount(); ++f) {
    const Tri& t = patch.triangles[f];
    const Vec3 e1 = patch.positions[t[1]] - patch.positions[t[0]], e2 = patch.positions[t[2]] - patch.positions[t[0]];
    const double l1 = e1.norm(), twiceArea = e1.cross(e2).norm();
    if (!(0.5 * twiceArea > kNegligibleArea * meanArea) || !(l1 > 0.0)) continue;  // weightless
    const std::array<Vec2, 3> x = {Vec2::Zero(), Vec2(l1, 0.0), Vec2(e2.dot(e1) / l1, twiceArea / l1)};
    FlatFace& ff = faces[f];
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = x[(k + 1) % 3] - x[k], b = x[(k + 2) % 3] - x[k];
      ff.weight[k] = 0.5 * a.dot(b) / twiceArea;  // cot of the angle at k, halved
      ff.edge[k] = x[(k + 1) % 3] - x[(k + 2) % 3];
    }
  }
  return faces;
}

double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

/// Per face, the rotation nearest to the map's Jacobian, and the ARAP energy at `uv` with them.
double localStep(const TriMesh& patch, const std::vector<FlatFace>& faces, const std::vector<Vec2>& uv,
                 std::vector<Eigen::Matrix2d>& rotation) {
  double energy = 0.0;
  for (int f = 0; f < patch.faceCount(); ++f) {
    const Tri& t = patch.triangles[f];
    Eigen::Matrix2d s = Eigen::Matrix2d::Zero();
    for (int k = 0; k < 3; ++k)
      s += faces[f].weight[k] * (uv[t[(k + 1) % 3]] - uv[t[(k + 2) % 3]]) * faces[f].edge[k].transpose();
    // The rotation maximising tr(R^T S): (cos, sin) along (s00 + s11, s10 - s01).
    const Vec2 cs(s(0, 0) + s(1, 1), s(1, 0) - s(0, 1));
    const double norm = cs.norm();
    const Vec2 unit = norm > 0.0 ? Vec2(cs / norm) : Vec2(1.0, 0.0);
    rotation[f] << unit.x(), -unit.y(), unit.y(), unit.x();
    for (int k = 0; k < 3; ++k)
      energy +=
          faces[f].weight[k] * (uv[t[(k + 1) % 3]] - uv[t[(k + 2) % 3]] - rotation[f] * faces[f].edge[k]).squaredNorm();
  }
  return energy;
}

/// The largest t in (0, 1] at which no face of `from + t (to - from)` has turned over (all faces
/// positive at t = 0), times kStepMargin where a face would turn.
double maxStep(const TriMesh& patch, const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  double t = 1.0;
  for (const Tri& tri : patch.triangles) {
    const Vec2 a0 = from[tri[1]] - from[tri[0]], b0 = from[tri[2]] - from[tri[0]];
    const Vec2 da = to[tri[1]] - to[tri[0]] - a0, db = to[tri[2]] - to[tri[0]] - b0;
    // 2 * area(s) = c + b s + a s^2
    const double c = cross2(a0, b0), b = cross2(a0, db) + cross2(da, b0), a = cross2(da, db);
    double root = std::numeric_limits<double>::infinity();
    if (std::abs(a) < 1e-300) {
      if (b < 0.0) root = -c / b;
    } else {
      const double disc = b * b - 4.0 * a * c;
      if (disc >= 0.0) {
        const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        for (double r : {q / a, q != 0.0 ? c / q : -1.0})
          if (r > 0.0) root = std::min(root, r);
      }
    }
    if (root <= 1.0) t = std::min(t, kStepMargin * root);
  }
  return t;
}

/// Scales uv about its centroid so that its area is the patch's.
void scaleToPatch(const TriMesh& patch, std::vector<Vec2>& uv) {
  double area3 = 0.0, area2 = 0.0;
  for (int f = 0; f < patch.faceCount(); ++f) {
    const Tri& t = patch.triangles[f];
    area3 += faceArea(patch, f);
    area2 += 0.5 * cross2(uv[t[1]] - uv[t[0]], uv[t[2]] - uv[t[0]]);
  }
  if (!(area2 > 0.0) || !(area3 > 0.0)) return;
  const double s = std::sqrt(area3 / area2);
  for (Vec2& q : uv) q *= s;
}

struct System {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  double proximal = 0.0;
};

Status factorise(const TriMesh& patch, const std::vector<FlatFace>& faces, System& system) {
  const int n = patch.vertexCount();
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(12 * faces.size() + n);
  double trace = 0.0;
  for (int f = 0; f < patch.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int i = patch.triangles[f][(k + 1) % 3], j = patch.triangles[f][(k + 2) % 3];
      const double w = faces[f].weight[k];
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
      entries.emplace_back(i, j, -w);
      entries.emplace_back(j, i, -w);
      trace += 2.0 * w;
    }
  system.proximal = kProximal * std::max(trace / std::max(n, 1), 1e-300);
  for (int v = 0; v < n; ++v) entries.emplace_back(v, v, system.proximal);
  Eigen::SparseMatrix<double> l(n, n);
  l.setFromTriplets(entries.begin(), entries.end());
  system.solver.compute(l);
  if (system.solver.info() != Eigen::Success)
    return internalError("ARAP relaxation: the Laplacian could not be factorised");
  return {};
}

/// The global step: the map whose edges best match the rotated flat edges.
std::vector<Vec2> globalStep(const TriMesh& patch, const std::vector<FlatFace>& faces,
                             const std::vector<Eigen::Matrix2d>& rotation, const std::vector<Vec2>& uv,
                             System& system) {
  const int n = patch.vertexCount();
  Eigen::MatrixXd rhs(n, 2);
  for (int v = 0; v < n; ++v) rhs.row(v) = system.proximal * uv[v].transpose();
  for (int f = 0; f < patch.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec2 target = faces[f].weight[k] * (rotation[f] * faces[f].edge[k]);
      rhs.row(patch.triangles[f][(k + 1) % 3]) += target.transpose();
      rhs.row(patch.triangles[f][(k + 2) % 3]) -= target.transpose();
    }
  const Eigen::MatrixXd x = system.solver.solve(rhs);
  std::vector<Vec2> out(n);
  for (int v = 0; v < n; ++v) out[v] = x.row(v).transpose();
  return out;
}

/// A step from `uv` towards `target` that keeps the map one-to-one; false if none was found.
bool injectiveStep(const TriMesh& patch, const std::vector<Vec2>& uv, const std::vector<Vec2>& target, double clearance,
                   std::vector<Vec2>& out) {
  double t = maxStep(patch, uv, target);
  for (int h = 0; h <= kHalvings && t > 0.0; ++h, t *= 0.5) {
    for (size_t v = 0; v < uv.size(); ++v) out[v] = uv[v] + t * (target[v] - uv[v]);
    if (checkUvAlongPositivePath(patch, out, clearance).injective()) return true;  // every face positive on the way
  }
  return false;
}

}  // namespace

Expected<ArapResult> relaxAsRigidAsPossible(const TriMesh& patch, std::vector<Vec2>& uv, const ArapParams& params,
                                            bool checked) {
  if (uv.size() != static_cast<size_t>(patch.vertexCount()))
    return invalidInput("ARAP relaxation: " + std::to_string(uv.size()) + " UVs for " +
                        std::to_string(patch.vertexCount()) + " vertices");
  if (params.rounds < 0 || !(params.tolerance >= 0.0) || !(params.negligible >= 0.0))
    return invalidInput("ARAP relaxation: rounds < 0, tolerance < 0 or negligible < 0");
  if (!checked && !checkUvInjectivity(patch, uv).injective())
    return invalidInput("ARAP relaxation: the map given is not one-to-one");
  ArapResult r;
  std::vector<Vec2> current = uv;
  scaleToPatch(patch, current);
  const std::vector<FlatFace> faces = flatFaces(patch);
  std::vector<Eigen::Matrix2d> rotation(patch.faceCount());
  r.energyBefore = r.energyAfter = localStep(patch, faces, current, rotation);
  uv = current;
  double area = 0.0;
  for (int f = 0; f < patch.faceCount(); ++f) area += faceArea(patch, f);
  const double negligible = params.negligible * area;
  if (params.rounds == 0 || r.energyBefore <= negligible) return r;
  System system;
  if (Status s = factorise(patch, faces, system); !s) return s;
  std::vector<Vec2> next(current.size());
  double energy = r.energyBefore;
  const double clearance = kBoundaryClearance * patch.meanEdgeLength();
  for (int round = 0; round < params.rounds; ++round) {
    if (!injectiveStep(patch, current, globalStep(patch, faces, rotation, current, system), clearance, next)) break;
    std::swap(current, next);
    ++r.rounds;
    const double previous = energy;
    energy = localStep(patch, faces, current, rotation);
    if (energy < r.energyAfter) {
      r.energyAfter = energy;
      uv = current;
    }
    if (!(previous - energy > params.tolerance * previous) || energy <= negligible) break;
  }
  return r;
}

}  // namespace gr
