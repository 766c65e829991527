#include "core/flatten/geodesic_lle.h"
#include "core/flatten/arap_relaxation.h"
#include "core/flatten/uv_map_quality.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <string>
#include <utility>

#include "core/base/math.h"
#include "core/geodesic/farthest_point_sampling.h"
#include "core/geodesic/fast_marching.h"

namespace gr {
namespace {

/// A face whose UV area is at most this share of the mean |area| counts as degenerate.
constexpr double kDegenerateArea = 1e-10;
/// Rounds of local untangling before the whole patch is mapped by Tutte's embedding instead.
constexpr int kUntangleRounds = 60;
/// Folds on more than this share of the faces mean the LLE map is wrong at large, not locally:
/// Tutte's embedding then, without untangling.
constexpr double kMaxUntangledShare = 0.2;
/// Every this many rounds the untangled set grows by a ring of vertices.
constexpr int kRoundsPerRing = 5;

Status checkPatch(const TriMesh& patch, const LleFlatteningParams& p) {
  const Topology& t = patch.topology;
  if (patch.faceCount() == 0) return invalidInput("LLE flattening: the patch has no faces");
  if (!t.isManifold())
    return nonManifold("LLE flattening needs a manifold patch; this one has " + std::to_string(t.nonManifoldEdges) +
                       " non-manifold edges and " + std::to_string(t.nonManifoldVertices) + " non-manifold vertices");
  if (t.components != 1 || t.boundaryLoops != 1 || t.eulerCharacteristic != 1)
    return invalidInput(
        "LLE flattening needs a topological disk (1 component, 1 boundary loop, Euler characteristic "
        "1); this patch has " +
        std::to_string(t.components) + " components, " + std::to_string(t.boundaryLoops) +
        " boundary loops, Euler characteristic " + std::to_string(t.eulerCharacteristic) + " (genus " +
        std::to_string(t.genus) + ")");
  if (t.inconsistentEdges > 0)
    return invalidInput("LLE flattening: the faces are not coherently oriented (" +
                        std::to_string(t.inconsistentEdges) +
                        " edges between faces of opposite orientation), so no map can keep every face's "
                        "orientation; re-orient them first");
  if (t.isolatedVertices > 0)
    return invalidInput("LLE flattening: " + std::to_string(t.isolatedVertices) + " vertices are in no face");
  for (const Vec3& q : patch.positions)
    if (!q.allFinite()) return invalidInput("LLE flattening: a vertex position is not finite");
  if (p.basePoints < 4)
    return invalidInput("LLE flattening: at least 4 base points, got " + std::to_string(p.basePoints));
  if (p.basePoints > patch.vertexCount())
    return invalidInput("LLE flattening: " + std::to_string(p.basePoints) + " base points asked on " +
                        std::to_string(patch.vertexCount()) + " vertices");
  if (p.neighbours < 3 || p.neighbours >= p.basePoints)
    return invalidInput("LLE flattening: the neighbours K must be >= 3 and below the base points B (K = " +
                        std::to_string(p.neighbours) + ", B = " + std::to_string(p.basePoints) + ")");
  if (!(p.regularisation >= 0.0) || !std::isfinite(p.regularisation))
    return invalidInput("LLE flattening: the regulariser must be finite and >= 0");
  if (p.arapRounds < 0) return invalidInput("LLE flattening: ARAP rounds must be >= 0");
  return Status::ok();
}

/// Reconstruction weights of a point from its neighbours, given the point's distances to them
/// (`toPoint`) and their pairwise distances (`between`, K x K): the local Gram matrix of the
/// distances, regularised, solved for G w = 1, normalised to sum 1.
Eigen::VectorXd lleWeights(const Eigen::VectorXd& toPoint, const Eigen::MatrixXd& between, double regularisation) {
  const int k = static_cast<int>(toPoint.size());
  Eigen::MatrixXd g(k, k);
  for (int a = 0; a < k; ++a)
    for (int b = 0; b < k; ++b)
      g(a, b) = 0.5 * (toPoint[a] * toPoint[a] + toPoint[b] * toPoint[b] - between(a, b) * between(a, b));
  const double trace = g.trace();
  g.diagonal().array() += regularisation * (trace > 0.0 ? trace / k : 1.0) + 1e-300;
  Eigen::VectorXd w = g.ldlt().solve(Eigen::VectorXd::Ones(k));
  const double sum = w.sum();
  if (!std::isfinite(sum) || std::abs(sum) < 1e-300) return Eigen::VectorXd::Constant(k, 1.0 / k);
  return w / sum;
}

/// The fronts from the base points: per vertex, the bases that reached it; between the bases,
/// their distances (where no front reached, the shortest path through the bases' own graph).
struct BaseField {
  std::vector<int> base;  ///< base vertices
  /// The bases whose front reached vertex v: near[nearBegin[v] .. nearBegin[v + 1]), (distance,
  /// base j), its K nearest first and in order.
  std::vector<int> nearBegin;
  std::vector<std::pair<double, int>> near;
  Eigen::MatrixXd between;  ///< between(i, j): from base j's front at base i (graph-completed)
};

/// Fronts stop at this many covering radii of the sampling (plane10k, B = 100: about 90k vertex
/// visits, against 345k at 5 radii and 1M for whole fronts). Inside the patch a vertex's K = 8
/// nearest bases lie within about 2.3 of them; near the patch's border and corners it sees fewer, and uses
/// those (at least kLeastBasesSeen, else the radius doubles around it, below). The Gram matrices
/// also need the distances between a vertex's neighbouring bases, up to twice as far apart: two
/// bases' distance is also the least over the vertices both fronts reached of the sum of their
/// distances there (exact where a vertex lies on the geodesic between them, so up to 5 radii);
/// beyond, the shortest path through the bases' own graph. Measured (bench_flatten, B = 100,
/// medians of 3): 2.5 radii plane10k 53.8 ms, cap10k 55.8 ms; 2.3: 49.4 and 53.2 ms; 2.2: 49.6
/// and 51.3 ms; 2.1: 50.7 and 59.6 ms (more vertices see too few bases, their bases run again);
/// 2.0: the 10k cap folds (3 faces, untangled), 75.8 ms. From 5 radii to 2.3 the stretch of the
/// plane, cylinder and caps and the atlases of fandisk and bunny00 (stretch, conformal distortion,
/// packing) are the same to the third decimal (tests/flatten, tests/atlas).
constexpr double kFrontRadii = 2.3;
/// A vertex must see at least this many bases (or K if smaller); fewer make the radius double.
constexpr int kLeastBasesSeen = 4;

/// The front from base j, up to `radius`: the vertices it reached, with their distances.
Status baseFront(FastMarcher& marcher, int source, double radius, std::vector<std::pair<int, double>>& reached) {
  marcher.reset();
  if (Status s = marcher.addSource(source, 0); !s) return s;
  FastMarchingParams limit;
  limit.maxDistance = radius;
  if (Status s = marcher.propagate(limit); !s) return s;
  reached.clear();
  for (int v : marcher.acceptedOrder()) reached.emplace_back(v, marcher.distance()[v]);
  return {};
}

/// Vertices reached by fewer than `need` fronts.
std::vector<int> underCovered(int vertices, const std::vector<std::vector<std::pair<int, double>>>& fronts, int need) {
  std::vector<int> count(vertices, 0), lacking;
  for (const auto& front : fronts)
    for (const auto& [v, d] : front) ++count[v];
  for (int v = 0; v < vertices; ++v)
    if (count[v] < need) lacking.push_back(v);
  return lacking;
}

/// Missing distances between bases: shortest paths through the known ones (a Dijkstra per base
/// on the graph of known pairs, up to `limit`: farther pairs are never read, and stay unreached).
void completeBetween(Eigen::MatrixXd& between, double limit) {
  const int nb = static_cast<int>(between.rows());
  std::vector<std::vector<std::pair<int, double>>> known(nb);
  for (int i = 0; i < nb; ++i)
    for (int j = i + 1; j < nb; ++j) {  // symmetric: the smaller of the two fronts' values
      const double d = std::min(between(i, j), between(j, i));
      between(i, j) = between(j, i) = d;
      if (std::isfinite(d)) {
        known[i].emplace_back(j, d);
        known[j].emplace_back(i, d);
      }
    }
  Eigen::MatrixXd complete = between;
  std::vector<double> d(nb, kUnreached);
  std::vector<int> reached;
  std::vector<std::pair<double, int>> heap;  // min-heap through std::greater
  for (int i = 0; i < nb; ++i) {
    d[i] = 0.0;
    reached.assign(1, i);
    heap.assign(1, {0.0, i});
    while (!heap.empty()) {
      std::pop_heap(heap.begin(), heap.end(), std::greater<>());
      const auto [du, u] = heap.back();
      heap.pop_back();
      if (du > d[u] || du > limit) continue;
      for (const auto& [j, w] : known[u])
        if (du + w < d[j]) {
          if (!std::isfinite(d[j])) reached.push_back(j);
          d[j] = du + w;
          heap.emplace_back(d[j], j);
          std::push_heap(heap.begin(), heap.end(), std::greater<>());
        }
    }
    for (int j : reached) {
      if (!std::isfinite(between(i, j))) complete(i, j) = d[j];
      d[j] = kUnreached;
    }
  }
  between = std::move(complete);
}

/// The first bases are chosen in 3D: one in this many of the B, by farthest-point sampling in the
/// straight distance (O(B n / 16)); the geodesic farthest-point sampling goes on from their field.
/// The first samples' fronts are the dearest of a greedy sampling (each covers much of the patch,
/// and the first sample alone needs two whole fronts): plane10k, B = 100, the sampling takes
/// 8.8 ms from one start vertex, 6.9 / 5.7 / 4.8 ms from 4 / 8 / 16 bases chosen in 3D, with the
/// same covering radius (fandisk: 5.4 ms, 3.8 ms from 4). More is not better for the whole
/// flattening: from 12 or more, the 10k cap's corners see fewer bases (13 fronts run again) and
/// its ARAP needs 10 rounds instead of 7 (58 ms instead of 50). A patch's extremities are found as
/// well in 3D; where it curls back on itself, the geodesic sampling fills what the 3D one left.
constexpr int kBasesPer3dBase = 16;

/// Bases one edge inside the border move onto it (to their nearest border neighbour that is not a
/// base): the border vertices beside such a base see it an edge away and the other bases far on
/// one side, and their extension folds (a 10k spherical cap: 4 faces beside two such bases).
void moveBasesOntoBorder(const TriMesh& patch, std::vector<int>& base) {
  const std::vector<char> border = boundaryVertexFlags(patch);
  std::vector<char> isBase(patch.vertexCount(), 0);
  for (int b : base) isBase[b] = 1;
  for (int& b : base) {
    if (border[b]) continue;
    int best = -1;
    for (const int* c = patch.cornersBegin(b); c != patch.cornersEnd(b); ++c)
      for (int w : {patch.vertex(TriMesh::next(*c)), patch.vertex(TriMesh::prev(*c))})
        if (border[w] && !isBase[w] &&
            (best < 0 || (patch.positions[w] - patch.positions[b]).squaredNorm() <
                             (patch.positions[best] - patch.positions[b]).squaredNorm()))
          best = w;
    if (best < 0) continue;
    isBase[b] = 0;
    isBase[best] = 1;
    b = best;
  }
}

/// B base points by farthest-point sampling; each base's front up to kFrontRadii covering radii,
/// then, while some vertex is reached by fewer than K + 1 fronts, the radius doubles for the bases
/// within it of those vertices (all fronts whole at last).
Expected<BaseField> baseDistances(const TriMesh& patch, const LleFlatteningParams& p, Progress& progress) {
  BaseField f;
  FastMarcher marcher(patch, Metric::uniform());
  FpsParams fps;
  fps.targetCount = p.basePoints;
  fps.seed = p.seed;
  fps.boundaryPriority = 1.0;
  fps.initialSamples = farthestPointsIn3d(patch, std::max(1, p.basePoints / kBasesPer3dBase), p.seed);
  Expected<FpsResult> sampled = farthestPointSampling(marcher, fps, progress.sub(0.0, 0.1));
  if (!sampled) return sampled.status();
  f.base = sampled->samples;
  moveBasesOntoBorder(patch, f.base);
  const int nb = static_cast<int>(f.base.size()), n = patch.vertexCount();
  std::vector<std::vector<std::pair<int, double>>> fronts(nb);
  std::vector<char> rerun(nb, 1);
  double radius = kFrontRadii * sampled->coveringRadius;
  for (int pass = 0;; ++pass) {
    const bool whole = !(radius > 0.0) || radius >= 2.0 * sampled->coveringRadius * nb;  // beyond the diameter
    for (int j = 0; j < nb; ++j) {
      if (!rerun[j]) continue;
      if (!progress.report(0.1 + 0.6 * double(j) / nb, "Geodesic LLE: fronts")) return cancelled();
      if (Status s = baseFront(marcher, f.base[j], whole ? kUnreached : radius, fronts[j]); !s) return s;
    }
    const std::vector<int> lacking = underCovered(n, fronts, std::min(p.neighbours, kLeastBasesSeen));
    if (lacking.empty() || whole) break;
    radius *= 2.0;  // the bases within the new radius of the under-covered vertices go again
    marcher.reset();
    for (int v : lacking)
      if (Status s = marcher.addSource(v, 0); !s) return s;
    FastMarchingParams limit;
    limit.maxDistance = radius;
    if (Status s = marcher.propagate(limit); !s) return s;
    for (int j = 0; j < nb; ++j) rerun[j] = std::isfinite(marcher.distance()[f.base[j]]);
  }
  std::vector<int> baseIndex(n, -1);
  for (int j = 0; j < nb; ++j) baseIndex[f.base[j]] = j;
  f.nearBegin.assign(n + 1, 0);
  for (const auto& front : fronts)
    for (const auto& [v, d] : front) ++f.nearBegin[v + 1];
  std::partial_sum(f.nearBegin.begin(), f.nearBegin.end(), f.nearBegin.begin());
  f.near.resize(f.nearBegin[n]);
  std::vector<int> fill(f.nearBegin.begin(), f.nearBegin.end() - 1);
  f.between = Eigen::MatrixXd::Constant(nb, nb, kUnreached);
  for (int j = 0; j < nb; ++j)
    for (const auto& [v, d] : fronts[j]) {
      f.near[fill[v]++] = {d, j};
      if (baseIndex[v] >= 0) f.between(baseIndex[v], j) = d;
    }
  for (int v = 0; v < n; ++v) {  // between bases: also through each vertex both fronts reached
    const auto* nn = f.near.data() + f.nearBegin[v];
    const int count = f.nearBegin[v + 1] - f.nearBegin[v];
    for (int a = 0; a < count; ++a)
      for (int b = a + 1; b < count; ++b) {
        double& d = f.between(nn[a].second, nn[b].second);
        d = std::min(d, nn[a].first + nn[b].first);
      }
  }
  for (int v = 0; v < n; ++v) {
    const auto begin = f.near.begin() + f.nearBegin[v], end = f.near.begin() + f.nearBegin[v + 1];
    std::partial_sort(begin, begin + std::min<std::ptrdiff_t>(p.neighbours, end - begin), end);
  }
  // The pairs read later (a base's or a vertex's K nearest bases, pairwise) lie within twice the
  // fronts' radius of each other; three times is a margin.
  completeBetween(f.between, radius > 0.0 ? 3.0 * radius : kUnreached);
  return f;
}

/// The K bases nearest to base i (graph-completed distances), nearest first.
std::vector<int> nearestBases(const BaseField& f, int i, int k) {
  std::vector<int> order(f.base.size());
  std::iota(order.begin(), order.end(), 0);
  order.erase(order.begin() + i);
  k = std::min<int>(k, order.size());
  std::partial_sort(order.begin(), order.begin() + k, order.end(),
                    [&](int a, int b) { return f.between(i, a) < f.between(i, b); });
  order.resize(k);
  return order;
}

/// Stress majorisation of the bases' layout on their neighbour pairs (Jacobi form of SMACOF):
/// each base moves to the mean over its pairs of y_j + d_ij (y_i - y_j) / |y_i - y_j|, so that the
/// planar distances approach the geodesic ones. LLE gives the layout's shape, not its lengths
/// (the 2x2 correction fixes only a global affinity); a few rounds make it locally isometric
/// where the patch allows.
void relaxStress(const BaseField& f, const std::vector<std::pair<int, int>>& pairs, int rounds, std::vector<Vec2>& y) {
  const int nb = static_cast<int>(y.size());
  for (int round = 0; round < rounds; ++round) {
    std::vector<Vec2> sum(nb, Vec2::Zero());
    std::vector<int> count(nb, 0);
    for (const auto& [i, j] : pairs) {
      const Vec2 e = y[i] - y[j];
      const double len = e.norm(), d = f.between(i, j);
      if (!(len > 0.0)) continue;
      sum[i] += y[j] + (d / len) * e;
      sum[j] += y[i] - (d / len) * e;
      ++count[i];
      ++count[j];
    }
    for (int i = 0; i < nb; ++i)
      if (count[i] > 0) y[i] = sum[i] / count[i];
  }
}

/// The base points' embedding: LLE on the bases, then the 2x2 metric correction.
std::vector<Vec2> embedBases(const BaseField& f, const LleFlatteningParams& p, bool* corrected) {
  const int nb = static_cast<int>(f.base.size()), k = p.neighbours;
  Eigen::MatrixXd iw = Eigen::MatrixXd::Identity(nb, nb);
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < nb; ++i) {
    const std::vector<int> nn = nearestBases(f, i, k);
    Eigen::VectorXd toPoint(k);
    Eigen::MatrixXd between(k, k);
    for (int a = 0; a < k; ++a) {
      toPoint[a] = f.between(i, nn[a]);
      for (int b = 0; b < k; ++b) between(a, b) = f.between(nn[b], nn[a]);
      pairs.push_back({i, nn[a]});
    }
    const Eigen::VectorXd w = lleWeights(toPoint, between, p.regularisation);
    for (int a = 0; a < k; ++a) iw(i, nn[a]) -= w[a];
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(iw.transpose() * iw);
  std::vector<Vec2> y(nb);
  for (int i = 0; i < nb; ++i) y[i] = Vec2(eigen.eigenvectors()(i, 1), eigen.eigenvectors()(i, 2));
  // The metric correction: (y_i - y_j)^T S (y_i - y_j) = d_ij^2 in the least-squares sense.
  Eigen::MatrixXd a(pairs.size(), 3);
  Eigen::VectorXd rhs(pairs.size());
  for (size_t r = 0; r < pairs.size(); ++r) {
    const Vec2 e = y[pairs[r].first] - y[pairs[r].second];
    a.row(r) << e.x() * e.x(), 2.0 * e.x() * e.y(), e.y() * e.y();
    const double d = f.between(pairs[r].first, pairs[r].second);
    rhs[r] = d * d;
  }
  const Eigen::Vector3d s = a.colPivHouseholderQr().solve(rhs);
  Eigen::Matrix2d metric;
  metric << s[0], s[1], s[1], s[2];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> se(metric);
  *corrected = se.eigenvalues().minCoeff() > 0.0;
  if (*corrected) {
    const Eigen::Matrix2d root = se.operatorSqrt();
    for (Vec2& q : y) q = root * q;
  }
  relaxStress(f, pairs, p.stressRounds, y);
  return y;
}

/// The Nyström extension: each vertex's LLE weights on its K nearest bases (from the same
/// fronts), applied to the bases' embedding.
std::vector<Vec2> extend(const TriMesh& patch, const BaseField& f, const std::vector<Vec2>& y,
                         const LleFlatteningParams& p) {
  const int nb = static_cast<int>(f.base.size());
  std::vector<int> baseIndex(patch.vertexCount(), -1);
  for (int j = 0; j < nb; ++j) baseIndex[f.base[j]] = j;
  std::vector<Vec2> uv(patch.vertexCount(), Vec2::Zero());
  Eigen::VectorXd toPoint;
  Eigen::MatrixXd between;
  for (int v = 0; v < patch.vertexCount(); ++v) {
    if (baseIndex[v] >= 0) {
      uv[v] = y[baseIndex[v]];
      continue;
    }
    // K of them (baseDistances sees to it on a connected patch; fewer only if some were unreachable)
    const int k = std::min(p.neighbours, f.nearBegin[v + 1] - f.nearBegin[v]);
    if (k == 0) continue;
    const std::pair<double, int>* nn = f.near.data() + f.nearBegin[v];
    toPoint.resize(k);
    between.resize(k, k);
    for (int a = 0; a < k; ++a) {
      toPoint[a] = nn[a].first;
      for (int b = 0; b < k; ++b) between(a, b) = f.between(nn[b].second, nn[a].second);
    }
    const Eigen::VectorXd w = lleWeights(toPoint, between, p.extensionRegularisation);
    Vec2 q = Vec2::Zero();
    for (int a = 0; a < k; ++a) q += w[a] * y[nn[a].second];
    uv[v] = q;
  }
  return uv;
}

/// Harmonic smoothing of the extension: `rounds` Jacobi steps in which every vertex but the bases
/// moves to the mean of its neighbours' UVs weighted by the positive part of the 3D cotangent
/// weights (a discrete harmonic map is locally conformal), boundary vertices towards their two
/// boundary neighbours only (the boundary keeps its shape instead of being pulled inward). The
/// Nyström values carry the fronts' error at the scale of an edge; a few steps take out that
/// jitter (and the folds it makes) and leave the base points' layout.
void smoothExtension(const TriMesh& patch, const std::vector<int>& base, std::vector<Vec2>& uv, int rounds) {
  const int n = patch.vertexCount();
  const std::vector<char> boundary = boundaryVertexFlags(patch);
  std::vector<Eigen::Triplet<double>> entries;
  for (int f = 0; f < patch.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Tri& t = patch.triangles[f];
      const int x = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const Vec3 ea = patch.positions[a] - patch.positions[x], eb = patch.positions[b] - patch.positions[x];
      const double sine = ea.cross(eb).norm();
      const double w = sine > 0.0 ? std::max(ea.dot(eb) / sine, 0.0) + 1e-3 : 1e-3;  // cot, kept positive
      entries.emplace_back(a, b, w);
      entries.emplace_back(b, a, w);
    }
  Eigen::SparseMatrix<double, Eigen::RowMajor> weight(n, n);
  weight.setFromTriplets(entries.begin(), entries.end());
  std::vector<char> fixed(n, 0);
  for (int v : base) fixed[v] = 1;
  for (int v = 0; v < n; ++v) fixed[v] |= boundary[v];
  std::vector<Vec2> next = uv;
  for (int round = 0; round < rounds; ++round) {
    for (int v = 0; v < n; ++v) {
      if (fixed[v]) continue;
      Vec2 sum = Vec2::Zero();
      double total = 0.0;
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(weight, v); it; ++it) {
        sum += it.value() * uv[it.col()];
        total += it.value();
      }
      if (total > 0.0) next[v] = sum / total;
    }
    uv.swap(next);
  }
}

/// Faces turned over (against the majority) or of zero area; turns the whole map over first if
/// most faces are.
int foldedFaces(const TriMesh& patch, std::vector<Vec2>& uv) {
  std::vector<double> area = uvSignedAreas(patch, uv);
  double sum = 0.0, mean = 0.0;
  for (double a : area) {
    sum += a;
    mean += std::abs(a);
  }
  mean /= std::max<size_t>(area.size(), 1);
  if (sum < 0.0) {
    for (Vec2& q : uv) q.y() = -q.y();
    for (double& a : area) a = -a;
  }
  int folded = 0;
  for (double a : area) folded += !(a > kDegenerateArea * mean);
  return folded;
}

/// Local untangling: the vertices of folded faces (and their neighbours, from the second round)
/// move to the mean of their neighbours' UVs, a few rounds; the faces still folded.
int untangle(const TriMesh& patch, std::vector<Vec2>& uv, int rounds) {
  std::vector<char> boundary(patch.vertexCount(), 0);
  for (int c = 0; c < 3 * patch.faceCount(); ++c)
    if (patch.oppositeCorner[c] < 0)
      boundary[patch.vertex(TriMesh::next(c))] = boundary[patch.vertex(TriMesh::prev(c))] = 1;
  int folded = foldedFaces(patch, uv);
  std::vector<char> moving(patch.vertexCount(), 0);
  for (int round = 0; round < rounds && folded > 0; ++round) {
    const std::vector<double> area = uvSignedAreas(patch, uv);
    double mean = 0.0;
    for (double a : area) mean += std::abs(a);
    mean /= std::max(1, patch.faceCount());
    for (int f = 0; f < patch.faceCount(); ++f)
      if (!(area[f] > kDegenerateArea * mean))
        for (int v : patch.triangles[f]) moving[v] = 1;
    if (round % kRoundsPerRing == kRoundsPerRing - 1) {  // the moving set grows by a ring
      std::vector<char> grown = moving;
      for (const Tri& t : patch.triangles)
        if (moving[t[0]] || moving[t[1]] || moving[t[2]]) grown[t[0]] = grown[t[1]] = grown[t[2]] = 1;
      moving = std::move(grown);
    }
    for (int v = 0; v < patch.vertexCount(); ++v) {
      if (!moving[v]) continue;
      Vec2 sum = Vec2::Zero();
      int count = 0;
      for (int k = patch.vertexCornerBegin[v]; k < patch.vertexCornerBegin[v + 1]; ++k) {
        const int c = patch.vertexCorners[k];
        for (int w : {patch.vertex(TriMesh::next(c)), patch.vertex(TriMesh::prev(c))})
          if (!boundary[v] || boundary[w]) {  // a boundary vertex follows its boundary neighbours
            sum += uv[w];
            ++count;
          }
      }
      if (count > 0) uv[v] = sum / count;
    }
    folded = foldedFaces(patch, uv);
  }
  return folded;
}

/// The boundary loop of a disk, in order.
std::vector<int> boundaryLoop(const TriMesh& patch) {
  std::vector<int> next(patch.vertexCount(), -1);
  int start = -1;
  for (int c = 0; c < 3 * patch.faceCount(); ++c)
    if (patch.oppositeCorner[c] < 0) {
      next[patch.vertex(TriMesh::next(c))] = patch.vertex(TriMesh::prev(c));
      start = patch.vertex(TriMesh::next(c));
    }
  std::vector<int> loop;
  for (int v = start; v >= 0 && (loop.empty() || v != start) && loop.size() <= next.size(); v = next[v])
    loop.push_back(v);
  return loop;
}

/// Floater's mean-value weight of the edge from x to each of the two other corners of a face,
/// from the face's 3D angle at x: tan(angle / 2) / |edge| (positive for every triangle).
void addMeanValueWeights(const TriMesh& patch, int f, int k, std::vector<Eigen::Triplet<double>>& w,
                         const std::vector<int>& index) {
  const Tri& t = patch.triangles[f];
  const int x = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];
  if (index[x] < 0) return;
  const Vec3 ea = patch.positions[a] - patch.positions[x], eb = patch.positions[b] - patch.positions[x];
  const double la = ea.norm(), lb = eb.norm();
  const double angle = std::atan2(ea.cross(eb).norm(), ea.dot(eb));
  const double half = std::tan(0.5 * std::clamp(angle, 1e-6, kPi - 1e-6));
  w.emplace_back(index[x], a, half / std::max(la, 1e-300));
  w.emplace_back(index[x], b, half / std::max(lb, 1e-300));
}

