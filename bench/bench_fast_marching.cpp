// Single-source geodesic distance: ours (fast marching) against the competitors, same process,
// same meshes, same source vertex (0).
//
//   Ours_FastMarcher          gr::FastMarcher reused with reset(): propagation only (no allocation)
//   Ours_fastMarching_oneshot gr::fastMarching(): engine construction + propagation + result copy
//   Dijkstra                  shortest paths along edges (CSR graph, binary heap, buffers reused):
//                             the baseline
//   Vcg_Geodesic              vcg::tri::Geodesic<M>::Compute, what MeshLab's "Colorize by geodesic
//                             distance" runs (float mesh, as MeshLab's CMeshO)
//   CgalHeat_BuildQuery       CGAL heat method (Direct): construction (factorisation) + one query
//   CgalHeat_Query            the same, one query on an already factorised solver
//   CgalHeatIdt_*             the same with the intrinsic Delaunay triangulation (not on the 1M mesh)
// The competitors are gr_oracles' (tests/oracles/geodesic_oracles.h: DijkstraSolver,
// VcgGeodesic<float>, HeatSolver), the code the accuracy tests compare against.
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
//   Ours_geodesicDistance     gr::geodesicDistance(), what the Fast marching filter calls: the
//                             triangulation test, then where it says the mesh is poor exact
//                             window propagation within its budget, else the intrinsic Delaunay
//                             refinement and the engine on it; the values at the input's vertices
//                             (counters: exact, windows, refined, inserted points)
//   Ours_geodesicDistance_fronts  the same without exact propagation (what the remeshing's fronts
//                             run on), sliver meshes only
//   Cgal_ShortestPath         CGAL's exact geodesics (Surface_mesh_shortest_path: mesh, source,
//                             every vertex queried), sliver meshes only
//
// Meshes: fandisk, bunny00, armadillo (libcgal-demo data) and armadillo subdivided 1-to-4 three
// times (1,664,002 vertices), built once per process on first use; a filter that excludes a mesh
// never builds it. Sliver meshes (issue 17), with the single-source families of ours, vcglib
// and CGAL's exact geodesics only: cheese.off and the four CAD-like meshes of tests/support/cad_meshes.h (cad_gear,
// cad_hole_plate, cad_cylinder, cad_bracket). Select families with --benchmark_filter, e.g. '^Ours', '/bunny00', '^FpsStep'.
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

#include "bench/bench_support.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_surface.h"
#include "core/geodesic/metric.h"
#include "core/mesh/tri_mesh.h"
#include "tests/oracles/geodesic_oracles.h"
#include "tests/support/cad_meshes.h"

