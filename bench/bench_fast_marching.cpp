// Single-source geodesic distance: ours (fast marching) against the competitors, same process,
// same meshes, same source vertex (0).
//
//   Ours_FastMarcher          gr::FastMarcher reused with reset(): propagation only (no allocation)
//   Ours_fastMarching_oneshot gr::fastMarching(): engine construction + propagation + result copy
//   Dijkstra                  shortest paths along edges (CSR graph, binary heap): the baseline
//   Vcg_Geodesic              vcg::tri::Geodesic<M>::Compute, what MeshLab's "Colorize by geodesic
//                             distance" runs (float mesh, as MeshLab's CMeshO)
//   CgalHeat_BuildQuery       CGAL heat method (Direct): construction (factorisation) + one query
//   CgalHeat_Query            the same, one query on an already factorised solver
//   CgalHeatIdt_*             the same with the intrinsic Delaunay triangulation (not on the 1M mesh)
//
// Farthest-point sampling (the inner loop of the remesher) on bunny00:
//   FpsStep_*   one step: the field of 999 sources is known, a 1000th source is added. Ours and
//               Dijkstra incrementally (U <- min(U, U_x), only improved vertices are visited),
//               timed around the step alone (manual time: restoring the 999-source field between
//               steps is not timed); ours, Dijkstra, vcglib and CGAL heat also as a full recompute
//               from the 1000 sources. The sources are the farthest-point order of the Dijkstra
//               distance from vertex 0 (cheap, deterministic), the same for every method.
//   Fps1000_*   a whole sampling of 1000 points from vertex 0, each at the argmax of the current
//               field (linear scan, the same for every method), updated incrementally.
//
// Meshes: fandisk, bunny00, armadillo (libcgal-demo data) and armadillo subdivided 1-to-4 three
// times (1,664,002 vertices), built once per process on first use; a filter that excludes a mesh
// never builds it. Select families with --benchmark_filter, e.g. '^Ours', '/bunny00', '^FpsStep'.
// Counters: vertices/s (reached vertices per second), reached, vertices, max_dist (sanity check
// that every method computed a field; accuracy is tested in tests/, not here).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/geodesic.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include "core/geodesic/fast_marching.h"
#include "core/geodesic/metric.h"
#include "core/mesh/tri_mesh.h"
#include "core/mesh/subdivide.h"
#include "core/mesh/vcg_mesh.h"

