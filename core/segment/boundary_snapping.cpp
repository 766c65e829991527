#include "core/segment/boundary_snapping.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "core/base/math.h"
#include "core/mesh/face_geometry.h"
#include "core/segment/geodesic_segmentation.h"

namespace gr {
namespace {

constexpr double kSmoothBelowDegrees = 30.0;  ///< edges flatter than this cost their full length
constexpr double kFreeAboveDegrees = 60.0;    ///< edges sharper than this cost nothing
constexpr double kKeepLabel = 1e-6;           ///< cost of moving a face, in mean edge lengths

/// Per corner, the weighted length w(e) |e| of the edge facing it (0 for a boundary edge).
std::vector<double> weightedLengths(const TriMesh& mesh) {
  const std::vector<Vec3> normal = unitFaceNormals(mesh);
  std::vector<double> w(3 * mesh.faceCount(), 0.0);
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int o = mesh.oppositeCorner[c];
    if (o < 0) continue;
    const double cosine = std::clamp(normal[c / 3].dot(normal[o / 3]), -1.0, 1.0);
    const double degrees = std::acos(cosine) * 180.0 / kPi;
    const double sharpness =
        std::clamp((degrees - kSmoothBelowDegrees) / (kFreeAboveDegrees - kSmoothBelowDegrees), 0.0, 1.0);
    const double length =
        (mesh.positions[mesh.vertex(TriMesh::next(c))] - mesh.positions[mesh.vertex(TriMesh::prev(c))]).norm();
    w[c] = (1.0 - sharpness) * length;
  }
  return w;
}

/// Maximum flow by shortest augmenting paths (Edmonds-Karp) on a small undirected graph; after
/// run(), onSourceSide(v) tells the minimum cut's side (what the residual graph reaches from the
/// source).
class MinCut {
 public:
  explicit MinCut(int nodes) : first_(nodes, -1), parentEdge_(nodes, -1) {}
  void connect(int a, int b, double capacity) {  // both ways: edges 2k and 2k + 1 are a pair
    if (!(capacity > 0.0)) return;
    add(a, b, capacity);
    add(b, a, capacity);
  }
  void run(int source, int sink) {
    while (augment(source, sink)) {}
    reach(source);
  }
  bool onSourceSide(int v) const { return reached_[v] != 0; }

 private:
  struct Edge {
    int to, next;
    double residual;
  };
  static constexpr double kEpsilon = 1e-15;
  void add(int a, int b, double capacity) {
    edges_.push_back({b, first_[a], capacity});
    first_[a] = static_cast<int>(edges_.size()) - 1;
  }
  /// Marks in reached_ what the residual graph reaches from `source` (parentEdge_: the BFS tree).
  void reach(int source) {
    reached_.assign(first_.size(), 0);
    queue_.assign(1, source);
    reached_[source] = 1;
    for (size_t i = 0; i < queue_.size(); ++i)
      for (int e = first_[queue_[i]]; e >= 0; e = edges_[e].next)
        if (edges_[e].residual > kEpsilon && !reached_[edges_[e].to]) {
          reached_[edges_[e].to] = 1;
          parentEdge_[edges_[e].to] = e;
          queue_.push_back(edges_[e].to);
        }
  }
  bool augment(int source, int sink) {
    reach(source);
    if (!reached_[sink]) return false;
    double flow = edges_[parentEdge_[sink]].residual;
    for (int v = sink; v != source; v = edges_[parentEdge_[v] ^ 1].to)
      flow = std::min(flow, edges_[parentEdge_[v]].residual);
    for (int v = sink; v != source; v = edges_[parentEdge_[v] ^ 1].to) {
      edges_[parentEdge_[v]].residual -= flow;
      edges_[parentEdge_[v] ^ 1].residual += flow;
    }
    return true;
  }
  std::vector<int> first_;
  std::vector<Edge> edges_;
  std::vector<int> parentEdge_;
  std::vector<char> reached_;
  std::vector<int> queue_;
};

/// Per pair of cells (a < b), the faces with a vertex in each, as (a, b, face) sorted.
std::vector<std::array<int, 3>> straddlingFaces(const TriMesh& mesh, const std::vector<int>& cell) {
  std::vector<std::array<int, 3>> out;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = cell[t[k]], b = cell[t[(k + 1) % 3]];
      if (a != b && a >= 0 && b >= 0) out.push_back({std::min(a, b), std::max(a, b), f});
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());  // a face of three cells: each pair once
  return out;
}

/// The faces labelled a or b with a vertex in cell a and one in cell b ([pairFirst, pairLast):
/// the pair's straddling faces), and their neighbours labelled a or b: where the boundary between a and b may move.
/// Marks them in `stamp`.
std::vector<int> bandOf(const TriMesh& mesh, const std::vector<int>& region, std::pair<int, int> ab,
                        const std::array<int, 3>* pairFirst, const std::array<int, 3>* pairLast,
                        std::vector<int>& stamp, int mark) {
  const auto [a, b] = ab;
  std::vector<int> band;
  for (const std::array<int, 3>* s = pairFirst; s != pairLast; ++s) {
    const int f = (*s)[2];
    if (stamp[f] == mark || (region[f] != a && region[f] != b)) continue;
    stamp[f] = mark;
    band.push_back(f);
  }
  const size_t across = band.size();
  for (size_t i = 0; i < across; ++i)
    for (int c = 3 * band[i]; c < 3 * band[i] + 3; ++c) {
      const int o = mesh.oppositeCorner[c];
      if (o < 0) continue;
      const int g = o / 3;
      if (stamp[g] != mark && (region[g] == a || region[g] == b)) {
        stamp[g] = mark;
        band.push_back(g);
      }
    }
  return band;
}

