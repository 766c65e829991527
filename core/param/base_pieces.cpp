#include "core/param/base_pieces.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <queue>
#include <string>
#include <unordered_map>

#include "core/field/adaptive_metric.h"
#include "core/geodesic/farthest_point_sampling.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_lloyd.h"
#include "core/geodesic/metric.h"
#include "core/remesh/geodesic_delaunay.h"
#include "core/remesh/remesh_surface.h"

namespace gr {
namespace {

/// A path's edge costs this many times its length where it leaves cells i and j of its base
/// edge (i, j): paths keep to their own cells while they can, and still find a way round when a
/// cell is too narrow for all the paths that cross it.
constexpr double kOutsideCells = 10.0;
/// A base vertex's star is split until it has this many more edges than base edges: one path
/// leaves it per base edge, and each needs an edge in the right sector.
constexpr int kValenceMargin = 2;
constexpr int kMaxStarSplits = 3;
/// Rounds of routing: the base edges whose path found no way are routed again after the edges
/// between paths are split (each round gives every corridor between two paths a free vertex),
/// as long as a round routes some of them (about half: bull.off with 200 base vertices, 224 of
/// 721 edges blocked after the spanning tree, then 87, 40, 18, 5, ...), at most this many rounds.
constexpr int kMaxRoutingRounds = 40;
/// A path's search settles at most this many vertices per vertex of its two cells (plus
/// kSearchMinimum) before it counts as blocked for the round: a path that must go that far is
/// going the wrong way, and a blocked search would otherwise cover the whole mesh (cheese.off,
/// genus 133, 200 base vertices: 142 s to fail, one whole-mesh search per blocked edge and round).
constexpr int kSearchPerCellVertex = 16;
constexpr int kSearchMinimum = 256;
/// The base's curvature is read over this many base spacings, and at most this many input edges:
/// the ball's cost goes as its area (armadillo subdivided to 1.66M vertices, 5,000 base vertices:
/// 16 s at 8.6 edges, the half spacing, against about 3.5 s at 3 edges).
constexpr double kCurvatureRadiusInSpacings = 0.5;
constexpr double kCurvatureRadiusInEdges = 3.0;
constexpr int kSamplesPerSampleIn3d = 64;
constexpr int kSamplesIn3d = 16;
/// The cut gives up when its splits have made the surface this many times the input's faces: the
/// paths' rounds make slow progress on a mesh too coarse for its base (cad_gear of tests/support,
/// 1,040 vertices, 500 base vertices: over two minutes, the surface growing each round).
constexpr size_t kMaxFacesPerInputFace = 32;
/// Rounds in a row that route none of the blocked edges before the routing gives up.
constexpr int kMaxStalledRounds = 3;

uint64_t edgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<uint64_t>(a) << 32) | static_cast<uint32_t>(b);
}

std::string edgeName(const std::pair<int, int>& e) {
  return "(" + std::to_string(e.first) + ", " + std::to_string(e.second) + ")";
}

/// The surface being cut: the input with edges split, each face in an input face.
struct Work {
  std::vector<Vec3> positions;
  std::vector<Tri> triangles;
  std::vector<int> originalFace;
  std::vector<Vec3> cornerBary;  // per corner, in originalFace
  std::vector<int> cell;         // per vertex
};

Work initialWork(const TriMesh& input, const std::vector<int>& cell) {
  Work w;
  // The splits append faces: room for a quarter more without moving the arrays.
  const size_t room = input.triangles.size() + input.triangles.size() / 4;
  w.triangles.reserve(room);
  w.originalFace.reserve(room);
  w.positions = input.positions;
  w.triangles.assign(input.triangles.begin(), input.triangles.end());
  w.originalFace.resize(input.faceCount());
  std::iota(w.originalFace.begin(), w.originalFace.end(), 0);
  w.cornerBary.reserve(3 * room);
  for (int f = 0; f < input.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) w.cornerBary.push_back(Vec3::Unit(k));
  w.cell = cell;
  return w;
}