namespace {

constexpr int kSource = 0;        ///< the source vertex of every single-source benchmark
constexpr int kFpsSources = 1000; ///< FpsStep_*: the field of kFpsSources-1 sources, plus one
constexpr double kInf = std::numeric_limits<double>::infinity();

// ------------------------------------------------------------------------------------------------
// Competitor mesh types

// vcglib: the components tri::Geodesic needs (VF adjacency, quality, mark, flags), float
// coordinates and quality as in MeshLab's CMeshO (MESHLAB_SCALAR = float).
class VVertex;
class VFace;
struct VUsedTypes
    : public vcg::UsedTypes<vcg::Use<VVertex>::AsVertexType, vcg::Use<VFace>::AsFaceType> {};
class VVertex : public vcg::Vertex<VUsedTypes, vcg::vertex::Coord3f, vcg::vertex::VFAdj,
                                   vcg::vertex::Qualityf, vcg::vertex::Mark, vcg::vertex::BitFlags> {};
class VFace : public vcg::Face<VUsedTypes, vcg::face::VertexRef, vcg::face::VFAdj, vcg::face::Mark,
                               vcg::face::BitFlags> {};
class VMesh : public vcg::tri::TriMesh<std::vector<VVertex>, std::vector<VFace>> {};

using Kernel = CGAL::Simple_cartesian<double>;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using SmVertex = SurfaceMesh::Vertex_index;
using HeatDirect =
    CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<SurfaceMesh, CGAL::Heat_method_3::Direct>;
using HeatIdt = CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<
    SurfaceMesh, CGAL::Heat_method_3::Intrinsic_Delaunay>;

// ------------------------------------------------------------------------------------------------
// Dijkstra along edges: the baseline

/// Vertex -> neighbour adjacency in CSR form with edge lengths, built once from the corners.
struct EdgeGraph {
  std::vector<int> begin;       ///< size n + 1
  std::vector<int> neighbour;
  std::vector<double> length;
  int vertexCount() const { return static_cast<int>(begin.size()) - 1; }
};

EdgeGraph buildEdgeGraph(const gr::TriMesh& m) {
  EdgeGraph g;
  const int nv = m.vertexCount();
  g.begin.assign(nv + 1, 0);
  g.neighbour.reserve(m.vertexCorners.size() + nv);
  g.length.reserve(m.vertexCorners.size() + nv);
  std::vector<int> ring;
  for (int v = 0; v < nv; ++v) {
    ring.clear();
    for (const int* it = m.cornersBegin(v); it != m.cornersEnd(v); ++it) {
      ring.push_back(m.vertex(gr::TriMesh::next(*it)));
      ring.push_back(m.vertex(gr::TriMesh::prev(*it)));
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    for (int w : ring) {
      g.neighbour.push_back(w);
      g.length.push_back((m.positions[v] - m.positions[w]).norm());
    }
    g.begin[v + 1] = static_cast<int>(g.neighbour.size());
  }
  return g;
}

/// Dijkstra with a binary heap and lazy deletion; buffers reused across runs like FastMarcher.
class Dijkstra {
 public:
  explicit Dijkstra(const EdgeGraph& g) : g_(g), d_(g.vertexCount(), kInf) {
    heap_.reserve(g.vertexCount());
    touched_.reserve(g.vertexCount());
  }

  void reset() {
    for (int v : touched_) d_[v] = kInf;
    touched_.clear();
    heap_.clear();
  }

  /// Full multi-source run on a reset engine; returns the number of reached vertices.
  int run(const std::vector<int>& sources) {
    for (int s : sources)
      if (d_[s] != 0.0) set(s, 0.0);
    int reached = 0;
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), Later{});
      const Entry e = heap_.back();
      heap_.pop_back();
      if (e.d != d_[e.v]) continue;  // stale
      ++reached;
      relax(e.v, e.d, nullptr);
    }
    return reached;
  }

  /// Adds a source to the current field: U <- min(U, U_s), visiting only the improved vertices.
  /// Every change is recorded as (vertex, old value) in `undo`, oldest first. Returns the number
  /// of changes.
  int addSourceIncremental(int s, std::vector<std::pair<int, double>>* undo) {
    if (d_[s] == 0.0) return 0;
    undo->push_back({s, d_[s]});
    set(s, 0.0);
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end(), Later{});
      const Entry e = heap_.back();
      heap_.pop_back();
      if (e.d != d_[e.v]) continue;
      relax(e.v, e.d, undo);
    }
    return static_cast<int>(undo->size());
  }

  /// Reverts the changes recorded by addSourceIncremental.
  void undo(const std::vector<std::pair<int, double>>& changes) {
    for (auto it = changes.rbegin(); it != changes.rend(); ++it) d_[it->first] = it->second;
  }

  const std::vector<double>& distance() const { return d_; }

 private:
  struct Entry {
    double d;
    int v;
  };
  struct Later {
    bool operator()(const Entry& x, const Entry& y) const { return x.d > y.d; }
  };

  void set(int v, double d) {
    if (d_[v] == kInf) touched_.push_back(v);
    d_[v] = d;
    heap_.push_back({d, v});
    std::push_heap(heap_.begin(), heap_.end(), Later{});
  }

  void relax(int v, double dv, std::vector<std::pair<int, double>>* undo) {
    for (int k = g_.begin[v]; k < g_.begin[v + 1]; ++k) {
      const int w = g_.neighbour[k];
      const double dw = dv + g_.length[k];
      if (dw < d_[w]) {
        if (undo) undo->push_back({w, d_[w]});
        set(w, dw);
      }
    }
  }

  const EdgeGraph& g_;
  std::vector<double> d_;
  std::vector<Entry> heap_;
  std::vector<int> touched_;
};

