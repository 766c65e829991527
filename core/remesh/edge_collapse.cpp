#include "core/remesh/edge_collapse.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

#include "core/mesh/face_geometry.h"
#include "core/mesh/self_intersection.h"

namespace gr {
namespace {

struct Box {
  Vec3 lo, hi;
  bool overlaps(const Box& o) const { return (lo.array() <= o.hi.array()).all() && (o.lo.array() <= hi.array()).all(); }
};

Box boxOf(const TriMesh& m, const Tri& t) {
  Box b{m.positions[t[0]], m.positions[t[0]]};
  for (int k = 1; k < 3; ++k) {
    b.lo = b.lo.cwiseMin(m.positions[t[k]]);
    b.hi = b.hi.cwiseMax(m.positions[t[k]]);
  }
  return b;
}

/// A uniform grid of the faces' boxes: a face is listed in every cell its box touches, again
/// after it moves (a stale entry costs one box test).
class FaceGrid {
 public:
  FaceGrid(const TriMesh& m, double cellSize) : size_(cellSize), seen_(m.faceCount(), 0) {
    for (int f = 0; f < m.faceCount(); ++f) insert(f, boxOf(m, m.triangles[f]));
  }
  void insert(int f, const Box& b) {
    forCells(b, [&](uint64_t key) { cells_[key].push_back(f); });
  }
  /// Calls visit(g) once for each face listed in a cell that `b` touches.
  template <class Visit>
  void near(const Box& b, const Visit& visit) {
    ++stamp_;
    forCells(b, [&](uint64_t key) {
      const auto it = cells_.find(key);
      if (it == cells_.end()) return;
      for (int g : it->second)
        if (seen_[g] != stamp_) {
          seen_[g] = stamp_;
          visit(g);
        }
    });
  }

 private:
  template <class Fn>
  void forCells(const Box& b, const Fn& fn) const {
    const auto cell = [this](double x) { return static_cast<int64_t>(std::floor(x / size_)); };
    for (int64_t x = cell(b.lo.x()); x <= cell(b.hi.x()); ++x)
      for (int64_t y = cell(b.lo.y()); y <= cell(b.hi.y()); ++y)
        for (int64_t z = cell(b.lo.z()); z <= cell(b.hi.z()); ++z)
          fn((static_cast<uint64_t>(x & 0x1FFFFF) << 42) | (static_cast<uint64_t>(y & 0x1FFFFF) << 21) |
             static_cast<uint64_t>(z & 0x1FFFFF));
  }

  double size_;
  std::unordered_map<uint64_t, std::vector<int>> cells_;
  std::vector<unsigned> seen_;
  unsigned stamp_ = 0;
};

/// One pass of collapses over `mesh`'s edges, shortest (weighted) first. The mesh's triangles are
/// rewritten in place; `onto` and `faceAlive` say what went.
class CollapsePass {
 public:
  /// `keep`: empty, or per vertex whether it may not be removed (it may still take a neighbour).
  CollapsePass(TriMesh& mesh, const std::vector<double>& weight, const std::vector<char>& keep)
      : onto(mesh.vertexCount(), -1),
        faceAlive(mesh.faceCount(), 1),
        m_(mesh),
        weight_(weight),
        keep_(keep),
        grid_(mesh, 2.0 * std::max(mesh.meanEdgeLength(), 1e-300)),
        touched_(mesh.vertexCount(), 0),
        onBoundary_(mesh.vertexCount(), 0) {}

  /// Collapses up to `excess` edges (only edges of the faces flagged in `faces`, if given);
  /// returns how many went.
  int run(int excess, const std::vector<char>* faces = nullptr) {
    std::vector<std::pair<double, std::array<int, 2>>> edges;
    for (int c = 0; c < 3 * m_.faceCount(); ++c) {
      const int o = m_.oppositeCorner[c];
      const int p = m_.vertex(TriMesh::next(c)), q = m_.vertex(TriMesh::prev(c));
      if (o < 0) onBoundary_[p] = onBoundary_[q] = 1;
      const bool wanted = !faces || (*faces)[c / 3] || (o >= 0 && (*faces)[o / 3]);
      if (wanted && (o > c || o < 0))  // each edge once
        edges.push_back({(m_.positions[p] - m_.positions[q]).norm() * 0.5 * (weight_[p] + weight_[q]), {p, q}});
    }
    std::sort(edges.begin(), edges.end());
    int done = 0;
    for (const auto& [length, e] : edges) {
      if (done == excess) break;
      const auto [a, b] = e;
      if (touched_[a] || touched_[b]) continue;
      if (!tryCollapse(a, b) && !tryCollapse(b, a)) continue;
      ++done;
      touchAround(a);
      touchAround(b);
    }
    return done;
  }

