#include "core/curvature.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace gr {
namespace {

/// What one vertex's cell carries: half of beta |e| ê êᵀ of each incident edge (symmetric, 6
/// entries xx xy xz yy yz zz), a third of the area of each incident face, and the cell's size.
/// 64 bytes: one cache line per vertex read in the neighbourhood loop.
struct CellMass {
  double t[6] = {0, 0, 0, 0, 0, 0};
  double area = 0.0;
  double size = 0.0;  ///< sqrt(area): the width of the weight's ramp at the ball's sphere
};

/// Vertex -> neighbour vertices, CSR, each neighbour once (both ends of every face edge, so
/// boundary and non-manifold fans are complete).
struct Neighbours {
  std::vector<int> begin;
  std::vector<int> list;
};

Neighbours buildNeighbours(const TriMesh& mesh) {
  const int n = mesh.vertexCount();
  Neighbours nb;
  nb.begin.assign(n + 1, 0);
  nb.list.reserve(mesh.vertexCorners.size() + mesh.vertexCorners.size() / 8);
  std::vector<int> scratch;
  for (int v = 0; v < n; ++v) {
    nb.begin[v] = static_cast<int>(nb.list.size());
    scratch.clear();
    for (const int* c = mesh.cornersBegin(v); c != mesh.cornersEnd(v); ++c) {
      scratch.push_back(mesh.vertex(TriMesh::next(*c)));
      scratch.push_back(mesh.vertex(TriMesh::prev(*c)));
    }
    std::sort(scratch.begin(), scratch.end());
    scratch.erase(std::unique(scratch.begin(), scratch.end()), scratch.end());
    nb.list.insert(nb.list.end(), scratch.begin(), scratch.end());
  }
  nb.begin[n] = static_cast<int>(nb.list.size());
  return nb;
}

/// Per-vertex masses and area-weighted normals (not normalised).
void buildMasses(const TriMesh& mesh, std::vector<CellMass>& mass, std::vector<Vec3>& normal) {
  const int nf = mesh.faceCount();
  mass.assign(mesh.vertexCount(), CellMass{});
  normal.assign(mesh.vertexCount(), Vec3::Zero());
  std::vector<Vec3> faceNormal(nf);
  for (int f = 0; f < nf; ++f) {
    const Tri& t = mesh.triangles[f];
    const Vec3 cross = (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]);
    const double norm = cross.norm();
    faceNormal[f] = norm > 0.0 ? Vec3(cross / norm) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      mass[t[k]].area += norm / 6.0;
      normal[t[k]] += cross;
    }
  }
  for (int c = 0; c < 3 * nf; ++c) {
    const int o = mesh.oppositeCorner[c];
    if (o < c) continue;  // boundary (-1), non-manifold (-2), or the pair seen from the other side
    const Vec3& n1 = faceNormal[TriMesh::face(c)];
    Vec3 n2 = faceNormal[TriMesh::face(o)];
    if (n1.squaredNorm() == 0.0 || n2.squaredNorm() == 0.0) continue;  // zero-area face: no angle
    const int a = mesh.vertex(TriMesh::next(c)), b = mesh.vertex(TriMesh::prev(c));
    if (mesh.vertex(TriMesh::next(o)) == a) n2 = -n2;  // the faces disagree on orientation
    const Vec3 e = mesh.positions[b] - mesh.positions[a];
    const double length = e.norm();
    if (length == 0.0) continue;
    // Convex (normal turning towards the direction of travel from f into g): (n1 x n2) . e > 0.
    const double beta = std::atan2(n1.cross(n2).dot(e) / length, n1.dot(n2));
    const double s = beta / (2.0 * length);  // half of beta |e| ê êᵀ = beta / (2 |e|) e eᵀ
    const double m[6] = {s * e.x() * e.x(), s * e.x() * e.y(), s * e.x() * e.z(),
                         s * e.y() * e.y(), s * e.y() * e.z(), s * e.z() * e.z()};
    for (int k = 0; k < 6; ++k) {
      mass[a].t[k] += m[k];
      mass[b].t[k] += m[k];
    }
  }
  for (CellMass& cm : mass) cm.size = std::sqrt(cm.area);
}

}  // namespace

