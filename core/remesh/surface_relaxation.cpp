#include "core/remesh/surface_relaxation.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <string>

#include "core/base/math.h"
#include "core/mesh/face_geometry.h"
#include "core/mesh/self_intersection.h"
#include "core/remesh/remesh_distance.h"

namespace gr {
namespace {

constexpr double kDegree = kPi / 180.0;
/// The polish and the Delaunay flips after it, at most this many times (RelaxationParams).
constexpr int kPolishPasses = 3;

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

/// Squared distance from p to triangle (a, b, c).
double squaredDistanceToTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 w = closestBary(p, a, b, c);
  return (p - (w[0] * a + w[1] * b + w[2] * c)).squaredNorm();
}

/// The input surface as the walks see it: faces, and which edges they may not cross.
class SurfaceWalker {
 public:
  // Everything is computed where the walks go: the cost follows the output, not the input
  // (apart from one byte per input corner for the blocked-edge cache), but for the short creases
  // (minCreaseLength > 0), found over the whole input once: O(F) (ignoreShortCreases).
  SurfaceWalker(const TriMesh& mesh, double featureAngleDegrees, double minCreaseLength)
      : mesh_(mesh), cosFeature_(std::cos(featureAngleDegrees * kDegree)), blocked_(3 * size_t(mesh.faceCount()), -1) {
    if (minCreaseLength > 0) ignoreShortCreases(minCreaseLength);
  }

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

  /// The input vertices joined to v by blocked edges, at most three of them (three means three or
  /// more: a corner of the feature curves); returns how many.
  int blockedNeighbours(int v, std::array<int, 3>& out) const {
    int n = 0;
    const auto add = [&](int u) {
      if (std::find(out.begin(), out.begin() + n, u) == out.begin() + n && n < 3) out[n++] = u;
    };
    for (const int* c = mesh_.cornersBegin(v); c != mesh_.cornersEnd(v); ++c) {
      if (blocked(TriMesh::prev(*c))) add(mesh_.vertex(TriMesh::next(*c)));  // edge (v, next)
      if (blocked(TriMesh::next(*c))) add(mesh_.vertex(TriMesh::prev(*c)));  // edge (v, prev)
    }
    return n;
  }

  /// The vertex after v on the feature curve that comes to v from `from` (a blocked neighbour of
  /// v), or -1 if v is a corner of the curves: not exactly two blocked edges, or a turn between
  /// them sharper than the feature angle (the corner of a square plate).
  int curveNext(int v, int from) const {
    std::array<int, 3> next{};
    if (blockedNeighbours(v, next) != 2) return -1;
    const int to = next[0] == from ? next[1] : next[0];
    const Vec3 in = mesh_.positions[v] - mesh_.positions[from], out = mesh_.positions[to] - mesh_.positions[v];
    if (!(in.dot(out) > cosFeature_ * in.norm() * out.norm())) return -1;
    return to;
  }

  /// The point at parameter t on the input edge from a to b (an edge of the mesh).
  SurfacePoint onInputEdge(int a, int b, double t) const {
    for (const int* c = mesh_.cornersBegin(a); c != mesh_.cornersEnd(a); ++c)
      for (const int other : {TriMesh::next(*c), TriMesh::prev(*c)})
        if (mesh_.vertex(other) == b) {
          Vec3 bary = Vec3::Zero();
          bary[*c % 3] = 1 - t;
          bary[other % 3] = t;
          return SurfacePoint::inFace(TriMesh::face(*c), bary);
        }
    return SurfacePoint::atVertex(a);  // not reached: a and b share an edge
  }

  const Vec3& position(int v) const { return mesh_.positions[v]; }
  const TriMesh& mesh() const { return mesh_; }

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

  /// The crease edges (blocked, not boundaries) per input vertex: (other end, a corner facing the edge).
  std::vector<std::vector<std::pair<int, int>>> creaseEdges() const {
    std::vector<std::vector<std::pair<int, int>>> creases(mesh_.vertexCount());
    for (int c = 0; c < 3 * mesh_.faceCount(); ++c) {
      const int o = mesh_.oppositeCorner[c];
      if (o < c || !blocked(c)) continue;  // each interior edge once
      const int p = mesh_.vertex(TriMesh::next(c)), q = mesh_.vertex(TriMesh::prev(c));
      creases[p].push_back({q, c});
      creases[q].push_back({p, c});
    }
    return creases;
  }

