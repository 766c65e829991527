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

/// n x 2, a vertex's u and v side by side: the right-hand side is scattered by vertex.
using UvMatrix = Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>;

struct System {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> solver;  // reads the lower triangle
  double proximal = 0.0;
};

/// The cotangent Laplacian (plus the proximal diagonal), lower triangle, assembled column by
/// column from the vertex -> corner lists: a quarter of the time of the same matrix from triplets.
Eigen::SparseMatrix<double> laplacian(const TriMesh& patch, const std::vector<FlatFace>& faces, double* trace) {
  const int n = patch.vertexCount();
  Eigen::SparseMatrix<double> l(n, n);
  std::vector<int> degree(n);
  for (int v = 0; v < n; ++v) degree[v] = 2 * patch.valence(v) + 1;  // neighbours (at most 2 per face) and v
  l.reserve(degree);
  std::vector<std::pair<int, double>> column;
  *trace = 0.0;
  for (int v = 0; v < n; ++v) {
    column.clear();
    double diagonal = 0.0;
    for (const int* c = patch.cornersBegin(v); c != patch.cornersEnd(v); ++c) {
      const int f = TriMesh::face(*c), k = *c % 3;
      // The edge to the next corner's vertex is opposite the previous corner, and conversely.
      const double wNext = faces[f].weight[(k + 2) % 3], wPrev = faces[f].weight[(k + 1) % 3];
      column.emplace_back(patch.vertex(TriMesh::next(*c)), wNext);
      column.emplace_back(patch.vertex(TriMesh::prev(*c)), wPrev);
      diagonal += wNext + wPrev;
    }
    *trace += diagonal;
    std::sort(column.begin(), column.end());
    l.insert(v, v) = diagonal;
    for (size_t i = 0; i < column.size();) {  // below the diagonal: rows > v, duplicates summed
      const int row = column[i].first;
      double w = 0.0;
      for (; i < column.size() && column[i].first == row; ++i) w += column[i].second;
      if (row > v) l.insert(row, v) = -w;
    }
  }
  return l;
}

Status factorise(const TriMesh& patch, const std::vector<FlatFace>& faces, System& system) {
  const int n = patch.vertexCount();
  double trace = 0.0;
  Eigen::SparseMatrix<double> l = laplacian(patch, faces, &trace);
  system.proximal = kProximal * std::max(trace / std::max(n, 1), 1e-300);
  for (int v = 0; v < n; ++v) l.coeffRef(v, v) += system.proximal;
  l.makeCompressed();
  system.solver.compute(l);
  if (system.solver.info() != Eigen::Success)
    return internalError("ARAP relaxation: the Laplacian could not be factorised");
  return {};
}

/// The global step: the map whose edges best match the rotated flat edges, into `target`
/// (`rhs` and `x` are the solve's buffers, reused across rounds).
void globalStep(const TriMesh& patch, const std::vector<FlatFace>& faces, const std::vector<Eigen::Matrix2d>& rotation,
                const std::vector<Vec2>& uv, System& system, UvMatrix& rhs, UvMatrix& x, std::vector<Vec2>& target) {
  const int n = patch.vertexCount();
  rhs.resize(n, 2);
  for (int v = 0; v < n; ++v) rhs.row(v) = system.proximal * uv[v].transpose();
  for (int f = 0; f < patch.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Vec2 t = faces[f].weight[k] * (rotation[f] * faces[f].edge[k]);
      rhs.row(patch.triangles[f][(k + 1) % 3]) += t.transpose();
      rhs.row(patch.triangles[f][(k + 2) % 3]) -= t.transpose();
    }
  x = system.solver.solve(rhs);
  target.resize(n);
  for (int v = 0; v < n; ++v) target[v] = x.row(v).transpose();
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
  std::vector<Vec2> next(current.size()), target;
  UvMatrix rhs, x;
  double energy = r.energyBefore;
  const double clearance = kBoundaryClearance * patch.meanEdgeLength();
  for (int round = 0; round < params.rounds; ++round) {
    globalStep(patch, faces, rotation, current, system, rhs, x, target);
    if (!injectiveStep(patch, current, target, clearance, next)) break;
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
