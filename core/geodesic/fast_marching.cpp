#include "core/geodesic/fast_marching.h"

#include <algorithm>
#include <cmath>
#include <future>
#include <string>

#include "core/base/math.h"
#include "core/geodesic/detail/eikonal_update.h"
#include "core/geodesic/detail/unfold.h"

namespace gr {
namespace {

/// Rings of faces beyond the source's own faces initialised by unfolding (seedByUnfolding). A
/// point inside a face needs a few rings before the triangle updates become causal; a vertex
/// source needs only the ring across its star's outer edges (addSource(int) seeds it directly).
constexpr int kSeedDepthFace = 3;

}  // namespace

FastMarcher::FastMarcher(const TriMesh& mesh, const Metric& metric) : FastMarcher(mesh, nullptr, metric) {}

FastMarcher::FastMarcher(const TriMesh& mesh, const std::vector<double>& cornerLength, const Metric& metric)
    : FastMarcher(mesh, &cornerLength, metric) {}

FastMarcher::FastMarcher(const TriMesh& mesh, const std::vector<double>* cornerLength, const Metric& metric)
    : mesh_(mesh), length_(mesh, cornerLength), uniform_(metric.isUniform()) {
  const int nv = mesh.vertexCount();
  // The acute splits (a fifth of the construction) on a second thread, while this one orders
  // the vertices; they are first needed by the star records. The same result either way.
  // (std::async: an exception in it reaches get(), and the future waits for it if this throws;
  // with deferred allowed too, libstdc++ runs it in get() when no thread can be started.)
  std::future<AcuteSplits> splitter = std::async(std::launch::async | std::launch::deferred,
                                                 [&mesh, cornerLength] { return findAcuteSplits(mesh, cornerLength); });
  orderSlotsBreadthFirst();
  P_.assign(nv, 1.0);
  if (!metric.isUniform())
    for (int i = 0; i < nv; ++i) P_[i] = metric.P[vertexOf_[i]];
  const AcuteSplits splits = splitter.get();
  quality_ = splits.quality;
  buildStars(splits);
  if (!uniform_) buildStarCosts();
  buildSplitRecords(splits);
  node_.assign(nv, Node{kUnreached, 0, -1});
  U_.assign(nv, kUnreached);
  cell_.assign(nv, -1);
  touched_.reserve(nv);
  accepted_.reserve(nv);
  acceptedVertices_.reserve(nv);
  heap_.resize(nv);
}

void FastMarcher::orderSlotsBreadthFirst() {
  const TriMesh& mesh = mesh_;
  const int nv = mesh.vertexCount();
  const std::vector<std::array<int, 2>> others = starNeighbours(mesh);  // read contiguously below
  // Slots: the vertices in breadth-first order, so a front touches nearby memory.
  slotOf_.assign(nv, -1);
  vertexOf_.reserve(nv);
  for (int root = 0; root < nv; ++root) {
    if (slotOf_[root] >= 0) continue;
    slotOf_[root] = static_cast<int>(vertexOf_.size());
    vertexOf_.push_back(root);
    for (size_t next = vertexOf_.size() - 1; next < vertexOf_.size(); ++next) {
      const int v = vertexOf_[next];
      for (int k = mesh.vertexCornerBegin[v]; k < mesh.vertexCornerBegin[v + 1]; ++k)
        for (int w : others[k])
          if (slotOf_[w] < 0) {
            slotOf_[w] = static_cast<int>(vertexOf_.size());
            vertexOf_.push_back(w);
          }
    }
  }
}

void FastMarcher::buildStars(const AcuteSplits& splits) {
  const TriMesh& mesh = mesh_;
  const int nv = mesh.vertexCount();
  // The star of each slot, contiguous, filled one face at a time: the face's three edge lengths
  // are computed once and written into the records of its three corners. A vertex's records
  // come in increasing face order, the order of its corners in the mesh.
  starBegin_.assign(nv + 1, 0);
  for (int i = 0; i < nv; ++i) starBegin_[i + 1] = starBegin_[i] + mesh.valence(vertexOf_[i]);
  star_.resize(mesh.vertexCorners.size());
  std::vector<int> fill(starBegin_.begin(), starBegin_.end() - 1);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    const double length[3] = {length_(3 * f), length_(3 * f + 1), length_(3 * f + 2)};  // facing each corner
    const int slot[3] = {slotOf_[t[0]], slotOf_[t[1]], slotOf_[t[2]]};
    const int* const splitOf = splits.splitOfCorner.data() + 3 * f;
    for (int k = 0; k < 3; ++k) {
      const int kn = (k + 1) % 3, kp = (k + 2) % 3;
      StarFace& r = star_[fill[slot[k]]++];
      r.a = slot[kn];
      r.b = slot[kp];
      r.lva = length[kp];
      r.lvb = length[kn];
      r.lab = length[k];
      r.split = splitOf[kn] >= 0 ? 2 * splitOf[kn] : splitOf[kp] >= 0 ? 2 * splitOf[kp] + 1 : -1;
    }
  }
}

