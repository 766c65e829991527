#include "core/remesh/remesh_distance.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>

#include "core/base/two_threads.h"
#include "core/mesh/face_geometry.h"

namespace gr {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// The distance from p to face f; `bary` receives the barycentric coordinates of the nearest point.
double distanceToFace(const Vec3& p, const TriMesh& m, int f, Vec3* bary = nullptr) {
  const Tri& t = m.triangles[f];
  const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
  const Vec3 w = closestPointBarycentric(p, a, b, c);
  if (bary) *bary = w;
  return (p - (w[0] * a + w[1] * b + w[2] * c)).norm();
}

/// Every face of a mesh as a bounding sphere (centroid, largest distance to a corner) and its
/// plane (unit normal, offset), to skip the faces that cannot be nearer than the nearest one found:
/// the distance to a face is at least the distance to its sphere and to its plane.
struct FaceSpheres {
  std::vector<Vec3> centre;
  std::vector<double> radius;
  std::vector<Vec3> normal;    ///< unit normal; 0 for a face of zero area (its plane bounds nothing)
  std::vector<double> offset;  ///< normal . centre
  FaceSpheres() = default;
  explicit FaceSpheres(const TriMesh& m)
      : centre(m.faceCount()), radius(m.faceCount()), normal(m.faceCount()), offset(m.faceCount()) {
    for (int f = 0; f < m.faceCount(); ++f) {
      const Tri& t = m.triangles[f];
      centre[f] = (m.positions[t[0]] + m.positions[t[1]] + m.positions[t[2]]) / 3.0;
      for (int v : t) radius[f] = std::max(radius[f], (m.positions[v] - centre[f]).norm());
      const Vec3 n = areaNormal(m, t);
      const double length = n.norm();
      normal[f] = length > 0.0 && std::isfinite(length) ? Vec3(n / length) : Vec3::Zero();
      offset[f] = normal[f].dot(centre[f]);
    }
  }
  /// Whether face f may be nearer to p than `bound` (its plane and its sphere are).
  bool mayBeNearer(const Vec3& p, int f, double bound) const {
    const double reach = bound + radius[f];
    return std::abs(normal[f].dot(p) - offset[f]) < bound && (p - centre[f]).squaredNorm() < reach * reach;
  }
  /// The distance from p to the nearest face of m (at most `bound`), by testing every face whose
  /// sphere is nearer.
  double nearest(const Vec3& p, const TriMesh& m, double bound) const {
    double d = bound;
    for (int f = 0; f < m.faceCount(); ++f)
      if (mayBeNearer(p, f, d)) d = std::min(d, distanceToFace(p, m, f));
    return d;
  }
};

/// From face f, steps toward p while a nearer face is found where the nearest point of the current
/// face says to look: the three faces across its sides if that point is inside it (a crease may
/// have the nearer face across), else the face across the side it lies on or the faces around the
/// corner it is, and if none of these is nearer, every face around the three corners. Ends at a
/// local minimum of the distance over the faces (exact where the surface near p is not folded
/// back). Returns the distance and the face.
std::pair<double, int> walkToNearest(const Vec3& p, const TriMesh& m, const FaceSpheres& spheres, int f) {
  for (int steps = 0;; ++steps) {
    const Tri& t = m.triangles[f];
    Vec3 w;
    const double d = distanceToFace(p, m, f, &w);
    const int zeros = (w[0] <= 0.0) + (w[1] <= 0.0) + (w[2] <= 0.0);
    if (steps == 256) return {d, f};
    int best = -1;
    double bestD = d;
    const auto tryFace = [&](int g) {
      if (g == f || !spheres.mayBeNearer(p, g, bestD)) return;
      const double dg = distanceToFace(p, m, g);
      if (dg < bestD) best = g, bestD = dg;
    };
    for (int k = 0; k < 3; ++k) {
      if (zeros == 0 || (zeros == 1 && w[k] <= 0.0)) {  // inside: all three sides; on the side facing k
        if (const int o = m.oppositeCorner[3 * f + k]; o >= 0) tryFace(o / 3);
      } else if (zeros == 2 && w[k] > 0.0) {  // at corner k
        for (const int* c = m.cornersBegin(t[k]); c != m.cornersEnd(t[k]); ++c) tryFace(*c / 3);
      }
    }
    if (best < 0 && zeros > 0)  // not there (a crease, a saddle): every face around the corners
      for (int v : t)
        for (const int* c = m.cornersBegin(v); c != m.cornersEnd(v); ++c) tryFace(*c / 3);
    if (best < 0) return {d, f};
    f = best;
  }
}

/// Per output vertex, an input face holding its origin.
std::vector<int> originFace(const TriMesh& input, const std::vector<SurfacePoint>& origin) {
  std::vector<int> face(origin.size(), -1);
  for (size_t i = 0; i < origin.size(); ++i) {
    const SurfacePoint& o = origin[i];
    if (o.vertex >= 0 && input.cornersBegin(o.vertex) != input.cornersEnd(o.vertex))
      face[i] = *input.cornersBegin(o.vertex) / 3;
    else if (o.vertex < 0)
      face[i] = o.face;
  }
  return face;
}

/// Sample points with an upper bound of their distance to the other surface, and the number of
/// the other measure's samples each stands for (an edge's midpoint, shared by two faces: 2).
struct Bounds {
  std::vector<Vec3> point;
  std::vector<double> upper;
  std::vector<double> weight;

