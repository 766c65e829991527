#include "core/remesh/delaunay_flips.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/base/math.h"
#include "core/mesh/face_geometry.h"

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

/// A face with an angle over this is a cap: its normal says little (which side of the line through
/// the other two corners rounding, a crease or a fold put the third), so it does not block a flip.
constexpr double kCapAngle = 170.0 * kPi / 180.0;

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

/// Refuses what the flips cannot work on: no faces, a non-manifold mesh, faces not oriented alike.
Status checkFlipInput(const TriMesh& mesh) {
  if (mesh.faceCount() == 0) return invalidInput("Delaunay flips: the mesh has no faces");
  if (!mesh.topology.isManifold())
    return nonManifold("Delaunay flips need a manifold mesh; this one has " +
                       std::to_string(mesh.topology.nonManifoldEdges) + " non-manifold edges and " +
                       std::to_string(mesh.topology.nonManifoldVertices) + " non-manifold vertices");
  if (mesh.topology.inconsistentEdges > 0)
    return invalidInput("Delaunay flips: the faces are not oriented coherently (" +
                        std::to_string(mesh.topology.inconsistentEdges) +
                        " edges have two faces that disagree): orient them first (orientCoherently)");
  return Status::ok();
}

/// Work list of the interior edges to check, each as the corner of its lower-numbered side.
class EdgeQueue {
 public:
  /// Every interior edge of the mesh, in corner order.
  explicit EdgeQueue(const TriMesh& mesh) : opp_(mesh.oppositeCorner), queued_(3 * mesh.triangles.size(), 0) {
    for (int c = 0; c < 3 * mesh.faceCount(); ++c)
      if (opp_[c] >= 0 && c < opp_[c]) {
        work_.push_back(c);
        queued_[c] = 1;
      }
  }
  bool empty() const { return work_.empty(); }
  /// The edge checked next (the last queued).
  int pop() {
    const int c = work_.back();
    work_.pop_back();
    queued_[c] = 0;
    return c;
  }
  /// Queues the edge facing corner c, unless it is a boundary or already queued.
  void push(int c) {
    if (opp_[c] < 0) return;
    const int k = std::min(c, opp_[c]);
    if (!queued_[k]) {
      queued_[k] = 1;
      work_.push_back(k);
    }
  }

 private:
  const std::vector<int>& opp_;  ///< the mesh's opposite corners, kept up to date by the flips
  std::vector<int> work_;
  std::vector<char> queued_;
};

/// Whether flipping the interior edge facing corner c (o on the other side), faces (x, a, b) and
/// (y, b, a), keeps the surface: (x, y) not already an edge, the new pair nearly coplanar, the
/// old pair too unless one is a cap (`capAllowed`), both new faces the same side up.
bool flipKeepsSurface(const TriMesh& mesh, int c, int o, double cosFeature, bool capAllowed) {
  const std::vector<Tri>& tris = mesh.triangles;
  const std::vector<Vec3>& pos = mesh.positions;
  const auto V = [&](int k) { return tris[k / 3][k % 3]; };
  const int x = V(c), a = V(TriMesh::next(c)), b = V(TriMesh::prev(c)), y = V(o);
  if (x == y || isNeighbour(mesh, c, y)) return false;
  const Vec3 &px = pos[x], &pa = pos[a], &pb = pos[b], &py = pos[y];
  const Vec3 n1 = unitNormal(px, pa, pb), n2 = unitNormal(py, pb, pa);
  const Vec3 m1 = unitNormal(px, pa, py), m2 = unitNormal(px, py, pb);
  if (m1.isZero() || m2.isZero()) return false;
  if (m1.dot(m2) < cosFeature) return false;
  if (!capAllowed && !n1.isZero() && !n2.isZero() && n1.dot(n2) < cosFeature) return false;
  const Vec3 before = (pa - px).cross(pb - px) + (pb - py).cross(pa - py);
  return m1.dot(before) > 0.0 && m2.dot(before) > 0.0;
}