void FastMarcher::buildStarCosts() {
  const int nv = mesh_.vertexCount();
  starCost_.resize(star_.size());
  for (int i = 0; i < nv; ++i)
    for (int k = starBegin_[i]; k < starBegin_[i + 1]; ++k) {
      const StarFace& f = star_[k];
      starCost_[k] = {0.5 * (P_[i] + P_[f.a]) * f.lva, 0.5 * (P_[i] + P_[f.b]) * f.lvb,
                      (P_[i] + P_[f.a] + P_[f.b]) * (1.0 / 3.0)};
    }
}

void FastMarcher::buildSplitRecords(const AcuteSplits& splits) {
  const TriMesh& mesh = mesh_;
  const int nv = mesh.vertexCount();
  nearSplits_.resize(splits.splits.size());
  for (size_t i = 0; i < splits.splits.size(); ++i) {
    const AcuteSplit& sp = splits.splits[i];
    nearSplits_[i] = {slotOf_[sp.vertex], sp.lenXR, sp.lenAR, sp.lenBR};
  }
  farSplitBegin_.assign(nv + 1, 0);
  farSplits_.reserve(splits.splits.size());
  for (int i = 0; i < nv; ++i) {
    const int vertex = vertexOf_[i];
    for (int k = splits.byVertexBegin[vertex]; k < splits.byVertexBegin[vertex + 1]; ++k) {
      const AcuteSplit& sp = splits.splits[splits.byVertex[k]];
      farSplits_.push_back({slotOf_[mesh.vertex(sp.corner)], slotOf_[mesh.vertex(TriMesh::next(sp.corner))],
                            slotOf_[mesh.vertex(TriMesh::prev(sp.corner))], sp.lenXA, sp.lenXB, sp.lenXR, sp.lenAR,
                            sp.lenBR});
    }
    farSplitBegin_[i + 1] = static_cast<int>(farSplits_.size());
  }
}

void FastMarcher::reset() {
  for (int slot : touched_) {
    node_[slot] = Node{kUnreached, 0, -1};
    U_[vertexOf_[slot]] = kUnreached;
    cell_[vertexOf_[slot]] = -1;
  }
  touched_.clear();
  accepted_.clear();
  acceptedVertices_.clear();
  saved_.clear();
  heap_.clear();
  sourceSlotOfCell_.clear();
  runOpen_ = false;
}

Status FastMarcher::startFromBound(const std::vector<double>& bound, const std::vector<int>& cell) {
  const int nv = mesh_.vertexCount();
  if (static_cast<int>(bound.size()) != nv || static_cast<int>(cell.size()) != nv)
    return invalidInput("fast marching: a bound needs one value and one cell per vertex");
  for (int v = 0; v < nv; ++v)
    if (!(bound[v] >= 0.0))
      return invalidInput("fast marching: a bound is negative or NaN at vertex " + std::to_string(v));
  reset();
  ++run_;  // the bound's values are those of a run that accepted them
  for (int slot = 0; slot < nv; ++slot) {
    const int v = vertexOf_[slot];
    const double u = bound[v];
    if (u == kUnreached) continue;
    node_[slot] = Node{u, run_, cell[v]};
    touched_.push_back(slot);
    U_[v] = u;
    cell_[v] = cell[v];
  }
  return Status::ok();
}