/// Relabels the band between regions a and b by the cut of least weighted length, the faces
/// around the band keeping theirs; the faces whose label changed.
int cutBand(const TriMesh& mesh, const std::vector<double>& weighted, std::vector<int>& region, std::pair<int, int> ab,
            const std::vector<int>& band, std::vector<int>& node, const std::vector<int>& stamp, int mark) {
  const auto [a, b] = ab;
  const int n = static_cast<int>(band.size()), source = n, sink = n + 1;
  for (int i = 0; i < n; ++i) node[band[i]] = i;
  MinCut cut(n + 2);
  // A face keeps its label unless moving it gains more than a millionth of an edge length: of
  // equal cuts, the one in place wins (a flat straight boundary stays where it is).
  double sum = 0.0;
  for (int f : band)
    for (int c = 3 * f; c < 3 * f + 3; ++c)
      sum += (mesh.positions[mesh.vertex(TriMesh::next(c))] - mesh.positions[mesh.vertex(TriMesh::prev(c))]).norm();
  const double keep = kKeepLabel * sum / (3.0 * n);
  for (int i = 0; i < n; ++i) {
    if (region[band[i]] == a)
      cut.connect(source, i, keep);
    else
      cut.connect(i, sink, keep);
  }
  for (int i = 0; i < n; ++i)
    for (int c = 3 * band[i]; c < 3 * band[i] + 3; ++c) {
      const int o = mesh.oppositeCorner[c];
      if (o < 0) continue;
      const int g = o / 3;
      if (stamp[g] == mark) {
        if (node[g] > i) cut.connect(i, node[g], weighted[c]);
      } else if (region[g] == a) {
        cut.connect(source, i, weighted[c]);
      } else if (region[g] == b) {
        cut.connect(i, sink, weighted[c]);
      }
    }
  cut.run(source, sink);
  int changed = 0;
  for (int i = 0; i < n; ++i) {
    const int label = cut.onSourceSide(i) ? a : b;
    changed += region[band[i]] != label;
    region[band[i]] = label;
  }
  return changed;
}

/// The pairs (a < b) of regions that share an edge.
std::vector<std::pair<int, int>> neighbouringRegions(const TriMesh& mesh, const std::vector<int>& faceRegion) {
  std::vector<std::pair<int, int>> pairs;
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int o = mesh.oppositeCorner[c];
    if (o < 0) continue;
    const int a = faceRegion[c / 3], b = faceRegion[o / 3];
    if (a < b) pairs.push_back({a, b});
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

int snapBoundariesToSharpEdges(const TriMesh& mesh, const std::vector<int>& cell, std::vector<int>& faceRegion,
                               int regions) {
  const std::vector<double> weighted = weightedLengths(mesh);
  std::vector<std::vector<int>> facesOfRegion(regions);
  for (int f = 0; f < mesh.faceCount(); ++f) facesOfRegion[faceRegion[f]].push_back(f);
  RegionTopologyCounter topology(mesh);
  std::vector<int> stamp(mesh.faceCount(), -1), node(mesh.faceCount(), -1), candidates, labels;
  const std::vector<std::array<int, 3>> straddling = straddlingFaces(mesh, cell);
  int moved = 0, mark = 0;
  for (const std::pair<int, int>& ab : neighbouringRegions(mesh, faceRegion)) {
    const std::array<int, 3> lo{ab.first, ab.second, -1}, hi{ab.first, ab.second, mesh.faceCount()};
    const auto first = std::lower_bound(straddling.begin(), straddling.end(), lo);
    const auto last = std::upper_bound(first, straddling.end(), hi);
    const std::vector<int> band = bandOf(mesh, faceRegion, ab, straddling.data() + (first - straddling.begin()),
                                         straddling.data() + (last - straddling.begin()), stamp, ++mark);
    labels.clear();
    for (int f : band) labels.push_back(faceRegion[f]);
    const int changed = cutBand(mesh, weighted, faceRegion, ab, band, node, stamp, mark);
    if (changed == 0) continue;
    std::vector<int>& a = facesOfRegion[ab.first];
    std::vector<int>& b = facesOfRegion[ab.second];
    candidates.assign(a.begin(), a.end());
    candidates.insert(candidates.end(), b.begin(), b.end());
    a.clear();
    b.clear();
    for (int f : candidates) (faceRegion[f] == ab.first ? a : b).push_back(f);
    if (topology.count(faceRegion, a, ab.first).isDisk() && topology.count(faceRegion, b, ab.second).isDisk()) {
      moved += changed;
      continue;
    }
    for (size_t i = 0; i < band.size(); ++i) faceRegion[band[i]] = labels[i];  // undone: a or b not a disk
    a.clear();
    b.clear();
    for (int f : candidates) (faceRegion[f] == ab.first ? a : b).push_back(f);
  }
  return moved;
}

}  // namespace gr