/// Splits `edges` (vertex pairs, repeats allowed) at their midpoints: a face with one, two or three
/// of them becomes two, three or four faces, oriented as it was, the first in its place and the
/// others appended (the faces of the surface are not copied: 88 bytes each with their corners'
/// barycentrics, 3.4M faces on armadillo subdivided to 1.66M vertices). Vertices keep their
/// numbers.
int splitEdges(Work& w, const std::vector<std::pair<int, int>>& edges) {
  std::unordered_map<uint64_t, int> mid;
  mid.reserve(2 * edges.size());
  std::vector<char> touched(w.positions.size(), 0);  // an end of a split edge
  for (const auto& [a, b] : edges)
    if (mid.emplace(edgeKey(a, b), static_cast<int>(w.positions.size())).second) {
      w.positions.push_back(0.5 * (w.positions[a] + w.positions[b]));
      w.cell.push_back(w.cell[a]);
      touched[a] = touched[b] = 1;
    }
  if (mid.empty()) return 0;
  struct P {
    int v;
    Vec3 b;
  };
  const int faces = static_cast<int>(w.triangles.size());
  for (int f = 0; f < faces; ++f) {
    const Tri t = w.triangles[f];
    if (touched[t[0]] + touched[t[1]] + touched[t[2]] < 2) continue;
    P p[3], m[3];
    int split = 0, unsplit = 0;
    for (int k = 0; k < 3; ++k) p[k] = {t[k], w.cornerBary[3 * f + k]};
    for (int k = 0; k < 3; ++k) {
      const auto it = mid.find(edgeKey(p[(k + 1) % 3].v, p[(k + 2) % 3].v));
      m[k] = {it == mid.end() ? -1 : it->second, 0.5 * (p[(k + 1) % 3].b + p[(k + 2) % 3].b)};
      if (m[k].v >= 0)
        ++split;
      else
        unsplit = k;
    }
    if (split == 0) continue;
    const int original = w.originalFace[f];
    bool first = true;
    auto emit = [&](const P& x, const P& y, const P& z) {
      if (first) {
        w.triangles[f] = {x.v, y.v, z.v};
        w.cornerBary[3 * f] = x.b;
        w.cornerBary[3 * f + 1] = y.b;
        w.cornerBary[3 * f + 2] = z.b;
        first = false;
        return;
      }
      w.triangles.push_back({x.v, y.v, z.v});
      w.originalFace.push_back(original);
      w.cornerBary.push_back(x.b);
      w.cornerBary.push_back(y.b);
      w.cornerBary.push_back(z.b);
    };
    if (split == 1) {
      const int k = m[0].v >= 0 ? 0 : (m[1].v >= 0 ? 1 : 2);
      emit(p[k], p[(k + 1) % 3], m[k]);
      emit(p[k], m[k], p[(k + 2) % 3]);
    } else if (split == 2) {
      const int k0 = unsplit, k1 = (k0 + 1) % 3, k2 = (k0 + 2) % 3;
      emit(p[k0], m[k2], m[k1]);
      emit(m[k2], p[k1], p[k2]);
      emit(m[k2], p[k2], m[k1]);
    } else {
      emit(p[0], m[2], m[1]);
      emit(p[1], m[0], m[2]);
      emit(p[2], m[1], m[0]);
      emit(m[0], m[1], m[2]);
    }
  }
  return static_cast<int>(mid.size());
}

/// The base's edges and, per base vertex, its fan: (a, b) for each base triangle (v, a, b).
struct BaseGraph {
  std::vector<std::pair<int, int>> edges;
  std::unordered_map<uint64_t, int> edgeIndex;
  std::vector<std::array<int, 3>> triangleEdge;
  std::vector<int> edgeFaces;  // triangles per edge
  std::vector<std::vector<std::pair<int, int>>> fan;

  int edge(int a, int b) const {
    const auto it = edgeIndex.find(edgeKey(a, b));
    return it == edgeIndex.end() ? -1 : it->second;
  }
  /// The neighbour before `j` clockwise around `i`: the a of base triangle (i, a, j); -1 if none.
  int clockwise(int i, int j) const {
    for (const auto& [a, b] : fan[i])
      if (b == j) return a;
    return -1;
  }
};

BaseGraph baseGraph(const BaseDomain& base) {
  BaseGraph g;
  g.fan.resize(base.baseVertex.size());
  for (const Tri& t : base.triangles) {
    std::array<int, 3> te{};
    for (int k = 0; k < 3; ++k) {
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      const auto [it, fresh] = g.edgeIndex.emplace(edgeKey(a, b), static_cast<int>(g.edges.size()));
      if (fresh) {
        g.edges.emplace_back(std::min(a, b), std::max(a, b));
        g.edgeFaces.push_back(0);
      }
      ++g.edgeFaces[it->second];
      te[k] = it->second;
      g.fan[t[k]].emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
    }
    g.triangleEdge.push_back(te);
  }
  return g;
}

/// The corner facing the edge a -> b or b -> a in one of its faces (-1 if a and b share none).
int cornerFacing(const TriMesh& mesh, int a, int b) {
  for (const int* c = mesh.cornersBegin(a); c != mesh.cornersEnd(a); ++c) {
    if (mesh.vertex(TriMesh::next(*c)) == b) return TriMesh::prev(*c);
    if (mesh.vertex(TriMesh::prev(*c)) == b) return TriMesh::next(*c);
  }
  return -1;
}

