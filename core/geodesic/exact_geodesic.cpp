#include "core/geodesic/exact_geodesic.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <queue>
#include <string>
#include <utility>

namespace gr {
namespace {

constexpr double kTwoPi = 6.283185307179586;
/// A vertex whose angle sum exceeds 2 pi by more than this (radians) is a saddle, where shortest
/// paths may bend; flat vertices (2 pi up to rounding) are not: the windows on either side of
/// one meet on the line through it.
constexpr double kSaddleExcess = 1e-9;
/// A window is dropped only when it is worse than a path through an end of its edge by more than
/// this share of its distance (rounding must not drop the best one).
constexpr double kDropTolerance = 1e-12;
/// A window sees a vertex when the vertex's projection on the window's edge is within this share
/// of the edge's length of the window's interval; shorter windows are not kept.
constexpr double kSeeTolerance = 1e-10;
/// The default budget's ceiling: about 7 s of work and, at worst, a few GB of live windows.
constexpr long long kMaxDefaultWindows = 30000000;

struct Point2 {
  double x = 0.0, y = 0.0;
};

/// |(x, y)|: std::hypot guards against overflow at several times the cost, and these lengths are
/// of the mesh's scale.
double norm2d(double x, double y) { return std::sqrt(x * x + y * y); }

/// An interval of an edge reached by straight lines from one image of a (pseudo-)source.
struct Window {
  int corner = -1;            ///< the edge facing this corner; the window crosses into the face beyond it
  int cell = -1;              ///< the source
  double t0 = 0.0, t1 = 0.0;  ///< interval along the edge, from vertex(next(corner)) to vertex(prev(corner))
  Point2 image;               ///< the (pseudo-)source in the edge's frame: y <= 0, on the corner's side
  double sigma = 0.0;         ///< the (pseudo-)source's own distance
};

/// A window in the queue: its smallest distance and its place in the pool (the heap moves 16
/// bytes per step instead of the whole window).
struct WindowEvent {
  double key;
  int slot;
  bool operator<(const WindowEvent& o) const { return key > o.key; }  // min-heap
};

struct VertexEvent {
  double key;
  int vertex;
  bool operator<(const VertexEvent& o) const { return key > o.key; }
};

/// The face a window crosses, in the window's edge frame: u0 at the origin, u1 on +x, c above.
struct CrossedFace {
  int u0, u1, c;
  Point2 p0, p1, pc;
  Point2 at(int v) const { return v == u0 ? p0 : (v == u1 ? p1 : pc); }
};

/// Position of the third corner of a triangle with base from (0,0) to (L,0), sides a (from the
/// origin) and b (from (L,0)), on the side of `sign` (+1 above, -1 below).
Point2 apex(double L, double a, double b, double sign) {
  const double x = (L * L + a * a - b * b) / (2.0 * L);
  return {x, sign * std::sqrt(std::max(0.0, a * a - x * x))};
}

class WindowPropagation {
 public:
  WindowPropagation(const TriMesh& mesh, const ExactGeodesicParams& params);
  Status run(const std::vector<int>& sources, Progress& progress);
  ExactGeodesicResult result();

 private:
  void offer(int v, double value, int cell);
  void settle(int v);
  void emitFrom(int v);
  void cross(const Window& w);
  void addChild(const Window& w, const CrossedFace& face, int childCorner, Point2 from, double x0, double x1);
  void push(const Window& w);
  bool dominated(const Window& w) const;

