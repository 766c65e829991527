#include "bench/bench_support.h"

#include "core/mesh/subdivide.h"
#include "core/mesh/vcg_mesh.h"
#include "tests/oracles/remesh_oracles.h"

namespace gr::bench {

std::string benchMeshPath(const std::string& file) { return std::string(GR_MESH_DIR) + "/" + file; }

Expected<TriMesh> loadBenchMesh(const std::string& file, int subdivisions) {
  Expected<TriMesh> m = loadTriMesh(benchMeshPath(file));
  if (!m || subdivisions == 0) return m;
  Expected<Subdivision> fine = subdivideMidpoint(*m, subdivisions);  // old vertices keep their indices
  if (!fine) return fine.status();
  return std::move(fine->mesh);
}

oracle::SurfaceMesh* cachedSurfaceMesh(benchmark::State& state, const TriMesh& mesh,
                                       std::unique_ptr<oracle::SurfaceMesh>& slot) {
  if (slot) return slot.get();
  Expected<std::unique_ptr<oracle::SurfaceMesh>> m = oracle::toSurfaceMesh(mesh);
  if (!m) {
    state.SkipWithError(m.status().message.c_str());
    return nullptr;
  }
  slot = std::move(*m);
  return slot.get();
}

std::optional<TriMesh> timeCgalRemeshing(benchmark::State& state, const oracle::SurfaceMesh& input, double edgeLength,
                                         int iterations) {
  std::optional<oracle::SurfaceMesh> out;
  for (auto _ : state) {
    state.PauseTiming();
    oracle::SurfaceMesh m = input;
    state.ResumeTiming();
    oracle::cgalIsotropicRemeshing(m, edgeLength, iterations);
    state.PauseTiming();
    out = std::move(m);  // freeing the output is not timed either
    state.ResumeTiming();
  }
  Expected<TriMesh> tri = oracle::toTriMesh(*out);
  if (!tri) {
    state.SkipWithError(("CGAL output: " + tri.status().message).c_str());
    return std::nullopt;
  }
  return std::move(*tri);
}

int runBenchmarks(int argc, char** argv, void (*registerAll)()) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  registerAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace gr::bench