namespace {

using gr::bench::MeshSpec;
using gr::oracle::DijkstraSolver;
using gr::oracle::HeatVariant;

constexpr int kSource = 0;         ///< the source vertex of every single-source benchmark
constexpr int kFpsSources = 1000;  ///< FpsStep_*: the field of kFpsSources-1 sources, plus one
constexpr double kInf = std::numeric_limits<double>::infinity();

// ------------------------------------------------------------------------------------------------
// Meshes

/// fandisk 6,475 v; bunny00 37,706 v; armadillo 26,002 v; armadillo_sub3 1,664,002 v.
const MeshSpec kMeshes[] = {
    {"fandisk", "fandisk.off", 0},
    {"bunny00", "bunny00.off", 0},
    {"armadillo", "armadillo.off", 0},
    {"armadillo_sub3", "armadillo.off", 3},
};
bool isLarge(const MeshSpec& s) { return s.subdivisions >= 3; }

/// Meshes the triangulation test refines; "cad:<name>" is built by test::cadMeshes().
const MeshSpec kSliverMeshes[] = {
    {"cheese", "cheese.off", 0},
    {"cad_gear", "cad:cad_gear", 0},
    {"cad_hole_plate", "cad:cad_hole_plate", 0},
    {"cad_cylinder", "cad:cad_cylinder", 0},
    {"cad_bracket", "cad:cad_bracket", 0},
};

/// A mesh and, built on first use, each competitor's object for it (never timed): the competitors
/// are gr_oracles' (tests/oracles/geodesic_oracles.h), the ones the accuracy tests use.
struct BenchMesh {
  explicit BenchMesh(gr::TriMesh mesh) : tri(std::move(mesh)) {}
  gr::TriMesh tri;
  std::unique_ptr<gr::oracle::VcgGeodesic<float>> vcg;  ///< float, as MeshLab's CMeshO
  std::optional<gr::oracle::HeatMesh> cgal;
  std::unique_ptr<gr::oracle::HeatSolver> heatDirect;  ///< factorised solvers, kept for the *_Query benchmarks
  std::unique_ptr<gr::oracle::HeatSolver> heatIdt;
  std::vector<int> fpsSources;  ///< kFpsSources vertices in farthest-point order
};

/// The mesh of `spec`, loaded (and subdivided) once per process; nullptr after SkipWithError.
BenchMesh* getMesh(benchmark::State& state, const MeshSpec& spec) {
  const std::string file = spec.file;
  if (file.rfind("cad:", 0) != 0) return gr::bench::cachedMesh<BenchMesh>(state, spec);
  static std::map<std::string, std::unique_ptr<BenchMesh>> cad;
  std::unique_ptr<BenchMesh>& slot = cad[spec.name];
  if (!slot)
    for (gr::test::CadMesh& m : gr::test::cadMeshes())
      if ("cad:" + m.name == file) slot = std::make_unique<BenchMesh>(std::move(m.mesh));
  if (!slot) state.SkipWithError(("no CAD mesh " + file).c_str());
  return slot.get();
}

gr::oracle::VcgGeodesic<float>& vcgGeodesic(BenchMesh& bm) {
  if (!bm.vcg) bm.vcg = std::make_unique<gr::oracle::VcgGeodesic<float>>(bm.tri);
  return *bm.vcg;
}

/// The CGAL copy and its distance property; vertex i of the TriMesh is vertex i of the
/// Surface_mesh. nullptr after SkipWithError when Surface_mesh rejects a face (non-manifold or
/// inconsistently oriented).
gr::oracle::HeatMesh* cgalMesh(benchmark::State& state, BenchMesh& bm) {
  if (bm.cgal) return &*bm.cgal;
  gr::Expected<gr::oracle::HeatMesh> m = gr::oracle::toHeatMesh(bm.tri);
  if (!m) {
    state.SkipWithError(m.status().message.c_str());
    return nullptr;
  }
  bm.cgal = std::move(*m);
  return &*bm.cgal;
}

std::unique_ptr<gr::oracle::HeatSolver>& heatSlot(BenchMesh& bm, HeatVariant variant) {
  return variant == HeatVariant::Direct ? bm.heatDirect : bm.heatIdt;
}

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
  DijkstraSolver dij(bm.tri);
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

void setCounters(benchmark::State& state, const BenchMesh& bm, double reached, double maxDist) {
  state.counters["vertices/s"] = benchmark::Counter(reached, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["reached"] = reached;
  state.counters["vertices"] = bm.tri.vertexCount();
  state.counters["max_dist"] = maxDist;
}

/// vcglib leaves max-float where it did not reach; CGAL's heat method leaves max-double (or NaN)
/// where its solve failed, e.g. where the heat underflowed to 0 far from the source on a fine
/// mesh: those are not counted as reached.
void setCounters(benchmark::State& state, const BenchMesh& bm, const gr::oracle::Reached& reached) {
  setCounters(state, bm, reached.count, reached.maxDistance);
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

template <gr::ExactPropagation kExact>
void BM_OursGeodesicDistance(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  const std::vector<int> sources{kSource};
  gr::GeodesicDistanceParams params;
  params.exact = kExact;
  double reached = 0, maxDist = 0, inserted = 0, refined = 0, exact = 0, windows = 0;
  for (auto _ : state) {
    gr::Expected<gr::GeodesicDistanceResult> r = gr::geodesicDistance(bm->tri, {}, sources, params);
    if (!r) {
      state.SkipWithError(r.status().message.c_str());
      return;
    }
    benchmark::DoNotOptimize(r->field.distance.data());
    reached = r->field.reachedCount();
    maxDist = r->field.maxDistance;
    inserted = r->insertedPoints;
    refined = r->refined;
    exact = r->exact;
    windows = static_cast<double>(r->windows);
  }
  setCounters(state, *bm, reached, maxDist);
  state.counters["inserted"] = inserted;
  state.counters["refined"] = refined;
  state.counters["exact"] = exact;
  state.counters["windows"] = windows;
}

/// CGAL's exact geodesics (Surface_mesh_shortest_path, the tests' oracle): its mesh built, the
/// source added, every vertex queried.
void BM_CgalShortestPath(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  double reached = 0, maxDist = 0;
  for (auto _ : state) {
    const std::vector<double> d = gr::oracle::exactGeodesic(bm->tri, kSource);
    benchmark::DoNotOptimize(d.data());
    reached = 0;
    maxDist = 0;
    for (double x : d)
      if (std::isfinite(x)) {
        ++reached;
        maxDist = std::max(maxDist, x);
      }
  }
  setCounters(state, *bm, reached, maxDist);
}

// ------------------------------------------------------------------------------------------------
// Single source: competitors

void BM_Dijkstra(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  DijkstraSolver dij(bm->tri);
  const std::vector<int> sources{kSource};
  int reached = 0;
  for (auto _ : state) {
    dij.reset();
    reached = dij.run(sources);
    benchmark::DoNotOptimize(dij.distance().data());
  }
  setCounters(state, *bm, reached, maxFinite(dij.distance()));
}

void BM_VcgGeodesic(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  gr::oracle::VcgGeodesic<float>& vcg = vcgGeodesic(*bm);
  vcg.setSources({kSource});
  for (auto _ : state) {
    // The call MeshLab's filter_geodesic makes (maxDistance = no limit).
    vcg.compute();
    benchmark::DoNotOptimize(&vcg);
  }
  setCounters(state, *bm, vcg.reached());
}

/// Construction (mass and cotan matrices, time step, factorisation of M + tL and of L) and one
/// query. The last solver built is kept for the *_Query benchmark of the same mesh.
template <HeatVariant variant>
void BM_CgalHeatBuildQuery(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  gr::oracle::HeatMesh* hm = cgalMesh(state, *bm);
  if (!hm) return;
  for (auto _ : state) {
    auto heat = std::make_unique<gr::oracle::HeatSolver>(*hm, variant);
    heat->addSource(kSource);
    heat->solve();
    benchmark::DoNotOptimize(heat.get());
    state.PauseTiming();  // not timed: keeping or freeing the solver
    if (!heatSlot(*bm, variant)) heatSlot(*bm, variant) = std::move(heat);
    heat.reset();
    state.ResumeTiming();
  }
  setCounters(state, *bm, hm->reached());
}

/// One query (two back-substitutions, gradient, divergence) on a factorised solver.
template <HeatVariant variant>
void BM_CgalHeatQuery(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  gr::oracle::HeatMesh* hm = cgalMesh(state, *bm);
  if (!hm) return;
  auto& heat = heatSlot(*bm, variant);
  if (!heat) heat = std::make_unique<gr::oracle::HeatSolver>(*hm, variant);  // not timed
  for (auto _ : state) {
    heat->addSource(kSource);  // marks the sources changed, so the query recomputes
    heat->solve();
    benchmark::DoNotOptimize(hm->distance.data());
  }
  setCounters(state, *bm, hm->reached());
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
double seconds(Clock::time_point t0, Clock::time_point t1) { return std::chrono::duration<double>(t1 - t0).count(); }

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
  DijkstraSolver dij(bm->tri);
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
  DijkstraSolver dij(bm->tri);
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
  gr::oracle::VcgGeodesic<float>& vcg = vcgGeodesic(*bm);
  vcg.setSources(sources);
  for (auto _ : state) {
    vcg.compute();
    benchmark::DoNotOptimize(&vcg);
  }
  setCounters(state, *bm, vcg.reached());
  state.counters["sources"] = sources.size();
}

/// The heat method adds a source by solving again (one query with n sources) on the factorised
/// solver (built untimed if the CgalHeat_* benchmarks of this mesh did not run).
void BM_FpsStepCgalHeatQuery(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  gr::oracle::HeatMesh* hm = cgalMesh(state, *bm);
  if (!hm) return;
  const std::vector<int>& sources = fpsSources(*bm);
  auto& heat = bm->heatDirect;
  if (!heat) heat = std::make_unique<gr::oracle::HeatSolver>(*hm, HeatVariant::Direct);
  heat->clearSources();
  for (size_t i = 0; i + 1 < sources.size(); ++i) heat->addSource(sources[i]);
  for (auto _ : state) {
    heat->addSource(sources.back());
    heat->solve();
    benchmark::DoNotOptimize(hm->distance.data());
  }
  heat->clearSources();
  setCounters(state, *bm, hm->reached());
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
  DijkstraSolver dij(bm->tri);
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
  DijkstraSolver dij(bm->tri);
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
    add("Ours_geodesicDistance", BM_OursGeodesicDistance<gr::ExactPropagation::WhereCheaper>, spec, slow);
    add("Dijkstra", BM_Dijkstra, spec);
    add("Vcg_Geodesic", BM_VcgGeodesic, spec, slow);
    add("CgalHeat_BuildQuery", BM_CgalHeatBuildQuery<HeatVariant::Direct>, spec, slow);
    add("CgalHeat_Query", BM_CgalHeatQuery<HeatVariant::Direct>, spec);
    if (!isLarge(spec)) {  // the intrinsic Delaunay variant on 1.6M vertices would double the run time
      add("CgalHeatIdt_BuildQuery", BM_CgalHeatBuildQuery<HeatVariant::IntrinsicDelaunay>, spec);
      add("CgalHeatIdt_Query", BM_CgalHeatQuery<HeatVariant::IntrinsicDelaunay>, spec);
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
  for (const MeshSpec& spec : kSliverMeshes) {
    add("Ours_FastMarcher", BM_OursFastMarcher, spec);
    add("Ours_fastMarching_oneshot", BM_OursOneShot, spec);
    add("Ours_geodesicDistance", BM_OursGeodesicDistance<gr::ExactPropagation::WhereCheaper>, spec);
    add("Ours_geodesicDistance_fronts", BM_OursGeodesicDistance<gr::ExactPropagation::Never>, spec);
    add("Vcg_Geodesic", BM_VcgGeodesic, spec);
    add("Cgal_ShortestPath", BM_CgalShortestPath, spec);
  }
}

}  // namespace

int main(int argc, char** argv) { return gr::bench::runBenchmarks(argc, argv, registerAll); }