Expected<CurvatureResult> totalCurvature(const TriMesh& mesh, const CurvatureParams& params, Progress progress) {
  const int n = mesh.vertexCount();
  if (n == 0 || mesh.faceCount() == 0) return invalidInput("the mesh has no vertices or no faces");
  if (mesh.oppositeCorner.size() != 3 * mesh.triangles.size() ||
      mesh.vertexCornerBegin.size() != static_cast<size_t>(n) + 1)
    return invalidInput("the mesh has no adjacency (build it with buildTriMesh)");
  if (!std::isfinite(params.radius) || params.radius < 0.0)
    return invalidInput("the curvature radius must be finite and >= 0 (0 = the mean edge length), got " +
                        std::to_string(params.radius));
  const double radius = params.radius > 0.0 ? params.radius : mesh.meanEdgeLength();

  std::vector<CellMass> mass;
  std::vector<Vec3> normal;
  buildMasses(mesh, mass, normal);
  const Neighbours nb = buildNeighbours(mesh);

  CurvatureResult result;
  result.radius = radius;
  result.tau.assign(n, 0.0);
  result.k1.assign(n, 0.0);
  result.k2.assign(n, 0.0);

  std::vector<int> seenBy(n, -1);  // seenBy[u] == v: u was looked at in v's neighbourhood
  std::vector<int> queue;
  std::vector<double> weight;      // parallel to queue
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  long totalSize = 0;
  for (int v = 0; v < n; ++v) {
    if ((v & 4095) == 0 && !progress.report(double(v) / n, "curvature")) return cancelled();
    if (nb.begin[v] == nb.begin[v + 1]) continue;  // isolated vertex
    const Vec3 pv = mesh.positions[v];
    // The ball's radius: the requested one, or the 1-ring's (mean distance to the neighbours).
    double ringRadius = 0.0;
    for (int i = nb.begin[v]; i < nb.begin[v + 1]; ++i) ringRadius += (mesh.positions[nb.list[i]] - pv).norm();
    ringRadius /= nb.begin[v + 1] - nb.begin[v];
    const double r = std::max(radius, ringRadius);
    if (radius <= ringRadius) ++result.oneRingRadius;
    // Flood fill from v through the vertices of positive weight.
    queue.clear();
    weight.clear();
    seenBy[v] = v;
    queue.push_back(v);
    weight.push_back(1.0);
    for (size_t head = 0; head < queue.size(); ++head) {
      const int u = queue[head];
      for (int i = nb.begin[u]; i < nb.begin[u + 1]; ++i) {
        const int x = nb.list[i];
        if (seenBy[x] == v) continue;
        seenBy[x] = v;
        const double d = (mesh.positions[x] - pv).norm();
        const double s = mass[x].size;
        const double w = s > 0.0 ? std::clamp(0.5 + (r - d) / s, 0.0, 1.0) : (d < r ? 1.0 : 0.0);
        if (w <= 0.0) continue;
        queue.push_back(x);
        weight.push_back(w);
      }
    }
    totalSize += static_cast<long>(queue.size());

    double t[6] = {0, 0, 0, 0, 0, 0};
    double area = 0.0;
    for (size_t i = 0; i < queue.size(); ++i) {
      const CellMass& cm = mass[queue[i]];
      const double w = weight[i];
      for (int k = 0; k < 6; ++k) t[k] += w * cm.t[k];
      area += w * cm.area;
    }
    if (!(area > 0.0)) continue;  // only zero-area faces around: no curvature
    Eigen::Matrix3d tensor;
    tensor << t[0], t[1], t[2], t[1], t[3], t[4], t[2], t[4], t[5];
    tensor /= area;
    solver.computeDirect(tensor);
    const Eigen::Vector3d lambda = solver.eigenvalues();
    // Drop the eigenvector closest to the normal; without a normal, the smallest eigenvalue.
    int dropped = 0;
    const double nn = normal[v].norm();
    if (nn > 0.0) {
      const Eigen::Vector3d dots = (solver.eigenvectors().transpose() * (normal[v] / nn)).cwiseAbs();
      dots.maxCoeff(&dropped);
    } else {
      lambda.cwiseAbs().minCoeff(&dropped);
    }
    double a = lambda[(dropped + 1) % 3], b = lambda[(dropped + 2) % 3];
    if (std::abs(a) < std::abs(b)) std::swap(a, b);
    result.k1[v] = a;
    result.k2[v] = b;
    result.tau[v] = std::abs(a) + std::abs(b);
  }
  result.meanNeighbourhoodSize = double(totalSize) / n;
  progress.report(1.0, "curvature");
  return result;
}

}  // namespace gr
