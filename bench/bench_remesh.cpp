// Uniform remeshing: ours (farthest-point sampling + geodesic Delaunay, paper §3) against CGAL's
// isotropic remeshing, same process, same meshes, same output vertex count.
//
//   Ours/<mesh>/<target>  gr::remeshSurface (core/remesh/remesh_surface.h) at the uniform filter's
//                         defaults, what the filter runs, without the measures of its log (angles,
//                         Hausdorff: no competitor computes them). Counters engine_ms, sampling_ms,
//                         delaunay_ms, relax_ms: each stage's wall time (RemeshStageTimes).
//   OursNoRelax/...       the same without the relaxation (the paper's triangulation alone).
//   OursSubVertex/...     the same as Ours with FpsParams::subVertexPlacement.
//   MeshLabIsotropic/...  MeshLab 2020.09's "Remeshing: Isotropic Explicit Remeshing" through the
//                         system meshlabserver, script bench/meshlab_isotropic_remeshing.mlx (MeshLab's
//                         defaults, TargetLen calibrated untimed to our vertex count as for CGAL).
//                         Wall time of `xvfb-run -a meshlabserver -i <mesh> -o out.off -s script`
//                         minus the median of 3 runs of the same command without the script (start-up,
//                         plugin loading, reading and writing the mesh): the filter's own time, about.
//                         Small meshes only.
//   Cgal/<mesh>/<target>  CGAL::Polygon_mesh_processing::isotropic_remeshing (gr_oracles:
//                         tests/oracles/remesh_oracles.h) on a Surface_mesh<Epick> copy (copy
//                         untimed), 3 iterations, protect_constraints(false). Target edge length L
//                         calibrated untimed so that its vertex count matches ours: start
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

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "bench/bench_support.h"
#include "core/measure/evaluation.h"
#include "core/mesh/tri_mesh.h"
#include "core/mesh/vcg_mesh.h"
#include "core/remesh/remesh_surface.h"
#include "tests/oracles/remesh_oracles.h"

namespace {

using gr::bench::MeshSpec;
using gr::oracle::SurfaceMesh;

constexpr int kCgalIterations = 3;        ///< isotropic_remeshing's number_of_iterations
constexpr int kCalibrationRuns = 3;       ///< untimed CGAL runs to match the vertex count
constexpr int kCalibrationRunsLarge = 1;  ///< the same on the 1.66M mesh (one CGAL run takes ~40 s)
constexpr double kCalibrationTolerance = 0.01;

// ------------------------------------------------------------------------------------------------
// Meshes

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
  explicit BenchMesh(gr::TriMesh mesh)
      : tri(std::move(mesh)), angles(gr::angleStatistics(tri)), diagonal(tri.boundingBoxDiagonal()) {}
  gr::TriMesh tri;
  gr::AngleStatistics angles;
  double diagonal = 0.0;
  std::unique_ptr<SurfaceMesh> cgal;
};

BenchMesh* getMesh(benchmark::State& state, const MeshSpec& spec) {
  return gr::bench::cachedMesh<BenchMesh>(state, spec);
}

int targetCount(const Case& c, const BenchMesh& bm) {
  return c.count > 0 ? c.count : static_cast<int>(std::lround(c.fraction * bm.tri.vertexCount()));
}

// ------------------------------------------------------------------------------------------------
// Ours

struct Variant {
  bool subVertex = false;                                            ///< FpsParams::subVertexPlacement
  int relaxation = gr::SurfaceRemeshParams().relaxation.iterations;  ///< the filter's default
};

/// gr::remeshSurface, what the uniform filter runs, without the log's measures (which no competitor
/// computes); nullopt after SkipWithError.
std::optional<gr::SurfaceRemeshResult> runOurs(benchmark::State& state, const BenchMesh& bm, int target,
                                               const Variant& variant) {
  gr::SurfaceRemeshParams params;
  params.sampling.targetCount = target;
  params.sampling.subVertexPlacement = variant.subVertex;
  params.relaxation.iterations = variant.relaxation;
  params.measure = false;
  gr::Expected<gr::SurfaceRemeshResult> r = gr::remeshSurface(bm.tri, params);
  if (!r) {
    state.SkipWithError(("remeshSurface: " + r.status().message).c_str());
    return std::nullopt;
  }
  return std::move(*r);
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
  const gr::oracle::TwoSidedDistance both = gr::oracle::twoSidedDistance(out, bm.tri);
  c["hausdorff_pct"] = 100.0 * gr::surfaceDistance(out, bm.tri).max / bm.diagonal;
  c["hausdorff2_pct"] = 100.0 * both.max / bm.diagonal;
  c["rms2_pct"] = 100.0 * both.rms / bm.diagonal;
}

