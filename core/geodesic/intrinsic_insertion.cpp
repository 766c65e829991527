// IntrinsicTriangulation, second part: inserting vertices and locating them on the input
// (intrinsic_triangulation.h; the construction, bookkeeping and flips are in
// intrinsic_triangulation.cpp).
#include "core/geodesic/intrinsic_triangulation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <vector>

#include "core/base/math.h"

namespace gr {
namespace {

constexpr double kTwoPi = 2.0 * kPi;
/// An inserted point this close to a vertex, relative to the face's longest edge, is refused.
constexpr double kInsertGuard = 1e-12;
/// A locating trace that stops (boundary) this close to its length, relative, is taken as arrived.
constexpr double kArrivalTolerance = 1e-9;

double wrapAngle(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}

double argument(const Vec2& u) { return wrapAngle(std::atan2(u.y(), u.x())); }

}  // namespace

// ------------------------------------------------------------------------------------------------
// Locating new vertices on the input

int IntrinsicTriangulation::pickPlan(const std::vector<TracePlan>& plans, int inputVertexCount) {
  const auto rank = [&](const TracePlan& p) { return std::make_tuple(p.from < inputVertexCount ? 0 : 1, p.length); };
  int best = 0;
  for (int i = 1; i < static_cast<int>(plans.size()); ++i)
    if (rank(plans[i]) < rank(plans[best])) best = i;
  return best;
}

bool IntrinsicTriangulation::locate(const TracePlan& plan, Located* where) const {
  TraceOptions options;
  options.maxFaces = 4 * input_.faceCount() + 64;
  TraceResult r;
  if (plan.from < inputVertexCount_) {
    r = traceFromVertex(input_, plan.from, plan.angle, plan.length, options);
  } else {
    const SurfacePoint& o = origin_[plan.from];
    const double psi = plan.angle + offset_[plan.from];
    r = traceFromFacePoint(input_, o.face, o.bary, Vec2(std::cos(psi), std::sin(psi)), plan.length, options);
  }
  const bool stoppedShort = r.stop == TraceStop::Boundary || r.stop == TraceStop::Vertex;
  if (!(r.stop == TraceStop::Reached || (stoppedShort && r.remaining <= kArrivalTolerance * plan.length))) return false;
  where->at = SurfacePoint::inFace(r.face, r.bary);
  where->arrival = r.direction;
  return true;
}

void IntrinsicTriangulation::alignVertex(int v, int halfedgeToStart, const Located& where) {
  offset_[v] = argument(-where.arrival) - mesh_.he[halfedgeToStart].signpost;
}

double IntrinsicTriangulation::boundaryParameter(int inputHalfedge, int v) const {
  const SurfacePoint& o = origin_[v];
  if (o.vertex >= 0) return o.vertex == input_.tip(inputHalfedge) ? 1.0 : 0.0;
  const int k = inputHalfedge % 3;
  const double along = o.bary[(k + 1) % 3], back = o.bary[k];
  return along + back > 0.0 ? along / (along + back) : 0.5;
}

SurfacePoint IntrinsicTriangulation::boundaryPoint(int h, double t) const {
  const int ih = mesh_.he[h].inputHalfedge;
  const double ta = boundaryParameter(ih, mesh_.tail(h)), tb = boundaryParameter(ih, mesh_.tip(h));
  const double s = (1.0 - t) * ta + t * tb;
  const int k = ih % 3;
  Vec3 bary = Vec3::Zero();
  bary[k] = 1.0 - s;
  bary[(k + 1) % 3] = s;
  return SurfacePoint::inFace(SignpostMesh::face(ih), bary);
}

// ------------------------------------------------------------------------------------------------
// Insertions

int IntrinsicTriangulation::insertVertex(int f, const Vec3& bary) {
  const std::array<Vec2, 3> p = mesh_.layout(f);
  const Vec2 q = bary[0] * p[0] + bary[1] * p[1] + bary[2] * p[2];
  std::array<double, 3> d{};
  double longest = 0.0;
  std::vector<TracePlan> plans;
  for (int k = 0; k < 3; ++k) {
    d[k] = (q - p[k]).norm();
    longest = std::max(longest, mesh_.length(3 * f + k));
    const int h = 3 * f + k;
    const double inCorner = std::clamp(angleBetween(p[(k + 1) % 3] - p[k], q - p[k]), 0.0, mesh_.cornerAngle(h));
    plans.push_back({mesh_.tail(h), mesh_.he[h].signpost + inCorner, d[k]});
  }
  if (!(std::min({d[0], d[1], d[2]}) > kInsertGuard * longest)) return -1;
  const int chosen = pickPlan(plans, inputVertexCount_);
  Located where;
  if (!locate(plans[chosen], &where)) return -1;
  const int v = addVertex(where.at, false);
  const Tri old = mesh_.tri[f];
  const int f1 = mesh_.faceCount(), f2 = f1 + 1;
  mesh_.tri.push_back({old[1], old[2], v});
  mesh_.tri.push_back({old[2], old[0], v});
  mesh_.he.resize(mesh_.he.size() + 6);
  moveHalfedges<2>(mesh_.he, {3 * f + 1, 3 * f + 2}, {3 * f1, 3 * f2});
  mesh_.tri[f] = {old[0], old[1], v};
  link(3 * f + 1, 3 * f1 + 2, d[1]);
  link(3 * f1 + 1, 3 * f2 + 2, d[2]);
  link(3 * f2 + 1, 3 * f + 2, d[0]);
  for (int h : {3 * f2 + 1, 3 * f + 1, 3 * f1 + 1}) mesh_.updateSignpostFromClockwise(h);  // v0, v1, v2 -> v
  const std::array<int, 3> fromV = {3 * f + 2, 3 * f1 + 2, 3 * f2 + 2};                    // v -> v0, v1, v2
  for (int k = 0; k < 3; ++k) mesh_.he[fromV[k]].signpost = argument(p[k] - q);
  alignVertex(v, fromV[chosen], where);
  for (int face : {f, f1, f2}) {
    for (int k = 0; k < 3; ++k) mesh_.claimVertexHalfedge(3 * face + k);
    touchFace(face);
  }
  return v;
}

int IntrinsicTriangulation::splitEdge(int h, double t) {
  using M = SignpostMesh;
  const int tw = mesh_.he[h].twin;
  if (tw < 0) return splitBoundaryEdge(h, t);
  const int f = M::face(h), g = M::face(tw);
  if (f == g) return -1;
  const int a = mesh_.tail(h), b = mesh_.tip(h), x = mesh_.tail(M::prev(h)), y = mesh_.tail(M::prev(tw));
  const double l = mesh_.length(h);
  const Vec2 pa(0.0, 0.0), pb(l, 0.0), q(t * l, 0.0);
  const Vec2 px = layoutThirdVertex(l, mesh_.length(M::prev(h)), mesh_.length(M::next(h)));
  const Vec2 py = layoutBelow(l, mesh_.length(M::next(tw)), mesh_.length(M::prev(tw)));
  const double da = t * l, db = (1.0 - t) * l, dx = (q - px).norm(), dy = (q - py).norm();
  if (!(std::min({da, db, dx, dy}) > kInsertGuard * l)) return -1;
  const double atX = std::clamp(angleBetween(pa - px, q - px), 0.0, mesh_.cornerAngle(M::prev(h)));
  const double atY = std::clamp(angleBetween(pb - py, q - py), 0.0, mesh_.cornerAngle(M::prev(tw)));
  const std::vector<TracePlan> plans = {{a, mesh_.he[h].signpost, da},
                                        {b, mesh_.he[tw].signpost, db},
                                        {x, mesh_.he[M::prev(h)].signpost + atX, dx},
                                        {y, mesh_.he[M::prev(tw)].signpost + atY, dy}};
  const int chosen = pickPlan(plans, inputVertexCount_);
  Located where;
  if (!locate(plans[chosen], &where)) return -1;
  const int v = addVertex(where.at, false);
  const double signA = mesh_.he[h].signpost, signB = mesh_.he[tw].signpost;
  // Faces f = (a, v, x), f1 = (v, b, x), g = (b, v, y), g1 = (v, a, y).
  const int f1 = mesh_.faceCount(), g1 = f1 + 1;
  mesh_.tri.push_back({v, b, x});
  mesh_.tri.push_back({v, a, y});
  mesh_.he.resize(mesh_.he.size() + 6);
  moveHalfedges<4>(mesh_.he, {M::prev(h), M::next(h), M::prev(tw), M::next(tw)},
                   {3 * f + 2, 3 * f1 + 1, 3 * g + 2, 3 * g1 + 1});
  mesh_.tri[f] = {a, v, x};
  mesh_.tri[g] = {b, v, y};
  link(3 * f, 3 * g1, da);
  link(3 * f + 1, 3 * f1 + 2, dx);
  link(3 * f1, 3 * g, db);
  link(3 * g + 1, 3 * g1 + 2, dy);
  mesh_.he[3 * f].signpost = signA;
  mesh_.he[3 * g].signpost = signB;
  mesh_.updateSignpostFromClockwise(3 * f1 + 2);  // x -> v
  mesh_.updateSignpostFromClockwise(3 * g1 + 2);  // y -> v
  mesh_.he[3 * f1].signpost = 0.0;                // v -> b (the old edge's direction)
  mesh_.he[3 * g1].signpost = kPi;                // v -> a
  mesh_.he[3 * f + 1].signpost = argument(px - q);
  mesh_.he[3 * g + 1].signpost = argument(py - q);
  const std::array<int, 4> toPlanned = {3 * g1, 3 * f1, 3 * f + 1, 3 * g + 1};  // v -> a, b, x, y
  alignVertex(v, toPlanned[chosen], where);
  for (int face : {f, f1, g, g1}) {
    for (int k = 0; k < 3; ++k) mesh_.claimVertexHalfedge(3 * face + k);
    touchFace(face);
  }
  return v;
}

int IntrinsicTriangulation::splitBoundaryEdge(int h, double t) {
  using M = SignpostMesh;
  const int f = M::face(h);
  const int a = mesh_.tail(h), b = mesh_.tip(h), x = mesh_.tail(M::prev(h));
  const double l = mesh_.length(h);
  const Vec2 q(t * l, 0.0);
  const Vec2 px = layoutThirdVertex(l, mesh_.length(M::prev(h)), mesh_.length(M::next(h)));
  const double da = t * l, db = (1.0 - t) * l, dx = (q - px).norm();
  if (!(std::min({da, db, dx}) > kInsertGuard * l)) return -1;
  const SignpostHalfedge old = mesh_.he[h];
  const int v = addVertex(boundaryPoint(h, t), true);
  // Faces f = (a, v, x), f1 = (v, b, x); both halves run along the same input boundary halfedge.
  const int f1 = mesh_.faceCount();
  mesh_.tri.push_back({v, b, x});
  mesh_.he.resize(mesh_.he.size() + 3);
  moveHalfedges<2>(mesh_.he, {M::prev(h), M::next(h)}, {3 * f + 2, 3 * f1 + 1});
  mesh_.tri[f] = {a, v, x};
  mesh_.he[3 * f] = SignpostHalfedge{-1, da, old.signpost, old.inputHalfedge};
  mesh_.he[3 * f1] = SignpostHalfedge{-1, db, 0.0, old.inputHalfedge};
  link(3 * f + 1, 3 * f1 + 2, dx);
  mesh_.updateSignpostFromClockwise(3 * f + 1);   // v -> x, from v -> b
  mesh_.updateSignpostFromClockwise(3 * f1 + 2);  // x -> v, from x -> a
  // Direction 0 of v is along the input boundary halfedge, in the layout of its face.
  const int ih = old.inputHalfedge, k = ih % 3;
  const std::array<Vec2, 3> p = input_.layout(M::face(ih));
  offset_[v] = argument(p[(k + 1) % 3] - p[k]);
  for (int face : {f, f1}) {
    for (int j = 0; j < 3; ++j) mesh_.claimVertexHalfedge(3 * face + j);
    touchFace(face);
  }
  return v;
}

}  // namespace gr