  const TriMesh& mesh_;
  ExactGeodesicParams params_;
  long long budget_ = 0;
  std::vector<double> len_;  ///< per corner, the length of the edge facing it
  /// Per corner c: the far vertex of the face across c's edge, in that edge's frame (origin at
  /// vertex(next(c)), +x to vertex(prev(c)), the face above); unused at a boundary edge.
  std::vector<Point2> beyond_;
  std::vector<char> pseudoSource_;
  std::vector<double> d_;
  std::vector<int> cell_;
  std::vector<char> settled_;
  std::vector<int> order_;
  std::priority_queue<WindowEvent> windows_;
  std::vector<Window> pool_;  ///< the queued windows, by slot
  std::vector<int> freeSlots_;
  std::priority_queue<VertexEvent> vertices_;
  long long created_ = 0;
};

WindowPropagation::WindowPropagation(const TriMesh& mesh, const ExactGeodesicParams& params)
    : mesh_(mesh), params_(params) {
  const int nv = mesh.vertexCount();
  budget_ = params.maxWindows > 0 ? params.maxWindows : std::min(2000LL * nv + 100000, kMaxDefaultWindows);
  len_.resize(3 * mesh.faceCount());
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    len_[c] = (mesh.positions[mesh.vertex(TriMesh::next(c))] - mesh.positions[mesh.vertex(TriMesh::prev(c))]).norm();
  beyond_.resize(3 * mesh.faceCount());
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int oc = mesh.oppositeCorner[c];
    if (oc < 0) continue;
    const int cn = TriMesh::next(oc), cp = TriMesh::prev(oc);
    const int atU0 = mesh.vertex(cn) == mesh.vertex(TriMesh::next(c)) ? cn : cp, atU1 = atU0 == cn ? cp : cn;
    beyond_[c] = apex(len_[c], len_[atU1], len_[atU0], 1.0);
  }
  std::vector<double> angleSum(nv, 0.0);
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const double a = len_[TriMesh::next(c)], b = len_[TriMesh::prev(c)], o = len_[c];
    angleSum[mesh.vertex(c)] += std::acos(std::clamp((a * a + b * b - o * o) / (2.0 * a * b), -1.0, 1.0));
  }
  pseudoSource_ = boundaryVertexFlags(mesh);
  for (int v = 0; v < nv; ++v)
    if (angleSum[v] > kTwoPi + kSaddleExcess) pseudoSource_[v] = 1;
  d_.assign(nv, kUnreached);
  cell_.assign(nv, -1);
  settled_.assign(nv, 0);
}

void WindowPropagation::offer(int v, double value, int cell) {
  if (settled_[v] || !(value < d_[v])) return;
  d_[v] = value;
  cell_[v] = cell;
  if (value <= params_.maxDistance) vertices_.push({value, v});
}

/// A vertex taken from the queue has its distance: its neighbours get the edge paths through it
/// and, at a (pseudo-)source, the faces around it get windows from it.
void WindowPropagation::settle(int v) {
  settled_[v] = 1;
  order_.push_back(v);
  for (const int* c = mesh_.cornersBegin(v); c != mesh_.cornersEnd(v); ++c) {
    offer(mesh_.vertex(TriMesh::next(*c)), d_[v] + len_[TriMesh::prev(*c)], cell_[v]);
    offer(mesh_.vertex(TriMesh::prev(*c)), d_[v] + len_[TriMesh::next(*c)], cell_[v]);
  }
  if (pseudoSource_[v]) emitFrom(v);
}

/// One window per face around v, on the edge facing v, seen whole from v.
void WindowPropagation::emitFrom(int v) {
  for (const int* pc = mesh_.cornersBegin(v); pc != mesh_.cornersEnd(v); ++pc) {
    const int c = *pc;
    if (mesh_.oppositeCorner[c] < 0) continue;  // nothing beyond a boundary edge
    const double L = len_[c];
    Window w;
    w.corner = c;
    w.cell = cell_[v];
    w.t0 = 0.0;
    w.t1 = L;
    w.image = apex(L, len_[TriMesh::prev(c)], len_[TriMesh::next(c)], -1.0);
    w.sigma = d_[v];
    if (-w.image.y > kSeeTolerance * L) push(w);  // v on the edge's line: the edge paths do it
  }
}

/// Every point of the window is reached more cheaply through an end of its edge: the distance
/// along the window minus the one through the end u0 only decreases towards u1, so the far end
/// decides (and the same for u1).
bool WindowPropagation::dominated(const Window& w) const {
  const double L = len_[w.corner];
  const int u0 = mesh_.vertex(TriMesh::next(w.corner)), u1 = mesh_.vertex(TriMesh::prev(w.corner));
  const double far1 = w.sigma + norm2d(w.t1 - w.image.x, w.image.y);
  if (far1 > (d_[u0] + w.t1) + kDropTolerance * far1) return true;
  const double far0 = w.sigma + norm2d(w.t0 - w.image.x, w.image.y);
  return far0 > (d_[u1] + (L - w.t0)) + kDropTolerance * far0;
}