/// Tutte's embedding with Floater's mean-value weights (positive, so one-to-one onto the convex
/// boundary by Floater's theorem, and far less stretched than uniform weights on irregular
/// triangles): the boundary on the unit circle by arc length, each interior vertex the weighted
/// mean of its neighbours (one sparse LU solve). Scaled to the patch's area by the caller.
Expected<std::vector<Vec2>> tutteEmbedding(const TriMesh& patch) {
  const std::vector<int> loop = boundaryLoop(patch);
  const int n = patch.vertexCount();
  std::vector<Vec2> uv(n, Vec2::Zero());
  std::vector<char> onBoundary(n, 0);
  double perimeter = 0.0;
  for (size_t i = 0; i < loop.size(); ++i)
    perimeter += (patch.positions[loop[(i + 1) % loop.size()]] - patch.positions[loop[i]]).norm();
  double along = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const double t = perimeter > 0.0 ? 2.0 * kPi * along / perimeter : 2.0 * kPi * i / loop.size();
    uv[loop[i]] = Vec2(std::cos(t), std::sin(t));
    onBoundary[loop[i]] = 1;
    along += (patch.positions[loop[(i + 1) % loop.size()]] - patch.positions[loop[i]]).norm();
  }
  std::vector<int> index(n, -1);
  int interior = 0;
  for (int v = 0; v < n; ++v)
    if (!onBoundary[v]) index[v] = interior++;
  if (interior == 0) return uv;
  std::vector<Eigen::Triplet<double>> weights, entries;  // weights: (row, neighbour vertex, w)
  for (int f = 0; f < patch.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) addMeanValueWeights(patch, f, k, weights, index);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(interior, 2);
  for (const auto& w : weights) {
    entries.emplace_back(w.row(), w.row(), w.value());
    if (index[w.col()] >= 0)
      entries.emplace_back(w.row(), index[w.col()], -w.value());
    else
      rhs.row(w.row()) += w.value() * uv[w.col()].transpose();
  }
  Eigen::SparseMatrix<double> l(interior, interior);
  l.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver(l);
  if (solver.info() != Eigen::Success) return internalError("LLE flattening: Tutte's system could not be factorised");
  const Eigen::MatrixXd x = solver.solve(rhs);
  for (int v = 0; v < n; ++v)
    if (index[v] >= 0) uv[v] = x.row(index[v]).transpose();
  return uv;
}