  /// RelaxationParams::minCreaseLength: the crease chains (joined at vertices with exactly two
  /// crease edges where the chain turns by less than the feature angle, as curveNext joins them)
  /// shorter than minLength are not blocked. Boundaries stay blocked.
  void ignoreShortCreases(double minLength) {
    const std::vector<std::vector<std::pair<int, int>>> creases = creaseEdges();
    const auto after = [&](int v, int from) {  // the chain's vertex after v coming from `from`, or -1
      if (creases[v].size() != 2) return -1;
      const int to = creases[v][0].first == from ? creases[v][1].first : creases[v][0].first;
      const Vec3 in = position(v) - position(from), out = position(to) - position(v);
      return in.dot(out) > cosFeature_ * in.norm() * out.norm() ? to : -1;
    };
    const auto corner = [&](int v, int u) {
      for (const auto& [w, c] : creases[v])
        if (w == u) return c;
      return -1;  // not reached: u is a crease neighbour of v
    };
    std::vector<char> done(blocked_.size(), 0);
    std::vector<int> chain;  // corners of the chain's edges
    for (int v = 0; v < mesh_.vertexCount(); ++v)
      for (const auto& [u, c0] : creases[v]) {
        if (done[c0]) continue;
        int a = v, b = u;  // back to the chain's first edge (a closed chain: once round)
        for (int w = after(a, b); w >= 0; w = after(a, b)) {
          b = a;
          a = w;
          if (a == v && b == u) break;
        }
        chain.clear();
        double length = 0;
        for (int x = a, y = b; y >= 0 && !done[corner(x, y)];) {
          const int c = corner(x, y);
          done[c] = 1;
          chain.push_back(c);
          length += (position(x) - position(y)).norm();
          const int z = after(y, x);
          x = y;
          y = z;
        }
        if (length < minLength)
          for (int c : chain) blocked_[c] = blocked_[mesh_.oppositeCorner[c]] = 0;
      }
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

/// The smallest angle of the mesh's faces (radians).
double smallestAngleOf(const TriMesh& mesh) {
  double largestCosine = -1;
  for (const Tri& t : mesh.triangles)
    largestCosine =
        std::max(largestCosine, smallestAngleCosine(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]));
  return std::acos(largestCosine);
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

/// A point on a feature curve of the input (a chain of blocked edges: boundaries and creases), at
/// t along the input edge from a to b.
struct CurvePoint {
  int a = -1, b = -1;
  double t = 0;
};

/// Where an output vertex may go: anywhere on its side of the creases, along a feature curve, or
/// nowhere (a corner of the curves: three or more blocked edges, the end of one, or a sharp turn).
enum class Freedom { Surface, Curve, None };

/// Where a point of `mesh` lies: at a vertex (vertex >= 0), on the edge facing corner `edgeCorner`
/// of its face (then `onEdge`: the point on that edge, from its first end), or inside a face (both
/// -1).
struct PointPlace {
  int vertex = -1;
  int edgeCorner = -1;
  CurvePoint onEdge;
};
PointPlace placeOf(const SurfacePoint& p, const TriMesh& mesh) {
  PointPlace place;
  if (p.vertex >= 0) {
    place.vertex = p.vertex;
    return place;
  }
  const Tri& t = mesh.triangles[p.face];
  const int zeros = (p.bary[0] == 0) + (p.bary[1] == 0) + (p.bary[2] == 0);
  if (zeros == 2) {  // at a corner of the face
    place.vertex = t[p.bary[0] != 0 ? 0 : p.bary[1] != 0 ? 1 : 2];
  } else if (zeros == 1) {  // on the edge facing the zero coordinate
    const int k = p.bary[0] == 0 ? 0 : p.bary[1] == 0 ? 1 : 2;
    place.edgeCorner = 3 * p.face + k;
    place.onEdge = {t[(k + 1) % 3], t[(k + 2) % 3], p.bary[(k + 2) % 3]};
  }
  return place;
}

/// The freedom of a point of the input and, for Curve, where it is on its curve.
Freedom freedomOf(const SurfacePoint& p, const SurfaceWalker& walker, CurvePoint& at) {
  const PointPlace place = placeOf(p, walker.mesh());
  if (place.edgeCorner >= 0) {
    if (!walker.blocked(place.edgeCorner)) return Freedom::Surface;
    at = place.onEdge;
    return Freedom::Curve;
  }
  const int v = place.vertex;
  if (v < 0) return Freedom::Surface;
  std::array<int, 3> next{};
  const int n = walker.blockedNeighbours(v, next);
  if (n == 0) return Freedom::Surface;
  if (walker.curveNext(v, next[0]) < 0) return Freedom::None;
  at = {v, next[1], 0.0};
  return Freedom::Curve;
}

/// The point at arc length s along the curve from `at` (toward b if s > 0, toward a if s < 0); it
/// stops at a corner of the curves (curveNext).
CurvePoint slide(CurvePoint at, double s, const SurfaceWalker& walker) {
  if (s < 0) {
    at = {at.b, at.a, 1 - at.t};
    s = -s;
  }
  for (int edges = 0; edges < 1000; ++edges) {
    const double length = (walker.position(at.b) - walker.position(at.a)).norm();
    const double left = (1 - at.t) * length;
    if (s < left) {
      at.t += s / length;
      return at;
    }
    s -= left;
    const int next = walker.curveNext(at.b, at.a);
    if (next < 0) return {at.a, at.b, 1.0};
    at = {at.b, next, 0.0};
  }
  return at;
}

/// Per output vertex, its freedom: None on an output boundary vertex that is not on an input
/// feature curve (it cannot be moved along the boundary), at a corner of the curves, in no face.
std::vector<Freedom> freedoms(const TriMesh& output, const std::vector<SurfacePoint>& points,
                              const SurfaceWalker& walker) {
  const int n = output.vertexCount();
  std::vector<char> onBoundary(n, 0);
  for (int c = 0; c < 3 * output.faceCount(); ++c)
    if (output.oppositeCorner[c] < 0) {
      onBoundary[output.vertex(TriMesh::next(c))] = 1;
      onBoundary[output.vertex(TriMesh::prev(c))] = 1;
    }
  std::vector<Freedom> freedom(n, Freedom::None);
  for (int i = 0; i < n; ++i) {
    CurvePoint at;
    const Freedom f = freedomOf(points[i], walker, at);
    if (output.valence(i) > 0 && !(onBoundary[i] && f != Freedom::Curve)) freedom[i] = f;
  }
  return freedom;
}

/// Per vertex of `mesh` (manifold), the first vertex of its boundary loop if that loop is shorter
/// than `maxLength`, else -1.
std::vector<int> tinyBoundaryLoops(const TriMesh& mesh, double maxLength) {
  const int n = mesh.vertexCount();
  std::vector<int> next(n, -1), loop(n, -1);  // next: along the boundary, as the faces run
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    if (mesh.oppositeCorner[c] < 0) next[mesh.vertex(TriMesh::next(c))] = mesh.vertex(TriMesh::prev(c));
  std::vector<char> seen(n, 0);
  for (int v = 0; v < n; ++v) {
    if (next[v] < 0 || seen[v]) continue;
    double length = 0;
    int u = v;
    for (; u >= 0 && !seen[u]; u = next[u]) {
      seen[u] = 1;
      if (next[u] >= 0) length += (mesh.positions[next[u]] - mesh.positions[u]).norm();
    }
    if (u != v || !(length < maxLength)) continue;
    for (int w = v; loop[w] < 0; w = next[w]) loop[w] = v;
  }
  return loop;
}

/// Moves the free vertices of the output, one at a time, on the input surface.
class Relaxer {
 public:
  Relaxer(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input, const SurfaceWalker& walker,
          double maxDeviation, double aim, const std::vector<char>& watched, const std::vector<double>* density,
          double tinyLoopLength)
      : output_(output),
        pos_(output.positions),
        points_(points),
        input_(input),
        density_(density),
        walker_(walker),
        maxDeviation_(maxDeviation),
        aim_(aim),
        watched_(watched),
        tinyLoop_(tinyBoundaryLoops(output, tinyLoopLength * output.meanEdgeLength())) {}

  /// The faces with a watched corner, which a watched vertex's faces may not cross (collected
  /// again each round: the flips change the faces).
  /// Before each round: the step aim from the mesh's smallest angle, the watched faces.
  void startRound() {
    stepAim_ = std::max(kSmallAngle, smallestAngleOf(output_) + kStepMargin);
    collectWatchedFaces();
  }
  void collectWatchedFaces() {
    watchedFaces_.clear();
    if (watched_.empty()) return;
    for (int f = 0; f < output_.faceCount(); ++f) {
      const Tri& t = output_.triangles[f];
      if (watched_[t[0]] || watched_[t[1]] || watched_[t[2]]) watchedFaces_.push_back(f);
    }
  }

  /// A round of relaxation: startRound, then each vertex not fixed moves toward its ring's mean
  /// (relaxAlongCurve on a feature curve, else relaxVertex).
  void meanRound(const std::vector<char>& fixed, const std::vector<Freedom>& freedom) {
    startRound();
    for (int v = 0; v < output_.vertexCount(); ++v)
      if (fixed[v])
        continue;
      else if (freedom[v] == Freedom::Curve)
        relaxAlongCurve(v);
      else
        relaxVertex(v);
  }

  /// Moves v toward the mean of its neighbours in its tangent plane, if that does not lower the
  /// smallest angle of its ring; then tries steps in eight tangent directions that raise it.
  void relaxVertex(int v) {
    const Vec3 p = pos_[v];
    Vec3 centre = Vec3::Zero();
    double weights = 0;
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      const int n = output_.vertex(TriMesh::next(*c));
      const double w = density_ ? interpolate(input_, points_[n], *density_) : 1.0;
      centre += w * pos_[n];  // each neighbour once: it is `next` in exactly one face of a closed fan
      weights += w;
    }
    if (!(weights > 0.0)) return;
    centre /= weights;
    const double ringLength = meanRingLength(v);
    const double maxAway = maxDeviation_ * ringLength;
    const int face = walker_.faceOf(points_[v]);
    const Vec3 normal = tangentNormal(v, face);
    if (normal.isZero()) return;
    Vec3 move = centre - p;
    move -= normal * normal.dot(move);
    const double before = ring(v, p, nullptr);
    double smallest = tryMove(v, p + move, face, before, maxAway);
    // A watched vertex whose move would make faces cross tries half and a quarter of it.
    for (double part = 0.5; refusedLast_ && part >= 0.25; part *= 0.5)
      smallest = tryMove(v, p + part * move, face, before, maxAway);
    if (smallest >= std::min(aim_, stepAim_)) return;
    // Under 30 degrees a bad triangle costs more than the error: no deviation limit then.
    const double stepAway =
        smallest >= kSmallAngle ? kStepDeviation * maxAway : std::numeric_limits<double>::infinity();
    tryTangentSteps(v, normal, ringLength, smallest, stepAway);
  }

  /// A vertex on a feature curve of the input: the step along the curve, both ways, that most
  /// raises the smallest angle of its ring (where tangent steps are tried: stepAim_). In the
  /// polish (`polishing`), finer steps too, and only steps that raise it by kPolishGain without
  /// adding a face under 30 degrees.
  void relaxAlongCurve(int v, bool polishing = false) {
    CurvePoint at;
    if (freedomOf(points_[v], walker_, at) != Freedom::Curve) return;
    const double before = ring(v, pos_[v], nullptr);
    if (!polishing && before >= std::min(aim_, stepAim_)) return;
    const int under = polishing ? ringFacesUnder30(v, pos_[v]) : 0;
    const double ringLength = meanRingLength(v);
    std::vector<std::pair<double, SurfacePoint>> better;  // (smallest angle there, point), best first
    for (const double step : {0.4, 0.2, 0.1, 0.05, 0.025, 0.0125}) {
      if (!polishing && step < 0.05) break;
      for (const double sign : {-1.0, 1.0}) {
        const CurvePoint to = slide(at, sign * step * ringLength, walker_);
        const SurfacePoint q = walker_.onInputEdge(to.a, to.b, to.t);
        const Vec3 x = walker_.pointOf(q.face, q.bary);
        const double s = ring(v, x, nullptr);
        if (polishing && !(s > before + kPolishGain && ringFacesUnder30(v, x) <= under)) continue;
        if (s > before) better.push_back({s, q});
      }
    }
    std::stable_sort(better.begin(), better.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    const int movesBefore = moves_;
    const double maxAway = maxDeviation_ * ringLength;
    std::vector<std::pair<Vec3, double>> curveNear;  // curveNearby, found for the first candidate
    for (const auto& [s, q] : better) {
      if (curveNear.empty()) curveNear = curveNearby(v, at, ringLength);
      if (!keepsCurve(v, curveNear, walker_.pointOf(q.face, q.bary), maxAway)) continue;
      tryMoveTo(v, q, before, maxAway);
      if (moves_ > movesBefore) break;
    }
  }

  /// The polish (RelaxationParams::polishMarginDegrees): free vertices taken worst first, by
  /// their ring's smallest angle, while it is under max(30 degrees, the first one's + margin);
  /// each climbs (ascend, or along its curve) and, if it moved, it and its neighbours are taken
  /// again. A vertex that cannot climb waits until a neighbour moves. Returns the vertices moved.
  int polish(const std::vector<char>& fixed, const std::vector<Freedom>& freedom, double margin) {
    using Item = std::pair<double, int>;  // (ring's smallest angle, vertex)
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    const int n = output_.vertexCount();
    std::vector<double> queued(n, -1.0);  // the value v was last queued with; -1: not queued
    const auto enqueue = [&](int u) {
      if (fixed[u] || output_.valence(u) == 0) return;
      queued[u] = ring(u, pos_[u], nullptr);
      queue.push({queued[u], u});
    };
    for (int v = 0; v < n; ++v) enqueue(v);
    if (anchor_.empty()) anchor_ = pos_;
    const long maxMoves = long(kPolishMovesPerVertex) * n;
    int moved = 0;
    while (!queue.empty() && polishMoves_ < maxMoves) {
      const auto [value, v] = queue.top();
      queue.pop();
      if (value != queued[v]) continue;  // queued again since, or waiting
      queued[v] = -1.0;
      if (polishAim_ < 0) polishAim_ = std::max(kSmallAngle, value + margin);
      if (value >= polishAim_) break;
      const int movesBefore = moves_;
      bool climbed = false;  // then it and its neighbours are taken again
      if (freedom[v] == Freedom::Curve) {
        relaxAlongCurve(v, true);
        climbed = moves_ > movesBefore;
      } else {
        climbed = ascend(v) > 0;
      }
      if (!climbed) continue;
      ++moved;
      ++polishMoves_;
      enqueue(v);
      for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c)
        enqueue(output_.vertex(TriMesh::next(*c)));
    }
    return moved;
  }

  /// The polish's flips with climbs: the edges of the worst face flipped in turn (flipOneEdge,
  /// creases up to featureAngleDegrees), then the quad's corners and their neighbours climb
  /// (ascend, kFlipClimbSweeps times over). A flip is kept if the smallest angle of the faces
  /// around the quad rises (by kStepGain), their faces under 30 degrees do not grow in number and
  /// the input under the edge flipped away stays near them (kFlipDeviation); else the flip and
  /// the moves are undone. The Delaunay flips and the ascents alone stop at such local tops
  /// (valences 5 and 8 side by side: knot2 at 30%, 33.7 -> 36.7 degrees). Then again from the new
  /// worst face, until its three flips all fail, kFlipClimbTries at most. Cost per try: O(F) to
  /// find the worst face and to rebuild the vertex lists after each flip and undo.
  /// Returns the flips kept.
  int flipAndClimb(const std::vector<char>& fixed, const std::vector<Freedom>& freedom, double featureAngleDegrees) {
    if (anchor_.empty()) anchor_ = pos_;
    int kept = 0;
    for (int tries = 0; tries < kFlipClimbTries; ++tries) {
      const int f = worstFace();
      bool better = false;
      for (int k = 0; k < 3 && !better; ++k)
        better = tryFlipAndClimb(3 * f + k, fixed, freedom, featureAngleDegrees, -1.0);
      if (!better) break;
      ++kept;
    }
    polishMoves_ += kept;
    return kept;
  }

  /// The polish's joint moves: the worst face's free vertices move together (jointMove), then
  /// again from the new worst face, until a move fails, kJointTries at most. One vertex at a time,
  /// the climbs stop where two faces hold the smallest angle and each move of one vertex lowers
  /// one of them. Returns the moves kept.
  int jointClimbs(const std::vector<char>& fixed, const std::vector<Freedom>& freedom) {
    anchor_ = pos_;
    int kept = 0;
    for (int tries = 0; tries < kJointTries && jointMove(worstFace(), fixed, freedom); ++tries) ++kept;
    polishMoves_ += kept;
    return kept;
  }

  /// A free vertex's candidate places for a joint move: along its curve both ways, or on the
  /// input in eight tangent directions, `step` ring lengths away.
  std::vector<std::pair<Vec3, SurfacePoint>> jointCandidates(int v, Freedom freedom, double step) const {
    std::vector<std::pair<Vec3, SurfacePoint>> out;
    const double length = step * meanRingLength(v);
    CurvePoint at;
    if (freedom == Freedom::Curve && freedomOf(points_[v], walker_, at) == Freedom::Curve) {
      for (const double sign : {-1.0, 1.0}) {
        const CurvePoint to = slide(at, sign * length, walker_);
        const SurfacePoint q = walker_.onInputEdge(to.a, to.b, to.t);
        out.push_back({walker_.pointOf(q.face, q.bary), q});
      }
      return out;
    }
    const int face = walker_.faceOf(points_[v]);
    const Vec3 normal = tangentNormal(v, face);
    if (normal.isZero()) return out;
    const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
    for (int k = 0; k < 8; ++k) {
      const SurfacePoint q =
          walker_.project(pos_[v] + length * (std::cos(k * kPi / 4) * e1 + std::sin(k * kPi / 4) * e2), face);
      out.push_back({walker_.pointOf(q.face, q.bary), q});
    }
    return out;
  }

  /// One joint move of face f's free vertices (two or three): every combination of their
  /// candidates (jointCandidates, each vertex staying or moving) at steps of 0.2 ring lengths
  /// halved down to kJointSmallestStep; the first step with a combination that raises the
  /// smallest angle of the faces around them by kStepGain, without more faces under 30 degrees,
  /// a face turned over, a face crossing another or, from 30 degrees up, a vertex's starting
  /// point farther than maxDeviation from its fan, or its curve's farthest point farther than
  /// both maxDeviation and before, takes the best. Whether it moved.
  bool jointMove(int f, const std::vector<char>& fixed, const std::vector<Freedom>& freedom) {
    std::vector<int> movers;
    for (const int v : output_.triangles[f])
      if (!fixed[v] && output_.valence(v) > 0 && freedom[v] != Freedom::None) movers.push_back(v);
    if (movers.size() < 2) return false;
    // The faces around the movers (the last one twice when there are two), as they are now.
    const std::pair<double, int> before = aroundVertices({movers[0], movers[1], movers.back(), movers.back()});
    const std::vector<int> faces = faces_;
    std::vector<Vec3> normals;
    for (const int g : faces) normals.push_back(faceNormal(g));
    std::vector<std::pair<Vec3, SurfacePoint>> start;
    std::vector<std::vector<std::pair<Vec3, double>>> curveNear(movers.size());
    for (size_t i = 0; i < movers.size(); ++i) {
      start.push_back({pos_[movers[i]], points_[movers[i]]});
      CurvePoint at;
      if (freedom[movers[i]] == Freedom::Curve && freedomOf(points_[movers[i]], walker_, at) == Freedom::Curve)
        curveNear[i] = curveNearby(movers[i], at, meanRingLength(movers[i]));
    }
    for (double step = 0.2; step >= kJointSmallestStep; step *= 0.5) {
      std::vector<std::vector<std::pair<Vec3, SurfacePoint>>> options;
      for (const int v : movers) {
        options.push_back(jointCandidates(v, freedom[v], step));
        options.back().insert(options.back().begin(), {pos_[v], points_[v]});  // staying
      }
      // Every combination, scored; the best that passes the checks is kept.
      std::vector<std::pair<double, std::vector<int>>> scored;
      std::vector<int> pick(movers.size(), 0);
      while (true) {
        size_t i = 0;
        for (; i < pick.size() && ++pick[i] == static_cast<int>(options[i].size()); ++i) pick[i] = 0;
        if (i == pick.size()) break;  // back to all staying: done
        for (size_t k = 0; k < movers.size(); ++k) pos_[movers[k]] = options[k][pick[k]].first;
        const std::pair<double, int> after = smallestOfFaces(faces);
        if (after.first > before.first + kStepGain && after.second <= before.second)
          scored.push_back({after.first, pick});
      }
      for (size_t k = 0; k < movers.size(); ++k) pos_[movers[k]] = start[k].first;
      std::stable_sort(scored.begin(), scored.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
      for (const auto& [smallest, chosen] : scored) {
        for (size_t k = 0; k < movers.size(); ++k) {
          pos_[movers[k]] = options[k][chosen[k]].first;
          points_[movers[k]] = options[k][chosen[k]].second;
        }
        if (jointMoveAllowed(movers, faces, normals, start, curveNear, smallest)) {
          moves_ += static_cast<int>(movers.size());
          return true;
        }
        for (size_t k = 0; k < movers.size(); ++k)
          pos_[movers[k]] = start[k].first, points_[movers[k]] = start[k].second;
      }
    }
    return false;
  }

  /// jointMove's checks of the movers where they are now (see there).
  bool jointMoveAllowed(const std::vector<int>& movers, const std::vector<int>& faces, const std::vector<Vec3>& normals,
                        const std::vector<std::pair<Vec3, SurfacePoint>>& start,
                        const std::vector<std::vector<std::pair<Vec3, double>>>& curveNear, double smallest) {
    for (size_t k = 0; k < faces.size(); ++k) {
      const Vec3 n = faceNormal(faces[k]);
      if (!(n.dot(normals[k]) > 0)) return false;
    }
    if (smallest >= kSmallAngle)
      for (size_t k = 0; k < movers.size(); ++k) {
        const int v = movers[k];
        const double maxAway = maxDeviation_ * meanRingLength(v);
        if (fanDistance(v, pos_[v], anchor_[v]) > maxAway || fanDistance(v, pos_[v], start[k].first) > maxAway)
          return false;
        // The curve's farthest point from the faces, not each point: two vertices sliding together
        // move their edge's chord along the curve, nearer some points and farther from others.
        double was = maxAway, is = 0;
        for (const auto& [x, now] : curveNear[k]) {
          was = std::max(was, now);
          is = std::max(is, fanDistance(v, pos_[v], x));
        }
        if (is > was) return false;
      }
    faces_ = faces;
    return !facesCrossAround();
  }

  /// A face's normal (not unit).
  Vec3 faceNormal(int f) const {
    const Tri& t = output_.triangles[f];
    return (pos_[t[1]] - pos_[t[0]]).cross(pos_[t[2]] - pos_[t[0]]);
  }

  /// Smallest angle (radians) of `faces` and how many have one under 30 degrees.
  std::pair<double, int> smallestOfFaces(const std::vector<int>& faces) const {
    double largestCosine = -1;
    int under = 0;
    for (const int f : faces) {
      const Tri& t = output_.triangles[f];
      const double c = smallestAngleCosine(pos_[t[0]], pos_[t[1]], pos_[t[2]]);
      largestCosine = std::max(largestCosine, c);
      under += c > kCos30;
    }
    return {std::acos(largestCosine), under};
  }

  /// The polish's second part's flips with climbs: each face with an angle under 30 degrees has
  /// its edges flipped in turn as flipAndClimb does, and a flip is kept if the faces around the
  /// quad under 30 degrees fall in number, none of them under `floor` (the mesh's smallest: never
  /// lowered) and no face crossing another; kFlipUnder30Tries tries at most. Returns the flips kept.
  int flipAndClimbUnder30(const std::vector<char>& fixed, const std::vector<Freedom>& freedom,
                          double featureAngleDegrees, double floor) {
    int kept = 0, tries = 0;
    for (int f = 0; f < output_.faceCount() && tries < kFlipUnder30Tries; ++f)
      for (int k = 0; k < 3 && tries < kFlipUnder30Tries; ++k) {
        const Tri& t = output_.triangles[f];  // flips keep face indices: f may be a new face
        if (smallestAngleCosine(pos_[t[0]], pos_[t[1]], pos_[t[2]]) <= kCos30) break;
        ++tries;
        if (tryFlipAndClimb(3 * f + k, fixed, freedom, featureAngleDegrees, floor)) ++kept;
      }
    polishMoves_ += kept;
    return kept;
  }

  /// The two-sided distance from an output (with its points on the input) to the input.
  using DistanceToInput = std::function<double(const TriMesh&, const std::vector<SurfacePoint>&)>;

  /// The polish's valence batches (kValenceBatches) in turn, each by valenceFlipsAndClimbs;
  /// returns the flips kept.
  Expected<int> valenceBatches(const std::vector<char>& fixed, const std::vector<Freedom>& freedom,
                               double featureAngleDegrees, double margin, const DistanceToInput& distance) {
    int kept = 0;
    double known = -1;  // the distance of the output as it is, once measured
    for (const ValenceBatch& batch : kValenceBatches) {
      const Expected<int> flips =
          valenceFlipsAndClimbs(fixed, freedom, featureAngleDegrees, margin, batch, distance, known);
      if (!flips) return flips;
      kept += *flips;
    }
    return kept;
  }

  /// One batch of the polish's valence flips (valenceFlipsAndClimbs).
  struct ValenceBatch {
    double slack;    ///< the new faces keep at least the mesh's smallest angle minus this (radians)
    int meanRounds;  ///< rounds of moves toward the rings' means (meanRound) after the flips
    bool measured;   ///< kept only if the distance to the input does not grow (`distance` given)
    double sliver;   ///< flips that leave a face under this (radians) undo the batch before the climbs
  };

  /// The output as it was before a batch (valenceFlipsAndClimbs) that is not kept.
  void restore(const TriMesh& saved, const std::vector<SurfacePoint>& savedPoints, int savedMoves) {
    output_ = saved;  // pos_ is output_.positions: the same vector, refilled
    points_ = savedPoints;
    polishMoves_ = savedMoves;
  }

  /// The polish's valence flips: flips toward valence 6 (flipTowardValenceSix, creases up to
  /// featureAngleDegrees, new faces down to the mesh's smallest angle minus batch.slack, the
  /// input near the faces: keepsInputNear; undone at once if they leave a face under
  /// batch.sliver), then batch.meanRounds rounds of moves toward the
  /// rings' means, the climbs (polish, with `margin`) and flipAndClimb, all as one batch: kept if
  /// the mesh's smallest angle rises, its faces under 30 degrees do not grow in number, no face
  /// changed crosses another and, for a measured batch, `distance` does not grow; else all
  /// undone. A measured batch without `distance` is not tried. `known`: the distance before, or
  /// negative if not measured yet; updated. The max-min climbs keep the connectivity of the
  /// farthest-point samples' Delaunay triangulation, whose valences spread from 4 to 8 (knot1 at
  /// 30%: mean squared excess over 6 of 0.75, CGAL's isotropic remeshing 0.31). Returns the flips
  /// kept.
  Expected<int> valenceFlipsAndClimbs(const std::vector<char>& fixed, const std::vector<Freedom>& freedom,
                                      double featureAngleDegrees, double margin, const ValenceBatch& batch,
                                      const DistanceToInput& distance, double& known) {
    if (batch.measured && !distance) return 0;
    const TriMesh saved = output_;
    const std::vector<SurfacePoint> savedPoints = points_;
    const int savedMoves = polishMoves_;
    const double smallest = smallestAngleOf(output_);
    const int under = facesUnder30();
    ValenceFlipParams params;
    params.minAngleDegrees = std::max(0.0, (smallest - batch.slack) / kDegree);
    params.featureAngleDegrees = featureAngleDegrees;
    params.accept = [&](int corner) { return keepsInputNear(corner); };
    const Expected<DelaunayFlipResult> flipped = flipTowardValenceSix(output_, params);
    if (!flipped) return flipped.status();
    if (flipped->flips == 0) return 0;
    if (smallestAngleOf(output_) < batch.sliver) {
      restore(saved, savedPoints, savedMoves);
      return 0;
    }
    for (int round = 0; round < batch.meanRounds; ++round) meanRound(fixed, freedom);
    polish(fixed, freedom, margin);
    const int climbed = flipAndClimb(fixed, freedom, featureAngleDegrees);
    // The cheap checks first: a distance costs about as much as a climb of every vertex.
    bool kept = smallestAngleOf(output_) > smallest + kStepGain && facesUnder30() <= under;
    double after = -1;
    if (kept && batch.measured) {
      if (known < 0) known = distance(saved, savedPoints);
      after = distance(output_, points_);
      kept = after <= known;
    }
    if (kept && !crossesSince(saved)) {
      known = after;  // negative (not measured) after an unmeasured batch
      return flipped->flips + climbed;
    }
    restore(saved, savedPoints, savedMoves);
    return 0;
  }

  /// Faces with an angle under 30 degrees.
  int facesUnder30() const {
    int n = 0;
    for (const Tri& t : output_.triangles) n += smallestAngleCosine(pos_[t[0]], pos_[t[1]], pos_[t[2]]) > kCos30;
    return n;
  }

  /// Whether the faces that differ from `before`'s (other corners, or a corner moved) cross any face.
  bool crossesSince(const TriMesh& before) {
    flagged_.assign(output_.faceCount(), 0);
    for (int f = 0; f < output_.faceCount(); ++f) {
      const Tri& t = output_.triangles[f];
      flagged_[f] = t != before.triangles[f] || pos_[t[0]] != before.positions[t[0]] ||
                    pos_[t[1]] != before.positions[t[1]] || pos_[t[2]] != before.positions[t[2]];
    }
    return !crossingsOfFaces(output_, flagged_).empty();
  }

  /// Whether flipping the edge facing `corner` keeps the input near the faces: the input's points
  /// under the middles of the edge and of the new one each end within flipLimit of the new faces,
  /// or no farther than from the old.
  bool keepsInputNear(int corner) const {
    const int o = output_.oppositeCorner[corner];
    const int x = output_.vertex(corner), a = output_.vertex(TriMesh::next(corner));
    const int b = output_.vertex(TriMesh::prev(corner)), y = output_.vertex(o);
    const double limit = flipLimit(a, b);
    const auto distance = [&](const Vec3& p, int u, int v, int w, int z) {  // to faces (u, v, w), (u, w, z)
      return std::sqrt(std::min(squaredDistanceToTriangle(p, pos_[u], pos_[v], pos_[w]),
                                squaredDistanceToTriangle(p, pos_[u], pos_[w], pos_[z])));
    };
    for (const auto& [p, q] : {std::pair<int, int>{a, b}, std::pair<int, int>{x, y}}) {
      const Vec3 m = inputUnderMiddle(p, q);
      // Old faces (x, a, b), (y, b, a) as (a, y, b), (a, b, x); new (x, a, y), (x, y, b).
      const double before = distance(m, a, y, b, x), after = distance(m, x, a, y, b);
      if (after > std::max(before, limit)) return false;
    }
    return true;
  }

  /// The input's point nearest the middle of output edge (p, q): on a ridge, a flip of the edge
  /// cuts it off.
  Vec3 inputUnderMiddle(int p, int q) const {
    const SurfacePoint below = walker_.project(0.5 * (pos_[p] + pos_[q]), walker_.faceOf(points_[p]));
    return walker_.pointOf(below.face, below.bary);
  }

  /// How far a flip of edge (a, b) may leave the input under its middle from the faces in any
  /// case: kFlipDeviation times maxDeviation times the edge's length.
  double flipLimit(int a, int b) const { return kFlipDeviation * maxDeviation_ * (pos_[a] - pos_[b]).norm(); }

  /// The face with the smallest angle.
  int worstFace() const {
    int worst = 0;
    double largestCosine = -2;
    for (int f = 0; f < output_.faceCount(); ++f) {
      const Tri& t = output_.triangles[f];
      const double c = smallestAngleCosine(pos_[t[0]], pos_[t[1]], pos_[t[2]]);
      if (c > largestCosine) largestCosine = c, worst = f;
    }
    return worst;
  }

  /// Smallest angle (radians) of the faces around `vertices`, and how many have one under 30 degrees.
  std::pair<double, int> aroundVertices(const std::array<int, 4>& vertices) {
    faces_.clear();
    for (const int v : vertices)
      for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) faces_.push_back(TriMesh::face(*c));
    std::sort(faces_.begin(), faces_.end());
    faces_.erase(std::unique(faces_.begin(), faces_.end()), faces_.end());
    return smallestOfFaces(faces_);
  }

  /// Distance from x to the faces of faces_ (aroundVertices').
  double facesDistance(const Vec3& x) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const int f : faces_) {
      const Tri& t = output_.triangles[f];
      nearest = std::min(nearest, squaredDistanceToTriangle(x, pos_[t[0]], pos_[t[1]], pos_[t[2]]));
    }
    return std::sqrt(nearest);
  }