/// Routes the paths of all base edges on one mesh, vertex-disjoint but at base vertices.
class Router {
 public:
  Router(const TriMesh& mesh, const Work& work, const BaseDomain& base, const BaseGraph& graph)
      : mesh_(mesh), work_(work), base_(base), graph_(graph) {
    baseOf_.assign(mesh.vertexCount(), -1);
    for (size_t i = 0; i < base.baseVertex.size(); ++i) baseOf_[base.baseVertex[i]] = static_cast<int>(i);
    onPath_.assign(mesh.vertexCount(), 0);
    cut_.assign(3 * mesh.faceCount(), 0);
    for (int c = 0; c < 3 * mesh.faceCount(); ++c) cut_[c] = mesh.oppositeCorner[c] < 0;
    wedge_.assign(3 * mesh.faceCount(), -1);
    dist_.assign(mesh.vertexCount(), kUnreached);
    from_.assign(mesh.vertexCount(), -1);
    paths_.resize(graph.edges.size());
    cellSize_.assign(base.baseVertex.size(), 0);
    for (int v = 0; v < mesh.vertexCount(); ++v)
      if (work.cell[v] >= 0) ++cellSize_[work.cell[v]];
  }

  /// Routes `edges` in that order; the interior ones that find no way are listed in `failed`.
  Status route(const std::vector<int>& edges, std::vector<int>* failed, Progress& progress);
  /// Cuts along paths routed before (on a mesh with more vertices, as the routing's retry has).
  void adopt(const std::vector<std::vector<int>>& paths) {
    for (size_t e = 0; e < paths.size(); ++e)
      if (!paths[e].empty()) cutAlong(static_cast<int>(e), paths[e]);
  }
  std::vector<std::vector<int>>& paths() { return paths_; }
  const std::vector<char>& cut() const { return cut_; }

 private:
  Status routeBoundaryEdge(int e);
  Status routeInteriorEdge(int e);
  void cutAlong(int e, std::vector<int> path);
  void labelWedges(int v);
  int startWedge(int i, int j);
  int firstStep(int e, int i) const {
    const std::vector<int>& p = paths_[e];
    return graph_.edges[e].first == i ? p[1] : p[p.size() - 2];
  }

  const TriMesh& mesh_;
  const Work& work_;
  const BaseDomain& base_;
  const BaseGraph& graph_;
  std::vector<int> baseOf_;
  std::vector<char> onPath_, cut_;
  std::vector<int> wedge_;  // per corner at a base vertex: its wedge (the first corner of it, CCW)
  std::vector<double> dist_;
  std::vector<int> from_;
  std::vector<std::vector<int>> paths_;
  std::vector<int> cellSize_;  // per base vertex, the vertices of its cell
};

void Router::cutAlong(int e, std::vector<int> path) {
  if (path.front() != base_.baseVertex[graph_.edges[e].first]) std::reverse(path.begin(), path.end());
  for (size_t k = 0; k + 1 < path.size(); ++k) {
    const int c = cornerFacing(mesh_, path[k], path[k + 1]);
    cut_[c] = 1;
    if (mesh_.oppositeCorner[c] >= 0) cut_[mesh_.oppositeCorner[c]] = 1;
  }
  for (size_t k = 1; k + 1 < path.size(); ++k) onPath_[path[k]] = 1;
  paths_[e] = std::move(path);
}

/// Labels the corners at v by the wedge (fan between two cut edges) they lie in.
void Router::labelWedges(int v) {
  bool anyStart = false;
  for (const int* it = mesh_.cornersBegin(v); it != mesh_.cornersEnd(v); ++it) {
    int c = *it;
    if (!cut_[TriMesh::prev(c)]) continue;  // its clockwise edge (v, next) is not cut
    anyStart = true;
    const int label = c;
    for (;;) {
      wedge_[c] = label;
      if (cut_[TriMesh::next(c)]) break;  // its counter-clockwise edge (v, prev) is cut
      c = TriMesh::next(mesh_.oppositeCorner[TriMesh::next(c)]);
    }
  }
  if (!anyStart)
    for (const int* it = mesh_.cornersBegin(v); it != mesh_.cornersEnd(v); ++it) wedge_[*it] = *mesh_.cornersBegin(v);
}