void FastMarcher::beginRun() {
  if (runOpen_) return;
  runOpen_ = true;
  ++run_;
  accepted_.clear();
  acceptedVertices_.clear();
  saved_.clear();
}

void FastMarcher::seedAcrossStar(int sv, int cell) {
  // The faces around sv, sv at the origin, read from its star records: their vertices get the
  // edge lengths; the vertex across each outer edge gets the straight line from sv in the
  // unfolding when that line crosses the edge (what seedByUnfolding does one ring deep, without
  // revisiting each face from its neighbours). The face across edge ab is found in a's star,
  // which the breadth-first slots keep near sv's: no read of the mesh's own arrays.
  const double u0 = node_[sv].u, pv = P_[sv];
  const StarFace* const first = star_.data() + starBegin_[sv];
  const StarFace* const last = star_.data() + starBegin_[sv + 1];
  for (const StarFace* f = first; f != last; ++f) {
    relax(f->a, u0 + 0.5 * (pv + P_[f->a]) * f->lva, cell);
    relax(f->b, u0 + 0.5 * (pv + P_[f->b]) * f->lvb, cell);
    if (!(f->lva > 0.0)) continue;
    int r = -1;
    double lar = 0.0, lbr = 0.0;
    for (const StarFace *g = star_.data() + starBegin_[f->a], *end = star_.data() + starBegin_[f->a + 1]; g != end;
         ++g) {
      if (g->b == f->b && g->a != sv) {  // face (a, R, b): the orientation of sv's face
        r = g->a, lar = g->lva, lbr = g->lab;
        break;
      }
      if (g->a == f->b && g->b != sv) {  // face (a, b, R): a mesh without a consistent orientation
        r = g->b, lar = g->lvb, lbr = g->lab;
        break;
      }
    }
    if (r < 0) continue;  // ab is a boundary edge
    const Vec2 a(f->lva, 0.0), b = layoutThirdVertex(f->lva, f->lvb, f->lab);
    if ((b - a).squaredNorm() <= 0.0) continue;
    const Vec2 q = unfold(a, b, Vec2(0.0, 0.0), lar, lbr);
    if (segmentsIntersect(Vec2(0.0, 0.0), q, a, b)) relax(r, u0 + 0.5 * (pv + P_[r]) * q.norm(), cell);
  }
}

void FastMarcher::setSaddleSeeding(bool on, bool boundaryOnly) {
  saddle_.clear();
  if (!on) return;
  const int nv = mesh_.vertexCount();
  const std::vector<char> onBoundary = boundaryVertexFlags(mesh_);
  saddle_.assign(nv, 0);
  for (int i = 0; i < nv; ++i) {
    if (boundaryOnly) {
      saddle_[i] = onBoundary[vertexOf_[i]];
      continue;
    }
    double angleSum = 0.0;
    for (int k = starBegin_[i]; k < starBegin_[i + 1]; ++k) {
      const StarFace& f = star_[k];
      if (f.lva > 0.0 && f.lvb > 0.0)
        angleSum +=
            std::acos(std::clamp((f.lva * f.lva + f.lvb * f.lvb - f.lab * f.lab) / (2.0 * f.lva * f.lvb), -1.0, 1.0));
    }
    saddle_[i] = onBoundary[vertexOf_[i]] || angleSum > 2.0 * kPi * (1.0 + 1e-6);
  }
}

void FastMarcher::setPathEdges(const std::vector<std::array<int, 2>>& edges, const std::vector<double>& lengths) {
  pathBegin_.clear();
  pathEdges_.clear();
  if (edges.empty()) return;
  const int nv = mesh_.vertexCount();
  pathBegin_.assign(nv + 1, 0);
  for (const auto& e : edges) {
    ++pathBegin_[slotOf_[e[0]] + 1];
    ++pathBegin_[slotOf_[e[1]] + 1];
  }
  for (int i = 0; i < nv; ++i) pathBegin_[i + 1] += pathBegin_[i];
  pathEdges_.resize(pathBegin_[nv]);
  std::vector<int> fill(pathBegin_.begin(), pathBegin_.end() - 1);
  for (size_t k = 0; k < edges.size(); ++k) {
    const int a = slotOf_[edges[k][0]], b = slotOf_[edges[k][1]];
    pathEdges_[fill[a]++] = {b, lengths[k]};
    pathEdges_[fill[b]++] = {a, lengths[k]};
  }
}