  /// flipAndClimb's try of the edge facing `corner` (`floor` negative), or flipAndClimbUnder30's
  /// (`floor` its smallest angle allowed, radians); whether it is kept.
  bool tryFlipAndClimb(int corner, const std::vector<char>& fixed, const std::vector<Freedom>& freedom,
                       double featureAngleDegrees, double floor) {
    const int o = output_.oppositeCorner[corner];
    if (o < 0) return false;
    const std::array<int, 4> quad = {output_.vertex(corner), output_.vertex(TriMesh::next(corner)),
                                     output_.vertex(TriMesh::prev(corner)), output_.vertex(o)};
    const std::pair<double, int> before = aroundVertices(quad);
    // The input under the middle of the edge flipped away, and its distance to the faces now.
    const Vec3 middle = inputUnderMiddle(quad[1], quad[2]);
    const double maxAway = std::max(facesDistance(middle), flipLimit(quad[1], quad[2]));
    const int back = flipOneEdge(output_, corner, featureAngleDegrees);
    if (back < 0) return false;
    climbers_.clear();
    for (const int v : quad) {
      climbers_.push_back(v);
      for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c)
        climbers_.push_back(output_.vertex(TriMesh::next(*c)));
    }
    std::sort(climbers_.begin(), climbers_.end());
    climbers_.erase(std::unique(climbers_.begin(), climbers_.end()), climbers_.end());
    saved_.clear();
    for (const int v : climbers_) saved_.push_back({pos_[v], points_[v]});
    for (int sweep = 0; sweep < kFlipClimbSweeps; ++sweep)
      for (const int v : climbers_)
        if (!fixed[v] && freedom[v] == Freedom::Surface) ascend(v);
    const std::pair<double, int> after = aroundVertices(quad);
    const bool better = floor < 0 ? after.first > before.first + kStepGain && after.second <= before.second
                                  : after.second < before.second && after.first >= floor && !facesCrossAround();
    if (better && facesDistance(middle) <= maxAway) return true;
    for (size_t k = 0; k < climbers_.size(); ++k)
      pos_[climbers_[k]] = saved_[k].first, points_[climbers_[k]] = saved_[k].second;
    flipOneEdge(output_, back, -1);
    return false;
  }

  /// Whether a face of faces_ (aroundVertices') crosses another face.
  bool facesCrossAround() {
    flagged_.assign(output_.faceCount(), 0);
    for (const int f : faces_) flagged_[f] = 1;
    return !crossingsOfFaces(output_, flagged_).empty();
  }

  /// An ascent step: a unit tangent direction and a length.
  struct AscentStep {
    Vec3 direction = Vec3::Zero();
    double length = 0;
  };

  /// Steepest ascent of the smallest angle of v's ring, on the input. Each step: the direction
  /// that raises every angle within a band of the smallest (the point of their gradients' convex
  /// hull nearest the origin; none if the hull holds it), a length where the angles' linear
  /// models say the smallest is largest, halved until the point projected on the input raises it
  /// without adding a face under 30 degrees; the band is 1 degree, narrowed by 4 down to 0.01
  /// while no step is found (angles near the smallest can pull apart). The point v started the
  /// polish from must stay within maxDeviation of its fan (from 30 degrees up). Returns the gain.
  double ascend(int v) {
    const double ringLength = meanRingLength(v);
    const double maxAway = maxDeviation_ * ringLength;
    const double start = ring(v, pos_[v], nullptr);
    for (int iteration = 0; iteration < kAscentIterations; ++iteration) {
      const int face = walker_.faceOf(points_[v]);
      const Vec3 normal = tangentNormal(v, face);
      if (normal.isZero()) break;
      const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
      const double before = angleGradients(v, e1, e2, ringLength);
      const double away = before >= kSmallAngle ? maxAway : std::numeric_limits<double>::infinity();
      bool stepped = false;
      for (double band = kActiveBand; band > kNarrowestBand && !stepped; band *= 0.25) {
        const AscentStep step = ascentStep(before, band, e1, e2, ringLength);
        if (step.length > 0) stepped = tryAscentStep(v, face, step, before, away, ringLength);
        if (refusedLast_) return ring(v, pos_[v], nullptr) - start;  // the move would make faces cross
      }
      if (!stepped) break;
    }
    return ring(v, pos_[v], nullptr) - start;
  }

  /// Moves v along `step` (halving it until it raises the ring's smallest angle above `before`
  /// without adding a face under 30 degrees); whether it moved.
  bool tryAscentStep(int v, int face, const AscentStep& step, double before, double away, double ringLength) {
    const Vec3 p = pos_[v];
    const int under = ringFacesUnder30(v, p);
    const int movesBefore = moves_;
    for (double t = step.length; t > kSmallestStep * ringLength && moves_ == movesBefore; t *= 0.5) {
      const SurfacePoint moved = walker_.project(p + t * step.direction, face);
      const Vec3 q = walker_.pointOf(moved.face, moved.bary);
      if (!(ring(v, q, nullptr) > before + kStepGain) || ringFacesUnder30(v, q) > under) continue;
      if (fanDistance(v, q, anchor_[v]) > away) continue;
      tryMoveTo(v, moved, before, away);
      if (refusedLast_) return false;
    }
    return moves_ > movesBefore;
  }

  /// The angles of v's ring (angles_[0]) and their gradients in the tangent plane (e1, e2) by
  /// finite differences (gradients_); returns the smallest.
  double angleGradients(int v, const Vec3& e1, const Vec3& e2, double ringLength) {
    const Vec3 p = pos_[v];
    const double h = kGradientStep * ringLength;
    ringAngles(v, p, angles_[0]);
    ringAngles(v, p + h * e1, angles_[1]);
    ringAngles(v, p + h * e2, angles_[2]);
    gradients_.clear();
    for (size_t i = 0; i < angles_[0].size(); ++i)
      gradients_.emplace_back((angles_[1][i] - angles_[0][i]) / h, (angles_[2][i] - angles_[0][i]) / h);
    return *std::min_element(angles_[0].begin(), angles_[0].end());
  }

  /// ascentStep's for the angles within `band` of the smallest, from the angles and gradients of
  /// angleGradients; length 0 if no direction raises them.
  AscentStep ascentStep(double smallest, double band, const Vec3& e1, const Vec3& e2, double ringLength) {
    AscentStep step;
    active_.clear();
    for (size_t i = 0; i < angles_[0].size(); ++i)
      if (angles_[0][i] < smallest + band) active_.push_back(gradients_[i]);
    const Eigen::Vector2d d = nearestToOrigin(active_);
    if (!(d.norm() > kStationary)) return step;
    const Eigen::Vector2d u = d.normalized();
    // The smallest of the angles' linear models along u is concave in the step: golden sections.
    const auto model = [&](double t) {
      double lowest = kPi;
      for (size_t i = 0; i < angles_[0].size(); ++i)
        lowest = std::min(lowest, angles_[0][i] + t * gradients_[i].dot(u));
      return lowest;
    };
    double lo = 0, hi = kMaxPolishStep * ringLength;
    for (int k = 0; k < kGoldenSections; ++k) {
      const double t1 = lo + (1 - kGolden) * (hi - lo), t2 = lo + kGolden * (hi - lo);
      if (model(t1) < model(t2))
        lo = t1;
      else
        hi = t2;
    }
    step.direction = u[0] * e1 + u[1] * e2;
    step.length = 0.5 * (lo + hi);
    return step;
  }

  /// The point of the convex hull of the 2D vectors `g` nearest the origin (zero if the hull
  /// holds it): a vector, or the foot on a segment between two, that no vector lies behind.
  static Eigen::Vector2d nearestToOrigin(const std::vector<Eigen::Vector2d>& g) {
    Eigen::Vector2d best = Eigen::Vector2d::Zero();
    double bestNorm = std::numeric_limits<double>::infinity();
    const auto consider = [&](const Eigen::Vector2d& d) {
      const double n2 = d.squaredNorm();
      if (n2 >= bestNorm) return;
      for (const Eigen::Vector2d& x : g)
        if (x.dot(d) < n2 * (1 - 1e-9)) return;
      best = d;
      bestNorm = n2;
    };
    for (size_t i = 0; i < g.size(); ++i) {
      consider(g[i]);
      for (size_t j = i + 1; j < g.size(); ++j) {
        const Eigen::Vector2d e = g[j] - g[i];
        const double t = e.squaredNorm() > 0 ? -g[i].dot(e) / e.squaredNorm() : 0.0;
        if (t > 0 && t < 1) consider(g[i] + t * e);
      }
    }
    return best;
  }

  /// The three angles of each face around v with v at x (radians), into `out`; the angle at v
  /// left out where it faces the edge of a tiny loop (facesTinyLoop).
  void ringAngles(int v, const Vec3& x, std::vector<double>& out) const {
    out.clear();
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      const int ia = output_.vertex(TriMesh::next(*c)), ib = output_.vertex(TriMesh::prev(*c));
      const Vec3& a = pos_[ia];
      const Vec3& b = pos_[ib];
      if (!facesTinyLoop(ia, ib)) out.push_back(angleAt(x, a, b));
      out.push_back(angleAt(a, x, b));
      out.push_back(angleAt(b, x, a));
    }
  }

  /// The faces around v with v at x that have an angle under 30 degrees.
  int ringFacesUnder30(int v, const Vec3& x) const {
    int n = 0;
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c)
      n += smallestAngleCosine(x, pos_[output_.vertex(TriMesh::next(*c))], pos_[output_.vertex(TriMesh::prev(*c))]) >
           kCos30;
    return n;
  }

  /// Mean length of v's edges.
  double meanRingLength(int v) const {
    double length = 0;
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c)
      length += (pos_[output_.vertex(TriMesh::next(*c))] - pos_[v]).norm();
    return length / output_.valence(v);
  }

  /// The normal of v's tangent plane: its output ring's, unless the ring is folded against the
  /// input face it lies in (zero if that face is degenerate).
  Vec3 tangentNormal(int v, int face) const {
    const Vec3 normal = walker_.normal(face);
    if (normal.isZero()) return normal;
    Vec3 ringNormal = Vec3::Zero();
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c)
      ringNormal +=
          (pos_[output_.vertex(TriMesh::next(*c))] - pos_[v]).cross(pos_[output_.vertex(TriMesh::prev(*c))] - pos_[v]);
    return ringNormal.dot(normal) > 0.5 * ringNormal.norm() ? Vec3(ringNormal.normalized()) : normal;
  }

  int polishMoves() const { return polishMoves_; }

  /// The polish's second part: each free vertex off the feature curves whose ring has faces under
  /// 30 degrees moves to the point, of 16 directions at 4 lengths, where its ring has the fewest
  /// (then the largest smallest angle), if fewer than now and its smallest angle stays at least
  /// `floor` (the mesh's smallest: never lowered). No deviation limit, as for the relaxation's
  /// steps under 30 degrees. Returns the vertices moved.
  int fewerUnder30(const std::vector<char>& fixed, const std::vector<Freedom>& freedom, double floor) {
    int moved = 0;
    for (int v = 0; v < output_.vertexCount(); ++v) {
      if (fixed[v] || freedom[v] != Freedom::Surface || output_.valence(v) == 0) continue;
      const int under = ringFacesUnder30(v, pos_[v]);
      if (under == 0) continue;
      const int face = walker_.faceOf(points_[v]);
      const Vec3 normal = tangentNormal(v, face);
      if (normal.isZero()) continue;
      const Vec3 e1 = normal.unitOrthogonal(), e2 = normal.cross(e1);
      const double ringLength = meanRingLength(v);
      const Vec3 p = pos_[v];
      std::pair<int, double> best{under, -1.0};  // (faces under 30 degrees, smallest angle)
      SurfacePoint to;
      for (const double step : {0.3, 0.15, 0.075, 0.0375})
        for (int k = 0; k < 16; ++k) {
          const double turn = k * kPi / 8;
          const SurfacePoint q =
              walker_.project(p + step * ringLength * (std::cos(turn) * e1 + std::sin(turn) * e2), face);
          const Vec3 x = walker_.pointOf(q.face, q.bary);
          const std::pair<int, double> there{ringFacesUnder30(v, x), ring(v, x, nullptr)};
          if (there.second < floor || there.first >= under) continue;
          if (there.first < best.first || (there.first == best.first && there.second > best.second)) {
            best = there;
            to = q;
          }
        }
      if (best.first == under) continue;
      const int movesBefore = moves_;
      tryMoveTo(v, to, floor, std::numeric_limits<double>::infinity(), floor);
      moved += moves_ > movesBefore;
    }
    polishMoves_ += moved;
    return moved;
  }

  int moves() const { return moves_; }
  int refusedCrossing() const { return refusedCrossing_; }
  static constexpr double kSmallAngle = 30.0 * kDegree;  ///< under it, tangent steps have no deviation limit

 private:
  /// Tangent steps are tried where the ring's smallest angle is under 30 degrees or within this
  /// of the mesh's smallest: the smallest angle is raised where it is, at a fraction of the cost
  /// of steps everywhere (bunny00 at 10%: 22 ms against 200 for the relaxation, for 34 deg
  /// against 38 deg).
  static constexpr double kStepMargin = 3.0 * kDegree;
  double stepAim_ = kPi;                         ///< this round's: steps where the ring's smallest angle is under it
  static constexpr double kStepDeviation = 2.0;  ///< tangent steps' deviation limit, in maxDeviation

  // The polish.
  static constexpr double kPolishGain = 0.05 * kDegree;     ///< a move must raise the ring's smallest angle by this
  static constexpr double kStepGain = 0.01 * kDegree;       ///< each ascent step must raise it by this
  static constexpr int kPolishMovesPerVertex = 16;          ///< at most this many moves per vertex, on average
  static constexpr int kAscentIterations = 16;              ///< ascent steps per vertex taken
  static constexpr double kActiveBand = 1.0 * kDegree;      ///< angles this close to the smallest rise with it
  static constexpr double kNarrowestBand = 0.01 * kDegree;  ///< ... or, near the top, this close
  static constexpr double kMaxPolishStep = 0.3;             ///< longest ascent step, in ring lengths
  static constexpr double kSmallestStep = 1e-3;             ///< shortest, in ring lengths
  static constexpr double kGradientStep = 1e-5;             ///< finite differences' step, in ring lengths
  static constexpr double kStationary = 1e-9;               ///< gradients under this: no ascent
  static constexpr int kGoldenSections = 40;
  static constexpr int kFlipClimbTries = 64;           ///< flipAndClimb's flips kept at most
  static constexpr int kFlipClimbSweeps = 4;           ///< ... and its sweeps of ascents after each flip
  static constexpr int kFlipUnder30Tries = 256;        ///< flipAndClimbUnder30's tries at most (each O(F))
  static constexpr int kJointTries = 64;               ///< jointClimbs' moves kept at most (each O(F))
  static constexpr double kJointSmallestStep = 0.005;  ///< jointMove halves its step down to this, in ring lengths
  /// The polish's valence batches, in turn (valenceFlipsAndClimbs). The first keeps the new faces
  /// near the smallest angle. The two after reach valences the first refuses, by flips with no
  /// bound on the new faces' angles, then by moves toward the rings' means: knot1 at 30% 33.8 ->
  /// 37.7 degrees, larger_sphere at 30% 40.6 -> 43.0 (CGAL's isotropic remeshing 36.0, 41.8). They
  /// move the surface more: unmeasured, three_peaks at 30% went from 1.89 to 2.94% of the
  /// diagonal in two-sided Hausdorff distance, mushroom at 10% 3.78 -> 4.88%. Measuring the first
  /// too lowered blobby_3cc at 30% 29.4 -> 28.8 degrees. The flips with no bound stop at once if
  /// they leave a face under 5 degrees: across a CAD part's creases they leave slivers (fandisk
  /// at 10%: 3.9 degrees, 71 faces under 30) that the climbs took 40 ms to bring to 4.9 before
  /// the batch was undone; the gains above need faces of 7.8-7.9 degrees after the flips.
  static constexpr std::array<ValenceBatch, 3> kValenceBatches = {
      {{5.0 * kDegree, 0, false, 0.0}, {kPi, 0, true, 5.0 * kDegree}, {5.0 * kDegree, 2, true, 0.0}}};
  /// flipAndClimb: the input's point under the edge flipped away ends within this times
  /// maxDeviation times the edge's length of the faces (or no farther than before). 2 gave
  /// ellipe0.003 at 5% 42.7 instead of 44.4 degrees; with no limit, bunny00 at 10% had a two-sided
  /// Hausdorff distance of 0.84% of the diagonal instead of 0.59%.
  static constexpr double kFlipDeviation = 4.0;
  static constexpr double kGolden = 0.6180339887498949;
  static inline const double kCos30 = std::sqrt(3.0) / 2;
  std::vector<Vec3> anchor_;  ///< positions when the polish began
  double polishAim_ = -1;     ///< vertices are polished while their ring's smallest angle is under it
  int polishMoves_ = 0;
  std::array<std::vector<double>, 3> angles_;  ///< ascentStep's ring angles, here and a step along e1, e2
  std::vector<Eigen::Vector2d> gradients_, active_;
  std::vector<int> faces_;                            ///< aroundVertices' faces
  std::vector<int> climbers_;                         ///< tryFlipAndClimb's quad and neighbours
  std::vector<char> flagged_;                         ///< facesCrossAround's faces
  std::vector<std::pair<Vec3, SurfacePoint>> saved_;  ///< ... and where they were

  /// Distance from x to the faces around v with v at position p.
  double fanDistance(int v, const Vec3& p, const Vec3& x) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      const Vec3& a = pos_[output_.vertex(TriMesh::next(*c))];
      const Vec3& b = pos_[output_.vertex(TriMesh::prev(*c))];
      nearest = std::min(nearest, squaredDistanceToTriangle(x, p, a, b));
    }
    return std::sqrt(nearest);
  }

  /// Points of the feature curve within 1.5 ring lengths of `from` (v's place on it), each with
  /// its distance to v's faces as they are.
  std::vector<std::pair<Vec3, double>> curveNearby(int v, const CurvePoint& from, double ringLength) const {
    std::vector<std::pair<Vec3, double>> near;
    for (int k = -kCurveSamples; k <= kCurveSamples; ++k) {
      const CurvePoint at = slide(from, k * 1.5 * ringLength / kCurveSamples, walker_);
      const Vec3 x = (1 - at.t) * walker_.position(at.a) + at.t * walker_.position(at.b);
      near.push_back({x, fanDistance(v, pos_[v], x)});
    }
    return near;
  }

  /// Whether moving v to q keeps the curve near v's faces: no point of `near` (curveNearby) ends
  /// farther from them than it was, or than maxAway. (Along a curved boundary, a longer chord
  /// strays farther from its arc.)
  bool keepsCurve(int v, const std::vector<std::pair<Vec3, double>>& near, const Vec3& q, double maxAway) const {
    for (const auto& [x, now] : near)
      if (fanDistance(v, q, x) > std::max(now, maxAway)) return false;
    return true;
  }
  static constexpr int kCurveSamples = 12;  ///< curve points checked each way (curveNearby)

  /// Whether the angle facing edge (a, b) does not count in a ring (ring, ringAngles): a and b on
  /// one tiny loop (RelaxationParams::tinyLoopLength).
  bool facesTinyLoop(int a, int b) const { return tinyLoop_[a] >= 0 && tinyLoop_[a] == tinyLoop_[b]; }

  /// Smallest angle (radians) of the faces around v with v at position p, and their normals;
  /// angles facing the edges of a tiny loop (facesTinyLoop) left out.
  double ring(int v, const Vec3& p, std::vector<Vec3>* normals) const {
    double largestCosine = -1;
    for (const int* c = output_.cornersBegin(v); c != output_.cornersEnd(v); ++c) {
      const int ia = output_.vertex(TriMesh::next(*c)), ib = output_.vertex(TriMesh::prev(*c));
      const Vec3& a = pos_[ia];
      const Vec3& b = pos_[ib];
      largestCosine = facesTinyLoop(ia, ib)
                          ? std::max({largestCosine, std::cos(angleAt(a, p, b)), std::cos(angleAt(b, p, a))})
                          : std::max(largestCosine, smallestAngleCosine(p, a, b));
      if (normals) normals->push_back((a - p).cross(b - p));
    }
    return std::acos(largestCosine);
  }

  /// Moves v to the input point closest to `target` if no face around v turns over (except to
  /// face the way the input does there), the ring's smallest angle does not fall below
  /// min(smallestBefore, aim) and the point v leaves stays within maxAway of the new fan.
  /// Returns the ring's smallest angle after (smallestBefore if v stays).
  double tryMove(int v, const Vec3& target, int face, double smallestBefore, double maxAway) {
    return tryMoveTo(v, walker_.project(target, face), smallestBefore, maxAway);
  }

  /// tryMove to a given point of the input.
  double tryMoveTo(int v, const SurfacePoint& moved, double smallestBefore, double maxAway, double aim = -1) {
    if (aim < 0) aim = aim_;
    refusedLast_ = false;
    const Vec3 q = walker_.pointOf(moved.face, moved.bary);
    const Vec3 normalThere = walker_.normal(moved.face);
    before_.clear();
    after_.clear();
    ring(v, pos_[v], &before_);
    const double smallest = ring(v, q, &after_);
    // A face may not turn over, unless it then faces the way the input does (an unfolding).
    for (size_t k = 0; k < after_.size(); ++k)
      if (!(after_[k].dot(before_[k]) > 0) && !(after_[k].dot(normalThere) > 0)) return smallestBefore;
    if (smallest < std::min(smallestBefore, aim)) return smallestBefore;
    // The point it leaves must stay close to the new fan: a vertex on a tip or a ridge keeps it.
    if (fanDistance(v, q, pos_[v]) > maxAway) return smallestBefore;
    const Vec3 from = pos_[v];
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

  /// Steps in eight tangent directions from where v is now, at three lengths: the one that most
  /// raises the smallest angle of its ring is kept (the mean of the ring is not always better: at
  /// a tip, a saddle, next to a fixed vertex), if the point v leaves stays within maxAway.
  void tryTangentSteps(int v, const Vec3& normal, double ringLength, double smallest, double maxAway) {
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
      tryMove(v, target, hereFace, smallest, maxAway);
      if (!refusedLast_) break;
    }
  }

  TriMesh& output_;
  std::vector<Vec3>& pos_;  ///< the output's positions
  std::vector<SurfacePoint>& points_;
  const TriMesh& input_;
  const std::vector<double>* density_;  ///< RelaxationParams::density
  const SurfaceWalker& walker_;
  double maxDeviation_;
  double aim_;                        ///< moves keep the ring's smallest angle at min(before, aim); none past it
  const std::vector<char>& watched_;  ///< per output vertex, or empty (RelaxationGuard::watched)
  std::vector<int> tinyLoop_;         ///< per output vertex, its tiny loop (tinyBoundaryLoops) or -1
  std::vector<int> watchedFaces_;     ///< faces with a watched corner (collectWatchedFaces)
  std::vector<Vec3> before_, after_;  ///< normals of v's faces before and after a move
  int moves_ = 0;
  int refusedCrossing_ = 0;
  bool refusedLast_ = false;  ///< the last tryMove was refused because faces would cross
};