  void add(const Vec3& p, double d, double w = 1.0) {
    point.push_back(p);
    upper.push_back(d);
    weight.push_back(w);
  }
  void append(const Bounds& o) {
    point.insert(point.end(), o.point.begin(), o.point.end());
    upper.insert(upper.end(), o.upper.begin(), o.upper.end());
    weight.insert(weight.end(), o.weight.begin(), o.weight.end());
  }
};

/// Per output face, the input face whose corners lie in its three corners' cells (the face whose
/// three fronts made it, in the geodesic Delaunay dual), or -1 where there is none (an edge the
/// Delaunay flips or the relaxation turned).
std::vector<int> dualFaces(const TriMesh& input, const TriMesh& output, const std::vector<int>& cell) {
  const auto key = [](std::array<int, 3> c) {
    std::sort(c.begin(), c.end());
    return (static_cast<uint64_t>(c[0]) << 42) | (static_cast<uint64_t>(c[1]) << 21) | static_cast<uint64_t>(c[2]);
  };
  std::unordered_map<uint64_t, int> faceOfTriple;
  for (int f = 0; f < input.faceCount(); ++f) {
    const Tri& t = input.triangles[f];
    const std::array<int, 3> c = {cell[t[0]], cell[t[1]], cell[t[2]]};
    if (c[0] >= 0 && c[1] >= 0 && c[2] >= 0 && c[0] != c[1] && c[1] != c[2] && c[0] != c[2])
      faceOfTriple.emplace(key(c), f);
  }
  std::vector<int> dual(output.faceCount(), -1);
  for (int f = 0; f < output.faceCount(); ++f) {
    const Tri& t = output.triangles[f];
    const auto it = faceOfTriple.find(key({t[0], t[1], t[2]}));
    if (it != faceOfTriple.end()) dual[f] = it->second;
  }
  return dual;
}

/// What both directions read: the faces as spheres and planes, and where the output's vertices and
/// faces lie on the input.
struct Shared {
  FaceSpheres inputFaces, outputFaces;
  std::vector<int> start;  ///< originFace
  std::vector<int> dual;   ///< dualFaces
};

/// A centroid whose walk from its face's dual input face ends farther than this times the face's
/// longest side is walked from the corners' origins too.
constexpr double kFarForItsSize = 0.1;

/// The output's vertices, against the input face holding their origin (they lie on it).
void outputVertices(const TriMesh& input, const TriMesh& output, const Shared& s, Bounds& b) {
  for (int i = 0; i < output.vertexCount(); ++i)
    b.add(output.positions[i], s.start[i] >= 0 ? distanceToFace(output.positions[i], input, s.start[i]) : kInf);
}

/// Output faces [begin, end): each centroid, walked over the input's faces (walkToNearest) from the
/// face's dual input face (dualFaces) or else from each corner's origin, and the midpoint of each
/// side, once per edge (in the face of the smaller index, standing for both faces' samples),
/// walked from where the centroid's walk ended and from the side's first corner's origin.
void outputFaces(const TriMesh& input, const TriMesh& output, const Shared& s, int begin, int end, Bounds& b) {
  for (int f = begin; f < end; ++f) {
    const Tri& t = output.triangles[f];
    const Vec3 &p = output.positions[t[0]], &q = output.positions[t[1]], &r = output.positions[t[2]];
    const Vec3 centroid = (p + q + r) / 3.0;
    std::pair<double, int> nearest = {kInf, -1};
    if (s.dual[f] >= 0) nearest = walkToNearest(centroid, input, s.inputFaces, s.dual[f]);
    // Far for the face's size: from the corners' origins too. They may lie on different sides of
    // a thin part or of a crease the face cuts across, where the walk from the dual face ends at a
    // local minimum.
    const double size = std::max({(q - p).squaredNorm(), (r - q).squaredNorm(), (p - r).squaredNorm()});
    if (nearest.first * nearest.first > kFarForItsSize * kFarForItsSize * size)
      for (int k = 0; k < 3; ++k)
        if (s.start[t[k]] >= 0 && s.start[t[k]] != nearest.second)
          nearest = std::min(nearest, walkToNearest(centroid, input, s.inputFaces, s.start[t[k]]));
    b.add(centroid, nearest.first);
    for (int k = 0; k < 3; ++k) {  // the side from corner k to k + 1, across from corner k + 2
      const int across = output.oppositeCorner[3 * f + (k + 2) % 3];
      if (across >= 0 && across / 3 < f) continue;  // measured with the other face
      const Vec3 x = 0.5 * (output.positions[t[k]] + output.positions[t[(k + 1) % 3]]);
      double d = nearest.second >= 0 ? walkToNearest(x, input, s.inputFaces, nearest.second).first : kInf;
      if (s.start[t[k]] >= 0) d = std::min(d, walkToNearest(x, input, s.inputFaces, s.start[t[k]]).first);
      b.add(x, d, across >= 0 ? 2.0 : 1.0);
    }
  }
}

/// `p`'s distance to the output triangles around output vertex c, then walked from the nearest of
/// them; infinite where c is no output vertex.
double fromCell(const Vec3& p, const TriMesh& output, int c, const Shared& s) {
  double d = kInf;
  int nearest = -1;
  if (c >= 0 && c < output.vertexCount())
    for (const int* k = output.cornersBegin(c); k != output.cornersEnd(c); ++k)
      if (s.outputFaces.mayBeNearer(p, *k / 3, d))
        if (const double e = distanceToFace(p, output, *k / 3); e < d) d = e, nearest = *k / 3;
  if (nearest >= 0) d = std::min(d, walkToNearest(p, output, s.outputFaces, nearest).first);
  return d;
}

/// The least of fromCell over the cells a, b and c, each distinct cell walked once (most input
/// faces lie inside one cell); c = -1 for a side's two ends.
double fromCells(const Vec3& p, const TriMesh& output, int a, int b, int c, const Shared& s) {
  double d = fromCell(p, output, a, s);
  if (b != a) d = std::min(d, fromCell(p, output, b, s));
  if (c >= 0 && c != a && c != b) d = std::min(d, fromCell(p, output, c, s));
  return d;
}

/// The input's vertices, each from its cell's output vertex (fromCell); with
/// VerticesMidpointsCentroids also each face's centroid, from its three corners' cells, and the
/// midpoint of each side, once per edge (standing for both faces' samples), from its two ends'.
Bounds inputBounds(const TriMesh& input, const TriMesh& output, const std::vector<int>& cell, const Shared& s,
                   DistanceSamples samples) {
  Bounds b;
  for (int v = 0; v < input.vertexCount(); ++v)
    b.add(input.positions[v], fromCell(input.positions[v], output, cell[v], s));
  if (samples != DistanceSamples::VerticesMidpointsCentroids) return b;
  for (int f = 0; f < input.faceCount(); ++f) {
    const Tri& t = input.triangles[f];
    const Vec3 centroid = (input.positions[t[0]] + input.positions[t[1]] + input.positions[t[2]]) / 3.0;
    b.add(centroid, fromCells(centroid, output, cell[t[0]], cell[t[1]], cell[t[2]], s));
    for (int k = 0; k < 3; ++k) {  // the side from corner k to k + 1, across from corner k + 2
      const int across = input.oppositeCorner[3 * f + (k + 2) % 3];
      if (across >= 0 && across / 3 < f) continue;  // measured with the other face
      const Vec3 x = 0.5 * (input.positions[t[k]] + input.positions[t[(k + 1) % 3]]);
      b.add(x, fromCells(x, output, cell[t[k]], cell[t[(k + 1) % 3]], -1, s), across >= 0 ? 2.0 : 1.0);
    }
  }
  return b;
}

/// The exact largest distance, from the bounds taken largest first (see the header), and the RMS
/// of the bounds (exact ones where measured), weighted. Empty if more than kMaxExactQueries were
/// needed.
std::optional<SurfaceDistance> certify(const Bounds& b, const TriMesh& to, const FaceSpheres& spheres, int& queries) {
  SurfaceDistance d;
  if (b.point.empty()) return d;
  std::vector<std::pair<double, int>> heap(b.point.size());
  double sumSq = 0.0, samples = 0.0;
  for (size_t q = 0; q < b.point.size(); ++q) {
    heap[q] = {b.upper[q], static_cast<int>(q)};
    sumSq += b.weight[q] * b.upper[q] * b.upper[q];
    samples += b.weight[q];
  }
  std::make_heap(heap.begin(), heap.end());
  double best = 0.0;
  for (int exact = 0; !heap.empty(); ++exact) {
    std::pop_heap(heap.begin(), heap.end());
    const auto [upper, q] = heap.back();
    heap.pop_back();
    if (upper <= best) break;
    if (exact == kMaxExactQueries) return std::nullopt;
    const double e = spheres.nearest(b.point[q], to, upper);
    ++queries;
    best = std::max(best, e);
    if (std::isfinite(upper)) sumSq -= b.weight[q] * (upper * upper - e * e);
  }
  d.max = best;
  d.rms = std::sqrt(std::max(0.0, sumSq) / samples);
  return d;
}

}  // namespace

