// Uniform remeshing: ours (farthest-point sampling + geodesic Delaunay, paper §3) against CGAL's
// isotropic remeshing, same process, same meshes, same output vertex count.
//
//   Ours/<mesh>/<target>  FastMarcher construction + farthestPointSampling + geodesicDelaunay on
//                         one engine, as filter_geodesic_remesh/uniform_remesh_filter.cpp runs them.
//                         Counters engine_ms, sampling_ms, delaunay_ms: each stage's thread CPU time.
//   Cgal/<mesh>/<target>  CGAL::Polygon_mesh_processing::isotropic_remeshing on a Surface_mesh<Epick>
//                         copy (copy untimed), 3 iterations, protect_constraints(false). Target edge
//                         length L calibrated untimed so that its vertex count matches ours: start
//                         from L = sqrt(2 A / (sqrt(3) N)), then up to 3 runs each followed by
//                         L *= sqrt(n_obtained / N) (stop when within 1%); on the 1.66M mesh one
//                         such run only (each takes about 40 s).
//
// Targets: 10% and 30% of the input vertex count on fandisk, bunny00, armadillo (3 repetitions);
// 100,000 samples on armadillo subdivided 1-to-4 three times (1,664,002 vertices; one run each,
// about 2 minutes with CGAL's calibration). A filter that excludes a mesh never builds it; select
// with --benchmark_filter, e.g. '/bunny00/', '^Ours', '-sub3' (all but the 1.66M mesh).
// Quality counters of each output (never timed): angle_std, angle_min (degrees), lt30_pct (% of
// triangles with an angle under 30 degrees), hausdorff_pct (one-sided Hausdorff distance output ->
// input, % of the input's bounding-box diagonal), vertices, faces, added (ours: samples added by the
// repair); in_* the same angle statistics of the input mesh.

#include <benchmark/benchmark.h>

#include <time.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include "core/evaluation.h"
#include "core/farthest_point_sampling.h"
#include "core/fast_marching.h"
#include "core/geodesic_delaunay.h"
#include "core/metric.h"
#include "core/tri_mesh.h"
#include "core/subdivide.h"
#include "core/vcg_mesh.h"

namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using SmVertex = SurfaceMesh::Vertex_index;

constexpr int kCgalIterations = 3;   ///< isotropic_remeshing's number_of_iterations
constexpr int kCalibrationRuns = 3;  ///< untimed CGAL runs to match the vertex count
constexpr int kCalibrationRunsLarge = 1;  ///< the same on the 1.66M mesh (one CGAL run takes ~40 s)
constexpr double kCalibrationTolerance = 0.01;

/// CPU time of the calling thread, in seconds (the machine may be shared).
double threadSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

// ------------------------------------------------------------------------------------------------
// Meshes

struct MeshSpec {
  const char* name;
  const char* file;
  int subdivisions;
};

/// One remeshing problem: a mesh and a target sample count (fraction of its vertices, or absolute).
struct Case {
  MeshSpec mesh;
  const char* label;  ///< the last part of the benchmark name
  double fraction;    ///< of the input vertex count; used when count == 0
  int count;
  std::string key() const { return std::string(mesh.name) + "/" + label; }
};

const Case kCases[] = {
    {{"fandisk", "fandisk.off", 0}, "10pct", 0.10, 0},
    {{"fandisk", "fandisk.off", 0}, "30pct", 0.30, 0},
    {{"bunny00", "bunny00.off", 0}, "10pct", 0.10, 0},
    {{"bunny00", "bunny00.off", 0}, "30pct", 0.30, 0},
    {{"armadillo", "armadillo.off", 0}, "10pct", 0.10, 0},
    {{"armadillo", "armadillo.off", 0}, "30pct", 0.30, 0},
    {{"armadillo_sub3", "armadillo.off", 3}, "100k", 0.0, 100000},
};

/// A mesh, its statistics and its CGAL copy, built once per process (never timed).
struct BenchMesh {
  gr::TriMesh tri;
  gr::AngleStatistics angles;
  double diagonal = 0.0;
  std::unique_ptr<SurfaceMesh> cgal;
};

BenchMesh* getMesh(benchmark::State& state, const MeshSpec& spec) {
  static std::map<std::string, std::unique_ptr<BenchMesh>> cache;
  auto& slot = cache[spec.name];
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
  slot->angles = gr::angleStatistics(slot->tri);
  slot->diagonal = slot->tri.boundingBoxDiagonal();
  return slot.get();
}