/// Flips toward fewer faces under 30 degrees (flipToBetterAngles), all undone if they make faces
/// cross: flips across creases of up to the feature angle can fold a thin part onto itself.
/// Returns the flips kept.
Expected<int> flipWithoutCrossing(TriMesh& output, const AngleFlipParams& params) {
  const std::vector<Tri> before = output.triangles;
  const std::vector<int> opposite = output.oppositeCorner;
  const Expected<DelaunayFlipResult> flipped = flipToBetterAngles(output, params);
  if (!flipped) return flipped.status();
  if (flipped->flips == 0) return 0;
  std::vector<char> changed(output.faceCount());
  for (int f = 0; f < output.faceCount(); ++f) changed[f] = output.triangles[f] != before[f];
  if (crossingsOfFaces(output, changed).empty()) return flipped->flips;
  output.triangles = before;
  output.oppositeCorner = opposite;
  rebuildVertexCorners(output);
  return 0;
}

/// The length under which the input's crease chains are not creases (RelaxationParams::
/// minCreaseLength times the output's mean edge length; 0 with a density).
double minCreaseLength(const TriMesh& output, const RelaxationParams& params) {
  return params.density ? 0.0 : params.minCreaseLength * output.meanEdgeLength();
}

/// The ways along the input's boundary from p: one per boundary edge at p's vertex, or both ways
/// along the boundary edge p lies on; none for a point inside a face or on an inner edge.
std::vector<CurvePoint> boundaryWaysFrom(const SurfacePoint& p, const TriMesh& input) {
  const PointPlace place = placeOf(p, input);
  if (place.edgeCorner >= 0) {
    if (input.oppositeCorner[place.edgeCorner] >= 0) return {};
    const CurvePoint& e = place.onEdge;
    return {e, {e.b, e.a, 1 - e.t}};
  }
  std::vector<CurvePoint> ways;
  const int v = place.vertex;
  if (v < 0) return ways;
  for (const int* c = input.cornersBegin(v); c != input.cornersEnd(v); ++c) {
    if (input.oppositeCorner[TriMesh::prev(*c)] < 0) ways.push_back({v, input.vertex(TriMesh::next(*c)), 0.0});
    if (input.oppositeCorner[TriMesh::next(*c)] < 0) ways.push_back({v, input.vertex(TriMesh::prev(*c)), 0.0});
  }
  return ways;
}