// ------------------------------------------------------------------------------------------------
// Meshes

struct MeshSpec {
  const char* name;
  const char* file;
  int subdivisions;
};

/// fandisk 6,475 v; bunny00 37,706 v; armadillo 26,002 v; armadillo_sub3 1,664,002 v.
const MeshSpec kMeshes[] = {
    {"fandisk", "fandisk.off", 0},
    {"bunny00", "bunny00.off", 0},
    {"armadillo", "armadillo.off", 0},
    {"armadillo_sub3", "armadillo.off", 3},
};
bool isLarge(const MeshSpec& s) { return s.subdivisions >= 3; }

/// A mesh and, built on first use, its copy in each competitor's structure (never timed).
struct BenchMesh {
  gr::TriMesh tri;
  std::unique_ptr<EdgeGraph> graph;
  std::unique_ptr<VMesh> vcg;
  std::unique_ptr<SurfaceMesh> cgal;
  SurfaceMesh::Property_map<SmVertex, double> cgalDistance;
  std::unique_ptr<HeatDirect> heatDirect;  ///< factorised solvers, kept for the *_Query benchmarks
  std::unique_ptr<HeatIdt> heatIdt;
  std::vector<int> fpsSources;             ///< kFpsSources vertices in farthest-point order
};

std::map<std::string, std::unique_ptr<BenchMesh>>& meshCache() {
  static std::map<std::string, std::unique_ptr<BenchMesh>> cache;
  return cache;
}

/// The mesh of `spec`, loaded (and subdivided) once per process; nullptr after SkipWithError.
BenchMesh* getMesh(benchmark::State& state, const MeshSpec& spec) {
  auto& slot = meshCache()[spec.name];
  if (slot) return slot.get();
  gr::Expected<gr::TriMesh> m = gr::loadTriMesh(std::string(GR_MESH_DIR) + "/" + spec.file);
  if (m && spec.subdivisions > 0) {  // gr::subdivideMidpoint: 1-to-4, old vertices keep their indices
    gr::Expected<gr::Subdivision> fine = gr::subdivideMidpoint(*m, spec.subdivisions);
    m = fine ? gr::Expected<gr::TriMesh>(std::move(fine->mesh)) : gr::Expected<gr::TriMesh>(fine.status());
  }
  if (!m) {
    state.SkipWithError(("mesh " + std::string(spec.name) + ": " + m.status().message).c_str());
    return nullptr;
  }
  slot = std::make_unique<BenchMesh>();
  slot->tri = std::move(*m);
  return slot.get();
}

const EdgeGraph& edgeGraph(BenchMesh& bm) {
  if (!bm.graph) bm.graph = std::make_unique<EdgeGraph>(buildEdgeGraph(bm.tri));
  return *bm.graph;
}

VMesh& vcgMesh(BenchMesh& bm) {
  if (bm.vcg) return *bm.vcg;
  auto m = std::make_unique<VMesh>();
  const gr::TriMesh& t = bm.tri;
  vcg::tri::Allocator<VMesh>::AddVertices(*m, t.vertexCount());
  for (int v = 0; v < t.vertexCount(); ++v)
    m->vert[v].P() = vcg::Point3f(float(t.positions[v].x()), float(t.positions[v].y()),
                                  float(t.positions[v].z()));
  vcg::tri::Allocator<VMesh>::AddFaces(*m, t.faceCount());
  for (int f = 0; f < t.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) m->face[f].V(k) = &m->vert[t.triangles[f][k]];
  vcg::tri::UpdateTopology<VMesh>::VertexFace(*m);
  bm.vcg = std::move(m);
  return *bm.vcg;
}