void FastMarcher::setChordBound(bool on) {
  chordPosition_.clear();
  if (!on || !uniform_) return;
  chordPosition_.resize(mesh_.vertexCount());
  for (int i = 0; i < mesh_.vertexCount(); ++i) chordPosition_[i] = mesh_.positions[vertexOf_[i]];
}

void FastMarcher::noteSourceOfCell(int cell, int slot) {
  if (cell < 0) return;
  if (cell >= static_cast<int>(sourceSlotOfCell_.size())) sourceSlotOfCell_.resize(cell + 1, -2);
  int& s = sourceSlotOfCell_[cell];
  s = s == -2 || s == slot ? slot : -1;
}

Status FastMarcher::addSource(int v, int cell) {
  if (v < 0 || v >= mesh_.vertexCount())
    return invalidInput("source vertex " + std::to_string(v) + " does not exist (the mesh has " +
                        std::to_string(mesh_.vertexCount()) + " vertices)");
  beginRun();
  if (node_[slotOf_[v]].u <= 0.0) return Status::ok();
  const int sv = slotOf_[v];
  noteSourceOfCell(cell, sv);
  push(sv, 0.0, cell);
  seedAcrossStar(sv, cell);
  return Status::ok();
}

void FastMarcher::seedByUnfolding(const Vec2& p, double pAtSource, int face, const std::array<Vec2, 3>& layout,
                                  int enteredThrough, int depth, int cell) {
  // A straight segment from p that crosses every edge of the chain is a path on the surface.
  for (int k = 0; k < 3; ++k) {
    bool inside = true;
    for (size_t e = 0; e < seedChain_.size() && inside; ++e)
      inside = segmentsIntersect(p, layout[k], seedChain_[e].first, seedChain_[e].second);
    if (inside) {
      const int w = slotOf_[mesh_.triangles[face][k]];
      relax(w, 0.5 * (pAtSource + P_[w]) * (layout[k] - p).norm(), cell);
    }
  }
  if (depth == 0) return;
  for (int k = 0; k < 3; ++k) {
    const int c = 3 * face + k;
    if (c == enteredThrough) continue;
    const int o = mesh_.oppositeCorner[c];
    if (o < 0) continue;
    const int cn = TriMesh::next(c), cp = TriMesh::prev(c);
    const Vec2 &q1 = layout[cn % 3], &q2 = layout[cp % 3];
    if ((q2 - q1).squaredNorm() <= 0.0) continue;
    // In the next face, the vertices of the shared edge keep their positions.
    const int g = TriMesh::face(o);
    std::array<Vec2, 3> next;
    // In g, the edge (R, V(cn)) faces the corner at V(cp), and (R, V(cp)) the corner at V(cn).
    double lenToCn = 0.0, lenToCp = 0.0;
    for (int j = 0; j < 3; ++j) {
      const int corner = 3 * g + j;
      if (corner == o) continue;
      const bool atCn = mesh_.vertex(corner) == mesh_.vertex(cn);
      next[j] = atCn ? q1 : q2;
      (atCn ? lenToCp : lenToCn) = length_(corner);
    }
    next[o % 3] = unfold(q1, q2, layout[k], lenToCn, lenToCp);
    seedChain_.push_back({q1, q2});
    seedByUnfolding(p, pAtSource, g, next, o, depth - 1, cell);
    seedChain_.pop_back();
  }
}

