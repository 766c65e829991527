#include "core/remesh/surface_relaxation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "core/base/math.h"
#include "core/mesh/face_geometry.h"
#include "core/mesh/self_intersection.h"

namespace gr {
namespace {

constexpr double kDegree = kPi / 180.0;

/// Barycentric coordinates of the point at parameter t on the edge from corner i to corner j.
Vec3 onEdge(int i, int j, double t) {
  Vec3 w = Vec3::Zero();
  w[i] = 1 - t;
  w[j] = t;
  return w;
}

/// Closest point of triangle (a, b, c) to p, as barycentric coordinates (Ericson, Real-Time
/// Collision Detection, 5.1.5). A coordinate is exactly 0 when the point is on the opposite edge.
Vec3 closestBary(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a;
  // The dot products of the edges ab and ac with the vector from corner q to p.
  const auto dots = [&](const Vec3& q) {
    const Vec3 qp = p - q;
    return std::array<double, 2>{ab.dot(qp), ac.dot(qp)};
  };
  const auto [d1, d2] = dots(a);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const auto [d3, d4] = dots(b);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return onEdge(0, 1, d1 / (d1 - d3));
  const auto [d5, d6] = dots(c);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return onEdge(0, 2, d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return onEdge(1, 2, (d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double denom = va + vb + vc;
  if (!(denom > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};  // degenerate face
  const double v = vb / denom, w = vc / denom;
  return {1 - v - w, v, w};
}

/// The input surface as the walks see it: faces, and which edges they may not cross.
class SurfaceWalker {
 public:
  // Everything is computed where the walks go: the cost follows the output, not the input
  // (apart from one byte per input corner for the blocked-edge cache).
  SurfaceWalker(const TriMesh& mesh, double featureAngleDegrees)
      : mesh_(mesh), cosFeature_(std::cos(featureAngleDegrees * kDegree)), blocked_(3 * size_t(mesh.faceCount()), -1) {}

  /// Unit normal of an input face (zero for a degenerate face).
  Vec3 normal(int face) const {
    const Vec3 n = areaNormal(mesh_, face);
    const double len = n.norm();
    return len > 0 ? Vec3(n / len) : Vec3::Zero();
  }

  /// Whether the edge facing `corner` may not be crossed: a boundary, a crease sharper than the
  /// feature angle, or an edge of a degenerate face.
  bool blocked(int corner) const {
    signed char& known = blocked_[corner];  // computed once per corner the walks reach
    if (known < 0) known = computeBlocked(corner);
    return known;
  }

  /// Whether input vertex v has a blocked edge (a crease, corner or boundary vertex).
  bool sharpVertex(int v) const {
    for (const int* c = mesh_.cornersBegin(v); c != mesh_.cornersEnd(v); ++c)
      if (blocked(TriMesh::next(*c)) || blocked(TriMesh::prev(*c))) return true;
    return false;
  }

  /// A face that contains the point (for a vertex: its first face).
  int faceOf(const SurfacePoint& p) const {
    if (p.vertex >= 0) return TriMesh::face(*mesh_.cornersBegin(p.vertex));
    return p.face;
  }

  /// The closest point to q reachable from `face` by steps to neighbouring faces that bring it
  /// strictly closer, never across a blocked edge.
  SurfacePoint project(const Vec3& q, int face) const {
    Vec3 bary = baryIn(q, face);
    double dist = (pointOf(face, bary) - q).squaredNorm();
    for (int step = 0; step < kMaxSteps; ++step) {
      int bestFace = -1;
      Vec3 bestBary;
      double best = dist;
      const auto tryFace = [&](int g) {
        const Vec3 b = baryIn(q, g);
        const double d = (pointOf(g, b) - q).squaredNorm();
        if (d < best) {
          best = d;
          bestFace = g;
          bestBary = b;
        }
      };
      // Zero coordinates say where on the face the closest point is: an edge, or a vertex.
      for (int k = 0; k < 3; ++k) {
        if (bary[k] != 0) continue;
        const int c = 3 * face + k;  // the corner facing the edge the point is on
        if (!blocked(c)) tryFace(TriMesh::face(mesh_.oppositeCorner[c]));
        if (bary[(k + 1) % 3] == 0) fan(3 * face + (k + 2) % 3, tryFace);
        if (bary[(k + 2) % 3] == 0) fan(3 * face + (k + 1) % 3, tryFace);
      }
      if (bestFace < 0) break;
      face = bestFace;
      bary = bestBary;
      dist = best;
    }
    return SurfacePoint::inFace(face, bary);
  }

  Vec3 pointOf(int face, const Vec3& bary) const {
    const Tri& t = mesh_.triangles[face];
    return bary[0] * mesh_.positions[t[0]] + bary[1] * mesh_.positions[t[1]] + bary[2] * mesh_.positions[t[2]];
  }

 private:
  static constexpr int kMaxSteps = 1000;

  Vec3 baryIn(const Vec3& q, int face) const {
    const Tri& t = mesh_.triangles[face];
    return closestBary(q, mesh_.positions[t[0]], mesh_.positions[t[1]], mesh_.positions[t[2]]);
  }

  /// Calls visit(face) for the faces around the vertex at `corner`, turning both ways from its
  /// face and stopping at blocked edges.
  template <class Visit>
  void fan(int corner, Visit& visit) const {
    for (int dir = 0; dir < 2; ++dir) {
      int c = corner;
      for (int guard = 0; guard < 64; ++guard) {
        // Cross the edge (corner's vertex, next) or (corner's vertex, prev) of c's face.
        const int facing = dir == 0 ? TriMesh::prev(c) : TriMesh::next(c);
        if (blocked(facing)) break;
        const int o = mesh_.oppositeCorner[facing];
        c = dir == 0 ? TriMesh::prev(o) : TriMesh::next(o);
        if (TriMesh::face(c) == TriMesh::face(corner)) break;
        visit(TriMesh::face(c));
      }
    }
  }

  bool computeBlocked(int corner) const {
    const int o = mesh_.oppositeCorner[corner];
    if (o < 0) return true;
    const Vec3 a = areaNormal(mesh_, TriMesh::face(corner)), b = areaNormal(mesh_, TriMesh::face(o));
    return !(a.dot(b) > cosFeature_ * std::sqrt(a.squaredNorm() * b.squaredNorm()));  // also if degenerate
  }

  const TriMesh& mesh_;
  double cosFeature_;
  mutable std::vector<signed char> blocked_;  ///< per input corner: -1 not computed yet, else 0 / 1
};

/// Cosine of the smallest angle of triangle (p, q, r): the angle facing the shortest edge.
/// A degenerate triangle gives 1 (angle 0).
double smallestAngleCosine(const Vec3& p, const Vec3& q, const Vec3& r) {
  const double a = (q - r).squaredNorm(), b = (r - p).squaredNorm(), c = (p - q).squaredNorm();
  double shortest = a, o1 = b, o2 = c;  // the angle facing `shortest`, between sides o1 and o2
  if (b < shortest) std::swap(shortest, o1);
  if (c < shortest) std::swap(shortest, o2);
  const double denominator = 2 * std::sqrt(o1 * o2);
  return denominator > 0 ? std::min(1.0, (o1 + o2 - shortest) / denominator) : 1.0;
}

/// Refuses what the relaxation cannot work on: points that do not match the output or the input,
/// a non-manifold mesh, an output without faces or with faces not oriented alike.
Status checkRelaxationInput(const TriMesh& output, const std::vector<SurfacePoint>& points, const TriMesh& input) {
  const int n = output.vertexCount();
  if (static_cast<int>(points.size()) != n)
    return invalidInput("relaxation: " + std::to_string(points.size()) + " surface points for " + std::to_string(n) +
                        " vertices");
  if (!output.topology.isManifold() || !input.topology.isManifold())
    return nonManifold(std::string("relaxation needs manifold meshes; the ") +
                       (output.topology.isManifold() ? "input" : "output") + " is not");
  if (output.topology.inconsistentEdges > 0)
    return invalidInput("relaxation: the faces of the output are not oriented coherently (" +
                        std::to_string(output.topology.inconsistentEdges) +
                        " edges have two faces that disagree): orient them first (orientCoherently)");
  if (output.faceCount() == 0) return invalidInput("relaxation: the output has no faces");
  for (const SurfacePoint& p : points) {
    const bool ok = p.vertex >= 0 ? p.vertex < input.vertexCount() && input.valence(p.vertex) > 0
                                  : p.face >= 0 && p.face < input.faceCount();
    if (!ok) return invalidInput("relaxation: a surface point out of range of the input");
  }
  return Status::ok();
}

/// Per output vertex, 1 if it does not move: on a boundary edge, on an input vertex with a
/// blocked edge (a crease, corner or boundary of the input), or in no face.
std::vector<char> fixedVertices(const TriMesh& output, const std::vector<SurfacePoint>& points,
                                const SurfaceWalker& walker) {
  const int n = output.vertexCount();
  std::vector<char> fixed(n, 0);
  for (int c = 0; c < 3 * output.faceCount(); ++c)
    if (output.oppositeCorner[c] < 0) {  // a boundary edge: both its vertices stay
      fixed[output.vertex(TriMesh::next(c))] = 1;
      fixed[output.vertex(TriMesh::prev(c))] = 1;
    }
  for (int i = 0; i < n; ++i) {
    if (points[i].vertex >= 0 && walker.sharpVertex(points[i].vertex)) fixed[i] = 1;
    if (output.valence(i) == 0) fixed[i] = 1;
  }
  return fixed;
}

/// Moves the free vertices of the output, one at a time, on the input surface.
class Relaxer {
 public:
  Relaxer(TriMesh& output, std::vector<SurfacePoint>& points, const SurfaceWalker& walker, double maxDeviation,
          const std::vector<char>& watched)
      : output_(output),
        pos_(output.positions),
        points_(points),
        walker_(walker),
        maxDeviation_(maxDeviation),
        watched_(watched) {}

  /// The faces with a watched corner, which a watched vertex's faces may not cross (collected
  /// again each round: the flips change the faces).
  void collectWatchedFaces() {
    watchedFaces_.clear();
    if (watched_.empty()) return;
    for (int f = 0; f < output_.faceCount(); ++f) {
      const Tri& t = output_.triangles[f];
      if (watched_[t[0]] || watched_[t[1]] || watched_[t[2]]) watchedFaces_.push_back(f);
    }
  }

  /// Moves v toward the mean of its neighbours in its tangent plane, if that improves its ring;
  /// where a small angle remains, tries steps in eight tangent directions.
  void relaxVertex(int v) {
    const Vec3 p = pos_[v];
    Vec3 centre = Vec3::Zero(), ringNormal = Vec3::Zero();
    double ringLength = 0;
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      const Vec3& a = pos_[output_.vertex(TriMesh::next(*c))];
      const Vec3& b = pos_[output_.vertex(TriMesh::prev(*c))];
      centre += a;  // each neighbour once: it is `next` in exactly one face of a closed fan
      ringNormal += (a - p).cross(b - p);
      ringLength += (a - p).norm();
    }
    centre /= output_.valence(v);
    ringLength /= output_.valence(v);
    const double maxAway = maxDeviation_ * ringLength;
    // The tangent plane: the output ring's, unless the ring is folded against the input.
    const int face = walker_.faceOf(points_[v]);
    Vec3 normal = walker_.normal(face);
    if (normal.isZero()) return;
    if (ringNormal.dot(normal) > 0.5 * ringNormal.norm()) normal = ringNormal.normalized();
    Vec3 move = centre - p;
    move -= normal * normal.dot(move);
    const double before = ring(v, p, nullptr);
    double smallest = tryMove(v, p + move, face, before, 0.0, maxAway);
    // A watched vertex whose move would make faces cross tries half and a quarter of it.
    for (double part = 0.5; refusedLast_ && part >= 0.25; part *= 0.5)
      smallest = tryMove(v, p + part * move, face, before, 0.0, maxAway);
    if (smallest >= kGoal) return;
    tryTangentSteps(v, normal, ringLength, smallest);
  }

  int moves() const { return moves_; }
  int refusedCrossing() const { return refusedCrossing_; }

 private:
  static constexpr double kGoal = 30.0 * kDegree;  ///< smallest angle a move need not exceed

  /// Smallest angle (radians) of the faces around v with v at position p, and their normals.
  double ring(int v, const Vec3& p, std::vector<Vec3>* normals) const {
    double largestCosine = -1;
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      const Vec3& a = pos_[output_.vertex(TriMesh::next(*c))];
      const Vec3& b = pos_[output_.vertex(TriMesh::prev(*c))];
      largestCosine = std::max(largestCosine, smallestAngleCosine(p, a, b));
      if (normals) normals->push_back((a - p).cross(b - p));
    }
    return std::acos(largestCosine);
  }

  /// Moves v to the input point closest to `target` if no face around v turns over (except to
  /// face the way the input does there), the ring's smallest angle stays at least
  /// max(min(before, goal), floor) and the point v leaves stays within maxAway of the new fan.
  /// Returns the ring's smallest angle after (smallestBefore if v stays).
  double tryMove(int v, const Vec3& target, int face, double smallestBefore, double floor, double maxAway) {
    refusedLast_ = false;
    const SurfacePoint moved = walker_.project(target, face);
    const Vec3 q = walker_.pointOf(moved.face, moved.bary);
    const Vec3 normalThere = walker_.normal(moved.face);
    before_.clear();
    after_.clear();
    ring(v, pos_[v], &before_);
    const double smallest = ring(v, q, &after_);
    // A face may not turn over, unless it then faces the way the input does (an unfolding).
    for (size_t k = 0; k < after_.size(); ++k)
      if (!(after_[k].dot(before_[k]) > 0) && !(after_[k].dot(normalThere) > 0)) return smallestBefore;
    if (smallest < std::max(std::min(smallestBefore, kGoal), floor)) return smallestBefore;
    // The point it leaves must stay close to the new fan: a vertex on a tip or a ridge keeps it.
    const Vec3& p = pos_[v];
    double away = std::numeric_limits<double>::infinity();
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      const Vec3& a = pos_[output_.vertex(TriMesh::next(*c))];
      const Vec3& b = pos_[output_.vertex(TriMesh::prev(*c))];
      const Vec3 w = closestBary(p, q, a, b);
      away = std::min(away, (p - (w[0] * q + w[1] * a + w[2] * b)).squaredNorm());
    }
    if (away > maxAway * maxAway) return smallestBefore;
    const Vec3 from = p;  // p refers to pos_[v]
    pos_[v] = q;
    if (!watched_.empty() && watched_[v] && fanCrossesWatchedFaces(v)) {
      pos_[v] = from;
      ++refusedCrossing_;
      refusedLast_ = true;
      return smallestBefore;
    }
    points_[v] = moved;
    ++moves_;
    return smallest;
  }

  /// Whether a face around v crosses one of the watched faces.
  bool fanCrossesWatchedFaces(int v) const {
    const auto box = [&](int f, Vec3& lo, Vec3& hi) {
      const Tri& t = output_.triangles[f];
      lo = pos_[t[0]].cwiseMin(pos_[t[1]]).cwiseMin(pos_[t[2]]);
      hi = pos_[t[0]].cwiseMax(pos_[t[1]]).cwiseMax(pos_[t[2]]);
    };
    Vec3 fanLo, fanHi, lo, hi;
    box(TriMesh::face(*output_.cornersBegin(v)), fanLo, fanHi);
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      box(TriMesh::face(*c), lo, hi);
      fanLo = fanLo.cwiseMin(lo);
      fanHi = fanHi.cwiseMax(hi);
    }
    for (int g : watchedFaces_) {
      box(g, lo, hi);
      if (!((lo.array() <= fanHi.array()).all() && (fanLo.array() <= hi.array()).all())) continue;
      for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c)
        if (TriMesh::face(*c) != g && facesCross(output_, TriMesh::face(*c), g)) return true;
    }
    return false;
  }