/// The CGAL copy; vertex i of the TriMesh is vertex i of the Surface_mesh. nullptr after
/// SkipWithError when Surface_mesh rejects a face (non-manifold or inconsistently oriented).
SurfaceMesh* cgalMesh(benchmark::State& state, BenchMesh& bm) {
  if (bm.cgal) return bm.cgal.get();
  auto m = std::make_unique<SurfaceMesh>();
  const gr::TriMesh& t = bm.tri;
  m->reserve(t.vertexCount(), 3 * t.faceCount() / 2 + t.topology.boundaryEdges, t.faceCount());
  for (const gr::Vec3& p : t.positions) m->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  for (int f = 0; f < t.faceCount(); ++f) {
    const gr::Tri& tr = t.triangles[f];
    if (m->add_face(SmVertex(tr[0]), SmVertex(tr[1]), SmVertex(tr[2])) == SurfaceMesh::null_face()) {
      state.SkipWithError(("CGAL Surface_mesh rejects face " + std::to_string(f)).c_str());
      return nullptr;
    }
  }
  bm.cgalDistance = m->add_property_map<SmVertex, double>("v:gr_distance", 0.0).first;
  bm.cgal = std::move(m);
  return bm.cgal.get();
}

template <class Heat>
std::unique_ptr<Heat>& heatSlot(BenchMesh& bm);
template <>
std::unique_ptr<HeatDirect>& heatSlot<HeatDirect>(BenchMesh& bm) { return bm.heatDirect; }
template <>
std::unique_ptr<HeatIdt>& heatSlot<HeatIdt>(BenchMesh& bm) { return bm.heatIdt; }

/// The vertex of largest finite distance (ties: the lowest index); -1 if every finite value is 0.
int argmaxFinite(const std::vector<double>& d) {
  int far = -1;
  double best = -1.0;
  for (int v = 0; v < static_cast<int>(d.size()); ++v)
    if (d[v] > best && d[v] != kInf) {
      best = d[v];
      far = v;
    }
  return best > 0.0 ? far : -1;
}

/// Farthest-point order under the Dijkstra distance, from kSource: deterministic and cheap
/// (incremental Dijkstra). The same list is given to every FpsStep_* method.
const std::vector<int>& fpsSources(BenchMesh& bm) {
  if (!bm.fpsSources.empty()) return bm.fpsSources;
  Dijkstra dij(edgeGraph(bm));
  std::vector<int> sources{kSource};
  dij.run(sources);
  std::vector<std::pair<int, double>> undo;
  while (static_cast<int>(sources.size()) < kFpsSources) {
    const int far = argmaxFinite(dij.distance());
    if (far < 0) break;  // fewer vertices than sources
    sources.push_back(far);
    undo.clear();
    dij.addSourceIncremental(far, &undo);
  }
  bm.fpsSources = std::move(sources);
  return bm.fpsSources;
}

// ------------------------------------------------------------------------------------------------
// Counters

double maxFinite(const std::vector<double>& d) {
  double m = 0.0;
  for (double x : d)
    if (x != kInf && x > m) m = x;
  return m;
}

/// CGAL's heat method leaves max-double (or NaN) where its solve failed, e.g. where the heat
/// underflowed to 0 far from the source on a fine mesh: those are not counted as reached.
std::pair<int, double> cgalReached(const BenchMesh& bm) {
  int reached = 0;
  double maxDist = 0.0;
  for (SmVertex v : bm.cgal->vertices()) {
    const double d = bm.cgalDistance[v];
    if (std::isfinite(d) && d < std::numeric_limits<double>::max()) {
      ++reached;
      maxDist = std::max(maxDist, d);
    }
  }
  return {reached, maxDist};
}