Status FastMarcher::addSource(const SurfacePoint& point, int cell) {
  if (point.vertex >= 0) return addSource(point.vertex, cell);
  if (point.face < 0 || point.face >= mesh_.faceCount())
    return invalidInput("source face " + std::to_string(point.face) + " does not exist");
  const Vec3& b = point.bary;
  if (!b.allFinite() || b.minCoeff() < -1e-9 || std::abs(b.sum() - 1.0) > 1e-6)
    return invalidInput("barycentric coordinates of a source must be >= 0 and sum to 1");
  beginRun();
  noteSourceOfCell(cell, -1);
  const int f = point.face;
  const Tri& t = mesh_.triangles[f];
  const double pAtPoint = b[0] * P_[slotOf_[t[0]]] + b[1] * P_[slotOf_[t[1]]] + b[2] * P_[slotOf_[t[2]]];
  // The face in its plane: t[0] at the origin, t[1] on the x axis.
  const double l01 = length_(3 * f + 2), l02 = length_(3 * f + 1), l12 = length_(3 * f);
  const std::array<Vec2, 3> layout = {Vec2(0.0, 0.0), Vec2(l01, 0.0), layoutThirdVertex(l01, l02, l12)};
  const Vec2 p = b[0] * layout[0] + b[1] * layout[1] + b[2] * layout[2];
  seedByUnfolding(p, pAtPoint, f, layout, -1, kSeedDepthFace, cell);
  return Status::ok();
}

// push and offerTriangle are forced inline into the hot loop: GCC keeps them out of line at -O2,
// which costs a call per neighbour update.
[[gnu::always_inline]] inline void FastMarcher::push(int v, double u, int cell) {
  Node& n = node_[v];
  if (n.u == kUnreached) {
    touched_.push_back(v);
  } else if (n.run != 0) {  // a value of an earlier run, improved: keep it to restore
    saved_.push_back({v, n.cell, n.run, n.u});
    n.run = 0;
  }
  n.u = u;
  n.cell = cell;
  heap_.pushOrDecrease(v, u);
}

void FastMarcher::relax(int x, double u, int cell) {
  if (u < node_[x].u) push(x, u, cell);
}

template <bool kUniform>
[[gnu::always_inline]] inline void FastMarcher::offerTriangle(Candidate& best, int /*x*/, int s, int t, double lxs,
                                                              double lxt, double lst, [[maybe_unused]] double p) const {
  const double us = node_[s].u, ut = node_[t].u;
  if (std::max(us, ut) >= best.u) return;  // causal values are >= both: it cannot win
  const TriangleFrame frame = triangleFrame(lxs, lxt, lst);
  double u;
  if constexpr (kUniform) {
    u = virtualSourceDistance(frame, us, ut);
  } else {
    const double q = 1.0 / p;  // distances in the triangle scale with its mean P
    u = p * virtualSourceDistance(frame, us * q, ut * q);
  }
  // Causality: a value below a neighbour's would break the acceptance order (obtuse angles).
  // The cell of the nearer vertex. Updates that mix two fronts are kept on purpose: skipping
  // them would make a multi-source field depend on the order the sources were added.
  if (u < best.u && u >= std::max(us, ut)) best = {u, us <= ut ? node_[s].cell : node_[t].cell};
}