/// The point of the input's boundary at arc length s from p along one of its ways nearest `aim`,
/// if within `tolerance` of it. A slide (which stops at corners of the feature curves) that starts
/// on the boundary stays on it: a boundary vertex has two boundary edges, and one more blocked
/// edge makes it a corner.
std::optional<SurfacePoint> alongBoundary(const SurfacePoint& p, double s, const Vec3& aim, double tolerance,
                                          const SurfaceWalker& walker) {
  std::optional<SurfacePoint> best;
  double nearest = tolerance;
  for (const CurvePoint& way : boundaryWaysFrom(p, walker.mesh())) {
    const CurvePoint to = slide(way, s, walker);
    const SurfacePoint q = walker.onInputEdge(to.a, to.b, to.t);
    const double d = (walker.pointOf(q.face, q.bary) - aim).norm();
    if (d <= nearest) {
      nearest = d;
      best = q;
    }
  }
  return best;
}

/// A face under 30 degrees held by a wide angle: its smallest angle (degrees) and its wide corner.
struct WideFace {
  double smallest;
  int corner;
};

/// The faces of `output` under 30 degrees whose widest angle is at least kSplitWideAngleDegrees
/// and faces an edge of the kind asked for, none flagged in `skip`, worst (smallest angle) first.
std::vector<WideFace> wideFaces(const TriMesh& output, const std::vector<char>& skip, SplitEdges edges) {
  std::vector<WideFace> wide;
  for (int f = 0; f < output.faceCount(); ++f) {
    std::array<double, 3> angle{};
    for (int k = 0; k < 3; ++k)
      angle[k] =
          angleAt(output.positions[output.vertex(3 * f + k)], output.positions[output.vertex(3 * f + (k + 1) % 3)],
                  output.positions[output.vertex(3 * f + (k + 2) % 3)]) /
          kDegree;
    const int k = static_cast<int>(std::max_element(angle.begin(), angle.end()) - angle.begin());
    const double smallest = *std::min_element(angle.begin(), angle.end());
    const bool skipped = f < static_cast<int>(skip.size()) && skip[f];
    const bool inner = output.oppositeCorner[3 * f + k] >= 0;
    if (smallest < 30.0 && angle[k] >= kSplitWideAngleDegrees && inner == (edges == SplitEdges::Inner) && !skipped)
      wide.push_back({smallest, 3 * f + k});
  }
  std::sort(wide.begin(), wide.end(), [](const WideFace& x, const WideFace& y) { return x.smallest < y.smallest; });
  return wide;
}

