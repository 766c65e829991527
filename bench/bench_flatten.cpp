// Flattening benchmarks (issue 19; the atlas and its competitors come with it):
//   Lle/<patch>/<B>   gr::flattenGeodesicLle with B base points and the defaults otherwise: the
//                     sampling, B fronts, the LLE eigenproblem, the Nyström extension, the fold
//                     check (and a repair if one is needed).
// Patches (generated once per process, untimed): plane10k, a jittered planar grid of 100 x 100
// vertices; cap10k, a 60-degree spherical cap of 100 x 100 vertices (not developable).
// Time: process CPU time. Counters: Sander's L2 stretch is in the tests; here `folded` (UV faces
// untangled after the Nyström step) and `tutte` (1 if the map fell back to Tutte's embedding).
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "bench/bench_support.h"
#include "core/flatten/geodesic_lle.h"
#include "tests/support/test_support.h"

namespace {

const gr::TriMesh& plane10k() {
  static const gr::TriMesh m = gr::test::planeGrid(99, 1.0, 0.2, 1);
  return m;
}

const gr::TriMesh& cap10k() {
  static const gr::TriMesh m = [] {
    gr::TriMesh flat = gr::test::planeGrid(99);
    for (gr::Vec3& p : flat.positions) {
      const double x = 2.0 * p.x() - 1.0, y = 2.0 * p.y() - 1.0;
      const double phi = std::sqrt(x * x + y * y) / std::sqrt(2.0) * 3.14159265358979323846 / 3.0;
      const double theta = std::atan2(y, x);
      p = gr::Vec3(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi));
    }
    return gr::buildTriMesh(flat.positions, flat.triangles).value();
  }();
  return m;
}

void lle(benchmark::State& state, const gr::TriMesh& (*patch)(), int base) {
  const gr::TriMesh& mesh = patch();
  gr::LleFlatteningParams params;
  params.basePoints = base;
  int folded = 0;
  bool tutte = false;
  for (auto _ : state) {
    const gr::Expected<gr::LleFlatteningResult> r = gr::flattenGeodesicLle(mesh, params);
    if (!r) return state.SkipWithError(r.status().message.c_str());
    folded = r->foldedBeforeRepair;
    tutte = r->tutte;
  }
  state.counters["vertices"] = mesh.vertexCount();
  state.counters["folded"] = folded;
  state.counters["tutte"] = tutte;
}

void registerAll() {
  for (int base : {50, 100, 200}) {
    benchmark::RegisterBenchmark(("Lle/plane10k/" + std::to_string(base)).c_str(), lle, plane10k, base)
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime();
    benchmark::RegisterBenchmark(("Lle/cap10k/" + std::to_string(base)).c_str(), lle, cap10k, base)
        ->Unit(benchmark::kMillisecond)
        ->MeasureProcessCPUTime();
  }
}

}  // namespace

int main(int argc, char** argv) { return gr::bench::runBenchmarks(argc, argv, registerAll); }
