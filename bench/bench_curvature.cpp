// Per-vertex curvature: ours (gr::totalCurvature, Cohen-Steiner–Morvan tensor over a ball, paper
// §3.4) against the two 1-ring estimators of vcglib that MeshLab's "Compute curvature principal
// directions" offers, same process, same meshes.
//
//   Ours/<mesh>/<radius>   gr::totalCurvature(mesh, {radius}): per-vertex masses + vertex adjacency
//                          + one ball per vertex + closed-form 3x3 eigen-decomposition, all timed.
//                          Radii: `default` (0 = the mean edge length h), `ring` (1e-9 h: each
//                          vertex's 1-ring), `2h`, `3h`. Counters: `ball` = vertices per ball on
//                          average, `radius_h` = the radius used / h.
//   Vcg_NormalCycle/<mesh> vcg::tri::UpdateCurvature<M>::PrincipalDirectionsNormalCycle(m): the
//                          normal-cycle tensor over the edges at each vertex (1-ring, no area
//                          normalisation, beta = asin, so |beta| <= 90 degrees); MeshLab's "Normal
//                          Cycles" option.
//   Vcg_Taubin/<mesh>      vcg::tri::UpdateCurvature<M>::PrincipalDirections(m): Taubin 1995 over
//                          the 1-ring (with its per-vertex normal update); MeshLab's default option.
//   vcglib runs on a float mesh, as MeshLab's CMeshO, with FF and VF adjacency and per-vertex normals
//   built once, untimed: gr_oracles' VcgCurvature (tests/oracles/curvature_oracles.h).
//
// Meshes: fandisk (6,475 vertices), bunny00 (37,706), armadillo (26,002) from libcgal-demo, and two
// meshes made in the set-up by three 1-to-4 midpoint subdivisions (gr::subdivideMidpoint):
// fandisk_large_sub3 (fandisk_large.off, 15,843 -> 1,013,826 vertices: the 1M target) and
// armadillo_sub3 (1,664,002 vertices, as in bench_fast_marching). A filter that excludes a mesh
// never builds it: e.g. --benchmark_filter='_sub3/', '^Ours', '-sub3'.
// Times are CPU time (single-threaded code); counter vertices/s = mesh vertices per second.

#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <utility>

#include "bench/bench_support.h"
#include "core/field/curvature.h"
#include "core/mesh/tri_mesh.h"
#include "tests/oracles/curvature_oracles.h"

namespace {

using gr::bench::MeshSpec;

const MeshSpec kMeshes[] = {
    {"fandisk", "fandisk.off", 0},          {"bunny00", "bunny00.off", 0},
    {"armadillo", "armadillo.off", 0},      {"fandisk_large_sub3", "fandisk_large.off", 3},
    {"armadillo_sub3", "armadillo.off", 3},
};

/// A mesh and its vcglib copy (gr_oracles' VcgCurvature), built once per process (never timed).
struct BenchMesh {
  explicit BenchMesh(gr::TriMesh mesh) : tri(std::move(mesh)), meanEdge(tri.meanEdgeLength()) {}
  gr::TriMesh tri;
  double meanEdge = 0.0;
  std::unique_ptr<gr::oracle::VcgCurvature> vcg;
};

BenchMesh* getMesh(benchmark::State& state, const MeshSpec& spec) {
  return gr::bench::cachedMesh<BenchMesh>(state, spec);
}

gr::oracle::VcgCurvature& vcgCurvature(BenchMesh& bm) {
  if (!bm.vcg) bm.vcg = std::make_unique<gr::oracle::VcgCurvature>(bm.tri);
  return *bm.vcg;
}

void setRate(benchmark::State& state, int vertices) {
  state.counters["vertices"] = vertices;
  state.counters["vertices/s"] = benchmark::Counter(double(vertices) * state.iterations(), benchmark::Counter::kIsRate);
}

// ------------------------------------------------------------------------------------------------

struct RadiusSpec {
  const char* label;
  double inEdges;  ///< radius / mean edge length; 0 = the default (which is 1)
};
const RadiusSpec kRadii[] = {{"default", 0.0}, {"ring", 1e-9}, {"2h", 2.0}, {"3h", 3.0}};

void BM_Ours(benchmark::State& state, const MeshSpec& spec, const RadiusSpec& radius) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  gr::CurvatureParams params;
  params.radius = radius.inEdges * bm->meanEdge;
  gr::CurvatureResult last;
  for (auto _ : state) {
    gr::Expected<gr::CurvatureResult> r = gr::totalCurvature(bm->tri, params);
    if (!r) {
      state.SkipWithError(r.status().message.c_str());
      return;
    }
    benchmark::DoNotOptimize(r->tau.data());
    state.PauseTiming();
    last = std::move(*r);  // freeing the previous result is not timed
    state.ResumeTiming();
  }
  setRate(state, bm->tri.vertexCount());
  state.counters["ball"] = last.meanNeighbourhoodSize;
  state.counters["radius_h"] = last.radius / bm->meanEdge;
}

void BM_VcgNormalCycle(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  gr::oracle::VcgCurvature& vcg = vcgCurvature(*bm);
  for (auto _ : state) {
    vcg.normalCycle();
    benchmark::DoNotOptimize(vcg.k1(0));
  }
  setRate(state, bm->tri.vertexCount());
}

void BM_VcgTaubin(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  gr::oracle::VcgCurvature& vcg = vcgCurvature(*bm);
  for (auto _ : state) {
    vcg.taubin();
    benchmark::DoNotOptimize(vcg.k1(0));
  }
  setRate(state, bm->tri.vertexCount());
}

// ------------------------------------------------------------------------------------------------

/// CPU time; 3 repetitions of at least 0.2 s each (the report takes the median).
constexpr int kRepetitions = 3;
constexpr double kMinTime = 0.2;

template <class Fn, class... Args>
void add(const std::string& name, Fn fn, Args... args) {
  benchmark::RegisterBenchmark(name.c_str(), fn, args...)
      ->Unit(benchmark::kMillisecond)
      ->MinTime(kMinTime)
      ->Repetitions(kRepetitions)
      ->DisplayAggregatesOnly(true);
}

void registerAll() {
  for (const MeshSpec& spec : kMeshes) {
    for (const RadiusSpec& radius : kRadii)
      add(std::string("Ours/") + spec.name + "/" + radius.label, BM_Ours, spec, radius);
    add(std::string("Vcg_NormalCycle/") + spec.name, BM_VcgNormalCycle, spec);
    add(std::string("Vcg_Taubin/") + spec.name, BM_VcgTaubin, spec);
  }
}

}  // namespace

int main(int argc, char** argv) { return gr::bench::runBenchmarks(argc, argv, registerAll); }
