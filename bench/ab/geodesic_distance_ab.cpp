// A/B driver for issue 17's "nothing slower where nothing was wrong": N calls of the distance
// from vertex 0, CPU time per call, min and median printed. Built twice by
// scripts/ab_geodesic_distance.sh: against the core of 0eaa430 (before issue 17, calling
// fastMarching()) and against this tree's core (-DGR_AB_NEW, calling geodesicDistance()), so
// that the two can be alternated on the same machine. Not a Google Benchmark binary: the old
// core predates this file, and the script needs the same driver on both sides.
//   geodesic_distance_ab <mesh.off> <subdivisions> <calls>
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/geodesic/fast_marching.h"
#ifdef GR_AB_NEW
#include "core/geodesic/geodesic_surface.h"
#endif
#include "core/mesh/subdivide.h"
#include "core/mesh/vcg_mesh.h"

namespace {

double cpuMilliseconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

double distanceFromVertex0(const gr::TriMesh& mesh) {
#ifdef GR_AB_NEW
  const gr::Expected<gr::GeodesicDistanceResult> r = gr::geodesicDistance(mesh, {}, {0});
  return r ? r->field.maxDistance : -1.0;
#else
  const gr::Expected<gr::FastMarchingResult> r = gr::fastMarching(mesh, gr::Metric::uniform(), {0});
  return r ? r->maxDistance : -1.0;
#endif
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s <mesh.off> <subdivisions> <calls>\n", argv[0]);
    return 2;
  }
  gr::Expected<gr::TriMesh> loaded = gr::loadTriMesh(argv[1]);
  const int levels = std::atoi(argv[2]), calls = std::max(1, std::atoi(argv[3]));
  if (!loaded) return 1;
  gr::TriMesh mesh = std::move(*loaded);
  if (levels > 0) mesh = gr::subdivideMidpoint(mesh, levels)->mesh;
  std::vector<double> ms;
  double check = 0.0;
  for (int i = 0; i < calls; ++i) {
    const double start = cpuMilliseconds();
    check = distanceFromVertex0(mesh);
    ms.push_back(cpuMilliseconds() - start);
  }
  std::sort(ms.begin(), ms.end());
#ifdef GR_AB_NEW
  const char* which = "new geodesicDistance";
#else
  const char* which = "old fastMarching";
#endif
  std::printf("%s %d v: min %.2f ms, median %.2f ms (farthest %.6g)\n", which, mesh.vertexCount(), ms.front(),
              ms[ms.size() / 2], check);
  return 0;
}