void WindowPropagation::push(const Window& w) {
  if (dominated(w)) return;
  const double nearest = std::clamp(w.image.x, w.t0, w.t1);
  const double key = w.sigma + norm2d(nearest - w.image.x, w.image.y);
  if (key > params_.maxDistance) return;
  int slot;
  if (freeSlots_.empty()) {
    slot = static_cast<int>(pool_.size());
    pool_.push_back(w);
  } else {
    slot = freeSlots_.back();
    freeSlots_.pop_back();
    pool_[slot] = w;
  }
  windows_.push({key, slot});
  ++created_;
}

/// The window crosses the face beyond its edge: the opposite vertex gets the straight line if the
/// window sees it, and the parts of the window's cone on the face's two other edges become
/// windows there.
void WindowPropagation::cross(const Window& w) {
  const int oc = mesh_.oppositeCorner[w.corner];
  if (oc < 0) return;
  CrossedFace f;
  f.u0 = mesh_.vertex(TriMesh::next(w.corner));
  f.u1 = mesh_.vertex(TriMesh::prev(w.corner));
  f.c = mesh_.vertex(oc);
  const int cn = TriMesh::next(oc), cp = TriMesh::prev(oc);
  const int cornerAtU0 = mesh_.vertex(cn) == f.u0 ? cn : cp, cornerAtU1 = cornerAtU0 == cn ? cp : cn;
  const double L = len_[w.corner];
  f.p1 = {L, 0.0};
  f.pc = beyond_[w.corner];
  const double h = -w.image.y;
  const double xc = w.image.x + (f.pc.x - w.image.x) * h / (f.pc.y + h);  // c seen on the edge
  const double tol = kSeeTolerance * L;
  if (xc >= w.t0 - tol && xc <= w.t1 + tol)
    offer(f.c, w.sigma + norm2d(f.pc.x - w.image.x, f.pc.y - w.image.y), w.cell);
  if (xc > w.t0 + tol) addChild(w, f, cornerAtU1, f.p0, w.t0, std::min(w.t1, xc));  // on edge u0 c
  if (xc < w.t1 - tol) addChild(w, f, cornerAtU0, f.p1, std::max(w.t0, xc), w.t1);  // on edge u1 c
}

/// The part [x0, x1] of the window's edge, seen from the image, lands on the edge from `from`
/// (u0 or u1) to c; that part becomes a window on the edge facing `childCorner`, in its frame.
void WindowPropagation::addChild(const Window& w, const CrossedFace& f, int childCorner, Point2 from, double x0,
                                 double x1) {
  const double h = -w.image.y;
  const Point2 to = f.pc;
  auto landing = [&](double x) {  // the point of from->c on the line from the image through (x, 0)
    const double den = (x - w.image.x) * to.y - h * (to.x - from.x);
    const double lambda = den != 0.0 ? std::clamp(h * (from.x - x) / den, 0.0, 1.0) : 0.0;
    return Point2{from.x + lambda * (to.x - from.x), from.y + lambda * (to.y - from.y)};
  };
  const Point2 q0 = landing(x0), q1 = landing(x1);
  // The child's frame: origin at vertex(next(childCorner)), +x to vertex(prev(childCorner)), the
  // crossed face below.
  const Point2 o = f.at(mesh_.vertex(TriMesh::next(childCorner)));
  const Point2 e1 = f.at(mesh_.vertex(TriMesh::prev(childCorner)));
  const double L = len_[childCorner];
  const Point2 ex{(e1.x - o.x) / L, (e1.y - o.y) / L};
  Point2 ey{-ex.y, ex.x};
  const Point2 third = f.at(mesh_.vertex(childCorner));
  double side = (third.x - o.x) * ey.x + (third.y - o.y) * ey.y;
  if (side == 0.0) side = (w.image.x - o.x) * ey.x + (w.image.y - o.y) * ey.y;  // a flat face
  if (side > 0.0) ey = {-ey.x, -ey.y};
  auto local = [&](Point2 p) {
    return Point2{(p.x - o.x) * ex.x + (p.y - o.y) * ex.y, (p.x - o.x) * ey.x + (p.y - o.y) * ey.y};
  };
  Window child;
  child.corner = childCorner;
  child.cell = w.cell;
  child.sigma = w.sigma;
  child.image = local(w.image);
  const double s0 = local(q0).x, s1 = local(q1).x;
  child.t0 = std::clamp(std::min(s0, s1), 0.0, L);
  child.t1 = std::clamp(std::max(s0, s1), 0.0, L);
  const double tol = kSeeTolerance * L;
  const int v0 = mesh_.vertex(TriMesh::next(childCorner)), v1 = mesh_.vertex(TriMesh::prev(childCorner));
  if (child.t0 <= tol) offer(v0, w.sigma + norm2d(child.image.x, child.image.y), w.cell);
  if (child.t1 >= L - tol) offer(v1, w.sigma + norm2d(L - child.image.x, child.image.y), w.cell);
  if (child.t1 - child.t0 <= tol || -child.image.y <= tol) return;
  if (mesh_.oppositeCorner[childCorner] >= 0) push(child);
}