template <bool kUniform>
void FastMarcher::scatter(int v) {
  // Local copies of the array pointers: push() writes through node_, and the compiler would
  // otherwise reload them from `this` after every store.
  Node* const node = node_.data();
  const StarFace* const star = star_.data();
  const StarCost* const cost = kUniform ? nullptr : starCost_.data();
  const double uv = node[v].u;
  const int cellOfV = node[v].cell;
  // The mean P of a virtual triangle (acute splits): read from P_ (rare).
  const auto meanP = [this](int x, int s, int t) { return kUniform ? 1.0 : (P_[x] + P_[s] + P_[t]) * (1.0 / 3.0); };
  // Triangles (v, a, b) around v: each offers a and b one candidate, the best of the edge
  // update, the triangle update and the virtual triangle of an acute split. A candidate starts
  // at the neighbour's current value when the edge update does not beat it: only improvements
  // matter, and the triangle solves then return early more often.
  const int first = starBegin_[v], last = starBegin_[v + 1];
  for (int k = first; k < last; ++k) {
    const StarFace f = star[k];
    if (node[f.a].run != run_) {  // target a, third vertex b
      const double ua = node[f.a].u;
      Candidate best{uv + (kUniform ? f.lva : cost[k].edgeA), cellOfV};
      if (!(best.u < ua)) best.u = ua;
      if (known(f.b)) offerTriangle<kUniform>(best, f.a, v, f.b, f.lva, f.lab, f.lvb, kUniform ? 1.0 : cost[k].face);
      if (f.split >= 0 && (f.split & 1) == 0) {  // obtuse at a: the virtual triangle a, v, R (v is B of that corner)
        const NearSplit& sp = nearSplits_[f.split >> 1];
        if (known(sp.r)) offerTriangle<kUniform>(best, f.a, v, sp.r, f.lva, sp.lenXR, sp.lenBR, meanP(f.a, v, sp.r));
      }
      if (best.u < ua) push(f.a, best.u, best.cell);
    }
    if (node[f.b].run != run_) {  // target b, third vertex a
      const double ub = node[f.b].u;
      Candidate best{uv + (kUniform ? f.lvb : cost[k].edgeB), cellOfV};
      if (!(best.u < ub)) best.u = ub;
      if (known(f.a)) offerTriangle<kUniform>(best, f.b, v, f.a, f.lvb, f.lab, f.lva, kUniform ? 1.0 : cost[k].face);
      if (f.split >= 0 && (f.split & 1) == 1) {  // obtuse at b: v is A of that corner
        const NearSplit& sp = nearSplits_[f.split >> 1];
        if (known(sp.r)) offerTriangle<kUniform>(best, f.b, v, sp.r, f.lvb, sp.lenXR, sp.lenAR, meanP(f.b, v, sp.r));
      }
      if (best.u < ub) push(f.b, best.u, best.cell);
    }
  }
  // v as the far vertex R of acute splits: the virtual triangles X, A, R and X, B, R.
  for (int i = farSplitBegin_[v]; i < farSplitBegin_[v + 1]; ++i) {
    const FarSplit& sp = farSplits_[i];
    const int x = sp.x, a = sp.a, b = sp.b;
    if (node[x].run == run_) continue;
    Candidate best{node[x].u, node[x].cell};
    if (known(a)) offerTriangle<kUniform>(best, x, a, v, sp.lenXA, sp.lenXR, sp.lenAR, meanP(x, a, v));
    if (known(b)) offerTriangle<kUniform>(best, x, b, v, sp.lenXB, sp.lenXR, sp.lenBR, meanP(x, b, v));
    if (best.u < node[x].u) push(x, best.u, best.cell);
  }
}

Status FastMarcher::propagate(const FastMarchingParams& params, Progress progress) {
  const int nv = mesh_.vertexCount();
  if (params.region && static_cast<int>(params.region->size()) != nv)
    return invalidInput("fast marching: the region has " + std::to_string(params.region->size()) + " labels for " +
                        std::to_string(nv) + " vertices");
  beginRun();
  const bool withTargets = !params.targets.empty();
  std::vector<int> targets;
  if (withTargets) {
    targets = params.targets;
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
  }
  size_t targetsReached = 0;
  int sinceReport = 0;
  while (!heap_.empty()) {
    if (heap_.top().key > params.maxDistance) break;  // left in the heap: endRun() clears it
    const int v = heap_.pop();
    if (!chordPosition_.empty() && belowChord(v)) {  // back into the heap at the bound
      const double bound = (chordPosition_[v] - chordPosition_[sourceSlotOfCell_[node_[v].cell]]).norm();
      node_[v].u = bound;
      heap_.pushOrDecrease(v, bound);
      continue;
    }
    if (!heap_.empty()) {
      // The star of the vertex now on top, most often the next one scattered: its records
      // (four cache lines at valence 6) load while v is scattered.
      const char* next = reinterpret_cast<const char*>(star_.data() + starBegin_[heap_.top().v]);
      for (int line = 0; line < 4; ++line) __builtin_prefetch(next + 64 * line);
    }
    node_[v].run = run_;
    accepted_.push_back(v);
    if (++sinceReport == 4096) {
      sinceReport = 0;
      if (!progress.report(double(accepted_.size()) / nv, "Fast marching")) {
        endRun();
        return cancelled();
      }
    }
    if (params.region && (*params.region)[vertexOf_[v]] != params.regionLabel) continue;  // a margin vertex
    if (!saddle_.empty() && saddle_[v]) seedAcrossStar(v, node_[v].cell);
    if (!pathBegin_.empty())
      for (int k = pathBegin_[v]; k < pathBegin_[v + 1]; ++k) {
        const PathEdge& e = pathEdges_[k];
        relax(e.to, node_[v].u + 0.5 * (P_[v] + P_[e.to]) * e.length, node_[v].cell);
      }
    if (uniform_) {
      scatter<true>(v);
    } else {
      scatter<false>(v);
    }
    if (withTargets && std::binary_search(targets.begin(), targets.end(), vertexOf_[v]) &&
        ++targetsReached == targets.size())
      break;
  }
  endRun();
  return Status::ok();
}

