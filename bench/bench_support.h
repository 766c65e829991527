// Benchmark plumbing the benchmark binaries share: the test meshes (optionally subdivided), cached
// once per process; the CGAL copy of a mesh, cached, or the benchmark skipped when CGAL rejects it;
// and main(). The competitors themselves (Dijkstra, vcglib, CGAL) live in tests/oracles
// (gr_oracles). Nothing here is timed unless a benchmark says so.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"
#include "tests/oracles/cgal_mesh.h"

namespace gr::bench {

/// A mesh of GR_MESH_DIR ("bunny00.off"), after `subdivisions` 1-to-4 midpoint subdivisions
/// (gr::subdivideMidpoint: old vertices keep their indices).
Expected<TriMesh> loadBenchMesh(const std::string& file, int subdivisions = 0);

/// The path of a mesh of GR_MESH_DIR.
std::string benchMeshPath(const std::string& file);

/// A benchmark mesh: its name in the benchmarks' names, its file in GR_MESH_DIR, and how many
/// 1-to-4 midpoint subdivisions make it from that file.
struct MeshSpec {
  const char* name;
  const char* file;
  int subdivisions;
};

/// The `T` of mesh `name`, made once per process as T(loadBenchMesh(file, subdivisions)) (never
/// timed); a filter that excludes every benchmark of a mesh never loads it. nullptr after marking
/// the benchmark skipped when the mesh cannot be loaded.
template <class T>
T* cachedMesh(benchmark::State& state, const std::string& name, const std::string& file, int subdivisions = 0) {
  static std::map<std::string, std::unique_ptr<T>> cache;
  std::unique_ptr<T>& slot = cache[name];
  if (slot) return slot.get();
  Expected<TriMesh> m = loadBenchMesh(file, subdivisions);
  if (!m) {
    state.SkipWithError(("mesh " + name + ": " + m.status().message).c_str());
    return nullptr;
  }
  slot = std::make_unique<T>(std::move(*m));
  return slot.get();
}

template <class T>
T* cachedMesh(benchmark::State& state, const MeshSpec& spec) {
  return cachedMesh<T>(state, spec.name, spec.file, spec.subdivisions);
}

/// `slot`, filled with oracle::toSurfaceMesh(mesh) on first use (never timed); nullptr after
/// marking the benchmark skipped when CGAL rejects the mesh.
oracle::SurfaceMesh* cachedSurfaceMesh(benchmark::State& state, const TriMesh& mesh,
                                       std::unique_ptr<oracle::SurfaceMesh>& slot);

/// CGAL's isotropic remeshing (oracle::cgalIsotropicRemeshing, `iterations` rounds towards
/// `edgeLength`) timed in the benchmark loop, each iteration on a fresh copy of `input` (making
/// the copy and freeing the output are not timed). The last output as a TriMesh; nullopt after
/// marking the benchmark skipped when it cannot be converted.
std::optional<TriMesh> timeCgalRemeshing(benchmark::State& state, const oracle::SurfaceMesh& input, double edgeLength,
                                         int iterations);

/// The whole main() of a benchmark binary: Google Benchmark's arguments, then `registerAll()`,
/// then the benchmarks the filter selects.
int runBenchmarks(int argc, char** argv, void (*registerAll)());

}  // namespace gr::bench
