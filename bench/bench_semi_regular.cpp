// Semi-regular remeshing benchmarks (issue 21):
//   SemiRegular/<mesh>      gr::semiRegularRemesh as the filter runs it (the base, the cut, the
//                           geodesic barycentric maps, the subdivision mapped back, the relaxation
//                           and the log's Hausdorff distance). Process CPU time.
//   MeshLabIsoParametrization/<mesh>  MeshLab 2020.09's "Iso Parametrization: Main" (its defaults:
//                           an abstract domain of 150-200 faces) then "Iso Parametrization
//                           Remeshing" (sampling rate 10) through the system meshlabserver
//                           (xvfb-run, wall time of the whole process); its remesh, the current
//                           layer, is saved and judged as ours.
// Meshes: bunny00 (500 base vertices, 3 levels: the filter's defaults), armadillo (the same), and
// armadillo subdivided three times (1,664,002 vertices; 5,000 base vertices, 3 levels; ours only,
// one iteration). Counters, measured the same way on both outputs: vertices, faces, holes
// (boundary loops; the inputs are closed), vertices of valence other than 6 (subdivision
// connectivity), two-sided Hausdorff distance (% of the diagonal, gr::surfaceDistance both ways)
// and smallest angle.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "core/measure/evaluation.h"
#include "core/mesh/vcg_mesh.h"
#include "core/param/semi_regular.h"

namespace {

struct Case {
  const char* name;
  const char* file;
  int subdivisions;
  int baseVertices;
};

const Case kCases[] = {{"bunny00", "bunny00.off", 0, 500},
                       {"armadillo", "armadillo.off", 0, 500},
                       {"armadillo_sub3", "armadillo.off", 3, 5000}};

void setCounters(benchmark::State& state, const gr::TriMesh& out, const gr::TriMesh& input) {
  std::vector<std::set<int>> neighbours(out.vertexCount());
  for (const gr::Tri& t : out.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbours[t[k]].insert(t[(k + 1) % 3]);
      neighbours[t[(k + 1) % 3]].insert(t[k]);
    }
  int irregular = 0;
  for (const auto& n : neighbours) irregular += n.size() != 6;
  const double diagonal = input.boundingBoxDiagonal();
  state.counters["vertices"] = out.vertexCount();
  state.counters["faces"] = out.faceCount();
  state.counters["holes"] = out.topology.boundaryLoops;
  state.counters["not_valence_6"] = irregular;
  state.counters["hausdorff_pct"] =
      100.0 * std::max(gr::surfaceDistance(out, input).max, gr::surfaceDistance(input, out).max) / diagonal;
  state.counters["min_angle"] = gr::angleStatistics(out).minDegrees;
}

void BM_SemiRegular(benchmark::State& state, const Case& c) {
  const gr::TriMesh* input = gr::bench::cachedMesh<gr::TriMesh>(state, c.name, c.file, c.subdivisions);
  if (input == nullptr) return;
  gr::SemiRegularParams p;
  p.base.baseVertices = c.baseVertices;
  gr::Expected<gr::SemiRegularResult> r = gr::invalidInput("not run");
  for (auto _ : state) {
    r = gr::semiRegularRemesh(*input, p);
    if (!r) return state.SkipWithError(r.status().message.c_str());
  }
  state.counters["base_vertices"] = r->baseVertices;
  setCounters(state, r->mesh, *input);
}

void BM_MeshLabIsoParametrization(benchmark::State& state, const Case& c) {
  const gr::TriMesh* input = gr::bench::cachedMesh<gr::TriMesh>(state, c.name, c.file, c.subdivisions);
  if (input == nullptr) return;
  char dirTemplate[] = "/tmp/bench_iso_XXXXXX";
  if (!mkdtemp(dirTemplate)) return state.SkipWithError("mkdtemp failed");
  const std::string dir = dirTemplate, script = dir + "/iso.mlx", out = dir + "/out.ply", log = dir + "/log.txt";
  std::ofstream(script) << "<!DOCTYPE FilterScript>\n<FilterScript>\n"
                           " <filter name=\"Iso Parametrization: Main\">\n"
                           "  <Param type=\"RichInt\" name=\"targetAbstractMinFaceNum\" value=\"150\"/>\n"
                           "  <Param type=\"RichInt\" name=\"targetAbstractMaxFaceNum\" value=\"200\"/>\n"
                           "  <Param type=\"RichEnum\" name=\"stopCriteria\" value=\"1\" enum_cardinality=\"4\" "
                           "enum_val0=\"Best Heuristic\" enum_val1=\"Area + Angle\" enum_val2=\"Regularity\" "
                           "enum_val3=\"L2\"/>\n"
                           "  <Param type=\"RichInt\" name=\"convergenceSpeed\" value=\"1\"/>\n"
                           "  <Param type=\"RichBool\" name=\"DoubleStep\" value=\"true\"/>\n"
                           "  <Param type=\"RichString\" name=\"AbsLoadName\" value=\"\"/>\n"
                           "  <Param type=\"RichString\" name=\"AbsSaveName\" value=\"\"/>\n"
                           " </filter>\n"
                           " <filter name=\"Iso Parametrization Remeshing\">\n"
                           "  <Param type=\"RichInt\" name=\"SamplingRate\" value=\"10\"/>\n"
                           " </filter>\n"
                           "</FilterScript>\n";
  const std::string command = "xvfb-run -a meshlabserver -i '" + gr::bench::benchMeshPath(c.file) + "' -o '" + out +
                              "' -s '" + script + "' > '" + log + "' 2>&1";
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = std::system(command.c_str());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (rc != 0) return state.SkipWithError(("meshlabserver failed, see " + log).c_str());
  }
  const gr::Expected<gr::TriMesh> remesh = gr::loadTriMesh(out);
  if (!remesh) return state.SkipWithError(("cannot read " + out + ": " + remesh.status().message).c_str());
  setCounters(state, *remesh, *input);
}

void registerAll() {
  for (const Case& c : kCases) {
    auto* b = benchmark::RegisterBenchmark((std::string("SemiRegular/") + c.name).c_str(), BM_SemiRegular, c)
                  ->Unit(benchmark::kMillisecond)
                  ->MeasureProcessCPUTime();
    if (c.subdivisions > 0) b->Iterations(1);
  }
  for (const Case& c : kCases)
    if (c.subdivisions == 0)
      benchmark::RegisterBenchmark((std::string("MeshLabIsoParametrization/") + c.name).c_str(),
                                   BM_MeshLabIsoParametrization, c)
          ->Unit(benchmark::kMillisecond)
          ->UseManualTime()
          ->Iterations(1);
}

}  // namespace

int main(int argc, char** argv) { return gr::bench::runBenchmarks(argc, argv, registerAll); }