SurfaceMesh* cgalMesh(benchmark::State& state, BenchMesh& bm) {
  if (bm.cgal) return bm.cgal.get();
  auto m = std::make_unique<SurfaceMesh>();
  for (const gr::Vec3& p : bm.tri.positions) m->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  for (int f = 0; f < bm.tri.faceCount(); ++f) {
    const gr::Tri& t = bm.tri.triangles[f];
    if (m->add_face(SmVertex(t[0]), SmVertex(t[1]), SmVertex(t[2])) == SurfaceMesh::null_face()) {
      state.SkipWithError(("CGAL Surface_mesh rejects face " + std::to_string(f)).c_str());
      return nullptr;
    }
  }
  bm.cgal = std::move(m);
  return bm.cgal.get();
}

int targetCount(const Case& c, const BenchMesh& bm) {
  return c.count > 0 ? c.count : static_cast<int>(std::lround(c.fraction * bm.tri.vertexCount()));
}

// ------------------------------------------------------------------------------------------------
// Ours

struct OursRun {
  gr::DelaunayResult result;
  double engineSeconds = 0, samplingSeconds = 0, delaunaySeconds = 0;
};

/// The filter's pipeline on a fresh engine; nullopt after SkipWithError.
std::optional<OursRun> runOurs(benchmark::State& state, const BenchMesh& bm, int target, bool subVertex) {
  const gr::Metric metric = gr::Metric::uniform();
  gr::FpsParams params;
  params.targetCount = target;
  params.subVertexPlacement = subVertex;
  OursRun run;
  const double t0 = threadSeconds();
  gr::FastMarcher marcher(bm.tri, metric);
  const double t1 = threadSeconds();
  gr::Expected<gr::FpsResult> s = gr::farthestPointSampling(marcher, params);
  const double t2 = threadSeconds();
  if (!s) {
    state.SkipWithError(("sampling: " + s.status().message).c_str());
    return std::nullopt;
  }
  gr::Expected<gr::DelaunayResult> d = gr::geodesicDelaunay(marcher, std::move(s->points));
  const double t3 = threadSeconds();
  if (!d) {
    state.SkipWithError(("triangulation: " + d.status().message).c_str());
    return std::nullopt;
  }
  run.result = std::move(*d);
  run.engineSeconds = t1 - t0;
  run.samplingSeconds = t2 - t1;
  run.delaunaySeconds = t3 - t2;
  return run;
}

/// Our output vertex count per case: the count CGAL is calibrated to.
std::map<std::string, int>& oursVertexCount() {
  static std::map<std::string, int> counts;
  return counts;
}

void setQualityCounters(benchmark::State& state, const BenchMesh& bm, const gr::TriMesh& out, int target) {
  const gr::AngleStatistics a = gr::angleStatistics(out);
  auto& c = state.counters;
  c["vertices_in"] = bm.tri.vertexCount();
  c["target"] = target;
  c["vertices"] = out.vertexCount();
  c["faces"] = out.faceCount();
  c["angle_std"] = a.stdDegrees;
  c["angle_min"] = a.minDegrees;
  c["lt30_pct"] = 100.0 * a.shareMinBelow30;
  c["in_angle_std"] = bm.angles.stdDegrees;
  c["in_angle_min"] = bm.angles.minDegrees;
  c["in_lt30_pct"] = 100.0 * bm.angles.shareMinBelow30;
  // One-sided (output to input), and two-sided with the RMS over both directions' samples.
  const gr::SurfaceDistance there = gr::surfaceDistance(out, bm.tri), back = gr::surfaceDistance(bm.tri, out);
  c["hausdorff_pct"] = 100.0 * there.max / bm.diagonal;
  c["hausdorff2_pct"] = 100.0 * std::max(there.max, back.max) / bm.diagonal;
  c["rms2_pct"] = 100.0 * std::sqrt(0.5 * (there.rms * there.rms + back.rms * back.rms)) / bm.diagonal;
}

void runOursCase(benchmark::State& state, const Case& c, bool subVertex) {
  BenchMesh* bm = getMesh(state, c.mesh);
  if (!bm) return;
  const int target = targetCount(c, *bm);
  double engine = 0, sampling = 0, delaunay = 0;
  std::optional<OursRun> run;
  for (auto _ : state) {
    run = runOurs(state, *bm, target, subVertex);
    if (!run) return;
    engine += run->engineSeconds;
    sampling += run->samplingSeconds;
    delaunay += run->delaunaySeconds;
  }
  const auto perRun = [](double s) { return benchmark::Counter(1e3 * s, benchmark::Counter::kAvgIterations); };
  state.counters["engine_ms"] = perRun(engine);
  state.counters["sampling_ms"] = perRun(sampling);
  state.counters["delaunay_ms"] = perRun(delaunay);
  state.counters["added"] = run->result.addedSamples;
  state.counters["repair_rounds"] = run->result.repairRounds;
  setQualityCounters(state, *bm, run->result.mesh, target);
  if (!subVertex) oursVertexCount()[c.key()] = run->result.mesh.vertexCount();
}

