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
//   built once, untimed.
//
// Meshes: fandisk (6,475 vertices), bunny00 (37,706), armadillo (26,002) from libcgal-demo, and two
// meshes made in the set-up by three 1-to-4 midpoint subdivisions (gr::subdivideMidpoint):
// fandisk_large_sub3 (fandisk_large.off, 15,843 -> 1,013,826 vertices: the 1M target) and
// armadillo_sub3 (1,664,002 vertices, as in bench_fast_marching). A filter that excludes a mesh
// never builds it: e.g. --benchmark_filter='_sub3/', '^Ours', '-sub3'.
// Times are CPU time (single-threaded code); counter vertices/s = mesh vertices per second.

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/curvature.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include "bench/bench_support.h"
#include "core/field/curvature.h"
#include "core/mesh/tri_mesh.h"
#include "core/mesh/vcg_mesh.h"

namespace {

// vcglib: what PrincipalDirections and PrincipalDirectionsNormalCycle need (FF and VF adjacency,
// normals, curvature and its directions), float like MeshLab's CMeshO.
class CVertex;
class CFace;
struct CUsedTypes : public vcg::UsedTypes<vcg::Use<CVertex>::AsVertexType, vcg::Use<CFace>::AsFaceType> {};
class CVertex : public vcg::Vertex<CUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::VFAdj,
                                   vcg::vertex::Curvaturef, vcg::vertex::CurvatureDirf, vcg::vertex::BitFlags> {};
class CFace : public vcg::Face<CUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::FFAdj,
                               vcg::face::VFAdj, vcg::face::BitFlags> {};
class CMesh : public vcg::tri::TriMesh<std::vector<CVertex>, std::vector<CFace>> {};

struct MeshSpec {
  const char* name;
  const char* file;
  int subdivisions;
};

const MeshSpec kMeshes[] = {
    {"fandisk", "fandisk.off", 0},
    {"bunny00", "bunny00.off", 0},
    {"armadillo", "armadillo.off", 0},
    {"fandisk_large_sub3", "fandisk_large.off", 3},
    {"armadillo_sub3", "armadillo.off", 3},
};

/// A mesh and its vcglib copy, built once per process (never timed).
struct BenchMesh {
  gr::TriMesh tri;
  double meanEdge = 0.0;
  std::unique_ptr<CMesh> vcg;
};

BenchMesh* getMesh(benchmark::State& state, const MeshSpec& spec) {
  static std::map<std::string, std::unique_ptr<BenchMesh>> cache;
  auto& slot = cache[spec.name];
  if (slot) return slot.get();
  gr::Expected<gr::TriMesh> m = gr::bench::loadBenchMesh(spec.file, spec.subdivisions);
  if (!m) {
    state.SkipWithError(("mesh " + std::string(spec.name) + ": " + m.status().message).c_str());
    return nullptr;
  }
  slot = std::make_unique<BenchMesh>();
  slot->tri = std::move(*m);
  slot->meanEdge = slot->tri.meanEdgeLength();
  return slot.get();
}

CMesh& vcgMesh(BenchMesh& bm) {
  if (bm.vcg) return *bm.vcg;
  auto m = std::make_unique<CMesh>();
  const gr::TriMesh& t = bm.tri;
  vcg::tri::Allocator<CMesh>::AddVertices(*m, t.vertexCount());
  for (int v = 0; v < t.vertexCount(); ++v)
    m->vert[v].P() = vcg::Point3f(float(t.positions[v].x()), float(t.positions[v].y()), float(t.positions[v].z()));
  vcg::tri::Allocator<CMesh>::AddFaces(*m, t.faceCount());
  for (int f = 0; f < t.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) m->face[f].V(k) = &m->vert[t.triangles[f][k]];
  vcg::tri::UpdateTopology<CMesh>::FaceFace(*m);
  vcg::tri::UpdateTopology<CMesh>::VertexFace(*m);
  vcg::tri::UpdateNormal<CMesh>::PerVertexNormalizedPerFace(*m);
  bm.vcg = std::move(m);
  return *bm.vcg;
}

void setRate(benchmark::State& state, int vertices) {
  state.counters["vertices"] = vertices;
  state.counters["vertices/s"] =
      benchmark::Counter(double(vertices) * state.iterations(), benchmark::Counter::kIsRate);
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
  CMesh& m = vcgMesh(*bm);
  for (auto _ : state) {
    vcg::tri::UpdateCurvature<CMesh>::PrincipalDirectionsNormalCycle(m);
    benchmark::DoNotOptimize(m.vert[0].K1());
  }
  setRate(state, bm->tri.vertexCount());
}

void BM_VcgTaubin(benchmark::State& state, const MeshSpec& spec) {
  BenchMesh* bm = getMesh(state, spec);
  if (!bm) return;
  CMesh& m = vcgMesh(*bm);
  for (auto _ : state) {
    vcg::tri::UpdateCurvature<CMesh>::PrincipalDirections(m);
    benchmark::DoNotOptimize(m.vert[0].K1());
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

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  registerAll();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