/// The wedge at base vertex i a path to base neighbour j must leave by: the one clockwise-bounded
/// by the path to the routed neighbour before j clockwise (any, when none is routed yet).
int Router::startWedge(int i, int j) {
  const int vi = base_.baseVertex[i];
  labelWedges(vi);
  int p = graph_.clockwise(i, j);
  for (size_t steps = 0; p >= 0 && p != j && steps <= graph_.fan[i].size(); ++steps) {
    const int e = graph_.edge(i, p);
    if (!paths_[e].empty()) {
      const int a = firstStep(e, i);
      for (const int* it = mesh_.cornersBegin(vi); it != mesh_.cornersEnd(vi); ++it)
        if (mesh_.vertex(TriMesh::next(*it)) == a) return wedge_[*it];
      return -1;
    }
    p = graph_.clockwise(i, p);
  }
  return wedge_[*mesh_.cornersBegin(vi)];
}

Status Router::routeBoundaryEdge(int e) {
  // The base triangle's edge x -> y runs the way the boundary does (interior on the left).
  int x = graph_.edges[e].first, y = graph_.edges[e].second;
  if (graph_.clockwise(x, y) >= 0) std::swap(x, y);  // triangle (x, ., y) holds y -> x
  const int to = base_.baseVertex[y];
  std::vector<int> path{base_.baseVertex[x]};
  while (path.back() != to) {
    int step = -1;
    for (const int* it = mesh_.cornersBegin(path.back()); it != mesh_.cornersEnd(path.back()); ++it)
      if (mesh_.oppositeCorner[TriMesh::prev(*it)] == kBoundary) step = mesh_.vertex(TriMesh::next(*it));
    if (step < 0 || (baseOf_[step] >= 0 && step != to) || path.size() > static_cast<size_t>(mesh_.vertexCount()))
      return {StatusCode::NotConverged, "geodesic parameterisation: the boundary between base vertices " +
                                            edgeName(graph_.edges[e]) + " meets another base vertex"};
    path.push_back(step);
  }
  cutAlong(e, std::move(path));
  return Status::ok();
}

Status Router::routeInteriorEdge(int e) {
  const auto [i, j] = graph_.edges[e];
  const int vi = base_.baseVertex[i], vj = base_.baseVertex[j];
  const int ws = startWedge(i, j), wt = startWedge(j, i);
  if (ws < 0 || wt < 0) return internalError("geodesic parameterisation: a path's wedge was not found");
  auto cost = [&](int a, int b) {
    const double f = (work_.cell[b] == i || work_.cell[b] == j) ? 1.0 : kOutsideCells;
    return f * (mesh_.positions[a] - mesh_.positions[b]).norm();
  };
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  std::vector<int> touched;
  auto offer = [&](int from, int v, double d) {
    if (d >= dist_[v]) return;
    if (dist_[v] == kUnreached) touched.push_back(v);
    dist_[v] = d;
    from_[v] = from;
    heap.push({d, v});
  };
  auto enter = [&](int from, int v, int corner, double d) {  // `corner`: v's corner in a face of the edge
    if (onPath_[v]) return;
    if (baseOf_[v] >= 0 && (v != vj || wedge_[corner] != wt)) return;
    offer(from, v, d);
  };
  for (const int* it = mesh_.cornersBegin(vi); it != mesh_.cornersEnd(vi); ++it) {
    const int c = *it;
    if (wedge_[c] != ws) continue;
    if (!cut_[TriMesh::prev(c)])
      enter(vi, mesh_.vertex(TriMesh::next(c)), TriMesh::next(c), cost(vi, mesh_.vertex(TriMesh::next(c))));
    if (!cut_[TriMesh::next(c)])
      enter(vi, mesh_.vertex(TriMesh::prev(c)), TriMesh::prev(c), cost(vi, mesh_.vertex(TriMesh::prev(c))));
  }
  bool found = false;
  const int budget = kSearchPerCellVertex * (cellSize_[i] + cellSize_[j]) + kSearchMinimum;
  for (int settled = 0; !heap.empty() && settled < budget;) {
    const auto [d, v] = heap.top();
    heap.pop();
    if (d > dist_[v]) continue;
    ++settled;
    if (v == vj) {
      found = true;
      break;
    }
    for (const int* it = mesh_.cornersBegin(v); it != mesh_.cornersEnd(v); ++it) {
      const int n1 = TriMesh::next(*it), n2 = TriMesh::prev(*it);
      enter(v, mesh_.vertex(n1), n1, d + cost(v, mesh_.vertex(n1)));
      enter(v, mesh_.vertex(n2), n2, d + cost(v, mesh_.vertex(n2)));
    }
  }
  std::vector<int> path;
  if (found)
    for (int v = vj; v != vi; v = from_[v]) path.push_back(v);
  for (int v : touched) dist_[v] = kUnreached;
  if (!found)
    return {StatusCode::NotConverged,
            "geodesic parameterisation: no way left between the paths already cut for "
            "base edge " +
                edgeName(graph_.edges[e])};
  path.push_back(vi);
  cutAlong(e, std::move(path));
  return Status::ok();
}

