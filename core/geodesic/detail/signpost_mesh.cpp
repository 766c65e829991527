#include "core/geodesic/detail/signpost_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/base/math.h"

namespace gr {

double angleFromLengths(double a, double b, double c) {
  // tan(A / 2) = sqrt((s - b)(s - c) / (s (s - a))): no arc cosine of a number near +-1.
  const double s = 0.5 * (a + b + c);
  const double num = std::max(0.0, (s - b) * (s - c));
  const double den = std::max(0.0, s * (s - a));
  if (den <= 0.0) return num > 0.0 ? kPi : 0.0;
  return 2.0 * std::atan2(std::sqrt(num), std::sqrt(den));
}

double tanHalfSquaredFromLengths(double a, double b, double c) {
  const double s = 0.5 * (a + b + c);
  const double num = std::max(0.0, (s - b) * (s - c));
  const double den = std::max(0.0, s * (s - a));
  if (den <= 0.0) return num > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  return num / den;
}

double angleBetween(const Vec2& u, const Vec2& w) { return std::atan2(cross2(u, w), u.dot(w)); }

double SignpostMesh::cornerAngle(int h) const {
  return angleFromLengths(he[next(h)].length, he[h].length, he[prev(h)].length);
}

double SignpostMesh::cornerTanHalfSquared(int h) const {
  return tanHalfSquaredFromLengths(he[next(h)].length, he[h].length, he[prev(h)].length);
}

std::array<Vec2, 3> SignpostMesh::layout(int f) const {
  const double l01 = he[3 * f].length, l12 = he[3 * f + 1].length, l20 = he[3 * f + 2].length;
  return {Vec2(0.0, 0.0), Vec2(l01, 0.0), layoutThirdVertex(l01, l20, l12)};
}

double SignpostMesh::standardAngle(int v, double angle) const {
  const double sum = vert[v].angleSum;
  if (vert[v].onBoundary) return std::clamp(angle, 0.0, sum);
  if (!(sum > 0.0)) return 0.0;
  double a = std::fmod(angle, sum);
  if (a < 0.0) a += sum;
  return a >= sum ? 0.0 : a;
}

void SignpostMesh::updateSignpostFromClockwise(int h) {
  const int t = he[h].twin;
  if (t < 0) {
    he[h].signpost = 0.0;
    return;
  }
  const int cw = next(t);
  he[h].signpost = standardAngle(tail(h), he[cw].signpost + cornerAngle(cw));
}

void SignpostMesh::claimVertexHalfedge(int h) {
  SignpostVertex& v = vert[tail(h)];
  if (!v.onBoundary || he[h].twin < 0) v.halfedge = h;
}

namespace {

/// Twins and lengths from the mesh's opposite corners: halfedge 3f+k is the edge facing corner
/// 3f+(k+2)%3, and the corner o facing it in the other face gives that face's halfedge next(o).
void linkHalfedges(SignpostMesh& m, const TriMesh& mesh, const std::vector<double>& cornerLength) {
  const int corners = 3 * mesh.faceCount();
  m.he.assign(corners, SignpostHalfedge{});
  for (int h = 0; h < corners; ++h) {
    const int facing = SignpostMesh::prev(h);
    const int o = mesh.oppositeCorner[facing];
    m.he[h].twin = o >= 0 ? TriMesh::next(o) : -1;
    m.he[h].length = cornerLength[facing];
    if (o < 0) m.he[h].inputHalfedge = h;
  }
}

/// Boundary flags and each vertex's first outgoing halfedge (the boundary one on the boundary).
void findVertexHalfedges(SignpostMesh& m) {
  m.vert.assign(m.vertexCount(), SignpostVertex{});
  for (int h = 0; h < 3 * m.faceCount(); ++h)
    if (m.he[h].twin < 0) m.vert[m.tail(h)].onBoundary = true;
  for (int h = 0; h < 3 * m.faceCount(); ++h) {
    SignpostVertex& v = m.vert[m.tail(h)];
    if (v.halfedge < 0 || (v.onBoundary && m.he[h].twin < 0)) v.halfedge = h;
  }
}

/// Signposts and angle sums: corner angles accumulated counter-clockwise from each vertex's first
/// halfedge.
void accumulateSignposts(SignpostMesh& m) {
  for (SignpostVertex& v : m.vert) {
    if (v.halfedge < 0) continue;
    double running = 0.0;
    int h = v.halfedge;
    int guard = 3 * m.faceCount();  // a manifold fan closes or ends long before
    do {
      m.he[h].signpost = running;
      running += m.cornerAngle(h);
      h = m.nextAround(h);
    } while (h >= 0 && h != v.halfedge && --guard > 0);
    v.angleSum = running;
  }
}

}  // namespace

SignpostMesh buildSignpostMesh(const TriMesh& mesh, const std::vector<double>& cornerLength) {
  SignpostMesh m;
  m.tri = mesh.triangles;
  m.vert.resize(mesh.vertexCount());
  linkHalfedges(m, mesh, cornerLength);
  findVertexHalfedges(m);
  accumulateSignposts(m);
  return m;
}

}  // namespace gr