void setCounters(benchmark::State& state, const BenchMesh& bm, double reached, double maxDist) {
  state.counters["vertices/s"] = benchmark::Counter(reached, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["reached"] = reached;
  state.counters["vertices"] = bm.tri.vertexCount();
  state.counters["max_dist"] = maxDist;
}

// ------------------------------------------------------------------------------------------------
// Single source: ours

void BM_OursFastMarcher(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const gr::Metric metric = gr::Metric::uniform();
  gr::FastMarcher marcher(bm->tri, metric);
  for (auto _ : state) {
    marcher.reset();
    (void)marcher.addSource(kSource, 0);
    if (gr::Status s = marcher.propagate(); !s) {
      state.SkipWithError(s.message.c_str());
      return;
    }
    benchmark::DoNotOptimize(marcher.distance().data());
  }
  setCounters(state, *bm, marcher.acceptedOrder().size(), maxFinite(marcher.distance()));
}

void BM_OursOneShot(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const gr::Metric metric = gr::Metric::uniform();
  const std::vector<int> sources{kSource};
  double reached = 0, maxDist = 0;
  for (auto _ : state) {
    gr::Expected<gr::FastMarchingResult> r = gr::fastMarching(bm->tri, metric, sources);
    if (!r) {
      state.SkipWithError(r.status().message.c_str());
      return;
    }
    benchmark::DoNotOptimize(r->distance.data());
    reached = r->reachedCount();
    maxDist = r->maxDistance;
  }
  setCounters(state, *bm, reached, maxDist);
}

// ------------------------------------------------------------------------------------------------
// Single source: competitors

void BM_Dijkstra(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  Dijkstra dij(edgeGraph(*bm));
  const std::vector<int> sources{kSource};
  int reached = 0;
  for (auto _ : state) {
    dij.reset();
    reached = dij.run(sources);
    benchmark::DoNotOptimize(dij.distance().data());
  }
  setCounters(state, *bm, reached, maxFinite(dij.distance()));
}

/// Counts the vertices vcglib reached (it leaves max-float in the others) and their max.
std::pair<int, double> vcgReached(const VMesh& m) {
  int reached = 0;
  double maxDist = 0.0;
  for (const VVertex& v : m.vert)
    if (v.cQ() < std::numeric_limits<float>::max()) {
      ++reached;
      maxDist = std::max(maxDist, double(v.cQ()));
    }
  return {reached, maxDist};
}

void BM_VcgGeodesic(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  VMesh& m = vcgMesh(*bm);
  const std::vector<VMesh::VertexPointer> seeds{&m.vert[kSource]};
  vcg::tri::EuclideanDistance<VMesh> dist;
  for (auto _ : state) {
    // The call MeshLab's filter_geodesic makes (maxDistance = no limit).
    vcg::tri::Geodesic<VMesh>::Compute(m, seeds, dist, std::numeric_limits<float>::max());
    benchmark::DoNotOptimize(m.vert.data());
  }
  const auto [reached, maxDist] = vcgReached(m);
  setCounters(state, *bm, reached, maxDist);
}

/// Construction (mass and cotan matrices, time step, factorisation of M + tL and of L) and one
/// query. The last solver built is kept for the *_Query benchmark of the same mesh.
template <class Heat>
void BM_CgalHeatBuildQuery(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  SurfaceMesh* sm = cgalMesh(state, *bm);
  if (!sm) return;
  for (auto _ : state) {
    auto heat = std::make_unique<Heat>(*sm);
    heat->add_source(SmVertex(kSource));
    heat->estimate_geodesic_distances(bm->cgalDistance);
    benchmark::DoNotOptimize(heat.get());
    state.PauseTiming();  // not timed: keeping or freeing the solver
    if (!heatSlot<Heat>(*bm)) heatSlot<Heat>(*bm) = std::move(heat);
    heat.reset();
    state.ResumeTiming();
  }
  const auto [reached, maxDist] = cgalReached(*bm);
  setCounters(state, *bm, reached, maxDist);
}

/// One query (two back-substitutions, gradient, divergence) on a factorised solver.
template <class Heat>
void BM_CgalHeatQuery(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  SurfaceMesh* sm = cgalMesh(state, *bm);
  if (!sm) return;
  auto& heat = heatSlot<Heat>(*bm);
  if (!heat) heat = std::make_unique<Heat>(*sm);  // not timed
  for (auto _ : state) {
    heat->add_source(SmVertex(kSource));  // marks the sources changed, so the query recomputes
    heat->estimate_geodesic_distances(bm->cgalDistance);
    benchmark::DoNotOptimize(bm->cgalDistance.data());
  }
  const auto [reached, maxDist] = cgalReached(*bm);
  setCounters(state, *bm, reached, maxDist);
}

// ------------------------------------------------------------------------------------------------
// One farthest-point-sampling step: the field of sources[0..n-2] is known, sources[n-1] is added.

/// Ours without the incremental path: reset and propagate from all n sources again.
void BM_FpsStepOursFullRecompute(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const std::vector<int>& sources = fpsSources(*bm);
  const gr::Metric metric = gr::Metric::uniform();
  gr::FastMarcher marcher(bm->tri, metric);
  for (auto _ : state) {
    marcher.reset();
    for (size_t i = 0; i < sources.size(); ++i) (void)marcher.addSource(sources[i], static_cast<int>(i));
    if (gr::Status s = marcher.propagate(); !s) {
      state.SkipWithError(s.message.c_str());
      return;
    }
    benchmark::DoNotOptimize(marcher.distance().data());
  }
  setCounters(state, *bm, marcher.acceptedOrder().size(), maxFinite(marcher.distance()));
  state.counters["sources"] = sources.size();
}

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point t0, Clock::time_point t1) {
  return std::chrono::duration<double>(t1 - t0).count();
}