Status Router::route(const std::vector<int>& edges, std::vector<int>* failed, Progress& progress) {
  for (size_t k = 0; k < edges.size(); ++k) {
    if (!progress.report(static_cast<double>(k) / edges.size(), "Cutting the surface along the base edges"))
      return cancelled();
    const int e = edges[k];
    if (graph_.edgeFaces[e] == 1) {
      if (Status s = routeBoundaryEdge(e); !s) return s;
    } else if (Status s = routeInteriorEdge(e); !s) {
      if (s.code != StatusCode::NotConverged) return s;
      failed->push_back(e);
    }
  }
  return Status::ok();
}

/// Boundary edges first (they bound the sectors at boundary base vertices), then a spanning tree
/// of the base (Kruskal, shortest first), then the other edges, shortest first (Praun et al.
/// 2001): once every base vertex is joined to the others, each new path closes one cycle, and
/// leaving and reaching its ends in the right sectors puts every base vertex on its right side;
/// a path routed earlier could pass any unjoined base vertex on the wrong side.
std::array<std::vector<int>, 2> routingOrder(const TriMesh& mesh, const BaseDomain& base, const BaseGraph& graph) {
  std::vector<int> order(graph.edges.size());
  std::iota(order.begin(), order.end(), 0);
  auto straight = [&](int e) {
    return (mesh.positions[base.baseVertex[graph.edges[e].first]] -
            mesh.positions[base.baseVertex[graph.edges[e].second]])
        .squaredNorm();
  };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return straight(a) < straight(b); });
  std::vector<int> root(base.baseVertex.size());
  std::iota(root.begin(), root.end(), 0);
  auto find = [&](int v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  std::vector<int> boundary, tree, rest;
  for (int e : order)
    if (graph.edgeFaces[e] == 1) {
      boundary.push_back(e);
      root[find(graph.edges[e].first)] = find(graph.edges[e].second);
    }
  for (int e : order) {
    if (graph.edgeFaces[e] == 1) continue;
    const int a = find(graph.edges[e].first), b = find(graph.edges[e].second);
    if (a != b) {
      root[a] = b;
      tree.push_back(e);
    } else {
      rest.push_back(e);
    }
  }
  boundary.insert(boundary.end(), tree.begin(), tree.end());
  return {boundary, rest};
}

/// Uncut edges whose two ends lie on paths or are base vertices: a corridor between two paths (or
/// base vertices) one face wide has no vertex for another path to pass through until they are split.
std::vector<std::pair<int, int>> edgesBetweenPaths(const TriMesh& mesh, const std::vector<char>& cut,
                                                   const std::vector<std::vector<int>>& paths,
                                                   const std::vector<int>& baseVertex) {
  std::vector<char> taken(mesh.vertexCount(), 0);
  for (int v : baseVertex) taken[v] = 1;
  for (const std::vector<int>& p : paths)
    for (int v : p) taken[v] = 1;
  std::vector<std::pair<int, int>> out;
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    if (cut[c] || mesh.oppositeCorner[c] < c) continue;
    const int a = mesh.vertex(TriMesh::next(c)), b = mesh.vertex(TriMesh::prev(c));
    if (taken[a] && taken[b]) out.emplace_back(a, b);
  }
  return out;
}

/// The base vertices' stars split until each has kValenceMargin more edges than base edges
/// (kMaxStarSplits rounds at most).
void splitStars(Work& work, const BaseDomain& base, const BaseGraph& graph, int* splits) {
  std::vector<int> baseOf(work.positions.size(), -1);
  for (size_t i = 0; i < base.baseVertex.size(); ++i) baseOf[base.baseVertex[i]] = static_cast<int>(i);
  for (int round = 0; round < kMaxStarSplits; ++round) {
    // Per base vertex, the edges facing it in its faces (its valence: their count), read from the
    // faces without building the mesh.
    std::vector<std::vector<std::pair<int, int>>> star(base.baseVertex.size());
    for (const Tri& t : work.triangles)
      for (int k = 0; k < 3; ++k)
        if (baseOf[t[k]] >= 0) star[baseOf[t[k]]].emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
    std::vector<std::pair<int, int>> link;
    for (size_t i = 0; i < star.size(); ++i)
      if (star[i].size() < graph.fan[i].size() + kValenceMargin)
        link.insert(link.end(), star[i].begin(), star[i].end());
    if (link.empty()) return;
    *splits += splitEdges(work, link);
    baseOf.resize(work.positions.size(), -1);
  }
}