void runOursCase(benchmark::State& state, const Case& c, const Variant& variant) {
  BenchMesh* bm = getMesh(state, c.mesh);
  if (!bm) return;
  const int target = targetCount(c, *bm);
  double engine = 0, sampling = 0, delaunay = 0, relax = 0;
  std::optional<gr::SurfaceRemeshResult> run;
  for (auto _ : state) {
    run = runOurs(state, *bm, target, variant);
    if (!run) return;
    engine += run->times.engine;
    sampling += run->times.sampling;
    delaunay += run->times.triangulation;
    relax += run->times.relaxation;
  }
  const auto perRun = [](double s) { return benchmark::Counter(1e3 * s, benchmark::Counter::kAvgIterations); };
  state.counters["engine_ms"] = perRun(engine);
  state.counters["sampling_ms"] = perRun(sampling);
  state.counters["delaunay_ms"] = perRun(delaunay);
  state.counters["relax_ms"] = perRun(relax);
  state.counters["added"] = run->addedSamples;
  state.counters["repair_rounds"] = run->repairRounds;
  setQualityCounters(state, *bm, run->mesh, target);
}

void BM_Ours(benchmark::State& state, const Case& c) {
  runOursCase(state, c, Variant{});
  if (!state.error_occurred()) oursVertexCount()[c.key()] = static_cast<int>(state.counters["vertices"]);
}
/// The paper's triangulation alone (the filter's Relaxation = 0).
void BM_OursNoRelax(benchmark::State& state, const Case& c) { runOursCase(state, c, Variant{false, 0}); }
/// With FpsParams::subVertexPlacement (the filter's SubVertexPlacement option).
void BM_OursSubVertex(benchmark::State& state, const Case& c) { runOursCase(state, c, Variant{true}); }

/// The vertex count the competitors are matched to: ours (filter defaults), run untimed if its
/// benchmark was filtered out; nullopt after SkipWithError.
std::optional<int> vertexCountToMatch(benchmark::State& state, const BenchMesh& bm, const Case& c) {
  auto found = oursVertexCount().find(c.key());
  if (found == oursVertexCount().end()) {
    std::optional<gr::SurfaceRemeshResult> run = runOurs(state, bm, targetCount(c, bm), Variant{});
    if (!run) return std::nullopt;
    found = oursVertexCount().emplace(c.key(), run->mesh.vertexCount()).first;
  }
  return found->second;
}

// ------------------------------------------------------------------------------------------------
// CGAL isotropic remeshing

void BM_Cgal(benchmark::State& state, const Case& c) {
  BenchMesh* bm = getMesh(state, c.mesh);
  if (!bm) return;
  SurfaceMesh* input = gr::bench::cachedSurfaceMesh(state, bm->tri, bm->cgal);
  if (!input) return;
  const std::optional<int> match = vertexCountToMatch(state, *bm, c);
  if (!match) return;
  const double n = *match;
  // Calibrated once per case (the repetitions reuse it).
  static std::map<std::string, gr::oracle::CgalCalibration> calibrated;
  gr::oracle::CgalCalibration& calibration = calibrated[c.key()];
  if (calibration.runs == 0)
    calibration = gr::oracle::calibrateCgalEdgeLength(
        *input, n, kCgalIterations, c.mesh.subdivisions > 0 ? kCalibrationRunsLarge : kCalibrationRuns,
        kCalibrationTolerance);
  const double length = calibration.edgeLength;
  const int calibrationRuns = calibration.runs;
  const std::optional<gr::TriMesh> tri = gr::bench::timeCgalRemeshing(state, *input, length, kCgalIterations);
  if (!tri) return;
  state.counters["edge_length"] = length;
  state.counters["calibration_runs"] = calibrationRuns;
  setQualityCounters(state, *bm, *tri, static_cast<int>(n));
}

// ------------------------------------------------------------------------------------------------
// MeshLab's isotropic explicit remeshing through the system meshlabserver

/// Wall seconds of a shell command, or a negative value if it failed.
double wallSeconds(const std::string& command) {
  const auto t0 = std::chrono::steady_clock::now();
  const int rc = std::system(command.c_str());
  const auto t1 = std::chrono::steady_clock::now();
  return rc == 0 ? std::chrono::duration<double>(t1 - t0).count() : -1.0;
}

/// bench/meshlab_isotropic_remeshing.mlx with TargetLen set to `length`.
bool writeIsotropicScript(const std::string& path, double length) {
  std::ifstream in(std::string(GR_BENCH_DIR) + "/meshlab_isotropic_remeshing.mlx");
  if (!in) return false;
  std::stringstream text;
  text << in.rdbuf();
  char value[64];
  std::snprintf(value, sizeof value, "%.9g", length);
  const std::string script = std::regex_replace(text.str(), std::regex("name=\"TargetLen\" value=\"[^\"]*\""),
                                                std::string("name=\"TargetLen\" value=\"") + value + "\"");
  std::ofstream(path) << script;
  return true;
}