/// Whether the interior edge facing corner c (o on the other side) should be flipped: not locally
/// Delaunay, the flip keeps the surface (above) and lowers the facing angles' sum.
bool shouldFlip(const TriMesh& mesh, int c, int o, double cosFeature, double tolerance) {
  const std::vector<Tri>& tris = mesh.triangles;
  const std::vector<Vec3>& pos = mesh.positions;
  const auto V = [&](int k) { return tris[k / 3][k % 3]; };
  // Faces (x, a, b) and (y, b, a) share the edge (a, b); x faces it in one, y in the other.
  const int x = V(c), a = V(TriMesh::next(c)), b = V(TriMesh::prev(c)), y = V(o);
  if (x == y) return false;
  const Vec3 &px = pos[x], &pa = pos[a], &pb = pos[b], &py = pos[y];
  // Two acute facing angles sum to less than pi: locally Delaunay without the arc tangents.
  if (tolerance >= 0.0 && (pa - px).dot(pb - px) > 0.0 && (pb - py).dot(pa - py) > 0.0) return false;
  const double atX = angleAt(px, pa, pb), atY = angleAt(py, pb, pa);
  const double facing = atX + atY;
  if (facing <= kPi + tolerance) return false;  // locally Delaunay
  // A cap (x, or y, within a degree of the line through a and b) is no feature: flipping it
  // away moves the surface by less than its own height, and its normal only says on which
  // side of the line rounding or a crease put x.
  if (!flipKeepsSurface(mesh, c, o, cosFeature, atX > kCapAngle || atY > kCapAngle)) return false;
  // The flip must make the edge Delaunay: the new facing angles (at a and b) sum to less.
  return !(angleAt(pa, py, px) + angleAt(pb, px, py) >= facing - tolerance);
}

/// Smallest angle of the faces (x, a, y) and (x, y, b) that flipping (a, b) would make, in radians.
double smallestAngleAfterFlip(const Vec3& px, const Vec3& pa, const Vec3& pb, const Vec3& py) {
  return std::min({angleAt(px, pa, py), angleAt(pa, py, px), angleAt(py, px, pa), angleAt(px, py, pb),
                   angleAt(py, pb, px), angleAt(pb, px, py)});
}

/// Flips the edge facing corner c (o on the other side): faces (x, a, b), (y, b, a) become
/// (x, a, y), (y, b, x) in place, with their opposite corners relinked.
void flipEdge(TriMesh& mesh, int c, int o) {
  std::vector<Tri>& tris = mesh.triangles;
  std::vector<int>& opp = mesh.oppositeCorner;
  const auto V = [&](int k) { return tris[k / 3][k % 3]; };
  const int x = V(c), a = V(TriMesh::next(c)), b = V(TriMesh::prev(c)), y = V(o);
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
}

/// Up to `passes` sweeps over the interior edges, in corner order, flipping each edge (facing
/// corner c, o on the other side, as faces (x, a, b) and (y, b, a)) for which wanted(c, o, x, a,
/// b, y) holds, until a sweep flips none; then the vertex lists are rebuilt. Returns the flips.
template <class Wanted>
int sweepFlips(TriMesh& mesh, int passes, Wanted wanted) {
  const std::vector<int>& opp = mesh.oppositeCorner;
  const auto V = [&](int k) { return mesh.triangles[k / 3][k % 3]; };
  int total = 0;
  for (int pass = 0; pass < passes; ++pass) {
    int flips = 0;
    for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
      const int o = opp[c];
      if (o < c) continue;  // each interior edge once (o < 0: boundary)
      if (!wanted(c, o, V(c), V(TriMesh::next(c)), V(TriMesh::prev(c)), V(o))) continue;
      flipEdge(mesh, c, o);
      ++flips;
    }
    total += flips;
    if (flips == 0) break;
  }
  if (total > 0) rebuildVertexCorners(mesh);
  return total;
}

}  // namespace

Expected<DelaunayFlipResult> flipToDelaunay(TriMesh& mesh, const DelaunayFlipParams& params) {
  if (Status s = checkFlipInput(mesh); !s) return s;
  DelaunayFlipResult r;
  const std::vector<int>& opp = mesh.oppositeCorner;
  const double cosFeature = std::cos(params.featureAngleDegrees * kPi / 180.0);
  const double tolerance = params.toleranceDegrees * kPi / 180.0;
  EdgeQueue work(mesh);
  const long maxFlips = long(params.maxFlipsPerFace) * mesh.faceCount();
  while (!work.empty() && r.flips < maxFlips) {
    const int c = work.pop();
    const int o = opp[c];
    if (o < 0) continue;
    if (!shouldFlip(mesh, c, o, cosFeature, tolerance)) continue;
    flipEdge(mesh, c, o);
    ++r.flips;
    // The quad's four outer edges, as corners of the new faces f = c / 3 and g = o / 3.
    const int f0 = 3 * (c / 3), g0 = 3 * (o / 3);
    for (int k : {f0, f0 + 2, g0, g0 + 2}) work.push(k);
  }
  // oppositeCorner is up to date and flips keep the topology: only the vertex lists change.
  if (r.flips > 0) rebuildVertexCorners(mesh);
  return r;
}