  std::vector<int> onto;        ///< per vertex, the vertex it went onto, or -1
  std::vector<char> faceAlive;  ///< 0 for the two faces of each collapsed edge

 private:
  void touchAround(int v) {
    touched_[v] = 1;
    for (const int* c = m_.cornersBegin(v); c != m_.cornersEnd(v); ++c)
      for (int x : m_.triangles[*c / 3]) touched_[x] = 1;
  }

  /// The other vertices of v's faces that are still there (a third vertex of an earlier collapse
  /// in this pass lost one), each face's two, sorted and unique.
  std::vector<int> neighbours(int v) const {
    std::vector<int> n;
    for (const int* c = m_.cornersBegin(v); c != m_.cornersEnd(v); ++c)
      if (faceAlive[*c / 3]) n.insert(n.end(), {m_.vertex(TriMesh::next(*c)), m_.vertex(TriMesh::prev(*c))});
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
    return n;
  }

  /// The link condition and the valences: u and v share exactly the third vertices of their
  /// `n` common faces (2 on an interior edge, 1 on a boundary edge), each of which keeps three
  /// neighbours (two on a boundary), as does v with u's.
  bool keepsTopology(int u, int v, const std::array<int, 2>& common, int n) const {
    std::array<int, 2> third{};
    for (int k = 0; k < n; ++k)
      for (int x : m_.triangles[common[k]])
        if (x != u && x != v) third[k] = x;
    if (n == 2 && third[0] == third[1]) return false;
    const std::vector<int> nu = neighbours(u), nv = neighbours(v);
    std::vector<int> both;
    std::set_intersection(nu.begin(), nu.end(), nv.begin(), nv.end(), std::back_inserter(both));
    if (static_cast<int>(both.size()) != n || !std::is_permutation(both.begin(), both.end(), third.begin()))
      return false;
    for (int k = 0; k < n; ++k)
      if (static_cast<int>(neighbours(third[k]).size()) < (onBoundary_[third[k]] ? 3 : 4)) return false;
    return static_cast<int>(nu.size() + nv.size()) - n - 2 >= 3;
  }

  /// Whether face f, as it is now, crosses a face other than the two going.
  bool crosses(int f, const std::array<int, 2>& going) {
    const Box box = boxOf(m_, m_.triangles[f]);
    bool found = false;
    grid_.near(box, [&](int g) {
      if (found || g == f || g == going[0] || g == going[1] || !faceAlive[g]) return;
      found = box.overlaps(boxOf(m_, m_.triangles[g])) && facesCross(m_, f, g);
    });
    return found;
  }

  /// Collapses u onto v if that keeps the topology, turns no face over and crosses nothing. A
  /// boundary vertex goes only along its boundary (onto a neighbour across a boundary edge).
  bool tryCollapse(int u, int v) {
    std::array<int, 2> common = {-1, -1};
    int commonCount = 0;
    std::vector<int> moving;
    for (const int* c = m_.cornersBegin(u); c != m_.cornersEnd(u); ++c) {
      const int f = *c / 3;
      const Tri& t = m_.triangles[f];
      if (t[0] == v || t[1] == v || t[2] == v) {
        if (commonCount == 2) return false;
        common[commonCount++] = f;
      } else {
        moving.push_back(f);
      }
    }
    const bool alongBoundary = commonCount == 1 && onBoundary_[u] && onBoundary_[v];
    if (commonCount != (alongBoundary ? 1 : 2) || (onBoundary_[u] && !alongBoundary)) return false;
    if (!keep_.empty() && keep_[u]) return false;
    if (!keepsTopology(u, v, common, commonCount)) return false;
    std::vector<Tri> before;
    for (int f : moving) before.push_back(m_.triangles[f]);
    const auto undo = [&] {
      for (size_t i = 0; i < moving.size(); ++i) m_.triangles[moving[i]] = before[i];
      return false;
    };
    for (int f : moving) {
      const Vec3 old = areaNormal(m_, f);
      for (int& x : m_.triangles[f])
        if (x == u) x = v;
      if (!(areaNormal(m_, f).dot(old) > 0.0)) return undo();
    }
    for (int f : moving)
      if (crosses(f, common)) return undo();
    for (int k = 0; k < commonCount; ++k) faceAlive[common[k]] = 0;
    for (int f : moving) grid_.insert(f, boxOf(m_, m_.triangles[f]));
    onto[u] = v;
    return true;
  }