/// Ours, incremental: addSource + propagate on the engine that holds the 999-source field; the
/// front enters only the vertices it improves. The field is restored by copying a prepared
/// engine before each step (not timed: manual time around the step).
void BM_FpsStepOursIncremental(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const std::vector<int>& sources = fpsSources(*bm);
  const int n = static_cast<int>(sources.size());
  const gr::Metric metric = gr::Metric::uniform();
  // The field of the first 999 sources; each timed step then adds the next farthest vertex, as
  // greedy sampling does: steps 1000, 1001, ... on a warm engine (manual time around the step).
  gr::FastMarcher marcher(bm->tri, metric);
  for (int i = 0; i + 1 < n; ++i) (void)marcher.addSource(sources[i], i);
  if (gr::Status s = marcher.propagate(); !s) {
    state.SkipWithError(s.message.c_str());
    return;
  }
  size_t changed = 0, steps = 0;
  int label = n - 1;
  for (auto _ : state) {
    const std::vector<double>& d = marcher.distance();
    const int next = static_cast<int>(std::max_element(d.begin(), d.end()) - d.begin());  // untimed
    const Clock::time_point t0 = Clock::now();
    (void)marcher.addSource(next, label++);
    const gr::Status s = marcher.propagate();
    benchmark::DoNotOptimize(marcher.distance().data());
    const Clock::time_point t1 = Clock::now();
    if (!s) {
      state.SkipWithError(s.message.c_str());
      return;
    }
    state.SetIterationTime(seconds(t0, t1));
    changed += marcher.acceptedOrder().size();
    ++steps;
  }
  setCounters(state, *bm, steps ? changed / steps : 0, maxFinite(marcher.distance()));  // "reached" = changed per step
  state.counters["sources"] = n;
}

/// Dijkstra, incremental: U <- min(U, U_x), visiting only the improved vertices. The field is
/// restored from the undo log after each step (not timed: manual time around the step).
void BM_FpsStepDijkstraIncremental(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const std::vector<int>& sources = fpsSources(*bm);
  Dijkstra dij(edgeGraph(*bm));
  dij.run(std::vector<int>(sources.begin(), sources.end() - 1));
  std::vector<std::pair<int, double>> changes;
  changes.reserve(bm->tri.vertexCount());
  for (auto _ : state) {
    changes.clear();
    const Clock::time_point t0 = Clock::now();
    dij.addSourceIncremental(sources.back(), &changes);
    benchmark::DoNotOptimize(dij.distance().data());
    const Clock::time_point t1 = Clock::now();
    state.SetIterationTime(seconds(t0, t1));
    dij.undo(changes);
  }
  changes.clear();
  dij.addSourceIncremental(sources.back(), &changes);
  std::vector<int> changed;
  for (const auto& c : changes) changed.push_back(c.first);
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  setCounters(state, *bm, changed.size(), maxFinite(dij.distance()));  // "reached" = changed
  state.counters["sources"] = sources.size();
}

