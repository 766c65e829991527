#include "core/fast_marching.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace gr {
namespace {

/// Min-heap order for std::push_heap / std::pop_heap.
struct Later {
  template <class E>
  bool operator()(const E& x, const E& y) const {
    return x.u > y.u;
  }
};

/// Distance at X from the front known at A and B (see the sketch in the header).
/// la = |XA|, lb = |XB|, lc = |AB|; da, db = U(A)/P, U(B)/P. Returns the unweighted length |SX|,
/// or +inf when the triangle cannot give an upwind update.
double virtualSourceDistance(double la, double lb, double lc, double da, double db) {
  if (lc <= 0.0) return kUnreached;
  const double inv2c = 0.5 / lc;
  // Frame: A = (0, 0), B = (lc, 0), X = (xx, xy) with xy > 0, S = (sx, sy) with sy <= 0.
  const double xx = (la * la + lc * lc - lb * lb) * inv2c;
  const double xy2 = la * la - xx * xx;
  if (!(xy2 > 0.0)) return kUnreached;  // degenerate triangle: edges only
  const double sx = (da * da - db * db + lc * lc) * inv2c;
  const double sy2 = da * da - sx * sx;
  if (sy2 < 0.0) return kUnreached;  // |da - db| > lc: no point at those distances
  const double xy = std::sqrt(xy2), sy = -std::sqrt(sy2);
  // Upwind: the segment S -> X crosses the line y = 0 inside [0, lc].
  const double t = sx + (xx - sx) * (-sy) / (xy - sy);
  if (t < 0.0 || t > lc) return kUnreached;
  return std::hypot(xx - sx, xy - sy);
}

}  // namespace

FastMarcher::FastMarcher(const TriMesh& mesh, const Metric& metric)
    : mesh_(mesh), splits_(findAcuteSplits(mesh)) {
  const int nv = mesh.vertexCount();
  P_ = metric.isUniform() ? std::vector<double>(nv, 1.0) : metric.P;
  edgeLength_.resize(3 * static_cast<size_t>(mesh.faceCount()));
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    edgeLength_[c] = (mesh.positions[mesh.vertex(TriMesh::next(c))] -
                      mesh.positions[mesh.vertex(TriMesh::prev(c))]).norm();
  U_.assign(nv, kUnreached);
  label_.assign(nv, -1);
  frozen_.assign(nv, 0);
  touched_.reserve(nv);
  accepted_.reserve(nv);
  heap_.reserve(nv);
}

void FastMarcher::reset() {
  for (int v : touched_) {
    U_[v] = kUnreached;
    label_[v] = -1;
    frozen_[v] = 0;
  }
  touched_.clear();
  accepted_.clear();
  heap_.clear();
}

Status FastMarcher::addSource(int v, int label) {
  if (v < 0 || v >= mesh_.vertexCount())
    return invalidInput("source vertex " + std::to_string(v) + " does not exist (the mesh has " +
                        std::to_string(mesh_.vertexCount()) + " vertices)");
  if (U_[v] == 0.0) return Status::ok();
  push(v, 0.0, label);
  return Status::ok();
}

void FastMarcher::push(int v, double u, int label) {
  if (U_[v] == kUnreached) touched_.push_back(v);
  U_[v] = u;
  label_[v] = label;
  heap_.push_back({u, v});
  std::push_heap(heap_.begin(), heap_.end(), Later{});
}

void FastMarcher::relax(int x, double u, int label) {
  if (u < U_[x]) push(x, u, label);
}

void FastMarcher::relax(int x, int s, int t, double lxs, double lxt, double lst) {
  const double p = (P_[x] + P_[s] + P_[t]) * (1.0 / 3.0);
  const double us = U_[s], ut = U_[t];
  const double u = p * virtualSourceDistance(lxs, lxt, lst, us / p, ut / p);
  // Causality: a value below a neighbour's would break the acceptance order (obtuse angles).
  if (u < U_[x] && u >= std::max(us, ut)) push(x, u, us <= ut ? label_[s] : label_[t]);
}