  TriMesh& m_;
  const std::vector<double>& weight_;
  const std::vector<char>& keep_;
  FaceGrid grid_;
  std::vector<char> touched_, onBoundary_;
};

/// Removes the collapsed vertices (onto[v] >= 0) and the faces not alive: compacts `mesh`'s arrays, `origin` and `weight`, and
/// renumbers `cell` (a removed vertex's cell goes to the vertex it went onto). False, with nothing
/// changed, if the result is not a valid mesh (the checks of each collapse should make that
/// impossible).
bool compact(TriMesh& mesh, const std::vector<int>& onto, const std::vector<char>& faceAlive,
             std::vector<SurfacePoint>& origin, std::vector<double>& weight, std::vector<int>& cell) {
  std::vector<int> index(mesh.vertexCount(), -1);
  std::vector<Vec3> positions;
  std::vector<SurfacePoint> keptOrigin;
  std::vector<double> keptWeight;
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    if (onto[v] >= 0) continue;
    index[v] = static_cast<int>(positions.size());
    positions.push_back(mesh.positions[v]);
    keptOrigin.push_back(origin[v]);
    keptWeight.push_back(weight[v]);
  }
  std::vector<Tri> triangles;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    if (!faceAlive[f]) continue;
    const Tri& t = mesh.triangles[f];
    triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
  }
  Expected<TriMesh> rebuilt = buildTriMesh(std::move(positions), std::move(triangles));
  if (!rebuilt || !rebuilt->topology.isManifold()) return false;
  for (int& c : cell) {
    if (c < 0 || c >= static_cast<int>(index.size())) continue;
    while (onto[c] >= 0) c = onto[c];
    c = index[c];
  }
  mesh = std::move(rebuilt).value();
  origin = std::move(keptOrigin);
  weight = std::move(keptWeight);
  return true;
}

/// One pass of up to `excess` collapses (of the edges of `faces`, if given) on a copy of `mesh`,
/// kept only if valid; counted in `r`. False when nothing went.
bool collapsePass(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<double>& weight, std::vector<int>& cell,
                  int excess, const std::vector<char>* faces, std::vector<char>& keep, CollapseResult& r) {
  TriMesh work = mesh;  // the pass rewrites triangles in place
  CollapsePass pass(work, weight, keep);
  const int done = pass.run(excess, faces);
  ++r.passes;
  if (done == 0 || !compact(work, pass.onto, pass.faceAlive, origin, weight, cell)) return false;
  if (!keep.empty()) {  // compacted as the vertices are (no kept vertex went)
    std::vector<char> kept;
    for (size_t v = 0; v < keep.size(); ++v)
      if (pass.onto[v] < 0) kept.push_back(keep[v]);
    keep = std::move(kept);
  }
  mesh = std::move(work);
  r.collapsed += done;
  return true;
}

}  // namespace

CollapseResult collapseToCount(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<double>& weight,
                               std::vector<int>& cell, int targetCount, std::vector<char> keep) {
  CollapseResult r;
  while (mesh.vertexCount() > targetCount)
    if (!collapsePass(mesh, origin, weight, cell, mesh.vertexCount() - targetCount, nullptr, keep, r)) break;
  return r;
}

CollapseResult collapseCrossingFaces(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<double>& weight,
                                     std::vector<int>& cell, const CrossingPairs& pairsOf, int rounds) {
  CollapseResult r;
  for (int round = 0; round < rounds; ++round) {
    const std::vector<std::pair<int, int>> pairs = pairsOf(mesh, cell);
    if (pairs.empty()) break;
    std::vector<char> crossing(mesh.faceCount(), 0);
    for (const auto& [f, g] : pairs) crossing[f] = crossing[g] = 1;
    std::vector<char> keepNone;
    if (!collapsePass(mesh, origin, weight, cell, static_cast<int>(2 * pairs.size()), &crossing, keepNone, r)) break;
  }
  return r;
}