RemeshDistances remeshDistances(const TriMesh& input, const TriMesh& output, const std::vector<int>& cell,
                                const std::vector<SurfacePoint>& origin, bool voronoiCells,
                                DistanceSamples inputSamples) {
  RemeshDistances r;
  if (input.faceCount() == 0 || output.faceCount() == 0) return r;
  Shared shared;
  onTwoThreads([&](bool helper) {
    if (helper) {
      shared.inputFaces = FaceSpheres(input);
    } else {
      shared.outputFaces = FaceSpheres(output);
      shared.start = originFace(input, origin);
      shared.dual = dualFaces(input, output, cell);
    }
  });
  // The helper measures the input's vertices, then both threads share the output's faces in
  // blocks until none is left (the output's side is the larger).
  constexpr int kBlock = 256;
  std::atomic<int> nextBlock{0};
  Bounds to[2], from;
  onTwoThreads([&](bool helper) {
    Bounds& mine = to[helper];
    if (helper && voronoiCells)
      from = inputBounds(input, output, cell, shared, inputSamples);
    else if (!helper)
      outputVertices(input, output, shared, mine);
    for (int block = nextBlock++; block * kBlock < output.faceCount(); block = nextBlock++)
      outputFaces(input, output, shared, block * kBlock, std::min(output.faceCount(), (block + 1) * kBlock), mine);
  });
  to[0].append(to[1]);
  int toQueries = 0, fromQueries = 0;
  std::optional<SurfaceDistance> toInput, fromInput;
  onTwoThreads([&](bool helper) {
    if (helper)
      toInput = certify(to[0], input, shared.inputFaces, toQueries);
    else if (voronoiCells)
      fromInput = certify(from, output, shared.outputFaces, fromQueries);
  });
  r.gridDirections = !toInput + !fromInput;  // !voronoiCells: the input's side by the grid
  r.toInput = toInput ? *toInput : surfaceDistance(output, input);
  r.fromInput = fromInput ? *fromInput : surfaceDistance(input, output, {}, 0, inputSamples);
  r.exactQueries = toQueries + fromQueries;
  return r;
}

}  // namespace gr
