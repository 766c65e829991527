#include "core/geodesic/detail/signpost_trace.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gr {
namespace {

/// A crossing this close to an end of the edge (relative to its length) is at that vertex.
constexpr double kSnap = 1e-9;
constexpr int kAllEdges = 7;
/// A crossing this far beyond an end of the edge (relative to its length) is still on it
/// (rounding); farther, it is on the edge's line only.
constexpr double kOnSegment = 1e-6;

Vec2 rotated(const Vec2& u, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vec2(c * u.x() - s * u.y(), s * u.x() + c * u.y());
}

/// The line being traced: where it is (face, layout, point, direction), how far it has to go,
/// and which edges of the face it may leave through (bit i: the edge facing vertex i).
class Walker {
 public:
  Walker(const SignpostMesh& m, const TraceOptions& options, double length)
      : m_(m), options_(options), remaining_(length) {}

  /// Starts at vertex v in direction `angle`; false for an isolated vertex.
  bool startAtVertex(int v, double angle);
  /// Starts at a point of face f (not near a vertex).
  void startInFace(int f, const Vec3& bary, const Vec2& direction);
  TraceResult run();

 private:
  /// The exit edge (vertex index facing it) and the distance to it; -1 if none.
  int exitEdge(double* t) const;
  TraceResult stopHere(TraceStop stop, const Vec2& at) const;
  /// At vertex slot w of the face, arriving along direction_: restarts on the far side; false
  /// (and *result set) when the trace has to stop there.
  bool passVertex(int w, TraceResult* result);
  /// Crosses the edge facing vertex index i at relative position s along it (from its tail);
  /// false (and *result set) at the boundary.
  bool crossEdge(int i, double s, const Vec2& at, TraceResult* result);

