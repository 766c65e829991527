#include "core/geodesic/detail/acute_split.h"

#include <cmath>

#include "core/base/math.h"
#include "core/geodesic/detail/unfold.h"
#include "core/mesh/face_geometry.h"

namespace gr {
namespace {

/// The corner of the face of `corner` whose vertex is v.
int cornerAt(const TriMesh& m, int corner, int v) {
  const int base = corner - corner % 3;
  for (int k = 0; k < 3; ++k)
    if (m.vertex(base + k) == v) return base + k;
  return -1;
}

/// Cosine of the angle at corner c: from the positions (a dot product, exact for right angles of
/// grid meshes) or, on an intrinsic triangulation, from its lengths (law of cosines).
double cornerCosine(const TriMesh& m, const CornerLengths& length, int c) {
  const int x = m.vertex(c), a = m.vertex(TriMesh::next(c)), b = m.vertex(TriMesh::prev(c));
  if (!length.intrinsic()) {
    const Vec3& px = m.positions[x];
    const Vec3 ea = m.positions[a] - px, eb = m.positions[b] - px;
    return ea.dot(eb) / (ea.norm() * eb.norm());
  }
  const double la = length(TriMesh::prev(c)), lb = length(TriMesh::next(c)), lab = length(c);
  return (la * la + lb * lb - lab * lab) / (2.0 * la * lb);
}

/// Whether the corner c is obtuse (its two edges point apart), without the cosine's square roots
/// and division: the sign of the dot product, or of la^2 + lb^2 - lab^2 on an intrinsic
/// triangulation. A zero-length side makes no obtuse corner.
bool isObtuse(const TriMesh& m, const CornerLengths& length, int c) {
  if (!length.intrinsic()) {
    const Vec3& px = m.positions[m.vertex(c)];
    return (m.positions[m.vertex(TriMesh::next(c))] - px).dot(m.positions[m.vertex(TriMesh::prev(c))] - px) < 0.0;
  }
  const double la = length(TriMesh::prev(c)), lb = length(TriMesh::next(c)), lab = length(c);
  return la > 0.0 && lb > 0.0 && la * la + lb * lb - lab * lab < 0.0;
}

bool findSplit(const TriMesh& m, const CornerLengths& length, int c, int maxUnfoldings, AcuteSplit& out) {
  const int x = m.vertex(c), a = m.vertex(TriMesh::next(c)), b = m.vertex(TriMesh::prev(c));
  const double la = length(TriMesh::prev(c)), lb = length(TriMesh::next(c));  // |XA|, |XB|
  if (la <= 0.0 || lb <= 0.0) return false;
  const double cosTheta = cornerCosine(m, length, c);
  if (!(cosTheta < 0.0)) return false;
  const double theta = std::acos(std::max(-1.0, cosTheta));
  const double halfPi = 0.5 * kPi;
  const Vec2 pa(la, 0.0), pb(lb * std::cos(theta), lb * std::sin(theta));

  // The current edge (p: A side of the bisector, q: B side) and the corner facing it.
  int pVert = a, qVert = b, facing = c;
  Vec2 p = pa, q = pb, third(0.0, 0.0);
  for (int step = 0; step < maxUnfoldings; ++step) {
    const int d = m.oppositeCorner[facing];
    if (d < 0) return false;  // boundary or non-manifold edge
    const int r = m.vertex(d);
    if (r == x || r == a || r == b) return false;
    // In the face of d, the edge (r, p) faces the corner at q and the edge (r, q) the corner at p.
    const int atP = cornerAt(m, d, pVert), atQ = cornerAt(m, d, qVert);
    if (atP < 0 || atQ < 0) return false;
    const Vec2 pr = unfold(p, q, third, length(atQ), length(atP));
    const double phi = std::atan2(pr.y(), pr.x());
    if (phi > theta - halfPi && phi < halfPi && phi > 0.0 && phi < theta) {
      out = {c, r, pr.norm(), (pr - pa).norm(), (pr - pb).norm(), la, lb};
      return true;
    }
    // Continue across the edge of triangle (p, q, r) that the bisector leaves through.
    if (phi < 0.5 * theta) {  // r is on the A side: the bisector exits through (r, q)
      facing = cornerAt(m, d, pVert);
      third = p;
      p = pr;
      pVert = r;
    } else {
      facing = cornerAt(m, d, qVert);
      third = q;
      q = pr;
      qVert = r;
    }
    if (facing < 0) return false;
  }
  return false;
}

}  // namespace

AcuteSplits findAcuteSplits(const TriMesh& mesh, const std::vector<double>* cornerLength, int maxUnfoldings) {
  const CornerLengths length(mesh, cornerLength);
  AcuteSplits s;
  const int nc = 3 * mesh.faceCount();
  s.splitOfCorner.assign(nc, -1);
  AcuteSplit split;
  const bool measured = !length.intrinsic() && mesh.faceCount() > 0;
  TriangulationTally tally(measured ? mesh.boundingBoxDiagonal() : 0.0);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (measured) {
      const Tri& t = mesh.triangles[f];
      tally.add(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    }
    for (int k = 0; k < 3; ++k) {  // corner 3f + k: obtuse if its two edges point apart
      const int c = 3 * f + k;
      if (!isObtuse(mesh, length, c)) continue;
      ++s.obtuseCorners;
      if (findSplit(mesh, length, c, maxUnfoldings, split)) {
        s.splitOfCorner[c] = static_cast<int>(s.splits.size());
        s.splits.push_back(split);
      }
    }
  }
  if (measured) s.quality = tally.result();
  s.byVertexBegin.assign(mesh.vertexCount() + 1, 0);
  for (const AcuteSplit& sp : s.splits) ++s.byVertexBegin[sp.vertex + 1];
  for (int v = 0; v < mesh.vertexCount(); ++v) s.byVertexBegin[v + 1] += s.byVertexBegin[v];
  s.byVertex.resize(s.splits.size());
  std::vector<int> fill(s.byVertexBegin.begin(), s.byVertexBegin.end() - 1);
  for (int i = 0; i < static_cast<int>(s.splits.size()); ++i) s.byVertex[fill[s.splits[i].vertex]++] = i;
  return s;
}

}  // namespace gr