Status FastMarcher::propagate(const FastMarchingParams& params, Progress progress) {
  const int nv = mesh_.vertexCount();
  int sinceReport = 0;
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const HeapEntry top = heap_.back();
    heap_.pop_back();
    const int v = top.v;
    if (frozen_[v] || top.u != U_[v]) continue;  // stale entry
    if (top.u > params.maxDistance) {
      heap_.clear();
      break;
    }
    frozen_[v] = 1;
    accepted_.push_back(v);
    if (++sinceReport == 4096) {
      sinceReport = 0;
      if (!progress.report(double(accepted_.size()) / nv, "Fast marching")) return cancelled();
    }

    const double uv = U_[v];
    const int lv = label_[v];
    // Triangles around v: each updates its two other vertices.
    for (const int* it = mesh_.cornersBegin(v); it != mesh_.cornersEnd(v); ++it) {
      const int c = *it;
      const int cn = TriMesh::next(c), cp = TriMesh::prev(c);
      const int a = mesh_.vertex(cn), b = mesh_.vertex(cp);
      // |v a| is the edge opposite cp, |v b| opposite cn, |a b| opposite c.
      const double lva = edgeLength_[cp], lvb = edgeLength_[cn], lab = edgeLength_[c];
      for (int k = 0; k < 2; ++k) {
        const int x = k == 0 ? a : b, y = k == 0 ? b : a;
        if (frozen_[x]) continue;
        const int cx = k == 0 ? cn : cp;           // corner at x in this face
        const double lxv = k == 0 ? lva : lvb, lvy = k == 0 ? lvb : lva;
        relax(x, uv + 0.5 * (P_[v] + P_[x]) * lxv, lv);
        if (frozen_[y]) relax(x, v, y, lxv, lab, lvy);
        const int split = splits_.splitOfCorner[cx];
        if (split >= 0) {  // obtuse at x: the virtual triangle x, v, R
          const AcuteSplit& sp = splits_.splits[split];
          if (frozen_[sp.vertex])
            relax(x, v, sp.vertex, lxv, sp.lenXR, mesh_.vertex(TriMesh::next(cx)) == v ? sp.lenAR : sp.lenBR);
        }
      }
    }
    // v as the far vertex R of acute splits: the virtual triangles X, A, R and X, B, R.
    for (int i = splits_.byVertexBegin[v]; i < splits_.byVertexBegin[v + 1]; ++i) {
      const AcuteSplit& sp = splits_.splits[splits_.byVertex[i]];
      const int x = mesh_.vertex(sp.corner);
      if (frozen_[x]) continue;
      const int a = mesh_.vertex(TriMesh::next(sp.corner)), b = mesh_.vertex(TriMesh::prev(sp.corner));
      if (frozen_[a]) relax(x, a, v, edgeLength_[TriMesh::prev(sp.corner)], sp.lenXR, sp.lenAR);
      if (frozen_[b]) relax(x, b, v, edgeLength_[TriMesh::next(sp.corner)], sp.lenXR, sp.lenBR);
    }
  }
  // Tentative values beyond the limit are not distances: clear them.
  for (int v : touched_)
    if (!frozen_[v]) {
      U_[v] = kUnreached;
      label_[v] = -1;
    }
  heap_.clear();
  return Status::ok();
}

Expected<FastMarchingResult> fastMarching(const TriMesh& mesh, const Metric& metric,
                                          const std::vector<int>& sources,
                                          const FastMarchingParams& params, Progress progress) {
  if (sources.empty()) return invalidInput("no source vertices were given");
  if (!metric.isUniform() && static_cast<int>(metric.P.size()) != mesh.vertexCount())
    return invalidInput("the metric has " + std::to_string(metric.P.size()) + " values for " +
                        std::to_string(mesh.vertexCount()) + " vertices");
  if (std::isnan(params.maxDistance) || params.maxDistance < 0.0)
    return invalidInput("the distance limit must be >= 0, got " + std::to_string(params.maxDistance));
  FastMarcher marcher(mesh, metric);
  for (size_t i = 0; i < sources.size(); ++i)
    if (Status s = marcher.addSource(sources[i], static_cast<int>(i)); !s) return s;
  if (Status s = marcher.propagate(params, std::move(progress)); !s) return s;
  FastMarchingResult r;
  r.distance = marcher.distance();
  r.nearestSource = marcher.label();
  r.acceptedOrder = marcher.acceptedOrder();
  for (int v : r.acceptedOrder) r.maxDistance = std::max(r.maxDistance, r.distance[v]);
  return r;
}

}  // namespace gr