  const SignpostMesh& m_;
  TraceOptions options_;
  double remaining_;
  int face_ = -1;
  std::array<Vec2, 3> p_{};
  Vec2 point_ = Vec2::Zero();
  Vec2 direction_ = Vec2::Zero();
  int allowed_ = kAllEdges;
  int steps_ = 0;
};

bool Walker::startAtVertex(int v, double angle) {
  const int first = m_.vert[v].halfedge;
  if (first < 0) return false;
  angle = m_.standardAngle(v, angle);
  const double sum = m_.vert[v].angleSum;
  // The corner whose angular range holds `angle`; failing that (rounding), the nearest one.
  int best = first;
  double bestExcess = std::numeric_limits<double>::infinity(), bestRel = 0.0;
  int h = first, guard = 3 * m_.faceCount();
  do {
    double rel = angle - m_.he[h].signpost;
    if (!m_.vert[v].onBoundary && rel < 0.0) rel += sum;
    const double corner = m_.cornerAngle(h);
    const double excess = rel < 0.0 ? -rel : std::max(0.0, rel - corner);
    if (excess < bestExcess) {
      bestExcess = excess;
      best = h;
      bestRel = std::clamp(rel, 0.0, corner);
    }
    if (excess == 0.0) break;
    h = m_.nextAround(h);
  } while (h >= 0 && h != first && --guard > 0);
  face_ = SignpostMesh::face(best);
  const int k = best % 3;
  p_ = m_.layout(face_);
  const Vec2 edge = p_[(k + 1) % 3] - p_[k];
  const double len = edge.norm();
  direction_ = len > 0.0 ? rotated(edge / len, bestRel) : Vec2(std::cos(bestRel), std::sin(bestRel));
  point_ = p_[k];
  allowed_ = 1 << k;  // out through the opposite edge, not back along the corner's own edges
  return true;
}

void Walker::startInFace(int f, const Vec3& bary, const Vec2& direction) {
  face_ = f;
  p_ = m_.layout(f);
  point_ = bary[0] * p_[0] + bary[1] * p_[1] + bary[2] * p_[2];
  direction_ = direction;
  allowed_ = kAllEdges;
}

int Walker::exitEdge(double* t) const {
  // The nearest edge line the direction crosses outwards. In a face of zero area two edges lie on
  // one line and are both crossed at once (t = 0): the one whose segment holds the crossing is the
  // way out; the other's end would be taken for a vertex the line runs into, up to an edge's
  // length away. So crossings off their segment count only when no edge has one on it.
  int best = -1, bestOff = -1;
  double tOff = std::numeric_limits<double>::infinity();
  *t = tOff;
  for (int i = 0; i < 3; ++i) {
    if (!(allowed_ & (1 << i))) continue;
    const Vec2& a = p_[(i + 1) % 3];
    const Vec2 e = p_[(i + 2) % 3] - a;
    const double rate = cross2(e, direction_);  // < 0: moving out across this edge's line
    if (!(rate < 0.0)) continue;
    const double ti = std::max(0.0, cross2(e, point_ - a)) / -rate;
    const double len2 = e.squaredNorm();
    const double s = len2 > 0.0 ? (point_ + ti * direction_ - a).dot(e) / len2 : 0.0;
    const bool onSegment = s >= -kOnSegment && s <= 1.0 + kOnSegment;
    if (onSegment && ti < *t) {
      *t = ti;
      best = i;
    } else if (!onSegment && ti < tOff) {
      tOff = ti;
      bestOff = i;
    }
  }
  if (best < 0) *t = tOff;
  return best >= 0 ? best : bestOff;
}

TraceResult Walker::stopHere(TraceStop stop, const Vec2& at) const {
  TraceResult r;
  r.stop = stop;
  r.face = face_;
  r.bary = baryInLayout(p_, at);
  r.direction = direction_;
  r.remaining = stop == TraceStop::Reached ? 0.0 : remaining_;
  return r;
}

bool Walker::passVertex(int w, TraceResult* result) {
  const int v = m_.tri[face_][w];
  if (!options_.throughVertices || m_.vert[v].onBoundary) {
    *result = stopHere(TraceStop::Vertex, p_[w]);
    result->vertex = v;
    return false;
  }
  // The arrival direction reversed, as an angle of v's coordinate (through this face's corner).
  const int hw = 3 * face_ + w;
  const double inCorner = std::clamp(angleBetween(p_[(w + 1) % 3] - p_[w], -direction_), 0.0, m_.cornerAngle(hw));
  const double incoming = m_.he[hw].signpost + inCorner;
  if (!startAtVertex(v, incoming + 0.5 * m_.vert[v].angleSum)) {
    *result = stopHere(TraceStop::Failed, p_[w]);
    return false;
  }
  return true;
}

bool Walker::crossEdge(int i, double s, const Vec2& at, TraceResult* result) {
  const int h = 3 * face_ + (i + 1) % 3;  // runs from vertex i+1 to vertex i+2
  const int twin = m_.he[h].twin;
  if (twin < 0) {
    *result = stopHere(TraceStop::Boundary, at);
    result->halfedge = h;
    return false;
  }
  const Vec2 edgeHere = p_[(i + 2) % 3] - p_[(i + 1) % 3];
  const int g = SignpostMesh::face(twin), j = twin % 3;
  const std::array<Vec2, 3> q = m_.layout(g);
  const Vec2 &tailThere = q[(j + 1) % 3], &tipThere = q[j];  // the twin runs the other way
  const Vec2 edgeThere = tipThere - tailThere;
  const double turn = angleBetween(edgeHere, edgeThere);
  direction_ = rotated(direction_, turn);
  point_ = tailThere + s * edgeThere;
  face_ = g;
  p_ = q;
  allowed_ = kAllEdges & ~(1 << ((j + 2) % 3));
  return true;
}

TraceResult Walker::run() {
  TraceResult result;
  while (true) {
    if (++steps_ > options_.maxFaces) return stopHere(TraceStop::Failed, point_);
    double t = 0.0;
    const int i = exitEdge(&t);
    if (i < 0) return stopHere(TraceStop::Failed, point_);
    if (t >= remaining_) return stopHere(TraceStop::Reached, point_ + remaining_ * direction_);
    const Vec2 at = point_ + t * direction_;
    remaining_ -= t;
    const Vec2& a = p_[(i + 1) % 3];
    const Vec2 e = p_[(i + 2) % 3] - a;
    const double len2 = e.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((at - a).dot(e) / len2, 0.0, 1.0) : 0.0;
    if (s < kSnap || s > 1.0 - kSnap) {
      point_ = at;
      if (!passVertex(s < kSnap ? (i + 1) % 3 : (i + 2) % 3, &result)) return result;
    } else if (!crossEdge(i, s, at, &result)) {
      return result;
    }
  }
}

}  // namespace

Vec3 baryInLayout(const std::array<Vec2, 3>& p, const Vec2& q) {
  Vec3 b;
  for (int i = 0; i < 3; ++i) {
    const Vec2& a = p[(i + 1) % 3];
    b[i] = std::max(0.0, cross2(p[(i + 2) % 3] - a, q - a));
  }
  const double sum = b.sum();
  if (sum > 0.0) return b / sum;
  // A face of zero area: the nearest vertex.
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if ((p[i] - q).squaredNorm() < (p[k] - q).squaredNorm()) k = i;
  return Vec3::Unit(k);
}

TraceResult traceFromVertex(const SignpostMesh& m, int v, double angle, double length, const TraceOptions& options) {
  Walker w(m, options, length);
  if (!w.startAtVertex(v, angle)) return TraceResult{};
  return w.run();
}

TraceResult traceFromFacePoint(const SignpostMesh& m, int f, const Vec3& bary, const Vec2& direction, double length,
                               const TraceOptions& options) {
  int k = 0;
  bary.maxCoeff(&k);
  if (bary[k] > 1.0 - kSnap) {
    const std::array<Vec2, 3> p = m.layout(f);
    const int h = 3 * f + k;
    const int v = m.tri[f][k];
    return traceFromVertex(m, v, m.he[h].signpost + angleBetween(p[(k + 1) % 3] - p[k], direction), length, options);
  }
  Walker w(m, options, length);
  w.startInFace(f, bary, direction);
  return w.run();
}

}  // namespace gr
