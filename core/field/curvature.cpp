#include "core/field/curvature.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <string>

#include "core/base/two_threads.h"
#include "core/mesh/sharp_cut.h"

namespace gr {
namespace {

/// What one vertex's cell carries: half of beta |e| ê êᵀ of each incident edge (symmetric, 6
/// entries xx xy xz yy yz zz) and a third of the area of each incident face. 64 bytes: one cache
/// line per vertex summed into a ball.
struct CellMass {
  double t[6] = {0, 0, 0, 0, 0, 0};
  double area = 0.0;
  double padding = 0.0;
};

/// What the flood fill reads of every vertex it looks at: the position and the width of the
/// weight's ramp, sqrt(cell area). 32 bytes.
struct CellPoint {
  double x = 0, y = 0, z = 0;
  double size = 0;
};

/// The mesh as the balls read it, in a local vertex order: the order in which the faces first
/// reach each vertex. Face order is usually spatially coherent (scans, and gr::subdivideMidpoint,
/// which numbers the 4 children of face f 4f..4f+3), vertex order often is not (subdivision
/// numbers new vertices level by level): renumbered, a ball's vertices are near each other in
/// memory, and every pass below reads the mesh sequentially.
struct LocalMesh {
  std::vector<int> original;     ///< local index -> mesh vertex
  std::vector<int> begin, list;  ///< neighbours (local indices), CSR; each neighbour once
  std::vector<CellPoint> point;  ///< local index -> position and ramp width
  std::vector<CellMass> mass;    ///< local index -> tensor and area of the cell
  std::vector<Vec3> normal;      ///< local index -> area-weighted normal (not normalised)
  double meanEdgeLength = 0.0;   ///< as TriMesh::meanEdgeLength(), same sums in the same order
};

/// Local triangles: a face's vertices as local indices.
using LocalTriangles = std::vector<std::array<int, 3>>;

/// Numbers the vertices in the order the faces first reach them, isolated vertices last: fills
/// local.original and local.point (ramp widths 0) and returns the faces in local indices.
LocalTriangles renumberByFaces(const TriMesh& mesh, LocalMesh& local) {
  const int n = mesh.vertexCount();
  const int nf = mesh.faceCount();
  std::vector<int> rank(n, -1);
  LocalTriangles localTri(nf);
  local.original.reserve(n);
  local.point.reserve(n);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int x = mesh.triangles[f][k];
      if (rank[x] < 0) {
        rank[x] = static_cast<int>(local.original.size());
        local.original.push_back(x);
        const Vec3& p = mesh.positions[x];
        local.point.push_back({p.x(), p.y(), p.z(), 0.0});
      }
      localTri[f][k] = rank[x];
    }
  for (int x = 0; x < n; ++x)  // isolated vertices last
    if (rank[x] < 0) {
      rank[x] = static_cast<int>(local.original.size());
      local.original.push_back(x);
      const Vec3& p = mesh.positions[x];
      local.point.push_back({p.x(), p.y(), p.z(), 0.0});
    }
  return localTri;
}

/// The vector from local vertex `from` to `to`.
Vec3 edgeVector(const std::vector<CellPoint>& point, int from, int to) {
  return Vec3(point[to].x - point[from].x, point[to].y - point[from].y, point[to].z - point[from].z);
}

/// Faces: a third of the area to each vertex's mass, the cross products to the normals, the mean
/// edge length. Returns the unit face normals (zero for a zero-area face).
std::vector<Vec3> addFaces(const LocalTriangles& localTri, LocalMesh& local) {
  const int nf = static_cast<int>(localTri.size());
  std::vector<Vec3> faceNormal(nf);
  double edgeSum = 0.0;
  for (int f = 0; f < nf; ++f) {
    const std::array<int, 3>& t = localTri[f];
    for (int k = 0; k < 3; ++k) edgeSum += edgeVector(local.point, t[(k + 1) % 3], t[k]).norm();
    const Vec3 cross = edgeVector(local.point, t[0], t[1]).cross(edgeVector(local.point, t[0], t[2]));
    const double norm = cross.norm();
    faceNormal[f] = norm > 0.0 ? Vec3(cross / norm) : Vec3::Zero();
    for (int k = 0; k < 3; ++k) {
      local.mass[t[k]].area += norm / 6.0;
      local.normal[t[k]] += cross;
    }
  }
  local.meanEdgeLength = edgeSum / (3.0 * nf);
  return faceNormal;
}

/// Is the edge (prev(c), V(c)) shared consistently, i.e. does another face have it after its corner?
bool reachedBefore(const TriMesh& mesh, int c) {
  const int o = mesh.oppositeCorner[TriMesh::next(c)];
  return o >= 0 && mesh.vertex(TriMesh::next(o)) == mesh.vertex(c);
}

/// Edges: half of beta |e| ê êᵀ to each end's mass. Returns per local vertex how many neighbour
/// entries it gets: the vertex after each corner in its face, and the one before when the edge to
/// it is not shared consistently with another face (there, no other face has it after the corner).
std::vector<int> addEdgesAndCountNeighbours(const TriMesh& mesh, const LocalTriangles& localTri,
                                            const std::vector<Vec3>& faceNormal, LocalMesh& local) {
  const int n = mesh.vertexCount();
  const int nf = mesh.faceCount();
  std::vector<int> degree(n, 0);
  for (int c = 0; c < 3 * nf; ++c) {
    degree[localTri[TriMesh::face(c)][c % 3]] += reachedBefore(mesh, c) ? 1 : 2;
    const int o = mesh.oppositeCorner[c];
    if (o < c) continue;  // boundary (-1), non-manifold (-2), or the pair seen from the other side
    const Vec3& n1 = faceNormal[TriMesh::face(c)];
    Vec3 n2 = faceNormal[TriMesh::face(o)];
    if (n1.squaredNorm() == 0.0 || n2.squaredNorm() == 0.0) continue;              // zero-area face: no angle
    if (mesh.vertex(TriMesh::next(o)) == mesh.vertex(TriMesh::next(c))) n2 = -n2;  // faces disagree on orientation
    const int la = localTri[TriMesh::face(c)][(c + 1) % 3], lb = localTri[TriMesh::face(c)][(c + 2) % 3];
    const Vec3 e = edgeVector(local.point, la, lb);
    const double length = e.norm();
    if (length == 0.0) continue;
    // Convex (normal turning towards the direction of travel from f into g): (n1 x n2) . e > 0.
    const double beta = std::atan2(n1.cross(n2).dot(e) / length, n1.dot(n2));
    const double s = beta / (2.0 * length);  // half of beta |e| ê êᵀ = beta / (2 |e|) e eᵀ
    const double m[6] = {s * e.x() * e.x(), s * e.x() * e.y(), s * e.x() * e.z(),
                         s * e.y() * e.y(), s * e.y() * e.z(), s * e.z() * e.z()};
    CellMass& ma = local.mass[la];
    CellMass& mb = local.mass[lb];
    for (int k = 0; k < 6; ++k) {
      ma.t[k] += m[k];
      mb.t[k] += m[k];
    }
  }
  return degree;
}

/// Drops the repeated entries of each vertex's neighbour list, keeping the first of each.
void removeRepeatedNeighbours(LocalMesh& local) {
  const int n = static_cast<int>(local.begin.size()) - 1;
  int at = 0;
  for (int v = 0; v < n; ++v) {
    const int first = at;
    for (int i = local.begin[v]; i < local.begin[v + 1]; ++i) {
      const int x = local.list[i];
      if (std::find(local.list.begin() + first, local.list.begin() + at, x) == local.list.begin() + at)
        local.list[at++] = x;
    }
    local.begin[v] = first;
  }
  local.begin[n] = at;
  local.list.resize(at);
}

/// The neighbour lists (local.begin, local.list) from the per-vertex entry counts, each
/// neighbour once.
void buildNeighbours(const TriMesh& mesh, const LocalTriangles& localTri, const std::vector<int>& degree,
                     LocalMesh& local) {
  const int n = mesh.vertexCount();
  const int nf = mesh.faceCount();
  local.begin.assign(n + 1, 0);
  for (int v = 0; v < n; ++v) local.begin[v + 1] = local.begin[v] + degree[v];
  local.list.resize(local.begin[n]);
  std::vector<int> fill(local.begin.begin(), local.begin.end() - 1);
  for (int c = 0; c < 3 * nf; ++c) {
    const std::array<int, 3>& t = localTri[TriMesh::face(c)];
    const int v = t[c % 3];
    local.list[fill[v]++] = t[(c + 1) % 3];
    if (!reachedBefore(mesh, c)) local.list[fill[v]++] = t[(c + 2) % 3];
  }
  // Boundaries, non-manifold edges and orientation flips can list a neighbour twice.
  if (mesh.topology.boundaryEdges > 0 || !mesh.topology.isManifold() || mesh.topology.inconsistentEdges > 0)
    removeRepeatedNeighbours(local);
}

LocalMesh buildLocalMesh(const TriMesh& mesh) {
  const int n = mesh.vertexCount();
  LocalMesh local;
  const LocalTriangles localTri = renumberByFaces(mesh, local);
  local.mass.assign(n, CellMass{});
  local.normal.assign(n, Vec3::Zero());
  const std::vector<Vec3> faceNormal = addFaces(localTri, local);
  const std::vector<int> degree = addEdgesAndCountNeighbours(mesh, localTri, faceNormal, local);
  for (int v = 0; v < n; ++v) local.point[v].size = std::sqrt(local.mass[v].area);
  buildNeighbours(mesh, localTri, degree, local);
  return local;
}

/// Index of the eigenvalue (of the sorted `lambda` of `tensor`) whose eigenvector is closest to
/// `normal`, without computing eigenvectors: with n the unit normal, the squared cosine of n with
/// the eigenvector e_i is (n . e_i)^2 = nᵀ (T - l_j)(T - l_k) n / ((l_i - l_j)(l_i - l_k)), and
/// nᵀ (T - l_j)(T - l_k) n = |T n|^2 - (l_j + l_k) nᵀ T n + l_j l_k. Two eigenvalues closer than
/// 1e-6 of the largest form one eigenspace (dropping either changes tau by less than the gap);
/// its share of n is 1 minus the third's. Without a normal: the eigenvalue of smallest magnitude.
int droppedEigenvalue(const Eigen::Matrix3d& tensor, const Eigen::Vector3d& lambda, const Vec3& normal) {
  const double scale = lambda.cwiseAbs().maxCoeff();
  const double nn = normal.norm();
  int dropped = 0;
  if (!(nn > 0.0) || !(scale > 0.0)) {
    lambda.cwiseAbs().minCoeff(&dropped);
    return dropped;
  }
  const Vec3 n = normal / nn;
  const Vec3 tn = tensor * n;
  const double b = n.dot(tn), c = tn.squaredNorm();
  auto share = [&](int i, int j, int k) {
    return (c - (lambda[j] + lambda[k]) * b + lambda[j] * lambda[k]) /
           ((lambda[i] - lambda[j]) * (lambda[i] - lambda[k]));
  };
  const double tolerance = 1e-6 * scale;
  const bool lowPair = lambda[1] - lambda[0] < tolerance, highPair = lambda[2] - lambda[1] < tolerance;
  if (lowPair && highPair) return 0;
  if (lowPair) return share(2, 0, 1) > 0.5 ? 2 : 0;
  if (highPair) return share(0, 1, 2) > 0.5 ? 0 : 2;
  const double w0 = share(0, 1, 2), w1 = share(1, 0, 2), w2 = share(2, 0, 1);
  return w0 >= w1 ? (w0 >= w2 ? 0 : 2) : (w1 >= w2 ? 1 : 2);
}

double squaredDistance(const CellPoint& a, const CellPoint& b) {
  const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return dx * dx + dy * dy + dz * dz;
}

/// Weight of a vertex at distance d in a ball of radius r: clamp(1/2 + (r - d) / size, 0, 1),
/// positive for d < r + size / 2 (d < r where size = 0).
double rampWeight(double r, double d, double size) {
  return size > 0.0 ? std::min(1.0, 0.5 + (r - d) / size) : (d < r ? 1.0 : 0.0);
}

/// The neighbourhood B(v) of the current vertex v: the local vertices in it (queue[0] = v) and
/// their weights; the buffers are reused from vertex to vertex.
struct Ball {
  std::vector<int> seenBy;  ///< seenBy[u] == v: u was looked at in v's ball
  std::vector<int> queue;
  std::vector<double> weight;  ///< parallel to queue
};

/// Starts v's ball with v and its 1-ring, the ring's `weight` being its distances to v (turned
/// into weights by weighOneRing). Returns the 1-ring's radius: the mean distance to the neighbours.
double startWithOneRing(const LocalMesh& local, int v, Ball& ball) {
  const std::vector<int>& begin = local.begin;
  const CellPoint pv = local.point[v];
  ball.queue.clear();
  ball.weight.clear();
  ball.seenBy[v] = v;
  ball.queue.push_back(v);
  ball.weight.push_back(1.0);
  double ringRadius = 0.0;
  for (int i = begin[v]; i < begin[v + 1]; ++i) {
    const int x = local.list[i];
    ball.seenBy[x] = v;
    const double d = std::sqrt(squaredDistance(local.point[x], pv));
    ringRadius += d;
    ball.queue.push_back(x);
    ball.weight.push_back(d);  // the distance, turned into the weight below
  }
  ringRadius /= begin[v + 1] - begin[v];
  return ringRadius;
}

/// Turns the 1-ring's distances into weights for the ball radius r, dropping the neighbours of
/// weight 0.
void weighOneRing(const LocalMesh& local, double r, Ball& ball) {
  std::vector<int>& queue = ball.queue;
  std::vector<double>& weight = ball.weight;
  size_t kept = 1;
  for (size_t i = 1; i < queue.size(); ++i) {
    const double w = rampWeight(r, weight[i], local.point[queue[i]].size);
    if (!(w > 0.0)) continue;
    queue[kept] = queue[i];
    weight[kept++] = w;
  }
  queue.resize(kept);
  weight.resize(kept);
}

/// Grows v's ball on from the 1-ring (a flood fill) through the vertices of positive weight.
void growBall(const LocalMesh& local, int v, double r, Ball& ball) {
  const std::vector<int>& begin = local.begin;
  const std::vector<int>& list = local.list;
  const std::vector<CellPoint>& point = local.point;
  const CellPoint pv = point[v];
  for (size_t head = 1; head < ball.queue.size(); ++head) {
    const int u = ball.queue[head];
    for (int i = begin[u]; i < begin[u + 1]; ++i) {
      const int x = list[i];
      if (ball.seenBy[x] == v) continue;
      ball.seenBy[x] = v;
      const CellPoint& px = point[x];
      const double reach = r + 0.5 * px.size;
      const double d2 = squaredDistance(px, pv);
      if (!(d2 < reach * reach)) continue;
      const double w = rampWeight(r, std::sqrt(d2), px.size);
      if (!(w > 0.0)) continue;
      ball.queue.push_back(x);
      ball.weight.push_back(w);
    }
  }
}

/// The principal curvatures k1 (larger magnitude), k2 of v from its ball's tensor; false when
/// the ball has no area (only zero-area faces around: no curvature).
bool principalCurvatures(const LocalMesh& local, int v, const Ball& ball,
                         Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& solver, double& k1, double& k2) {
  double t[6] = {0, 0, 0, 0, 0, 0};
  double area = 0.0;
  for (size_t i = 0; i < ball.queue.size(); ++i) {
    const CellMass& cm = local.mass[ball.queue[i]];
    const double w = ball.weight[i];
    for (int k = 0; k < 6; ++k) t[k] += w * cm.t[k];
    area += w * cm.area;
  }
  if (!(area > 0.0)) return false;
  Eigen::Matrix3d tensor;
  tensor << t[0], t[1], t[2], t[1], t[3], t[4], t[2], t[4], t[5];
  tensor /= area;
  solver.computeDirect(tensor, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d lambda = solver.eigenvalues();
  const int dropped = droppedEigenvalue(tensor, lambda, local.normal[v]);
  double a = lambda[(dropped + 1) % 3], b = lambda[(dropped + 2) % 3];
  if (std::abs(a) < std::abs(b)) std::swap(a, b);
  k1 = a;
  k2 = b;
  return true;
}

/// The checks of totalCurvature's input: a mesh with faces and adjacency, a usable radius.
Status checkCurvatureInput(const TriMesh& mesh, const CurvatureParams& params) {
  const int n = mesh.vertexCount();
  if (n == 0 || mesh.faceCount() == 0) return invalidInput("the mesh has no vertices or no faces");
  if (mesh.oppositeCorner.size() != 3 * mesh.triangles.size() ||
      mesh.vertexCornerBegin.size() != static_cast<size_t>(n) + 1)
    return invalidInput("the mesh has no adjacency (build it with buildTriMesh)");
  if (!std::isfinite(params.radius) || params.radius < 0.0)
    return invalidInput("the curvature radius must be finite and >= 0 (0 = the mean edge length), got " +
                        std::to_string(params.radius));
  return Status::ok();
}

/// totalCurvature of a mesh whose fans of faces around each vertex are one (no non-manifold vertex).
Expected<CurvatureResult> curvatureOfOneFanVertices(const TriMesh& mesh, const CurvatureParams& params,
                                                    Progress progress) {
  const int n = mesh.vertexCount();
  const LocalMesh local = buildLocalMesh(mesh);
  const double radius = params.radius > 0.0 ? params.radius : local.meanEdgeLength;

  CurvatureResult result;
  result.radius = radius;
  result.tau.assign(n, 0.0);
  result.k1.assign(n, 0.0);
  result.k2.assign(n, 0.0);

  // The vertices in two halves of the local order, the second on a helper thread: each ball
  // reads the mesh only and writes its own vertex (1.66M vertices, radius 3 edges: 3.7 s on one).
  struct Share {
    long totalSize = 0;
    int oneRingRadius = 0;
  };
  std::array<Share, 2> shares;
  std::atomic<bool> stop{false};
  onTwoThreads([&](bool helper) {
    Share& share = shares[helper];
    Ball ball;
    ball.seenBy.assign(n, -1);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
    const int first = helper ? n / 2 : 0, last = helper ? n : n / 2;
    for (int v = first; v < last && !stop; ++v) {
      if (!helper && (v & 4095) == 0 && !progress.report(double(v) / last, "Curvature")) stop = true;
      if (local.begin[v] == local.begin[v + 1]) continue;  // isolated vertex
      // The 1-ring: its distances give the ball's radius, the requested one or the 1-ring's
      // (mean distance to the neighbours).
      const double ringRadius = startWithOneRing(local, v, ball);
      const double r = std::max(radius, ringRadius);
      if (radius <= ringRadius) ++share.oneRingRadius;
      weighOneRing(local, r, ball);
      growBall(local, v, r, ball);
      share.totalSize += static_cast<long>(ball.queue.size());
      double a, b;
      if (!principalCurvatures(local, v, ball, solver, a, b)) continue;
      const int original = local.original[v];
      result.k1[original] = a;
      result.k2[original] = b;
      result.tau[original] = std::abs(a) + std::abs(b);
    }
  });
  if (stop) return cancelled();
  result.oneRingRadius = shares[0].oneRingRadius + shares[1].oneRingRadius;
  const long totalSize = shares[0].totalSize + shares[1].totalSize;
  result.meanNeighbourhoodSize = double(totalSize) / n;
  result.looseFaces = mesh.looseFaceCount();
  result.looksLikeTriangleSoup = TriMesh::looksLikeTriangleSoup(result.looseFaces, mesh.faceCount());
  progress.report(1.0, "Curvature");
  return result;
}

}  // namespace

Expected<CurvatureResult> totalCurvature(const TriMesh& mesh, const CurvatureParams& params, Progress progress) {
  if (Status s = checkCurvatureInput(mesh, params); !s) return s;
  if (mesh.topology.nonManifoldVertices == 0 || mesh.topology.nonManifoldEdges > 0)
    return curvatureOfOneFanVertices(mesh, params, std::move(progress));
  // Fans meeting at a vertex: each its own surface (one vertex copy per fan), so that no ball
  // reaches from one through the vertex into another; a vertex gets its largest copy's value.
  Expected<CutSurface> split = splitNonManifoldVertices(mesh);
  if (!split) return split.status();
  Expected<CurvatureResult> r = curvatureOfOneFanVertices(split->mesh, params, std::move(progress));
  if (!r) return r;
  const int n = mesh.vertexCount();
  for (int copy = n; copy < split->mesh.vertexCount(); ++copy) {
    const int v = split->origin[copy];
    if (!(r->tau[copy] > r->tau[v])) continue;
    r->tau[v] = r->tau[copy];
    r->k1[v] = r->k1[copy];
    r->k2[v] = r->k2[copy];
  }
  r->tau.resize(n);
  r->k1.resize(n);
  r->k2.resize(n);
  r->splitVertices = mesh.topology.nonManifoldVertices;
  return r;
}

}  // namespace gr