void BM_MeshLabIsotropic(benchmark::State& state, const Case& c) {
  BenchMesh* bm = getMesh(state, c.mesh);
  if (!bm) return;
  const std::optional<int> match = vertexCountToMatch(state, *bm, c);
  if (!match) return;
  const double n = *match;
  char dirTemplate[] = "/tmp/bench_remesh_XXXXXX";
  if (!mkdtemp(dirTemplate)) {
    state.SkipWithError("mkdtemp failed");
    return;
  }
  const std::string dir = dirTemplate, script = dir + "/script.mlx", out = dir + "/out.off", log = dir + "/log.txt";
  const std::string input = gr::bench::benchMeshPath(c.mesh.file);
  const std::string startup = "xvfb-run -a meshlabserver -i '" + input + "' -o '" + out + "' > '" + log + "' 2>&1";
  const std::string command =
      "xvfb-run -a meshlabserver -i '" + input + "' -o '" + out + "' -s '" + script + "' > '" + log + "' 2>&1";
  // Untimed: the edge length that gives our vertex count, as for CGAL (L from the area, then
  // L *= sqrt(n_obtained / N) until within 2%, at most 4 runs).
  double area = 0.0;
  for (const gr::Tri& t : bm->tri.triangles)
    area += 0.5 * (bm->tri.positions[t[1]] - bm->tri.positions[t[0]])
                      .cross(bm->tri.positions[t[2]] - bm->tri.positions[t[0]])
                      .norm();
  double length = std::sqrt(2.0 * area / (std::sqrt(3.0) * n));
  int calibrationRuns = 0;
  gr::Expected<gr::TriMesh> result = gr::invalidInput("not run");
  for (; calibrationRuns < 4; ++calibrationRuns) {
    if (!writeIsotropicScript(script, length) || wallSeconds(command) < 0) {
      state.SkipWithError(("meshlabserver failed, see " + log).c_str());
      return;
    }
    result = gr::loadTriMesh(out);
    if (!result) {
      state.SkipWithError(("MeshLab output: " + result.status().message).c_str());
      return;
    }
    const double obtained = result->vertexCount();
    if (std::abs(obtained - n) <= 0.02 * n) break;
    length *= std::sqrt(obtained / n);
  }
  std::vector<double> startupRuns;
  for (int i = 0; i < 3; ++i) startupRuns.push_back(wallSeconds(startup));
  std::sort(startupRuns.begin(), startupRuns.end());
  const double startupSeconds = startupRuns[1];
  if (startupSeconds < 0) {
    state.SkipWithError(("meshlabserver (start-up run) failed, see " + log).c_str());
    return;
  }
  for (auto _ : state) {
    const double seconds = wallSeconds(command);
    if (seconds < 0) {
      state.SkipWithError(("meshlabserver failed, see " + log).c_str());
      return;
    }
    state.SetIterationTime(std::max(0.0, seconds - startupSeconds));
  }
  result = gr::loadTriMesh(out);
  if (!result) {
    state.SkipWithError(("MeshLab output: " + result.status().message).c_str());
    return;
  }
  state.counters["edge_length"] = length;
  state.counters["calibration_runs"] = calibrationRuns + 1;
  state.counters["startup_ms"] = 1e3 * startupSeconds;
  setQualityCounters(state, *bm, *result, static_cast<int>(n));
  for (const std::string& f : {script, out, log}) std::remove(f.c_str());
  rmdir(dir.c_str());
}

// ------------------------------------------------------------------------------------------------

/// Times are CPU time. Each small case runs 3 repetitions of at least 0.2 s (the report takes the
/// median); the 1.66M-vertex case runs once.
constexpr int kRepetitions = 3;
constexpr double kMinTime = 0.2;

void add(const char* family, void (*fn)(benchmark::State&, const Case&), const Case& c) {
  auto* b = benchmark::RegisterBenchmark((std::string(family) + "/" + c.key()).c_str(), fn, c);
  b->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();  // the engine's helper thread counts too
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
    add("OursNoRelax", BM_OursNoRelax, c);
    if (c.mesh.subdivisions == 0) add("OursSubVertex", BM_OursSubVertex, c);
    if (c.mesh.subdivisions == 0)  // one meshlabserver process per run: wall time, 3 single runs
      benchmark::RegisterBenchmark(("MeshLabIsotropic/" + c.key()).c_str(), BM_MeshLabIsotropic, c)
          ->Unit(benchmark::kMillisecond)
          ->UseManualTime()
          ->Iterations(1)
          ->Repetitions(kRepetitions)
          ->DisplayAggregatesOnly(true);
  }
}

}  // namespace

int main(int argc, char** argv) { return gr::bench::runBenchmarks(argc, argv, registerAll); }