void FastMarcher::endRun() {
  // Values still tentative are not distances: restore what earlier runs had, clear the rest.
  for (const Saved& s : saved_)
    if (node_[s.v].run != run_) node_[s.v] = Node{s.u, s.run, s.cell};
  for (const IndexedHeap::Entry& e : heap_.entries())
    if (node_[e.v].run == 0) node_[e.v] = Node{kUnreached, 0, -1};
  // The public arrays: only vertices this run changed.
  const auto publish = [this](int slot) {
    U_[vertexOf_[slot]] = node_[slot].u;
    cell_[vertexOf_[slot]] = node_[slot].cell;
  };
  acceptedVertices_.clear();
  for (int slot : accepted_) {
    publish(slot);
    acceptedVertices_.push_back(vertexOf_[slot]);
  }
  for (const Saved& s : saved_) publish(s.v);
  for (const IndexedHeap::Entry& e : heap_.entries()) publish(e.v);
  heap_.clear();
  saved_.clear();
  runOpen_ = false;
}

Status checkSourcesAndLimit(const TriMesh& mesh, const std::vector<int>& sources, double maxDistance) {
  if (sources.empty()) return invalidInput("no source vertices were given");
  for (int s : sources)
    if (s < 0 || s >= mesh.vertexCount())
      return invalidInput("source vertex " + std::to_string(s) + " does not exist (the mesh has " +
                          std::to_string(mesh.vertexCount()) + " vertices)");
  if (std::isnan(maxDistance) || maxDistance < 0.0)
    return invalidInput("the distance limit must be >= 0, got " + std::to_string(maxDistance));
  return Status::ok();
}

Expected<FastMarchingResult> fastMarching(const TriMesh& mesh, const Metric& metric, const std::vector<int>& sources,
                                          const FastMarchingParams& params, Progress progress) {
  if (sources.empty()) return invalidInput("no source vertices were given");
  if (!metric.isUniform() && static_cast<int>(metric.P.size()) != mesh.vertexCount())
    return invalidInput("the metric has " + std::to_string(metric.P.size()) + " values for " +
                        std::to_string(mesh.vertexCount()) + " vertices");
  if (std::isnan(params.maxDistance) || params.maxDistance < 0.0)
    return invalidInput("the distance limit must be >= 0, got " + std::to_string(params.maxDistance));
  for (int t : params.targets)
    if (t < 0 || t >= mesh.vertexCount()) return invalidInput("target vertex " + std::to_string(t) + " does not exist");
  FastMarcher marcher(mesh, metric);
  for (size_t i = 0; i < sources.size(); ++i)
    if (Status s = marcher.addSource(sources[i], static_cast<int>(i)); !s) return s;
  if (Status s = marcher.propagate(params, std::move(progress)); !s) return s;
  FastMarchingResult r;
  r.distance = marcher.distance();
  r.cell = marcher.cell();
  r.acceptedOrder = marcher.acceptedOrder();
  for (int v : r.acceptedOrder) r.maxDistance = std::max(r.maxDistance, r.distance[v]);
  return r;
}

Expected<FastMarchingResult> fastMarchingWithSpeed(const TriMesh& mesh, const std::vector<double>& speed,
                                                   const std::vector<int>& sources, const FastMarchingParams& params,
                                                   Progress progress) {
  if (speed.empty()) return fastMarching(mesh, Metric::uniform(), sources, params, std::move(progress));
  Expected<Metric> metric = Metric::fromSpeed(mesh, speed);
  if (!metric) return metric.status();
  return fastMarching(mesh, *metric, sources, params, std::move(progress));
}

}  // namespace gr