void BM_FpsStepDijkstraFullRecompute(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const std::vector<int>& sources = fpsSources(*bm);
  Dijkstra dij(edgeGraph(*bm));
  int reached = 0;
  for (auto _ : state) {
    dij.reset();
    reached = dij.run(sources);
    benchmark::DoNotOptimize(dij.distance().data());
  }
  setCounters(state, *bm, reached, maxFinite(dij.distance()));
  state.counters["sources"] = sources.size();
}

/// vcglib has no incremental update either: Compute from all n seeds.
void BM_FpsStepVcgGeodesic(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const std::vector<int>& sources = fpsSources(*bm);
  VMesh& m = vcgMesh(*bm);
  std::vector<VMesh::VertexPointer> seeds;
  for (int s : sources) seeds.push_back(&m.vert[s]);
  vcg::tri::EuclideanDistance<VMesh> dist;
  for (auto _ : state) {
    vcg::tri::Geodesic<VMesh>::Compute(m, seeds, dist, std::numeric_limits<float>::max());
    benchmark::DoNotOptimize(m.vert.data());
  }
  const auto [reached, maxDist] = vcgReached(m);
  setCounters(state, *bm, reached, maxDist);
  state.counters["sources"] = sources.size();
}

/// The heat method adds a source by solving again (one query with n sources) on the factorised
/// solver (built untimed if the CgalHeat_* benchmarks of this mesh did not run).
void BM_FpsStepCgalHeatQuery(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  SurfaceMesh* sm = cgalMesh(state, *bm);
  if (!sm) return;
  const std::vector<int>& sources = fpsSources(*bm);
  auto& heat = bm->heatDirect;
  if (!heat) heat = std::make_unique<HeatDirect>(*sm);
  heat->clear_sources();
  for (size_t i = 0; i + 1 < sources.size(); ++i) heat->add_source(SmVertex(sources[i]));
  for (auto _ : state) {
    heat->add_source(SmVertex(sources.back()));
    heat->estimate_geodesic_distances(bm->cgalDistance);
    benchmark::DoNotOptimize(bm->cgalDistance.data());
  }
  heat->clear_sources();
  const auto [reached, maxDist] = cgalReached(*bm);
  setCounters(state, *bm, reached, maxDist);
  state.counters["sources"] = sources.size();
}

// ------------------------------------------------------------------------------------------------
// A whole farthest-point sampling of kFpsSources points: start at vertex 0, then repeatedly add the
// vertex of largest finite distance (argmaxFinite, a linear scan) and update the field.

void BM_Fps1000OursIncremental(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const gr::Metric metric = gr::Metric::uniform();
  gr::FastMarcher marcher(bm->tri, metric);
  double visited = 0;
  int samples = 0;
  for (auto _ : state) {
    marcher.reset();
    visited = 0;
    int next = kSource;
    for (samples = 0; samples < kFpsSources && next >= 0; ++samples) {
      (void)marcher.addSource(next, samples);
      if (gr::Status s = marcher.propagate(); !s) {
        state.SkipWithError(s.message.c_str());
        return;
      }
      visited += marcher.acceptedOrder().size();
      next = argmaxFinite(marcher.distance());
    }
  }
  setCounters(state, *bm, visited, maxFinite(marcher.distance()));  // "reached" = vertex visits
  state.counters["sources"] = samples;
}

void BM_Fps1000DijkstraIncremental(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  Dijkstra dij(edgeGraph(*bm));
  std::vector<std::pair<int, double>> changes;
  changes.reserve(bm->tri.vertexCount());
  double visited = 0;
  int samples = 0;
  for (auto _ : state) {
    dij.reset();
    visited = dij.run({kSource});
    for (samples = 1; samples < kFpsSources; ++samples) {
      const int next = argmaxFinite(dij.distance());
      if (next < 0) break;
      changes.clear();
      visited += dij.addSourceIncremental(next, &changes);
    }
  }
  setCounters(state, *bm, visited, maxFinite(dij.distance()));  // "reached" = vertex updates
  state.counters["sources"] = samples;
}