/// Where the edge (a, b) of `output`, facing c in one face and d in the other (d < 0: a boundary
/// edge), is split: of five points of the edge (0.3 to 0.7 of it), the one whose new faces have the
/// largest smallest angle, each taken on the input: the point nearest it by a walk from a's point
/// (as the relaxation's) or, on a boundary edge, the point of the input's boundary as far along
/// it from a's point (alongBoundary; none if no such point lies within a quarter of the edge).
std::optional<SurfacePoint> splitPoint(const TriMesh& output, const std::vector<SurfacePoint>& points,
                                       const SurfaceWalker& walker, int c, int a, int b, int d) {
  const Vec3 &pc = output.positions[c], &pa = output.positions[a], &pb = output.positions[b];
  const double length = (pb - pa).norm();
  std::optional<SurfacePoint> at;
  double bestCosine = 2;
  for (const double t : {0.5, 0.4, 0.6, 0.3, 0.7}) {
    const Vec3 aim = (1 - t) * pa + t * pb;
    const std::optional<SurfacePoint> q = d >= 0 ? walker.project(aim, walker.faceOf(points[a]))
                                                 : alongBoundary(points[a], t * length, aim, 0.25 * length, walker);
    if (!q) continue;
    const Vec3 x = walker.pointOf(q->face, q->bary);
    double cosine = std::max(smallestAngleCosine(pc, pa, x), smallestAngleCosine(pc, x, pb));
    if (d >= 0) {
      const Vec3& pd = output.positions[d];
      cosine = std::max({cosine, smallestAngleCosine(pd, pb, x), smallestAngleCosine(pd, x, pa)});
    }
    if (cosine < bestCosine) {
      bestCosine = cosine;
      at = q;
    }
  }
  return at;
}