Expected<DelaunayFlipResult> flipTowardValenceSix(TriMesh& mesh, const ValenceFlipParams& params) {
  if (Status s = checkFlipInput(mesh); !s) return s;
  const std::vector<int>& opp = mesh.oppositeCorner;
  const int nv = mesh.vertexCount();
  std::vector<int> valence(nv, 0), target(nv, 6);
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    ++valence[mesh.vertex(c)];
    if (opp[c] < 0) target[mesh.vertex(TriMesh::next(c))] = 4;  // one boundary edge starts there
  }
  for (int v = 0; v < nv; ++v) valence[v] += target[v] == 4;  // a boundary fan has one edge more than faces
  const auto excess = [&](int v, int change) {
    const int e = valence[v] + change - target[v];
    return e * e;
  };
  const double cosFeature = std::cos(params.featureAngleDegrees * kPi / 180.0);
  const double minAngle = params.minAngleDegrees * kPi / 180.0;
  const std::vector<Vec3>& pos = mesh.positions;
  DelaunayFlipResult r;
  r.flips = sweepFlips(mesh, params.passes, [&](int c, int o, int x, int a, int b, int y) {
    if (valence[a] <= 3 || valence[b] <= 3) return false;
    if (excess(a, -1) + excess(b, -1) + excess(x, 1) + excess(y, 1) >=
        excess(a, 0) + excess(b, 0) + excess(x, 0) + excess(y, 0))
      return false;
    if (smallestAngleAfterFlip(pos[x], pos[a], pos[b], pos[y]) < minAngle) return false;
    if (!flipKeepsSurface(mesh, c, o, cosFeature, false)) return false;
    if (params.accept && !params.accept(c)) return false;
    --valence[a];
    --valence[b];
    ++valence[x];
    ++valence[y];
    return true;
  });
  return r;
}

Expected<DelaunayFlipResult> flipToBetterAngles(TriMesh& mesh, const AngleFlipParams& params) {
  if (Status s = checkFlipInput(mesh); !s) return s;
  const double cosFeature = std::cos(params.featureAngleDegrees * kPi / 180.0);
  const double minAngle = params.minAngleDegrees * kPi / 180.0;
  constexpr double k30 = kPi / 6, kRise = 1e-6;
  const std::vector<Vec3>& pos = mesh.positions;
  const auto smallest = [&](int p, int q, int s) {
    return std::min(
        {angleAt(pos[p], pos[q], pos[s]), angleAt(pos[q], pos[s], pos[p]), angleAt(pos[s], pos[p], pos[q])});
  };
  DelaunayFlipResult r;
  r.flips = sweepFlips(mesh, params.passes, [&](int c, int o, int x, int a, int b, int y) {
    if (x == y) return false;
    // Faces (x, a, b), (y, b, a) now; (x, a, y), (y, b, x) after.
    const double f = smallest(x, a, b), g = smallest(y, b, a);
    const int under = (f < k30) + (g < k30);
    if (under == 0) return false;
    const double f2 = smallest(x, a, y), g2 = smallest(y, b, x);
    const int underAfter = (f2 < k30) + (g2 < k30);
    if (std::min(f2, g2) < minAngle) return false;
    if (underAfter > under || (underAfter == under && std::min(f2, g2) <= std::min(f, g) + kRise)) return false;
    return flipKeepsSurface(mesh, c, o, cosFeature, false);
  });
  return r;
}

int flipOneEdge(TriMesh& mesh, int corner, double featureAngleDegrees) {
  const int o = mesh.oppositeCorner[corner];
  if (o < 0 || mesh.vertex(corner) == mesh.vertex(o)) return -1;
  const double cosFeature = std::cos(featureAngleDegrees * kPi / 180.0);
  if (featureAngleDegrees >= 0 && !flipKeepsSurface(mesh, corner, o, cosFeature, false)) return -1;
  flipEdge(mesh, corner, o);
  rebuildVertexCorners(mesh);
  return 3 * (corner / 3) + 1;  // a, in the new face (x, a, y), faces the new edge (y, x)
}

}  // namespace gr