void BM_Ours(benchmark::State& state, const Case& c) { runOursCase(state, c, false); }
/// The same with FpsParams::subVertexPlacement (the filter's SubVertexPlacement option).
void BM_OursSubVertex(benchmark::State& state, const Case& c) { runOursCase(state, c, true); }

// ------------------------------------------------------------------------------------------------
// CGAL isotropic remeshing

void remeshCgal(SurfaceMesh& m, double edgeLength) {
  PMP::isotropic_remeshing(faces(m), edgeLength, m,
                           CGAL::parameters::number_of_iterations(kCgalIterations).protect_constraints(false));
}

gr::Expected<gr::TriMesh> toTriMesh(SurfaceMesh& m) {
  m.collect_garbage();
  std::vector<gr::Vec3> positions;
  positions.reserve(m.number_of_vertices());
  for (SmVertex v : m.vertices()) {
    const Kernel::Point_3& p = m.point(v);
    positions.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<gr::Tri> triangles;
  triangles.reserve(m.number_of_faces());
  for (auto f : m.faces()) {
    gr::Tri t{};
    int k = 0;
    for (SmVertex v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++ % 3] = static_cast<int>(v.idx());
    triangles.push_back(t);
  }
  return gr::buildTriMesh(std::move(positions), std::move(triangles));
}

void BM_Cgal(benchmark::State& state, const Case& c) {
  BenchMesh* bm = getMesh(state, c.mesh);
  if (!bm) return;
  SurfaceMesh* input = cgalMesh(state, *bm);
  if (!input) return;
  // The vertex count to match: ours, run untimed if its benchmark was filtered out.
  auto found = oursVertexCount().find(c.key());
  if (found == oursVertexCount().end()) {
    std::optional<OursRun> run = runOurs(state, *bm, targetCount(c, *bm), false);
    if (!run) return;
    found = oursVertexCount().emplace(c.key(), run->result.mesh.vertexCount()).first;
  }
  const double n = found->second;
  // Calibrated once per case (the repetitions reuse it).
  static std::map<std::string, std::pair<double, int>> calibrated;  // length, runs
  auto& [length, calibrationRuns] = calibrated[c.key()];
  if (calibrationRuns == 0) {
    length = std::sqrt(2.0 * PMP::area(*input) / (std::sqrt(3.0) * n));
    const int maxRuns = c.mesh.subdivisions > 0 ? kCalibrationRunsLarge : kCalibrationRuns;
    while (calibrationRuns < maxRuns) {
      SurfaceMesh m = *input;
      remeshCgal(m, length);
      ++calibrationRuns;
      const double obtained = m.number_of_vertices();
      if (std::abs(obtained / n - 1.0) <= kCalibrationTolerance) break;
      length *= std::sqrt(obtained / n);
    }
  }
  std::optional<SurfaceMesh> out;
  for (auto _ : state) {
    state.PauseTiming();
    SurfaceMesh m = *input;
    state.ResumeTiming();
    remeshCgal(m, length);
    state.PauseTiming();
    out = std::move(m);  // freeing the output is not timed either
    state.ResumeTiming();
  }
  gr::Expected<gr::TriMesh> tri = toTriMesh(*out);
  if (!tri) {
    state.SkipWithError(("CGAL output: " + tri.status().message).c_str());
    return;
  }
  state.counters["edge_length"] = length;
  state.counters["calibration_runs"] = calibrationRuns;
  setQualityCounters(state, *bm, *tri, static_cast<int>(n));
}

// ------------------------------------------------------------------------------------------------

/// Times are CPU time. Each small case runs 3 repetitions of at least 0.2 s (the report takes the
/// median); the 1.66M-vertex case runs once.
constexpr int kRepetitions = 3;
constexpr double kMinTime = 0.2;

void add(const char* family, void (*fn)(benchmark::State&, const Case&), const Case& c) {
  auto* b = benchmark::RegisterBenchmark((std::string(family) + "/" + c.key()).c_str(), fn, c);
  b->Unit(benchmark::kMillisecond);
  if (c.mesh.subdivisions > 0) {
    b->Iterations(1);
    return;
  }
  b->MinTime(kMinTime)->Repetitions(kRepetitions)->DisplayAggregatesOnly(true);
}

void registerAll() {
  for (const Case& c : kCases) {
    add("Ours", BM_Ours, c);  // before Cgal: it records the vertex count CGAL is calibrated to
    add("Cgal", BM_Cgal, c);
    if (c.mesh.subdivisions == 0) add("OursSubVertex", BM_OursSubVertex, c);
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
