// Segmentation (paper §4.2, Table 2 "1 Lloyd iter."): one geodesic Lloyd iteration, whole
// segmentations (what the filter runs), and the anchors on the same meshes and counts.
//
//   LloydIteration/<mesh>/<regions>   one gr::geodesicLloyd iteration from the farthest-point
//                          samples (sampling untimed), uniform metric.
//   Segmentation/<mesh>/<regions>/<iterations>   gr::segmentSurface with the filter's defaults
//                          (feature alignment 8 from the total curvature) and that many iterations:
//                          the metric, the sampling, Lloyd, the labelling and the disk rounds.
//   CgalVsa/<mesh>/<regions>   CGAL 5.5 Variational Shape Approximation (L21, 30 iterations,
//                          hierarchical seeding; oracle::cgalVsaSegmentation, the Surface_mesh copy
//                          included).
//   KMeans/<mesh>/<regions>    area-weighted k-means++ of the face centroids (30 iterations, seed 0).
// The anchors are not run on armadillo_sub3 (1.66M vertices).
//
// Time: process CPU time. Counters (never timed; the same code for every method, from the face
// labels alone): regions, non_disks (regions that are not one edge-connected topological disk),
// area_cv (coefficient of variation of the region areas), isoperimetric (mean 4 pi A / P^2),
// on_sharp (share of region-boundary length on edges of dihedral angle > 60 deg), sharp_covered
// (share of sharp-edge length on region boundaries).
#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "core/geodesic/farthest_point_sampling.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_lloyd.h"
#include "core/segment/geodesic_segmentation.h"
#include "tests/oracles/segmentation_oracles.h"
#include "tests/support/segmentation_figures.h"

namespace {

using gr::bench::MeshSpec;

const MeshSpec kFandisk = {"fandisk", "fandisk.off", 0};
const MeshSpec kBunny = {"bunny00", "bunny00.off", 0};
const MeshSpec kArmadilloSub3 = {"armadillo_sub3", "armadillo.off", 3};

void setFigures(benchmark::State& state, const gr::TriMesh& mesh, const std::vector<int>& region) {
  const gr::test::SegmentationFigures f = gr::test::segmentationFigures(mesh, region);
  state.counters["regions"] = f.regions;
  state.counters["non_disks"] = f.nonDisks;
  state.counters["area_cv"] = f.areaCv;
  state.counters["isoperimetric"] = f.meanIsoperimetric;
  state.counters["on_sharp"] = f.boundaryOnSharp;
  state.counters["sharp_covered"] = f.sharpCovered;
}

void lloydIteration(benchmark::State& state, MeshSpec spec, int regions) {
  const gr::TriMesh* mesh = gr::bench::cachedMesh<gr::TriMesh>(state, spec);
  if (!mesh) return;
  gr::FastMarcher marcher(*mesh, gr::Metric::uniform());
  gr::FpsParams fps;
  fps.targetCount = regions;
  fps.boundaryPriority = 1.0;
  const gr::Expected<gr::FpsResult> samples = gr::farthestPointSampling(marcher, fps);
  if (!samples) return state.SkipWithError(samples.status().message.c_str());
  gr::LloydParams params;
  params.iterations = 1;
  params.tolerance = 0.0;
  double ratio = 0.0;
  for (auto _ : state) {
    const gr::Expected<gr::LloydResult> r =
        gr::geodesicLloyd(*mesh, gr::Metric::uniform(), marcher, samples->origin, params);
    if (!r) return state.SkipWithError(r.status().message.c_str());
    ratio = r->energy.back() / r->energy.front();
  }
  state.counters["energy_ratio"] = ratio;
}

void segmentation(benchmark::State& state, MeshSpec spec, int regions, int iterations) {
  const gr::TriMesh* mesh = gr::bench::cachedMesh<gr::TriMesh>(state, spec);
  if (!mesh) return;
  gr::SegmentationParams params;
  params.regions = regions;
  params.lloyd.iterations = iterations;
  std::vector<int> region;
  int added = 0, done = 0;
  for (auto _ : state) {
    const gr::Expected<gr::SegmentationResult> r = gr::segmentSurface(*mesh, {}, params);
    if (!r) return state.SkipWithError(r.status().message.c_str());
    region = r->faceRegion;
    added = r->regionsAdded;
    done = r->iterations;
  }
  setFigures(state, *mesh, region);
  state.counters["added"] = added;
  state.counters["iterations"] = done;
}

void cgalVsa(benchmark::State& state, MeshSpec spec, int regions) {
  const gr::TriMesh* mesh = gr::bench::cachedMesh<gr::TriMesh>(state, spec);
  if (!mesh) return;
  std::vector<int> region;
  for (auto _ : state) region = gr::oracle::cgalVsaSegmentation(*mesh, regions, 30);
  if (region.empty()) return state.SkipWithError("CGAL VSA failed");
  setFigures(state, *mesh, region);
}

void kMeans(benchmark::State& state, MeshSpec spec, int regions) {
  const gr::TriMesh* mesh = gr::bench::cachedMesh<gr::TriMesh>(state, spec);
  if (!mesh) return;
  std::vector<int> region;
  for (auto _ : state) region = gr::oracle::kmeansFaceCentroids(*mesh, regions, 0, 30);
  setFigures(state, *mesh, region);
}

void registerAll() {
  const auto name = [](const std::string& family, const MeshSpec& m, const std::string& rest) {
    return family + "/" + m.name + "/" + rest;
  };
  const auto timed = [](benchmark::internal::Benchmark* b) {
    b->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
  };
  timed(benchmark::RegisterBenchmark(name("LloydIteration", kFandisk, "100").c_str(), lloydIteration, kFandisk, 100));
  timed(benchmark::RegisterBenchmark(name("LloydIteration", kBunny, "500").c_str(), lloydIteration, kBunny, 500));
  struct Case {
    MeshSpec mesh;
    int regions, iterations;
  };
  for (const Case& c : {Case{kFandisk, 20, 20}, Case{kFandisk, 50, 20}, Case{kBunny, 100, 20}, Case{kBunny, 500, 20},
                        Case{kArmadilloSub3, 1000, 10}}) {
    const std::string counts = std::to_string(c.regions);
    timed(
        benchmark::RegisterBenchmark(name("Segmentation", c.mesh, counts + "/" + std::to_string(c.iterations)).c_str(),
                                     segmentation, c.mesh, c.regions, c.iterations));
    if (c.mesh.subdivisions > 0) continue;  // the anchors take minutes (k-means: faces x regions x 30) at 3.3M faces
    timed(benchmark::RegisterBenchmark(name("CgalVsa", c.mesh, counts).c_str(), cgalVsa, c.mesh, c.regions));
    timed(benchmark::RegisterBenchmark(name("KMeans", c.mesh, counts).c_str(), kMeans, c.mesh, c.regions));
  }
}

}  // namespace

int main(int argc, char** argv) { return gr::bench::runBenchmarks(argc, argv, registerAll); }