/// Scales uv so that its area is the patch's.
void matchArea(const TriMesh& patch, std::vector<Vec2>& uv) {
  double area3 = 0.0, area2 = 0.0;
  for (int f = 0; f < patch.faceCount(); ++f) {
    const Tri& t = patch.triangles[f];
    area3 +=
        0.5 *
        (patch.positions[t[1]] - patch.positions[t[0]]).cross(patch.positions[t[2]] - patch.positions[t[0]]).norm();
  }
  for (double a : uvSignedAreas(patch, uv)) area2 += std::abs(a);
  if (!(area2 > 0.0)) return;
  const double s = std::sqrt(area3 / area2);
  for (Vec2& q : uv) q *= s;
}

/// The map after params.arapRounds of ARAP relaxation (one-to-one kept; a map the relaxation
/// refuses, which a one-to-one map is not, is returned as it was). `checked`: r.uv was just found
/// one-to-one.
Expected<LleFlatteningResult> relaxed(const TriMesh& patch, const LleFlatteningParams& params, LleFlatteningResult r,
                                      bool checked) {
  if (params.arapRounds <= 0) return r;
  ArapParams arap;
  arap.rounds = params.arapRounds;
  std::vector<Vec2> uv = r.uv;
  Expected<ArapResult> a = relaxAsRigidAsPossible(patch, uv, arap, checked);
  if (!a) return a.status().code == StatusCode::InvalidInput ? Expected<LleFlatteningResult>(std::move(r)) : a.status();
  r.uv = std::move(uv);
  r.arapRounds = a->rounds;
  return r;
}

}  // namespace