/// Per piece of faces joined across uncut edges: its faces' base triangle, after checking that
/// its boundary meets exactly the three corners of one base triangle, in its order, and that it
/// is a disk (one boundary loop, V - E + F = 1).
Expected<std::vector<int>> assignPieces(const TriMesh& mesh, const std::vector<char>& cut, const BaseDomain& base,
                                        const BaseGraph& graph) {
  const int nf = mesh.faceCount();
  std::vector<int> baseOf(mesh.vertexCount(), -1);
  for (size_t i = 0; i < base.baseVertex.size(); ++i) baseOf[base.baseVertex[i]] = static_cast<int>(i);
  std::unordered_map<uint64_t, int> triangleOf;  // (corner 0's base vertex, corner 1's) -> triangle
  for (size_t t = 0; t < base.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      triangleOf[(static_cast<uint64_t>(base.triangles[t][k]) << 32) |
                 static_cast<uint32_t>(base.triangles[t][(k + 1) % 3])] = static_cast<int>(t);
  std::vector<int> triangle(nf, -1), owner(base.triangles.size(), -1);
  std::vector<int> stack, faces;
  std::vector<int> mark(mesh.vertexCount(), -1);
  for (int seed = 0; seed < nf; ++seed) {
    if (triangle[seed] >= 0) continue;
    faces.assign(1, seed);
    triangle[seed] = -2;
    for (size_t k = 0; k < faces.size(); ++k)
      for (int c = 3 * faces[k]; c < 3 * faces[k] + 3; ++c)
        if (!cut[c] && triangle[TriMesh::face(mesh.oppositeCorner[c])] == -1) {
          triangle[TriMesh::face(mesh.oppositeCorner[c])] = -2;
          faces.push_back(TriMesh::face(mesh.oppositeCorner[c]));
        }
    // The boundary loop from the first cut corner; the base vertices it meets, in order.
    int start = -1, cutCorners = 0, vertices = 0;
    for (int f : faces)
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        if (cut[c] && start < 0) start = c;
        cutCorners += cut[c];
        if (mark[mesh.vertex(c)] != seed) {
          mark[mesh.vertex(c)] = seed;
          ++vertices;
        }
      }
    std::vector<int> corners;
    int loop = 0;
    for (int c = start; start >= 0;) {
      ++loop;
      const int b = mesh.vertex(TriMesh::prev(c));
      if (baseOf[b] >= 0) corners.push_back(baseOf[b]);
      int k = TriMesh::next(c);
      while (!cut[k]) k = TriMesh::next(mesh.oppositeCorner[k]);
      c = k;
      if (c == start || loop > cutCorners) break;
    }
    const int edges = (3 * static_cast<int>(faces.size()) + cutCorners) / 2;
    int t = -1;
    if (corners.size() == 3 && loop == cutCorners && vertices - edges + static_cast<int>(faces.size()) == 1) {
      const auto it = triangleOf.find((static_cast<uint64_t>(corners[0]) << 32) | static_cast<uint32_t>(corners[1]));
      if (it != triangleOf.end()) {
        const Tri& bt = base.triangles[it->second];
        const int k0 = static_cast<int>(std::find(bt.begin(), bt.end(), corners[0]) - bt.begin());
        if (bt[(k0 + 2) % 3] == corners[2]) t = it->second;
      }
    }
    if (t < 0 || owner[t] >= 0)
      return Status{StatusCode::NotConverged, "geodesic parameterisation: a piece of " + std::to_string(faces.size()) +
                                                  " faces is not the disk of one base triangle (it meets " +
                                                  std::to_string(corners.size()) + " base vertices)"};
    owner[t] = seed;
    for (int f : faces) triangle[f] = t;
  }
  for (size_t t = 0; t < owner.size(); ++t)
    if (owner[t] < 0)
      return Status{StatusCode::NotConverged,
                    "geodesic parameterisation: base triangle " + std::to_string(t) + " got no piece"};
  (void)graph;
  return triangle;
}

