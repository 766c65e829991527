#include "core/mesh/tri_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "core/base/two_threads.h"

namespace gr {
namespace {

/// Union-find with path halving; sizes are fixed at construction.
class DisjointSets {
 public:
  explicit DisjointSets(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

std::string formatVec(const Vec3& p) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return text;
}

Status validate(const std::vector<Vec3>& positions, const std::vector<Tri>& triangles) {
  if (positions.empty()) return invalidInput("the mesh has no vertices");
  if (triangles.empty())
    return invalidInput("the mesh has no faces (" + std::to_string(positions.size()) +
                        " vertices): a point cloud cannot carry geodesics");
  for (size_t v = 0; v < positions.size(); ++v)
    if (!positions[v].allFinite())
      return invalidInput("vertex " + std::to_string(v) + " has a non-finite coordinate " + formatVec(positions[v]));
  // Distances are computed from squared differences: they must not overflow.
  Vec3 lo = positions[0], hi = positions[0];
  for (const Vec3& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (!std::isfinite((hi - lo).squaredNorm()))
    return invalidInput("the coordinates are too large (bounding box " + formatVec(lo) + " to " + formatVec(hi) +
                        "): squared distances overflow; scale the mesh down first");
  const int n = static_cast<int>(positions.size());
  for (size_t f = 0; f < triangles.size(); ++f) {
    const Tri& t = triangles[f];
    for (int k = 0; k < 3; ++k)
      if (t[k] < 0 || t[k] >= n)
        return invalidInput("face " + std::to_string(f) + " references vertex " + std::to_string(t[k]) +
                            ", which does not exist");
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return degenerate("face " + std::to_string(f) + " uses vertex " +
                        std::to_string(t[0] == t[1] || t[0] == t[2] ? t[0] : t[1]) +
                        " twice (remove duplicated vertices and zero-area faces first)");
  }
  return Status::ok();
}

}  // namespace

void rebuildVertexCorners(TriMesh& m) {
  const int nv = m.vertexCount();
  m.vertexCornerBegin.assign(nv + 1, 0);
  for (const Tri& t : m.triangles)
    for (int v : t) ++m.vertexCornerBegin[v + 1];
  for (int v = 0; v < nv; ++v) m.vertexCornerBegin[v + 1] += m.vertexCornerBegin[v];
  m.vertexCorners.resize(3 * m.triangles.size());
  std::vector<int> fill(m.vertexCornerBegin.begin(), m.vertexCornerBegin.end() - 1);
  for (int c = 0; c < 3 * m.faceCount(); ++c) m.vertexCorners[fill[m.vertex(c)]++] = c;
}

std::vector<std::array<int, 2>> starNeighbours(const TriMesh& m) {
  std::vector<std::array<int, 2>> others(m.vertexCorners.size());
  for (size_t k = 0; k < others.size(); ++k) {
    const int c = m.vertexCorners[k];
    others[k] = {m.vertex(TriMesh::next(c)), m.vertex(TriMesh::prev(c))};
  }
  return others;
}

namespace {

/// buildOppositeCorners for the edges whose smaller endpoint is in [first, last).
void buildOppositeCorners(TriMesh& m, const std::vector<std::array<int, 2>>& others, int first, int last) {
  for (int p = first; p < last; ++p) {
    const int begin = m.vertexCornerBegin[p], end = m.vertexCornerBegin[p + 1];
    for (int k = begin; k < end; ++k)
      for (int side = 0; side < 2; ++side) {
        const int x = others[k][side];
        if (x < p) continue;  // edge {p, x} is done from x
        // The corner of this face facing edge {p, x}, and the same in every other face with it.
        const int c = m.vertexCorners[k];
        const int facing = side == 0 ? TriMesh::prev(c) : TriMesh::next(c);
        int found = kBoundary;
        for (int j = begin; j < end; ++j) {
          if (j == k) continue;
          int across;
          if (others[j][0] == x)
            across = TriMesh::prev(m.vertexCorners[j]);
          else if (others[j][1] == x)
            across = TriMesh::next(m.vertexCorners[j]);
          else
            continue;
          found = (found == kBoundary) ? across : kNonManifold;
        }
        m.oppositeCorner[facing] = found;
      }
  }
}

/// Runs work(begin, end) over [0, n) in two halves, the second on a helper thread (onTwoThreads)
/// when n is large enough to pay for one (bunny00's 38k vertices: the topology in 11.7 ms instead
/// of 15).
template <class Work>
void overTwoHalves(int n, const Work& work) {
  constexpr int kMinForThread = 20000;
  if (n < kMinForThread) return work(0, n);
  onTwoThreads([&](bool helper) { helper ? work(n / 2, n) : work(0, n / 2); });
}

/// For each corner, finds the face across its opposite edge {p, q} among the corners of p, the
/// smaller endpoint: O(sum of valence^2), no hash map. Each corner is written from one vertex only
/// (its edge's smaller endpoint), so vertex ranges run side by side.
void buildOppositeCorners(TriMesh& m, const std::vector<std::array<int, 2>>& others) {
  m.oppositeCorner.assign(3 * m.faceCount(), kBoundary);
  overTwoHalves(m.vertexCount(), [&](int first, int last) { buildOppositeCorners(m, others, first, last); });
}

/// Fans around vertex v: its corners joined through the manifold edges at v (edges {v, x} in
/// exactly two faces), whichever way the faces are oriented. Returns the number of fans;
/// `parent` is scratch space.
int countFans(const TriMesh& m, const std::vector<std::array<int, 2>>& others, int v, std::vector<int>& parent) {
  const int begin = m.vertexCornerBegin[v], n = m.vertexCornerBegin[v + 1] - begin;
  parent.resize(n);
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&parent](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (int i = 0; i < n; ++i)
    for (int x : others[begin + i]) {
      int other = -1, count = 0;
      for (int j = 0; j < n; ++j)
        if (j != i && (others[begin + j][0] == x || others[begin + j][1] == x)) {
          other = j;
          ++count;
        }
      if (count == 1) parent[find(i)] = find(other);
    }
  int fans = 0;
  for (int i = 0; i < n; ++i) fans += find(i) == i;
  return fans;
}

/// Boundary edges, and manifold edges whose two faces disagree on orientation. Returns the number
/// of corners facing a non-manifold edge.
int countBoundaryAndInconsistentEdges(const TriMesh& m, Topology& t) {
  const int nc = 3 * m.faceCount();
  // Edges: each manifold edge is seen from two corners, others from one (boundary) or 3+.
  int nonManifoldCorners = 0;
  for (int c = 0; c < nc; ++c) {
    const int o = m.oppositeCorner[c];
    if (o == kBoundary) {
      ++t.boundaryEdges;
    } else if (o == kNonManifold) {
      ++nonManifoldCorners;
    } else if (c < o) {
      // Consistent orientation: the shared edge runs p->q in one face and q->p in the other.
      if (m.vertex(TriMesh::next(c)) == m.vertex(TriMesh::next(o))) ++t.inconsistentEdges;
    }
  }
  return nonManifoldCorners;
}

/// Non-manifold edges: their corners grouped by (min, max) endpoint pair.
void countNonManifoldEdges(const TriMesh& m, int nonManifoldCorners, Topology& t) {
  const int nv = m.vertexCount();
  const int nc = 3 * m.faceCount();
  std::vector<std::pair<long long, int>> keys;
  keys.reserve(nonManifoldCorners);
  for (int c = 0; c < nc; ++c)
    if (m.oppositeCorner[c] == kNonManifold) {
      long long p = m.vertex(TriMesh::next(c)), q = m.vertex(TriMesh::prev(c));
      if (p > q) std::swap(p, q);
      keys.push_back({p * nv + q, c});
    }
  std::sort(keys.begin(), keys.end());
  for (size_t i = 0; i < keys.size(); ++i)
    if (i == 0 || keys[i].first != keys[i - 1].first) ++t.nonManifoldEdges;
}

/// The number of v's corners reached from its first corner by crossing edges at v that have an
/// opposite corner (whichever way the faces are oriented), both ways round: v's valence when it
/// has one fan through manifold edges (every vertex of a clean mesh), fewer otherwise.
int cornersOfFirstFan(const TriMesh& m, int v) {
  const int first = *m.cornersBegin(v);
  int reached = 1;
  for (int dir = 0; dir < 2; ++dir) {
    int leave = dir == 0 ? TriMesh::prev(first) : TriMesh::next(first);  // the corner facing the edge crossed next
    for (int steps = 0; steps < m.valence(v); ++steps) {
      const int o = m.oppositeCorner[leave];
      if (o < 0) break;
      const int f = TriMesh::face(o);
      int at = -1;  // the corner of f at v
      for (int k = 0; k < 3; ++k)
        if (m.triangles[f][k] == v) at = 3 * f + k;
      if (at < 0 || at == first) return at == first ? reached : -1;  // closed: all of the fan
      ++reached;
      leave = 3 * f + (3 - at % 3 - o % 3);  // the third corner of f faces v's other edge in f
    }
  }
  return reached;
}

/// Whether v's corners form one closed fan of consistently oriented faces, read from its star
/// neighbours alone (contiguous, no walk over the faces): every corner's next vertex differs from
/// the others' next vertices, likewise its previous vertex, and following each corner's previous
/// vertex to the corner whose next vertex it is visits all of them in one cycle. Then every edge
/// at v has exactly two faces, so v has one fan. False leaves the question to the walk
/// (boundaries, orientation flips, non-manifold configurations).
bool oneOrientedCycle(const std::vector<std::array<int, 2>>& others, int begin, int n) {
  const std::array<int, 2>* star = others.data() + begin;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (star[i][0] == star[j][0] || star[i][1] == star[j][1]) return false;
  int at = 0;
  for (int steps = 1; steps < n; ++steps) {
    int next = -1;
    for (int j = 0; j < n && next < 0; ++j)
      if (star[j][0] == star[at][1]) next = j;
    if (next <= 0) return false;  // no such corner (an open fan), or the cycle closed early
    at = next;
  }
  return star[at][1] == star[0][0];
}

/// Isolated vertices, and non-manifold ones: a vertex with more than one fan of faces.
void countNonManifoldVertices(const TriMesh& m, const std::vector<std::array<int, 2>>& others, Topology& t) {
  std::array<Topology, 2> halves;  // the two halves' counts, merged in vertex order
  overTwoHalves(m.vertexCount(), [&](int first, int last) {
    Topology& h = halves[first > 0];
    std::vector<int> scratch;
    for (int v = first; v < last; ++v) {
      if (m.valence(v) == 0) {
        ++h.isolatedVertices;
        continue;
      }
      if (oneOrientedCycle(others, m.vertexCornerBegin[v], m.valence(v))) continue;  // the common case
      if (cornersOfFirstFan(m, v) != m.valence(v) && countFans(m, others, v, scratch) > 1) {
        ++h.nonManifoldVertices;
        h.nonManifoldVertexList.push_back(v);
      }
    }
  });
  for (const Topology& h : halves) {
    t.isolatedVertices += h.isolatedVertices;
    t.nonManifoldVertices += h.nonManifoldVertices;
    t.nonManifoldVertexList.insert(t.nonManifoldVertexList.end(), h.nonManifoldVertexList.begin(),
                                   h.nonManifoldVertexList.end());
  }
}

/// Components over face-connected vertices, numbered in order of their smallest vertex.
void labelComponents(const TriMesh& m, Topology& t) {
  const int nv = m.vertexCount();
  DisjointSets comps(nv);
  for (const Tri& tri : m.triangles) {
    comps.unite(tri[0], tri[1]);
    comps.unite(tri[1], tri[2]);
  }
  t.componentOfVertex.assign(nv, -1);
  std::vector<int> idOfRoot(nv, -1);
  for (int v = 0; v < nv; ++v) {
    if (m.valence(v) == 0) continue;
    int& id = idOfRoot[comps.find(v)];
    if (id < 0) id = t.components++;
    t.componentOfVertex[v] = id;
  }
}

/// Boundary loops: boundary edges joined at their shared endpoints. Returns the number of loops
/// of each component.
std::vector<int> countBoundaryLoops(const TriMesh& m, Topology& t) {
  const int nv = m.vertexCount();
  const int nc = 3 * m.faceCount();
  DisjointSets loops(nv);
  std::vector<char> onBoundary(nv, 0);
  for (int c = 0; c < nc; ++c)
    if (m.oppositeCorner[c] == kBoundary) {
      const int p = m.vertex(TriMesh::next(c)), q = m.vertex(TriMesh::prev(c));
      loops.unite(p, q);
      onBoundary[p] = onBoundary[q] = 1;
    }
  std::vector<char> loopSeen(nv, 0);
  std::vector<int> loopsOfComponent(t.components, 0);
  for (int v = 0; v < nv; ++v)
    if (onBoundary[v] && !loopSeen[loops.find(v)]) {
      loopSeen[loops.find(v)] = 1;
      ++t.boundaryLoops;
      ++loopsOfComponent[t.componentOfVertex[v]];
    }
  return loopsOfComponent;
}

/// Euler characteristic per component: chi_i = V_i - E_i + F_i; genus_i = (2 - chi_i - b_i) / 2.
/// A manifold edge is seen from two corners, a boundary edge from one.
void countEulerCharacteristicAndGenus(const TriMesh& m, const std::vector<int>& loopsOfComponent, Topology& t) {
  const int nv = m.vertexCount();
  const int nc = 3 * m.faceCount();
  std::vector<long long> vCount(t.components, 0), fCount(t.components, 0), eTwice(t.components, 0);
  for (int v = 0; v < nv; ++v)
    if (t.componentOfVertex[v] >= 0) ++vCount[t.componentOfVertex[v]];
  for (const Tri& tri : m.triangles) ++fCount[t.componentOfVertex[tri[0]]];
  for (int c = 0; c < nc; ++c) {
    const int o = m.oppositeCorner[c];
    eTwice[t.componentOfVertex[m.vertex(c)]] += (o == kBoundary) ? 2 : (o >= 0 ? 1 : 0);
  }
  long long chiAll = 0;
  for (int i = 0; i < t.components; ++i) {
    const long long chiI = vCount[i] - eTwice[i] / 2 + fCount[i];
    chiAll += chiI;
    t.genus += static_cast<int>((2 - chiI - loopsOfComponent[i]) / 2);
  }
  // Non-manifold edges were left out of the per-component edge counts; subtract them globally.
  t.eulerCharacteristic = static_cast<int>(chiAll - t.nonManifoldEdges);
}

void countTopology(TriMesh& m, const std::vector<std::array<int, 2>>& others) {
  Topology& t = m.topology;
  t = Topology{};
  const int nonManifoldCorners = countBoundaryAndInconsistentEdges(m, t);
  countNonManifoldEdges(m, nonManifoldCorners, t);
  countNonManifoldVertices(m, others, t);
  labelComponents(m, t);
  const std::vector<int> loopsOfComponent = countBoundaryLoops(m, t);
  countEulerCharacteristicAndGenus(m, loopsOfComponent, t);
}

}  // namespace

namespace {

/// The checks, the vertex -> corner lists and the opposite corners; `others` receives the
/// star neighbours (starNeighbours), which the topology counts read too.
Expected<TriMesh> withAdjacency(std::vector<Vec3> positions, std::vector<Tri> triangles,
                                std::vector<std::array<int, 2>>& others) {
  if (Status s = validate(positions, triangles); !s) return s;
  TriMesh m;
  m.positions = std::move(positions);
  m.triangles = std::move(triangles);
  rebuildVertexCorners(m);
  others = starNeighbours(m);
  buildOppositeCorners(m, others);
  return m;
}

}  // namespace

Expected<TriMesh> buildTriMesh(std::vector<Vec3> positions, std::vector<Tri> triangles) {
  std::vector<std::array<int, 2>> others;
  Expected<TriMesh> m = withAdjacency(std::move(positions), std::move(triangles), others);
  if (m) countTopology(*m, others);
  return m;
}

Expected<TriMesh> buildAdjacency(std::vector<Vec3> positions, std::vector<Tri> triangles) {
  std::vector<std::array<int, 2>> others;
  return withAdjacency(std::move(positions), std::move(triangles), others);
}

void countTopology(TriMesh& mesh) { countTopology(mesh, starNeighbours(mesh)); }

std::string Topology::nonManifoldCounts() const {
  return std::to_string(nonManifoldEdges) + " non-manifold edges and " + std::to_string(nonManifoldVertices) +
         " non-manifold vertices";
}

double TriMesh::boundingBoxDiagonal() const {
  if (positions.empty()) return 0.0;
  Vec3 lo = positions[0], hi = positions[0];
  for (const Vec3& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

int TriMesh::looseFaceCount() const {
  int loose = 0;
  for (int f = 0; f < faceCount(); ++f)
    loose += oppositeCorner[3 * f] < 0 && oppositeCorner[3 * f + 1] < 0 && oppositeCorner[3 * f + 2] < 0;
  return loose;
}

double TriMesh::meanEdgeLength() const {
  if (triangles.empty()) return 0.0;
  double sum = 0.0;
  for (const Tri& t : triangles)
    for (int k = 0; k < 3; ++k) sum += (positions[t[k]] - positions[t[(k + 1) % 3]]).norm();
  return sum / (3.0 * triangles.size());
}

std::vector<char> boundaryVertexFlags(const TriMesh& mesh) {
  std::vector<char> onBoundary(mesh.vertexCount(), 0);
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    if (mesh.oppositeCorner[c] == kBoundary)
      onBoundary[mesh.vertex(TriMesh::next(c))] = onBoundary[mesh.vertex(TriMesh::prev(c))] = 1;
  return onBoundary;
}

std::vector<int> facesOfComponent(const TriMesh& mesh, int component) {
  std::vector<int> faces;
  for (int f = 0; f < mesh.faceCount(); ++f)
    if (mesh.topology.componentOfVertex[mesh.triangles[f][0]] == component) faces.push_back(f);
  return faces;
}

}  // namespace gr
