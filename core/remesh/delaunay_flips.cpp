#include "core/remesh/delaunay_flips.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

#include "core/base/math.h"

namespace gr {
namespace {

/// Whether vertex y is a neighbour of the vertex at `corner`, turning around that vertex through
/// the (up to date) opposite corners: both ways if the fan is open.
bool isNeighbour(const TriMesh& m, int corner, int y) {
  for (int dir = 0; dir < 2; ++dir) {
    int k = corner;
    while (true) {
      if (m.vertex(TriMesh::next(k)) == y || m.vertex(TriMesh::prev(k)) == y) return true;
      const int o = m.oppositeCorner[dir == 0 ? TriMesh::prev(k) : TriMesh::next(k)];
      if (o < 0) break;  // the fan is open: turn the other way from the start
      k = dir == 0 ? TriMesh::prev(o) : TriMesh::next(o);
      if (k == corner) return false;  // all the way round
    }
  }
  return false;
}

/// Angle at p of the triangle (p, q, r), in radians.
double angleAt(const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 u = q - p, w = r - p;
  return std::atan2(u.cross(w).norm(), u.dot(w));
}

constexpr double kCapAngle = 179.0 * kPi / 180.0;

/// Unit normal of (p, q, r), or zero when the triangle is too flat for its normal to mean
/// anything: twice its area under 1e-4 times its squared longest edge (its largest angle within
/// about 0.01 degree of 180). Three samples on one straight line of the input (a crease, an edge
/// of a subdivided face) stored in MeshLab's floats are off the line by rounding only, so such a
/// cap's normal points anywhere around the line; it must neither block the flip that removes the
/// cap (as a crease would) nor be created by one.
Vec3 unitNormal(const Vec3& p, const Vec3& q, const Vec3& r) {
  const Vec3 n = (q - p).cross(r - p);
  const double scale = std::max({(q - p).squaredNorm(), (r - q).squaredNorm(), (p - r).squaredNorm()});
  const double len = n.norm();
  return len > 1e-4 * scale ? Vec3(n / len) : Vec3::Zero();
}

}  // namespace

DelaunayFlipResult flipToDelaunay(TriMesh& mesh, const DelaunayFlipParams& params) {
  DelaunayFlipResult r;
  if (!mesh.topology.isManifold() || mesh.topology.inconsistentEdges > 0 || mesh.faceCount() == 0) return r;
  std::vector<Tri>& tris = mesh.triangles;
  std::vector<int>& opp = mesh.oppositeCorner;
  const std::vector<Vec3>& pos = mesh.positions;
  const double cosFeature = std::cos(params.featureAngleDegrees * kPi / 180.0);
  const double tolerance = params.toleranceDegrees * kPi / 180.0;
  const auto V = [&](int c) { return tris[c / 3][c % 3]; };

  // Work list of corners; each interior edge is checked from the corner of its lower-numbered side.
  std::vector<int> work;
  std::vector<char> queued(3 * tris.size(), 0);
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    if (opp[c] >= 0 && c < opp[c]) {
      work.push_back(c);
      queued[c] = 1;
    }
  const auto enqueue = [&](int c) {
    if (opp[c] < 0) return;
    const int k = std::min(c, opp[c]);
    if (!queued[k]) {
      queued[k] = 1;
      work.push_back(k);
    }
  };
  const long maxFlips = long(params.maxFlipsPerFace) * mesh.faceCount();
  while (!work.empty() && r.flips < maxFlips) {
    const int c = work.back();
    work.pop_back();
    queued[c] = 0;
    const int o = opp[c];
    if (o < 0) continue;
    // Faces (x, a, b) and (y, b, a) share the edge (a, b); x faces it in one, y in the other.
    const int x = V(c), a = V(TriMesh::next(c)), b = V(TriMesh::prev(c)), y = V(o);
    if (x == y) continue;
    const Vec3 &px = pos[x], &pa = pos[a], &pb = pos[b], &py = pos[y];
    // Two acute facing angles sum to less than pi: locally Delaunay without the arc tangents.
    if (tolerance >= 0.0 && (pa - px).dot(pb - px) > 0.0 && (pb - py).dot(pa - py) > 0.0) continue;
    const double atX = angleAt(px, pa, pb), atY = angleAt(py, pb, pa);
    const double facing = atX + atY;
    if (facing <= kPi + tolerance) continue;  // locally Delaunay
    if (isNeighbour(mesh, c, y)) continue;  // (x, y) is already an edge
    // Feature and orientation checks: both old and new pairs nearly coplanar, same side up.
    const Vec3 n1 = unitNormal(px, pa, pb), n2 = unitNormal(py, pb, pa);
    const Vec3 m1 = unitNormal(px, pa, py), m2 = unitNormal(px, py, pb);
    if (m1.isZero() || m2.isZero()) continue;
    if (m1.dot(m2) < cosFeature) continue;
    // A cap (x, or y, within a degree of the line through a and b) is no feature: flipping it
    // away moves the surface by less than its own height, and its normal only says on which
    // side of the line rounding or a crease put x.
    const bool cap = atX > kCapAngle || atY > kCapAngle;
    if (!cap && !n1.isZero() && !n2.isZero() && n1.dot(n2) < cosFeature) continue;
    const Vec3 before = (pa - px).cross(pb - px) + (pb - py).cross(pa - py);
    if (m1.dot(before) <= 0.0 || m2.dot(before) <= 0.0) continue;
    // The flip must make the edge Delaunay: the new facing angles (at a and b) sum to less.
    if (angleAt(pa, py, px) + angleAt(pb, px, py) >= facing - tolerance) continue;

    // Outer corners: the ones facing x->a (corner of b in f), b->x (a in f), a->y (b in g), y->b (a in g).
    const int f = c / 3, g = o / 3;
    const int oXA = opp[TriMesh::prev(c)], oBX = opp[TriMesh::next(c)];
    const int oAY = opp[TriMesh::next(o)], oYB = opp[TriMesh::prev(o)];
    // New faces: f = (x, a, y), g = (y, b, x).
    tris[f] = {x, a, y};
    tris[g] = {y, b, x};
    const int f0 = 3 * f, g0 = 3 * g;
    const auto link = [&](int corner, int other) {
      opp[corner] = other;
      if (other >= 0) opp[other] = corner;
    };
    link(f0 + 0, oAY);     // x faces a->y
    link(f0 + 1, g0 + 1);  // a and b face the new diagonal
    link(f0 + 2, oXA);     // y faces x->a
    link(g0 + 0, oBX);     // y faces b->x
    link(g0 + 2, oYB);     // x faces y->b
    ++r.flips;
    for (int k : {f0, f0 + 2, g0, g0 + 2}) enqueue(k);
  }
  // oppositeCorner is up to date and flips keep the topology: only the vertex lists change.
  if (r.flips > 0) rebuildVertexCorners(mesh);
  return r;
}

}  // namespace gr