std::vector<double> uvSignedAreas(const TriMesh& mesh, const std::vector<Vec2>& uv) {
  std::vector<double> area(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    const Vec2 a = uv[t[1]] - uv[t[0]], b = uv[t[2]] - uv[t[0]];
    area[f] = 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  return area;
}

Expected<LleFlatteningResult> flattenGeodesicLle(const TriMesh& patch, const LleFlatteningParams& params,
                                                 Progress progress) {
  if (Status s = checkPatch(patch, params); !s) return s;
  LleFlatteningResult r;
  if (params.boundary == LleBoundary::Free) {
    Expected<BaseField> field = baseDistances(patch, params, progress);
    if (!field) return field.status();
    r.basePoints = field->base;
    if (!progress.report(0.75, "Geodesic LLE: embedding")) return cancelled();
    const std::vector<Vec2> y = embedBases(*field, params, &r.metricCorrected);
    r.uv = extend(patch, *field, y, params);
    smoothExtension(patch, field->base, r.uv, params.smoothingRounds);
    r.foldedBeforeRepair = foldedFaces(patch, r.uv);
    const bool local = r.foldedBeforeRepair <= kMaxUntangledShare * patch.faceCount();
    const bool unfolded = r.foldedBeforeRepair == 0 || (local && untangle(patch, r.uv, kUntangleRounds) == 0);
    // No fold left; the boundary may still run over itself (a free boundary bends freely).
    if (unfolded && checkUvInjectivity(patch, r.uv).injective()) {
      if (!r.metricCorrected) matchArea(patch, r.uv);
      return relaxed(patch, params, std::move(r), /*checked=*/true);
    }
  }
  Expected<std::vector<Vec2>> tutte = tutteEmbedding(patch);
  if (!tutte) return tutte.status();
  r.uv = std::move(*tutte);
  r.tutte = true;
  foldedFaces(patch, r.uv);  // orientation as the patch's
  matchArea(patch, r.uv);
  if (params.boundary == LleBoundary::Circle) return r;
  return relaxed(patch, params, std::move(r), /*checked=*/false);
}

}  // namespace gr