/// Edges inside a piece whose two ends lie on one of its sides (a corner lies on two).
std::vector<std::pair<int, int>> chords(const TriMesh& mesh, const std::vector<char>& cut, const BaseDomain& base,
                                        const BaseGraph& graph, const std::vector<std::vector<int>>& paths) {
  std::vector<int> side(mesh.vertexCount(), -1), baseOf(mesh.vertexCount(), -1);
  for (size_t i = 0; i < base.baseVertex.size(); ++i) baseOf[base.baseVertex[i]] = static_cast<int>(i);
  for (size_t e = 0; e < paths.size(); ++e)
    for (size_t k = 1; k + 1 < paths[e].size(); ++k) side[paths[e][k]] = static_cast<int>(e);
  auto onSide = [&](int v, int e) {  // v lies on the side of base edge e
    return side[v] == e ||
           (baseOf[v] >= 0 && (graph.edges[e].first == baseOf[v] || graph.edges[e].second == baseOf[v]));
  };
  std::vector<std::pair<int, int>> out;
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    if (cut[c] || mesh.oppositeCorner[c] < c) continue;
    const int a = mesh.vertex(TriMesh::next(c)), b = mesh.vertex(TriMesh::prev(c));
    bool chord = false;
    if (baseOf[a] >= 0 && baseOf[b] >= 0)
      chord = true;
    else if (side[a] >= 0)
      chord = onSide(b, side[a]);
    else if (side[b] >= 0)
      chord = onSide(a, side[b]);
    if (chord) out.emplace_back(a, b);
  }
  return out;
}

std::vector<char> cutFlags(const TriMesh& mesh, const std::vector<std::vector<int>>& paths) {
  std::vector<char> cut(3 * mesh.faceCount(), 0);
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) cut[c] = mesh.oppositeCorner[c] < 0;
  for (const std::vector<int>& p : paths)
    for (size_t k = 0; k + 1 < p.size(); ++k) {
      const int c = cornerFacing(mesh, p[k], p[k + 1]);
      cut[c] = 1;
      if (mesh.oppositeCorner[c] >= 0) cut[mesh.oppositeCorner[c]] = 1;
    }
  return cut;
}

Status checkBase(const TriMesh& input, const BaseDomain& base) {
  if (base.triangles.empty() || base.baseVertex.empty())
    return invalidInput("geodesic parameterisation: the base has no triangle");
  if (static_cast<int>(base.cell.size()) != input.vertexCount())
    return invalidInput("geodesic parameterisation: the base's cells are not the input's vertices");
  for (int v : base.baseVertex)
    if (v < 0 || v >= input.vertexCount())
      return invalidInput("geodesic parameterisation: a base vertex is out of range");
  for (const Tri& t : base.triangles)
    for (int i : t)
      if (i < 0 || i >= static_cast<int>(base.baseVertex.size()))
        return invalidInput("geodesic parameterisation: a base corner is no base vertex");
  if (!input.topology.isManifold())
    return nonManifold("geodesic parameterisation: the input has " + input.topology.nonManifoldCounts());
  return Status::ok();
}

}  // namespace

Expected<BaseDomain> buildBaseDomain(const TriMesh& input, const BaseDomainParams& params, Progress progress) {
  if (params.baseVertices < 4) return invalidInput("geodesic parameterisation: BaseVertices must be at least 4");
  if (params.centroidalIterations < 0)
    return invalidInput("geodesic parameterisation: CentroidalIterations must be at least 0");
  if (!(params.curvatureStrength >= 0.0))
    return invalidInput("geodesic parameterisation: the curvature strength must be >= 0");
  FpsParams fps;
  fps.targetCount = std::min(params.baseVertices, input.vertexCount() - input.topology.isolatedVertices);
  fps.seed = params.seed;
  Metric metric = Metric::uniform();
  if (params.curvatureStrength > 0.0) {
    AdaptiveMetricParams adaptive;
    adaptive.speed.strength = params.curvatureStrength;
    adaptive.curvature.radius = std::min(kCurvatureRadiusInSpacings * targetSpacing(input, fps),
                                         kCurvatureRadiusInEdges * input.meanEdgeLength());
    Expected<AdaptiveMetricResult> a = adaptiveMetric(input, {}, adaptive);
    if (!a) return a.status();
    metric = a->speed.metric;
  }
  FastMarcher marcher(input, metric);
  // The first samples' fronts are the dearest (each covers much of the surface): one in
  // kSamplesPerSampleIn3d, at most kSamplesIn3d, chosen in 3D first (as segment/ does).
  fps.initialSamples =
      farthestPointsIn3d(input, std::min(kSamplesIn3d, fps.targetCount / kSamplesPerSampleIn3d), params.seed);
  Expected<FpsResult> sampled = farthestPointSampling(marcher, fps, progress.sub(0.0, 0.3));
  if (!sampled) return sampled.status();
  // The marcher holds the samples' field, sample i in cell i (as Lloyd leaves it too): the dual is
  // read from it, with no new engine and no front over the whole surface again.
  std::vector<SurfacePoint> samples = std::move(sampled->origin);
  if (params.centroidalIterations > 0) {
    LloydParams lloyd;
    lloyd.iterations = params.centroidalIterations;
    lloyd.vertexSeeds = true;
    lloyd.keepBoundarySeeds = true;
    lloyd.marcherHoldsSeedsField = true;
    Expected<LloydResult> relaxed = geodesicLloyd(input, metric, marcher, samples, lloyd, progress.sub(0.3, 0.6));
    if (!relaxed) return relaxed.status();
    samples = std::move(relaxed->seeds);
  }
  DelaunayParams delaunay;
  delaunay.delaunayFlips = false;  // the base must stay the dual of the cells the paths follow
  Expected<DelaunayResult> dual = geodesicDelaunay(marcher, std::move(samples), delaunay, progress.sub(0.6, 1.0));
  if (!dual) return dual.status();
  BaseDomain base;
  base.triangles = dual->mesh.triangles;
  for (const SurfacePoint& o : dual->origin) base.baseVertex.push_back(o.vertex);
  base.cell = dual->cell;
  base.addedSamples = dual->addedSamples;
  return base;
}

