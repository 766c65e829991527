#include "tests/support/cad_meshes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <utility>

#include "core/base/math.h"

namespace gr::test {
namespace {

using Vec2 = Eigen::Vector2d;

/// Twice the signed area of (o, a, b): > 0 if the turn o -> a -> b is counter-clockwise.
double turn(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

/// p in the closed triangle (a, b, c), given counter-clockwise.
bool inTriangle(const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
  return turn(a, b, p) >= 0.0 && turn(b, c, p) >= 0.0 && turn(c, a, p) >= 0.0;
}

/// The polygon being clipped: a cycle of nodes, each one occurrence of a point (a bridge to a
/// hole makes two occurrences of each of its ends).
struct Cycle {
  const std::vector<Vec2>& points;
  std::vector<int> point, next, prev;
  int size = 0;

  const Vec2& at(int node) const { return points[point[node]]; }
  /// A new node for point p after `node` (-1: the first node of an empty cycle).
  int insertAfter(int node, int p) {
    const int n = static_cast<int>(point.size());
    point.push_back(p);
    next.push_back(node < 0 ? n : next[node]);
    prev.push_back(node < 0 ? n : node);
    if (node >= 0) {
      prev[next[node]] = n;
      next[node] = n;
    }
    ++size;
    return n;
  }
  void remove(int node) {
    next[prev[node]] = next[node];
    prev[next[node]] = prev[node];
    --size;
  }
  /// The direction from the node's point to q lies inside the polygon's angle at the node.
  bool locallyInside(int node, const Vec2& q) const {
    const Vec2 &a = at(prev[node]), &b = at(node), &c = at(next[node]);
    if (turn(a, b, c) > 0.0) return turn(a, b, q) > 0.0 && turn(b, c, q) > 0.0;
    return turn(a, b, q) > 0.0 || turn(b, c, q) > 0.0;
  }
};

/// The node of the current polygon that the hole's rightmost point m is joined to (Eberly): the
/// nearest edge hit by the ray from m towards +x, its endpoint of larger x, unless a vertex
/// inside the triangle (m, hit, endpoint) hides it; then that vertex of smallest angle to the ray.
/// Only upward edges can be hit first (the interior is left of each edge, so west of an upward
/// one); this also picks, of the two copies of a bridge, the one that faces m.
int bridgeTarget(const Cycle& c, int start, const Vec2& m) {
  double hitX = std::numeric_limits<double>::infinity();
  int hitNode = -1, node = start;
  do {
    const Vec2 &a = c.at(node), &b = c.at(c.next[node]);
    if (a.y() <= m.y() && b.y() > m.y()) {
      const double x = a.x() + (m.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (x > m.x() && x < hitX) hitX = x, hitNode = node;
    }
    node = c.next[node];
  } while (node != start);
  if (hitNode < 0) throw std::runtime_error("earClip: a hole is not inside the outline");
  int target = c.at(c.next[hitNode]).x() > c.at(hitNode).x() ? c.next[hitNode] : hitNode;
  const Vec2 hit(hitX, m.y()), p = c.at(target);
  const bool ccw = turn(m, hit, p) > 0.0;
  double bestAngle = std::numeric_limits<double>::infinity(), bestDistance = bestAngle;
  node = start;
  do {
    const Vec2& q = c.at(node);
    const bool inside = node != target && q != p && (ccw ? inTriangle(q, m, hit, p) : inTriangle(q, m, p, hit));
    if (inside && c.locallyInside(node, m)) {
      const double angle = std::atan2(std::abs(q.y() - m.y()), q.x() - m.x()), distance = (q - m).norm();
      if (angle < bestAngle || (angle == bestAngle && distance < bestDistance))
        bestAngle = angle, bestDistance = distance, target = node;
    }
    node = c.next[node];
  } while (node != start);
  // Of several occurrences of the target point (ends of earlier bridges), the one that sees m.
  if (!c.locallyInside(target, m)) {
    node = start;
    do {
      if (c.point[node] == c.point[target] && c.locallyInside(node, m)) target = node;
      node = c.next[node];
    } while (node != start);
  }
  return target;
}

/// Joins the hole of points [first, first + count) to the polygon by a bridge from its rightmost
/// point: ..., target, m, (the hole from m around to m), m, target, ...
void bridgeHole(Cycle& c, int start, int first, int count) {
  int m = first;
  for (int i = first + 1; i < first + count; ++i)
    if (c.points[i].x() > c.points[m].x()) m = i;
  const int target = bridgeTarget(c, start, c.points[m]);
  int node = target;
  for (int k = 0; k <= count; ++k) node = c.insertAfter(node, first + (m - first + k) % count);
  c.insertAfter(node, c.point[target]);
}

bool isEar(const Cycle& c, int node) {
  const int pa = c.point[c.prev[node]], pb = c.point[node], pc = c.point[c.next[node]];
  const Vec2 &a = c.points[pa], &b = c.points[pb], &p = c.points[pc];
  if (!(turn(a, b, p) > 0.0)) return false;
  for (int k = c.next[c.next[node]]; k != c.prev[node]; k = c.next[k]) {
    const int q = c.point[k];
    if (q != pa && q != pb && q != pc && inTriangle(c.points[q], a, b, p)) return false;
  }
  return true;
}

/// Clips ears until three nodes are left; after an ear the next try is at the node after it (a
/// fan from the node before). Zero-width remains of a bridge (a point twice in a row, or a spike
/// p, q, p) are dropped without a triangle.
std::vector<Tri> clipEars(Cycle& c, int node) {
  std::vector<Tri> tris;
  int tries = 0;
  while (c.size > 3) {
    const int before = c.prev[node], after = c.next[node];
    if (c.point[node] == c.point[after] || c.point[before] == c.point[after]) {
      if (c.point[before] == c.point[after]) c.remove(after);
      c.remove(node);
      node = before, tries = 0;
    } else if (isEar(c, node)) {
      tris.push_back({c.point[before], c.point[node], c.point[after]});
      c.remove(node);
      node = after, tries = 0;
    } else {
      node = after;
      if (++tries > c.size) throw std::runtime_error("earClip: no ear left (the profile is not a simple polygon)");
    }
  }
  if (turn(c.at(c.prev[node]), c.at(node), c.at(c.next[node])) > 0.0)
    tris.push_back({c.point[c.prev[node]], c.point[node], c.point[c.next[node]]});
  return tris;
}

Polygon2 circle(const Vec2& centre, double radius, int segments, bool clockwise) {
  Polygon2 p;
  const double sign = clockwise ? -1.0 : 1.0;
  // Holes start 0.3 of a segment off the x axis: no two holes of a row share a y coordinate, so
  // no bridge ray runs through a vertex.
  const double offset = clockwise ? 0.3 : 0.0;
  for (int k = 0; k < segments; ++k) {
    const double t = sign * 2.0 * kPi * (k + offset) / segments;
    p.push_back(centre + radius * Vec2(std::cos(t), std::sin(t)));
  }
  return p;
}

}  // namespace

std::vector<Tri> earClip(const Polygon2& outline, const std::vector<Polygon2>& holes) {
  std::vector<Vec2> points = outline;
  std::vector<std::pair<int, int>> holeRanges;  // first point, count
  for (const Polygon2& h : holes) {
    holeRanges.push_back({static_cast<int>(points.size()), static_cast<int>(h.size())});
    points.insert(points.end(), h.begin(), h.end());
  }
  Cycle c{points, {}, {}, {}};
  int node = -1;
  for (int i = 0; i < static_cast<int>(outline.size()); ++i) node = c.insertAfter(node, i);
  const int start = c.next[node];  // the outline's first point
  // Holes in decreasing order of their largest x: each bridge goes right, over merged holes only.
  const auto maxX = [&points](const std::pair<int, int>& h) {
    double x = -std::numeric_limits<double>::infinity();
    for (int i = h.first; i < h.first + h.second; ++i) x = std::max(x, points[i].x());
    return x;
  };
  std::stable_sort(holeRanges.begin(), holeRanges.end(),
                   [&maxX](const auto& a, const auto& b) { return maxX(a) > maxX(b); });
  for (const auto& [first, count] : holeRanges) bridgeHole(c, start, first, count);
  // Outline nodes are numbered as their points. Clipping starts halfway round the outline, so the
  // fans' apexes lie across the face from point 0 (vertex 0, the usual source): the hard case.
  return clipEars(c, static_cast<int>(outline.size()) / 2);
}

TriMesh extrudeProfile(const Polygon2& outline, const std::vector<Polygon2>& holes, double height) {
  const std::vector<Tri> cap = earClip(outline, holes);
  std::vector<Vec2> points = outline;
  std::vector<std::pair<int, int>> rings = {{0, static_cast<int>(outline.size())}};
  for (const Polygon2& h : holes) {
    rings.push_back({static_cast<int>(points.size()), static_cast<int>(h.size())});
    points.insert(points.end(), h.begin(), h.end());
  }
  const int n = static_cast<int>(points.size());
  std::vector<Vec3> positions;
  for (double z : {0.0, height})
    for (const Vec2& p : points) positions.emplace_back(p.x(), p.y(), z);
  std::vector<Tri> tris;
  for (const Tri& t : cap) {
    tris.push_back({t[0], t[2], t[1]});              // bottom, facing -z
    tris.push_back({n + t[0], n + t[1], n + t[2]});  // top, facing +z
  }
  // Sides: the interior is left of each ring's direction, so (b_i, b_j, t_j) faces outwards.
  for (const auto& [first, count] : rings)
    for (int k = 0; k < count; ++k) {
      const int i = first + k, j = first + (k + 1) % count;
      tris.push_back({i, j, n + j});
      tris.push_back({i, n + j, n + i});
    }
  Expected<TriMesh> mesh = buildTriMesh(std::move(positions), std::move(tris));
  if (!mesh) throw std::runtime_error("extrudeProfile: " + mesh.status().message);
  return std::move(mesh).value();
}

TriMesh cadGear(const CadGearParams& params) {
  // One tooth: (fraction of the pitch, height between root and tip): root arc, rising flank,
  // tip arc, falling flank, root arc up to the next tooth.
  static const double kTooth[][2] = {{0.0, 0.0},      {0.1, 0.0},  {0.2, 0.0},  {0.3, 0.0},  {0.35, 1 / 3.0},
                                     {0.4, 2 / 3.0},  {0.45, 1.0}, {0.55, 1.0}, {0.65, 1.0}, {0.7, 2 / 3.0},
                                     {0.75, 1 / 3.0}, {0.8, 0.0},  {0.9, 0.0}};
  const double tip = 0.5 * params.diameter, root = tip - params.toothDepthFraction * params.diameter;
  Polygon2 outline;
  for (int i = 0; i < params.teeth; ++i)
    for (const auto& [u, h] : kTooth) {
      const double t = 2.0 * kPi * (i + u) / params.teeth, r = root + h * (tip - root);
      outline.push_back(r * Vec2(std::cos(t), std::sin(t)));
    }
  std::vector<Polygon2> holes;
  if (params.boreFraction > 0.0)
    holes.push_back(circle(Vec2(0, 0), 0.5 * params.boreFraction * params.diameter, params.boreSegments, true));
  return extrudeProfile(outline, holes, params.thicknessFraction * params.diameter);
}

TriMesh cadHolePlate(const CadHolePlateParams& params) {
  const double l = params.length, w = params.width;
  const Polygon2 outline = {{0.0, 0.0}, {l, 0.0}, {l, w}, {0.0, w}};
  std::vector<Polygon2> holes;
  for (int j = 0; j < params.holeRows; ++j)
    for (int i = 0; i < params.holeColumns; ++i) {
      const Vec2 centre(l * (i + 0.5) / params.holeColumns, w * (j + 0.5) / params.holeRows);
      holes.push_back(circle(centre, params.holeRadius, params.holeSegments, true));
    }
  return extrudeProfile(outline, holes, params.thickness);
}

TriMesh cadCylinder(const CadCylinderParams& params) {
  return extrudeProfile(circle(Vec2(0, 0), params.radius, params.segments, false), {}, params.height);
}

TriMesh cadBracket(const CadBracketParams& params) {
  const double l = params.legLength, t = params.thickness, r = params.filletRadius;
  Polygon2 outline = {{0.0, 0.0}, {l, 0.0}, {l, t}};
  // The fillet: a quarter circle around (t + r, t + r) from (t + r, t) to (t, t + r).
  for (int k = 0; k <= params.filletSegments; ++k) {
    const double a = -0.5 * kPi - 0.5 * kPi * k / params.filletSegments;
    outline.push_back(Vec2(t + r, t + r) + r * Vec2(std::cos(a), std::sin(a)));
  }
  outline.push_back({t, l});
  outline.push_back({0.0, l});
  return extrudeProfile(outline, {}, params.depth);
}

std::vector<CadMesh> cadMeshes() {
  std::vector<CadMesh> meshes;
  meshes.push_back({"cad_gear", cadGear(), 0});
  meshes.push_back(
      {"cad_hole_plate", cadHolePlate(), CadHolePlateParams{}.holeColumns * CadHolePlateParams{}.holeRows});
  meshes.push_back({"cad_cylinder", cadCylinder(), 0});
  meshes.push_back({"cad_bracket", cadBracket(), 0});
  return meshes;
}

bool writeOff(const TriMesh& mesh, const std::string& path) {
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << mesh.vertexCount() << ' ' << mesh.faceCount() << " 0\n";
  for (const Vec3& p : mesh.positions) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Tri& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out.close();
  return static_cast<bool>(out);
}

}  // namespace gr::test