Status WindowPropagation::run(const std::vector<int>& sources, Progress& progress) {
  for (size_t i = 0; i < sources.size(); ++i) offer(sources[i], 0.0, static_cast<int>(i));
  for (int s : sources) pseudoSource_[s] = 1;  // a source is seen whole from itself
  const double nv = mesh_.vertexCount();
  long long steps = 0;
  while (!windows_.empty() || !vertices_.empty()) {
    if ((++steps & 4095) == 0 && !progress.report(order_.size() / nv, "Exact geodesics")) return cancelled();
    const bool vertexFirst = !vertices_.empty() && (windows_.empty() || vertices_.top().key <= windows_.top().key);
    if (vertexFirst) {
      const VertexEvent e = vertices_.top();
      vertices_.pop();
      if (!settled_[e.vertex] && e.key == d_[e.vertex]) settle(e.vertex);
      continue;
    }
    const int slot = windows_.top().slot;
    windows_.pop();
    const Window w = pool_[slot];
    freeSlots_.push_back(slot);
    if (!dominated(w)) cross(w);
    if (created_ > budget_) return Status::ok();
  }
  return Status::ok();
}

ExactGeodesicResult WindowPropagation::result() {
  ExactGeodesicResult r;
  r.windows = created_;
  r.budgetExhausted = created_ > budget_;
  r.field.distance.assign(mesh_.vertexCount(), kUnreached);
  r.field.cell.assign(mesh_.vertexCount(), -1);
  for (int v : order_) {
    r.field.distance[v] = d_[v];
    r.field.cell[v] = cell_[v];
    r.field.maxDistance = std::max(r.field.maxDistance, d_[v]);
  }
  r.field.acceptedOrder = std::move(order_);
  return r;
}

}  // namespace

Expected<ExactGeodesicResult> exactGeodesicDistance(const TriMesh& mesh, const std::vector<int>& sources,
                                                    const ExactGeodesicParams& params, Progress progress) {
  if (Status s = checkSourcesAndLimit(mesh, sources, params.maxDistance); !s) return s;
  if (!mesh.topology.isManifold())
    return nonManifold("exact geodesics need a manifold mesh: " + mesh.topology.nonManifoldCounts());
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    if (mesh.positions[mesh.vertex(TriMesh::next(c))] == mesh.positions[mesh.vertex(TriMesh::prev(c))])
      return invalidInput("exact geodesics need edges of non-zero length (face " + std::to_string(TriMesh::face(c)) +
                          " has one)");
  try {
    WindowPropagation propagation(mesh, params);
    if (Status s = propagation.run(sources, progress); !s) return s;
    return propagation.result();
  } catch (const std::bad_alloc&) {
    return outOfMemory("exact geodesics ran out of memory for their windows");
  }
}

}  // namespace gr