Expected<BasePieces> cutIntoBasePieces(const TriMesh& input, const BaseDomain& base, Progress progress) {
  if (Status s = checkBase(input, base); !s) return s;
  const BaseGraph graph = baseGraph(base);
  Work work = initialWork(input, base.cell);
  BasePieces out;
  splitStars(work, base, graph, &out.splitEdges);
  Expected<TriMesh> mesh = buildAdjacency(work.positions, work.triangles);
  if (!mesh) return mesh.status();
  // Phase 0: the boundary and a spanning tree, until all are routed; phase 1: the other edges.
  // A path of phase 1 routed while the tree misses an edge could pass a base vertex on its
  // wrong side, so the phases do not mix.
  std::array<std::vector<int>, 2> phases = routingOrder(*mesh, base, graph);
  std::vector<int> pending = std::move(phases[0]);
  out.path.resize(graph.edges.size());
  for (int round = 0, phase = 0, stalled = 0;; ++round) {
    Router router(*mesh, work, base, graph);
    router.adopt(out.path);
    std::vector<int> failed;
    Progress step = progress.sub(phase == 0 ? 0.0 : 0.2, 1.0);
    if (Status s = router.route(pending, &failed, step); !s) return s;
    out.path = std::move(router.paths());
    if (failed.empty() && phase == 1) break;
    if (failed.empty()) {
      pending = std::move(phases[1]);
      phase = 1;
      continue;
    }
    stalled = failed.size() < pending.size() ? 0 : stalled + 1;
    if (round >= kMaxRoutingRounds || stalled >= kMaxStalledRounds)
      return Status{StatusCode::NotConverged, "geodesic parameterisation: " + std::to_string(failed.size()) +
                                                  " base edges found no way between the paths already cut, e.g. " +
                                                  edgeName(graph.edges[failed.front()])};
    out.splitEdges += splitEdges(work, edgesBetweenPaths(*mesh, router.cut(), out.path, base.baseVertex));
    if (work.triangles.size() > kMaxFacesPerInputFace * static_cast<size_t>(input.faceCount()))
      return Status{StatusCode::NotConverged,
                    "geodesic parameterisation: cutting the surface along " + std::to_string(failed.size()) +
                        " more base edges would take more than " + std::to_string(kMaxFacesPerInputFace) +
                        " times the input's faces: the mesh is too coarse for " +
                        std::to_string(base.baseVertex.size()) + " base vertices (ask for fewer BaseVertices)"};
    mesh = buildAdjacency(work.positions, work.triangles);
    if (!mesh) return mesh.status();
    pending = std::move(failed);
  }
  std::vector<char> cut = cutFlags(*mesh, out.path);
  Expected<std::vector<int>> assigned = assignPieces(*mesh, cut, base, graph);
  if (!assigned) return assigned.status();
  const std::vector<std::pair<int, int>> toSplit = chords(*mesh, cut, base, graph, out.path);
  if (!toSplit.empty()) {
    out.splitEdges += splitEdges(work, toSplit);
    mesh = buildAdjacency(work.positions, work.triangles);
    if (!mesh) return mesh.status();
    cut = cutFlags(*mesh, out.path);
    assigned = assignPieces(*mesh, cut, base, graph);
    if (!assigned) return assigned.status();
  }
  countTopology(*mesh);  // the rounds built the adjacency only
  out.mesh = std::move(*mesh);
  out.originalFace = std::move(work.originalFace);
  out.cornerBary = std::move(work.cornerBary);
  out.triangle = std::move(*assigned);
  out.onCut = std::move(cut);
  out.edges = graph.edges;
  out.triangleEdge = graph.triangleEdge;
  return out;
}

}  // namespace gr