namespace {

/// The corner at the tip m of face f if f is an ear: two boundary edges, m (between them) in no
/// other face, the third edge (facing m) interior; else -1.
int earCorner(const TriMesh& mesh, int f) {
  int interior = -1, boundaryEdges = 0;
  for (int k = 0; k < 3; ++k) {
    if (mesh.oppositeCorner[3 * f + k] < 0)
      ++boundaryEdges;
    else
      interior = 3 * f + k;
  }
  return boundaryEdges == 2 && mesh.valence(mesh.vertex(interior)) == 1 ? interior : -1;
}

/// The ears removeFlatEars takes in one round: per vertex, the vertex it goes onto (or -1), and
/// per face, 0 for an ear; false if there is none. Ears that share a vertex wait for a later round.
bool markFlatEars(const TriMesh& mesh, double maxHeight, std::vector<int>& onto, std::vector<char>& faceAlive) {
  onto.assign(mesh.vertexCount(), -1);
  faceAlive.assign(mesh.faceCount(), 1);
  std::vector<char> touched(mesh.vertexCount(), 0);
  bool any = false;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const int interior = earCorner(mesh, f);
    if (interior < 0) continue;
    const int m = mesh.vertex(interior), a = mesh.vertex(TriMesh::next(interior)),
              b = mesh.vertex(TriMesh::prev(interior));
    if (touched[m] || touched[a] || touched[b]) continue;
    const Vec3 &pm = mesh.positions[m], &pa = mesh.positions[a], &pb = mesh.positions[b];
    const double base = (pb - pa).norm();
    const double height = (pa - pm).cross(pb - pm).norm() / base;
    const double smallest = std::min(angleAt(pa, pm, pb), angleAt(pb, pa, pm));
    if (!(base > 0) || !(smallest < kEarAngle) || !(height <= maxHeight * base)) continue;
    onto[m] = (pm - pa).squaredNorm() <= (pm - pb).squaredNorm() ? a : b;
    faceAlive[f] = 0;
    touched[m] = touched[a] = touched[b] = 1;
    any = true;
  }
  return any;
}

}  // namespace

CollapseResult removeFlatEars(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<int>& cell,
                              double maxHeight) {
  CollapseResult r;
  std::vector<int> onto;
  std::vector<char> faceAlive;
  std::vector<double> weight;
  for (int round = 0; round < kEarRounds && markFlatEars(mesh, maxHeight, onto, faceAlive); ++round) {
    const int removed = static_cast<int>(std::count_if(onto.begin(), onto.end(), [](int v) { return v >= 0; }));
    weight.assign(mesh.vertexCount(), 1.0);
    if (removed >= mesh.vertexCount() - 2 || !compact(mesh, onto, faceAlive, origin, weight, cell)) break;
    r.collapsed += removed;
    ++r.passes;
  }
  return r;
}

std::vector<int> thinEars(const TriMesh& mesh, double maxDepth) {
  std::vector<std::pair<double, int>> ears;  // (smallest angle, face)
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const int tip = earCorner(mesh, f);
    if (tip < 0) continue;
    const Vec3 &pm = mesh.positions[mesh.vertex(tip)], &pa = mesh.positions[mesh.vertex(TriMesh::next(tip))],
               &pb = mesh.positions[mesh.vertex(TriMesh::prev(tip))];
    const double smallest = smallestAngle(pm, pa, pb);
    const double base = (pb - pa).norm();
    if (smallest < kEarAngle && base > 0 && (pa - pm).cross(pb - pm).norm() / base <= maxDepth)
      ears.push_back({smallest, f});
  }
  std::sort(ears.begin(), ears.end());
  std::vector<int> faces;
  for (const auto& [angle, f] : ears) faces.push_back(f);
  return faces;
}

bool removeEar(TriMesh& mesh, std::vector<SurfacePoint>& origin, std::vector<int>& cell, int face) {
  const int tip = earCorner(mesh, face);
  if (tip < 0 || mesh.vertexCount() <= 3) return false;
  const int m = mesh.vertex(tip), a = mesh.vertex(TriMesh::next(tip)), b = mesh.vertex(TriMesh::prev(tip));
  std::vector<int> onto(mesh.vertexCount(), -1);
  std::vector<char> faceAlive(mesh.faceCount(), 1);
  const Vec3& pm = mesh.positions[m];
  onto[m] = (pm - mesh.positions[a]).squaredNorm() <= (pm - mesh.positions[b]).squaredNorm() ? a : b;
  faceAlive[face] = 0;
  std::vector<double> weight(mesh.vertexCount(), 1.0);
  return compact(mesh, onto, faceAlive, origin, weight, cell);
}

}  // namespace gr