/// Per vertex, 1 if it does not move: a corner of the feature curves, or on one while sliding is off.
std::vector<char> fixedVertices(const std::vector<Freedom>& freedom, const RelaxationParams& params,
                                RelaxationResult& r) {
  std::vector<char> fixed(freedom.size(), 0);
  for (size_t v = 0; v < freedom.size(); ++v) {
    fixed[v] = freedom[v] == Freedom::None || (freedom[v] == Freedom::Curve && !params.slideAlongFeatures);
    r.fixedVertices += fixed[v];
    r.slidingVertices += !fixed[v] && freedom[v] == Freedom::Curve;
  }
  return fixed;
}

}  // namespace

Expected<RelaxationResult> relaxOnSurface(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                                          const RelaxationParams& params, const RelaxationGuard& guard) {
  RelaxationResult r;
  if (Status s = checkRelaxationInput(output, points, input); !s) return s;
  for (const std::vector<char>* flags : {&guard.pinned, &guard.watched})
    if (!flags->empty() && static_cast<int>(flags->size()) != output.vertexCount())
      return invalidInput("relaxation: one pinned or watched flag per output vertex is needed");
  if (params.density && static_cast<int>(params.density->size()) != input.vertexCount())
    return invalidInput("relaxation: the density needs one value per vertex of the surface");
  if (params.iterations <= 0) return r;

  const SurfaceWalker walker(input, params.featureAngleDegrees, minCreaseLength(output, params));
  const std::vector<Freedom> freedom = freedoms(output, points, walker);
  std::vector<char> fixed = fixedVertices(freedom, params, r);
  for (size_t v = 0; v < guard.pinned.size(); ++v) {
    r.pinnedVertices += guard.pinned[v] && !fixed[v];
    fixed[v] |= guard.pinned[v];
  }
  for (size_t v = 0; v < guard.watched.size(); ++v) r.watchedVertices += guard.watched[v] && !fixed[v];
  const double aim = params.raiseSmallestAngle ? kPi : Relaxer::kSmallAngle;
  Relaxer relaxer(output, points, input, walker, params.maxDeviation, aim, guard.watched, params.density,
                  params.tinyLoopLength);
  for (int it = 0; it < params.iterations; ++it) {
    relaxer.meanRound(fixed, freedom);
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

Expected<RelaxationResult> polishOnSurface(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                                           const RelaxationParams& params, const PolishGuard& guard) {
  RelaxationResult r;
  if (Status s = checkRelaxationInput(output, points, input); !s) return s;
  const std::vector<char>& pinned = guard.pinned;
  if (!pinned.empty() && static_cast<int>(pinned.size()) != output.vertexCount())
    return invalidInput("polish: one pinned flag per output vertex is needed");
  if (guard.cell &&
      (static_cast<int>(guard.cell->size()) != input.vertexCount() ||
       std::any_of(guard.cell->begin(), guard.cell->end(), [&](int c) { return c < -1 || c >= output.vertexCount(); })))
    return invalidInput("polish: one cell per input vertex is needed, each an output vertex or -1");
  if (params.polishMarginDegrees < 0) return r;
  const SurfaceWalker walker(input, params.featureAngleDegrees, minCreaseLength(output, params));
  const std::vector<Freedom> freedom = freedoms(output, points, walker);
  std::vector<char> fixed = fixedVertices(freedom, params, r);
  for (size_t v = 0; v < pinned.size(); ++v) {
    r.pinnedVertices += pinned[v] && !fixed[v];
    fixed[v] |= pinned[v];
  }
  const std::vector<char> noneWatched;
  Relaxer relaxer(output, points, input, walker, params.maxDeviation, kPi, noneWatched, params.density,
                  params.tinyLoopLength);
  for (int pass = 0; pass < kPolishPasses; ++pass) {
    const int moved = relaxer.polish(fixed, freedom, params.polishMarginDegrees * kDegree);
    // The output is manifold, oriented and has faces (checked above), and moves keep that.
    Expected<DelaunayFlipResult> flipped = flipToDelaunay(output, params.flips);
    if (!flipped) return flipped.status();
    r.flips += flipped->flips;
    ++r.iterations;
    if (moved == 0 || flipped->flips == 0) break;  // flips give the polish new rings
  }
  // Flips across creases up to the input's feature angle: the coarse outputs of thin parts
  // (knot2 at 5%: a tube a few vertices round) have edges of 50 degrees where a Delaunay flip's
  // 30 would hold the face under 30 degrees; input creases sharper than that stay edges.
  const double flipCrease = std::max(params.flips.featureAngleDegrees, params.featureAngleDegrees);
  if (params.flips.maxFlipsPerFace > 0) r.flips += relaxer.flipAndClimb(fixed, freedom, flipCrease);
  Relaxer::DistanceToInput distance;  // two-sided, at remeshDistances' samples
  if (guard.cell)
    distance = [&](const TriMesh& mesh, const std::vector<SurfacePoint>& on) {
      const RemeshDistances d = remeshDistances(input, mesh, *guard.cell, on, guard.voronoiCells);
      return std::max(d.toInput.max, d.fromInput.max);
    };
  if (params.flips.maxFlipsPerFace > 0) {
    const Expected<int> valence =
        relaxer.valenceBatches(fixed, freedom, flipCrease, params.polishMarginDegrees * kDegree, distance);
    if (!valence) return valence.status();
    r.flips += *valence;
  }
  const double floor = smallestAngleOf(output);
  AngleFlipParams under30;
  under30.minAngleDegrees = floor / kDegree;
  under30.featureAngleDegrees = flipCrease;
  if (params.flips.maxFlipsPerFace <= 0) under30.passes = 0;  // no flips asked for
  for (int pass = 0; pass < kPolishPasses; ++pass) {
    const Expected<int> flips = flipWithoutCrossing(output, under30);
    if (!flips) return flips.status();
    r.flips += *flips;
    const int moved = relaxer.fewerUnder30(fixed, freedom, floor);
    const int climbed =
        params.flips.maxFlipsPerFace > 0 ? relaxer.flipAndClimbUnder30(fixed, freedom, flipCrease, floor) : 0;
    r.flips += climbed;
    if (moved == 0 && *flips == 0 && climbed == 0) break;
  }
  r.moves = r.polishMoves = relaxer.polishMoves();
  return r;
}

Expected<int> climbJointly(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                           const RelaxationParams& params, const std::vector<char>& pinned) {
  if (Status s = checkRelaxationInput(output, points, input); !s) return s;
  if (!pinned.empty() && static_cast<int>(pinned.size()) != output.vertexCount())
    return invalidInput("joint climbs: one pinned flag per output vertex is needed");
  const SurfaceWalker walker(input, params.featureAngleDegrees, minCreaseLength(output, params));
  const std::vector<Freedom> freedom = freedoms(output, points, walker);
  RelaxationResult counts;
  std::vector<char> fixed = fixedVertices(freedom, params, counts);
  for (size_t v = 0; v < pinned.size(); ++v) fixed[v] |= pinned[v];
  const std::vector<char> noneWatched;
  Relaxer relaxer(output, points, input, walker, params.maxDeviation, kPi, noneWatched, params.density,
                  params.tinyLoopLength);
  return relaxer.jointClimbs(fixed, freedom);
}

Expected<int> splitWideFaces(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                             const RelaxationParams& params, int maxSplits, const std::vector<char>& skip,
                             SplitEdges edges) {
  if (Status s = checkRelaxationInput(output, points, input); !s) return s;
  const std::vector<WideFace> wide = wideFaces(output, skip, edges);
  const SurfaceWalker walker(input, params.featureAngleDegrees, minCreaseLength(output, params));
  std::vector<Vec3> positions = output.positions;
  std::vector<Tri> triangles = output.triangles;
  std::vector<char> split(output.faceCount(), 0);  // faces already split
  int splits = 0;
  for (const WideFace& w : wide) {
    if (splits >= maxSplits) break;
    const int o = output.oppositeCorner[w.corner];
    const int f = TriMesh::face(w.corner), g = o >= 0 ? TriMesh::face(o) : -1;
    if (split[f] || (g >= 0 && split[g])) continue;
    //        c                 c
    //       / \               /|\        f = (c, a, b) and g = (d, b, a) become
    //      a---b     ->      a-m-b      (c, a, m), (c, m, b), (d, b, m), (d, m, a);
    //       \ /               \|/        on a boundary edge (no g), f only
    //        d                 d
    const int c = output.vertex(w.corner), a = output.vertex(TriMesh::next(w.corner));
    const int b = output.vertex(TriMesh::prev(w.corner)), d = o >= 0 ? output.vertex(o) : -1;
    if (c == d) continue;  // two faces on the same three vertices
    const std::optional<SurfacePoint> at = splitPoint(output, points, walker, c, a, b, d);
    if (!at) continue;
    const int m = static_cast<int>(positions.size());
    positions.push_back(walker.pointOf(at->face, at->bary));
    points.push_back(*at);
    triangles[f] = Tri{c, a, m};
    triangles.push_back(Tri{c, m, b});
    split[f] = 1;
    if (g >= 0) {
      triangles[g] = Tri{d, b, m};
      triangles.push_back(Tri{d, m, a});
      split[g] = 1;
    }
    ++splits;
  }
  if (splits == 0) return 0;
  Expected<TriMesh> done = buildAdjacency(std::move(positions), std::move(triangles));
  if (!done) return done.status();
  output = std::move(*done);
  return splits;
}

std::vector<int> featureCorners(const TriMesh& input, const RelaxationParams& params) {
  const SurfaceWalker walker(input, params.featureAngleDegrees, 0.0);
  std::vector<int> corners;
  for (int v = 0; v < input.vertexCount(); ++v) {
    std::array<int, 3> next{};
    const int n = input.valence(v) > 0 ? walker.blockedNeighbours(v, next) : 0;
    if (n > 0 && (n != 2 || walker.curveNext(v, next[0]) < 0)) corners.push_back(v);
  }
  return corners;
}

}  // namespace gr