  /// Still a small angle at v (at a tip, a saddle, next to a fixed vertex): the mean of the ring
  /// is not better, so try steps in eight tangent directions from where the vertex is now and
  /// keep the best. No deviation limit: a bad triangle costs more than the error.
  void tryTangentSteps(int v, const Vec3& normal, double ringLength, double smallest) {
    const Vec3 here = pos_[v];
    const int hereFace = walker_.faceOf(points_[v]);
    const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    std::vector<std::pair<double, Vec3>> better;  // (smallest angle there, target), best first
    for (const double step : {0.4, 0.2, 0.1})
      for (int k = 0; k < 8; ++k) {
        const Vec3 target = here + step * ringLength * (std::cos(k * kPi / 4) * e1 + std::sin(k * kPi / 4) * e2);
        const SurfacePoint moved = walker_.project(target, hereFace);
        const double s = ring(v, walker_.pointOf(moved.face, moved.bary), nullptr);
        if (s > smallest) better.push_back({s, target});
      }
    std::stable_sort(better.begin(), better.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    // The best; for a watched vertex, the next best while a move is refused for crossing faces.
    for (const auto& [s, target] : better) {
      tryMove(v, target, hereFace, smallest, smallest, std::numeric_limits<double>::infinity());
      if (!refusedLast_) break;
    }
  }

  TriMesh& output_;
  std::vector<Vec3>& pos_;  ///< the output's positions
  std::vector<SurfacePoint>& points_;
  const SurfaceWalker& walker_;
  double maxDeviation_;
  const std::vector<char>& watched_;  ///< per output vertex, or empty (RelaxationGuard::watched)
  std::vector<int> watchedFaces_;     ///< faces with a watched corner (collectWatchedFaces)
  std::vector<Vec3> before_, after_;  ///< normals of v's faces before and after a move
  int moves_ = 0;
  int refusedCrossing_ = 0;
  bool refusedLast_ = false;  ///< the last tryMove was refused because faces would cross
};

}  // namespace

Expected<RelaxationResult> relaxOnSurface(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                                          const RelaxationParams& params, const RelaxationGuard& guard) {
  RelaxationResult r;
  if (Status s = checkRelaxationInput(output, points, input); !s) return s;
  for (const std::vector<char>* flags : {&guard.pinned, &guard.watched})
    if (!flags->empty() && static_cast<int>(flags->size()) != output.vertexCount())
      return invalidInput("relaxation: one pinned or watched flag per output vertex is needed");
  if (params.iterations <= 0) return r;

  const SurfaceWalker walker(input, params.featureAngleDegrees);
  std::vector<char> fixed = fixedVertices(output, points, walker);
  for (const char f : fixed) r.fixedVertices += f;
  for (size_t v = 0; v < guard.pinned.size(); ++v) {
    r.pinnedVertices += guard.pinned[v] && !fixed[v];
    fixed[v] |= guard.pinned[v];
  }
  for (size_t v = 0; v < guard.watched.size(); ++v) r.watchedVertices += guard.watched[v] && !fixed[v];
  Relaxer relaxer(output, points, walker, params.maxDeviation, guard.watched);
  for (int it = 0; it < params.iterations; ++it) {
    relaxer.collectWatchedFaces();
    for (int v = 0; v < output.vertexCount(); ++v)
      if (!fixed[v]) relaxer.relaxVertex(v);
    // The output is manifold, oriented and has faces (checked above), and moves keep that.
    Expected<DelaunayFlipResult> flipped = flipToDelaunay(output, params.flips);
    if (!flipped) return flipped.status();
    r.flips += flipped->flips;
    if (params.valenceFlips) {
      Expected<DelaunayFlipResult> valence = flipTowardValenceSix(output, params.valence);
      if (!valence) return valence.status();
      r.flips += valence->flips;
    }
    ++r.iterations;
  }
  r.moves = relaxer.moves();
  r.refusedCrossing = relaxer.refusedCrossing();
  return r;
}

}  // namespace gr
