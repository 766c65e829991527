#include "core/geodesic/intrinsic_triangulation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/base/math.h"

namespace gr {
namespace {

constexpr double kTwoPi = 2.0 * kPi;
/// Mollified faces get a triangle-inequality margin of this times the mean edge length.
constexpr double kMollifyRelative = 1e-10;
/// Flat faces (no zero-length edge, no violation) get a margin of this times the mean edge length.
constexpr double kFlatMarginRelative = 1e-14;
/// Lengths violating the triangle inequality by more than this times the longest (not rounding).
constexpr double kViolationRelative = 1e-12;
/// A flip is refused when a new face's twice-area is below this times the sum of its squared lengths.
constexpr double kFlipAreaGuard = 1e-12;
constexpr double kDelaunayTolerance = 1e-9;

/// Length of the edge facing each corner, from the 3D positions.
std::vector<double> cornerLengths(const TriMesh& m) {
  std::vector<double> len(3 * m.faceCount());
  for (int c = 0; c < 3 * m.faceCount(); ++c)
    len[c] = (m.positions[m.vertex(TriMesh::next(c))] - m.positions[m.vertex(TriMesh::prev(c))]).norm();
  return len;
}

/// The least epsilon that, added to every length, gives every face a triangle-inequality margin of
/// `delta`; <= 0 when every face has it already.
double epsilonForMargin(const std::vector<double>& len, double delta) {
  double eps = 0.0;
  for (size_t f = 0; f + 2 < len.size(); f += 3)
    for (int i = 0; i < 3; ++i) eps = std::max(eps, delta - (len[f + (i + 1) % 3] + len[f + (i + 2) % 3] - len[f + i]));
  return eps;
}

/// The epsilon added to every length (0 if none is needed): a zero-length edge (coincident
/// vertices) or lengths that violate the inequality beyond rounding get the margin
/// kMollifyRelative * mean length; flat faces (a margin of zero up to rounding, angles 0, 0, pi)
/// get only kFlatMarginRelative * mean, which makes them thin triangles that the refinement splits
/// and fronts cross (zero-area faces can glue two parts of a surface along a segment that no
/// triangle update crosses: degtri_sliding.off, 14.5% mean error unmollified, 0% mollified) while
/// bending the surface by only about sqrt(epsilon * length), 1e-7 of the mean length.
double mollificationEpsilon(const std::vector<double>& len) {
  if (len.empty()) return 0.0;
  double mean = 0.0;
  for (double l : len) mean += l;
  mean /= static_cast<double>(len.size());
  const double delta = kMollifyRelative * mean;
  bool needed = false;
  for (size_t f = 0; f + 2 < len.size(); f += 3) {
    const double longest = std::max({len[f], len[f + 1], len[f + 2]});
    for (int i = 0; i < 3; ++i) {
      const double margin = len[f + (i + 1) % 3] + len[f + (i + 2) % 3] - len[f + i];
      needed = needed || !(len[f + i] > delta) || margin < -kViolationRelative * longest;
    }
  }
  if (needed) return epsilonForMargin(len, delta);
  return std::max(0.0, epsilonForMargin(len, kFlatMarginRelative * mean));
}

double twiceArea(const Vec2& p, const Vec2& q, const Vec2& r) { return cross2(q - p, r - p); }

bool wellShaped(const Vec2& p, const Vec2& q, const Vec2& r) {
  const double scale = (q - p).squaredNorm() + (r - q).squaredNorm() + (p - r).squaredNorm();
  return twiceArea(p, q, r) > kFlipAreaGuard * scale;
}

}  // namespace

IntrinsicTriangulation::IntrinsicTriangulation(const TriMesh& input) : inputVertexCount_(input.vertexCount()) {
  std::vector<double> len = cornerLengths(input);
  mollification_ = mollificationEpsilon(len);
  for (double& l : len) l += mollification_;
  input_ = buildSignpostMesh(input, len);
  mesh_ = input_;
  origin_.resize(inputVertexCount_);
  for (int v = 0; v < inputVertexCount_; ++v) origin_[v] = SurfacePoint::atVertex(v);
  offset_.assign(inputVertexCount_, 0.0);
  queued_.assign(mesh_.he.size(), 0);
  for (int f = 0; f < mesh_.faceCount(); ++f) touchFace(f);
}

// ------------------------------------------------------------------------------------------------
// Bookkeeping

void IntrinsicTriangulation::touchFace(int f) {
  changed_.push_back(f);
  if (queued_.size() < mesh_.he.size()) queued_.resize(mesh_.he.size(), 0);
  for (int h = 3 * f; h < 3 * f + 3; ++h) {
    const int t = mesh_.he[h].twin;
    if (t < 0) continue;
    const int key = std::min(h, t);
    if (!queued_[key]) {
      queued_[key] = 1;
      flipQueue_.push_back(key);
    }
  }
}

void IntrinsicTriangulation::queueAllEdges() {
  queued_.resize(mesh_.he.size(), 0);
  for (int h = 0; h < static_cast<int>(mesh_.he.size()); ++h)
    if (mesh_.he[h].twin > h && !queued_[h]) {
      queued_[h] = 1;
      flipQueue_.push_back(h);
    }
}

std::vector<int> IntrinsicTriangulation::takeChangedFaces() {
  std::vector<int> out;
  out.swap(changed_);
  return out;
}

void IntrinsicTriangulation::link(int h, int g, double length) {
  mesh_.he[h] = SignpostHalfedge{g, length, 0.0, -1};
  mesh_.he[g] = SignpostHalfedge{h, length, 0.0, -1};
}

int IntrinsicTriangulation::addVertex(const SurfacePoint& origin, bool onBoundary) {
  SignpostVertex v;
  v.angleSum = onBoundary ? kPi : kTwoPi;
  v.onBoundary = onBoundary;
  mesh_.vert.push_back(v);
  origin_.push_back(origin);
  offset_.push_back(0.0);
  return mesh_.vertexCount() - 1;
}

bool IntrinsicTriangulation::joins(int v, int w) const {
  const int first = mesh_.vert[v].halfedge;
  if (first < 0) return false;
  int h = first, guard = 3 * mesh_.faceCount();
  do {
    if (mesh_.tip(h) == w || mesh_.tail(SignpostMesh::prev(h)) == w) return true;
    h = mesh_.nextAround(h);
  } while (h >= 0 && h != first && --guard > 0);
  return false;
}

bool IntrinsicTriangulation::isNonSimplicial(int h) const {
  const int v = mesh_.tail(h), w = mesh_.tip(h);
  if (v == w) return true;
  int edges = 0, g = mesh_.vert[v].halfedge, guard = 3 * mesh_.faceCount();
  const int first = g;
  do {
    if (mesh_.tip(g) == w) ++edges;
    const int in = SignpostMesh::prev(g);  // the incoming boundary edge ends a boundary fan
    if (mesh_.he[in].twin < 0 && mesh_.tail(in) == w) ++edges;
    g = mesh_.nextAround(g);
  } while (g >= 0 && g != first && --guard > 0);
  return edges > 1;
}

std::vector<int> IntrinsicTriangulation::nonSimplicialEdges() const {
  // Per vertex v, its neighbours w around it, with a stamp per w instead of a sorted ring: a
  // self-edge (w == v) is reported from each of its halfedges; of the k > 1 edges joining v to
  // the same w (v < w), every one but the one with the smallest halfedge. O(V + F).
  std::vector<int> out;
  const int nv = mesh_.vertexCount();
  std::vector<int> stampOf(nv, -1), smallestHalfedge(nv, -1);
  const auto meet = [&](int v, int w, int h) {
    if (w == v) {
      out.push_back(h);
    } else if (stampOf[w] != v) {
      stampOf[w] = v;
      smallestHalfedge[w] = h;
    } else if (v < w) {
      out.push_back(std::max(smallestHalfedge[w], h));
      smallestHalfedge[w] = std::min(smallestHalfedge[w], h);
    }
  };
  for (int v = 0; v < nv; ++v) {
    const int first = mesh_.vert[v].halfedge;
    if (first < 0) continue;
    int h = first, guard = 3 * mesh_.faceCount();
    do {
      meet(v, mesh_.tip(h), h);
      const int in = SignpostMesh::prev(h);
      if (mesh_.he[in].twin < 0) meet(v, mesh_.tail(in), in);
      h = mesh_.nextAround(h);
    } while (h >= 0 && h != first && --guard > 0);
  }
  // One halfedge per edge (a self-edge is met from both of its halfedges).
  for (int& h : out) h = mesh_.he[h].twin >= 0 ? std::min(h, mesh_.he[h].twin) : h;
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// ------------------------------------------------------------------------------------------------
// Flips

bool IntrinsicTriangulation::isDelaunay(int h, double toleranceRadians) const {
  const int t = mesh_.he[h].twin;
  if (t < 0) return true;
  // Half-angles x, y in [0, pi/2]: x + y <= pi/2 exactly when tan x tan y <= 1 (no arc tangent,
  // the common case); otherwise the angles themselves, against the tolerance.
  if (mesh_.cornerTanHalfSquared(SignpostMesh::prev(h)) * mesh_.cornerTanHalfSquared(SignpostMesh::prev(t)) <= 1.0)
    return true;
  return mesh_.cornerAngle(SignpostMesh::prev(h)) + mesh_.cornerAngle(SignpostMesh::prev(t)) <= kPi + toleranceRadians;
}

bool IntrinsicTriangulation::flip(int h, bool keepSimplicial) {
  using M = SignpostMesh;
  const int t = mesh_.he[h].twin;
  if (t < 0) return false;
  const int f = M::face(h), g = M::face(t);
  if (f == g) return false;
  const int a = mesh_.tail(h), b = mesh_.tip(h), x = mesh_.tail(M::prev(h)), y = mesh_.tail(M::prev(t));
  if (keepSimplicial && (x == y || joins(x, y))) return false;
  // Faces (a, b, x) and (b, a, y) laid out: a at the origin, b on the x axis, x above, y below.
  const double lab = mesh_.length(h);
  const Vec2 pa(0.0, 0.0), pb(lab, 0.0);
  const Vec2 px = layoutThirdVertex(lab, mesh_.length(M::prev(h)), mesh_.length(M::next(h)));
  const Vec2 py = layoutBelow(lab, mesh_.length(M::next(t)), mesh_.length(M::prev(t)));
  if (!wellShaped(px, pa, py) || !wellShaped(py, pb, px)) return false;
  const double lxy = (px - py).norm();
  if (!std::isfinite(lxy) || !(lxy > 0.0)) return false;
  // New faces f = (x, a, y), g = (y, b, x); the outer halfedges move with their data.
  moveHalfedges<4>(mesh_.he, {M::prev(h), M::next(t), M::prev(t), M::next(h)}, {3 * f, 3 * f + 1, 3 * g, 3 * g + 1});
  mesh_.tri[f] = {x, a, y};
  mesh_.tri[g] = {y, b, x};
  link(3 * f + 2, 3 * g + 2, lxy);
  mesh_.updateSignpostFromClockwise(3 * g + 2);  // x -> y, from x -> a
  mesh_.updateSignpostFromClockwise(3 * f + 2);  // y -> x, from y -> b
  for (int k = 0; k < 3; ++k) {
    mesh_.claimVertexHalfedge(3 * f + k);
    mesh_.claimVertexHalfedge(3 * g + k);
  }
  touchFace(f);
  touchFace(g);
  ++flips_;
  return true;
}

int IntrinsicTriangulation::flipToDelaunay(bool keepSimplicial, long maxFlips) {
  const long cap = maxFlips >= 0 ? maxFlips : 10L * static_cast<long>(mesh_.he.size()) + 1000;
  long count = 0;
  while (!flipQueue_.empty() && count < cap) {
    const int h = flipQueue_.back();
    flipQueue_.pop_back();
    queued_[h] = 0;
    if (isDelaunay(h, kDelaunayTolerance)) continue;
    if (flip(h, keepSimplicial)) ++count;
  }
  return static_cast<int>(count);
}

}  // namespace gr