/// The floor of both: the kFpsSources - 1 argmax scans alone, on a fixed field.
void BM_Fps1000ArgmaxScans(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  Dijkstra dij(edgeGraph(*bm));
  dij.run({kSource});
  for (auto _ : state) {
    long sum = 0;
    for (int i = 1; i < kFpsSources; ++i) {
      benchmark::DoNotOptimize(dij.distance().data());
      sum += argmaxFinite(dij.distance());
    }
    benchmark::DoNotOptimize(sum);
  }
  setCounters(state, *bm, double(kFpsSources - 1) * bm->tri.vertexCount(), 0.0);  // "reached" = reads
  state.counters["sources"] = kFpsSources;
}

// ------------------------------------------------------------------------------------------------

using BenchFn = void (*)(benchmark::State&, const MeshSpec&);

/// Each benchmark runs kRepetitions times (median reported by scripts/bench_report.py) with a short
/// minimum time, which resists a busy machine better than one long run; the slow ones on the
/// 1M mesh run once.
constexpr int kRepetitions = 3;
constexpr double kMinTime = 0.2;  // seconds per repetition

/// Times are CPU time of the whole process (the machine may be shared with builds and tests; the
/// engine's constructor runs a helper thread, counted too), except for manual-time benchmarks,
/// which time a region of the loop with a steady clock. iterations: 0 = as many as
/// kMinTime needs, 1 = a single run (no repetitions), n > 1 = n per repetition.
void add(const char* family, BenchFn fn, const MeshSpec& spec, int iterations = 0, bool manualTime = false) {
  auto* b = benchmark::RegisterBenchmark((std::string(family) + "/" + spec.name).c_str(), fn, spec);
  b->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
  if (manualTime) b->UseManualTime();
  if (iterations == 1) {
    b->Iterations(1);
    return;
  }
  if (iterations > 1)
    b->Iterations(iterations);
  else
    b->MinTime(kMinTime);
  b->Repetitions(kRepetitions)->DisplayAggregatesOnly(true);
}

void registerAll() {
  for (const MeshSpec& spec : kMeshes) {
    const int slow = isLarge(spec) ? 1 : 0;  // a single run on the 1M mesh
    add("Ours_FastMarcher", BM_OursFastMarcher, spec);
    add("Ours_fastMarching_oneshot", BM_OursOneShot, spec);
    add("Dijkstra", BM_Dijkstra, spec);
    add("Vcg_Geodesic", BM_VcgGeodesic, spec, slow);
    add("CgalHeat_BuildQuery", BM_CgalHeatBuildQuery<HeatDirect>, spec, slow);
    add("CgalHeat_Query", BM_CgalHeatQuery<HeatDirect>, spec);
    if (!isLarge(spec)) {  // the intrinsic Delaunay variant on 1.6M vertices would double the run time
      add("CgalHeatIdt_BuildQuery", BM_CgalHeatBuildQuery<HeatIdt>, spec);
      add("CgalHeatIdt_Query", BM_CgalHeatQuery<HeatIdt>, spec);
    }
    if (std::string(spec.name) == "bunny00") {
      // 200 consecutive sampling steps per repetition, from the 1000th source on.
      add("FpsStep_Ours_Incremental", BM_FpsStepOursIncremental, spec, 200, true);
      add("FpsStep_Dijkstra_Incremental", BM_FpsStepDijkstraIncremental, spec, 0, true);
      add("FpsStep_Ours_FullRecompute", BM_FpsStepOursFullRecompute, spec);
      add("FpsStep_Dijkstra_FullRecompute", BM_FpsStepDijkstraFullRecompute, spec);
      add("FpsStep_Vcg_Geodesic", BM_FpsStepVcgGeodesic, spec);
      add("FpsStep_CgalHeat_Query", BM_FpsStepCgalHeatQuery, spec);
      add("Fps1000_Ours_Incremental", BM_Fps1000OursIncremental, spec);
      add("Fps1000_Dijkstra_Incremental", BM_Fps1000DijkstraIncremental, spec);
      add("Fps1000_ArgmaxScans", BM_Fps1000ArgmaxScans, spec);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  registerAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
