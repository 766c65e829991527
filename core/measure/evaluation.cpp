#include "core/measure/evaluation.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <system_error>
#include <thread>
#include <vector>

#include <vcg/complex/algorithms/closest.h>
#include <vcg/space/index/grid_static_ptr.h>

#include "core/base/math.h"
#include "core/mesh/vcg_mesh.h"

namespace gr {

DistanceError distanceError(const std::vector<double>& d, const std::vector<double>& reference) {
  DistanceError e;
  double refMax = 0.0;
  for (size_t v = 0; v < reference.size(); ++v)
    if (std::isfinite(reference[v]) && std::isfinite(d[v])) refMax = std::max(refMax, reference[v]);
  if (refMax <= 0.0) return e;
  double sum = 0.0, maxAbs = 0.0;
  for (size_t v = 0; v < reference.size(); ++v) {
    if (!std::isfinite(reference[v]) || !std::isfinite(d[v])) continue;
    const double err = std::abs(d[v] - reference[v]);
    maxAbs = std::max(maxAbs, err);
    if (reference[v] >= 0.05 * refMax) {
      sum += err / reference[v];
      ++e.comparedVertices;
    }
  }
  e.meanRelative = e.comparedVertices ? sum / e.comparedVertices : 0.0;
  e.maxRelativeToMax = maxAbs / refMax;
  return e;
}

AngleStatistics angleStatistics(const TriMesh& mesh) {
  AngleStatistics a;
  if (mesh.faceCount() == 0) return a;
  double sumSq = 0.0;
  int below30 = 0;
  for (const Tri& t : mesh.triangles) {
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]];
      const Vec3 w = mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[k]];
      const double nu = u.norm(), nw = w.norm();
      double angle = 0.0;
      if (nu > 0.0 && nw > 0.0)
        angle = std::acos(std::clamp(u.dot(w) / (nu * nw), -1.0, 1.0)) * 180.0 / kPi;
      else if (nu > 0.0 || nw > 0.0)
        angle = 0.0;
      sumSq += (angle - 60.0) * (angle - 60.0);
      smallest = std::min(smallest, angle);
      a.maxDegrees = std::max(a.maxDegrees, angle);
    }
    a.minDegrees = std::min(a.minDegrees, smallest);
    below30 += smallest < 30.0;
  }
  a.stdDegrees = std::sqrt(sumSq / (3.0 * mesh.faceCount()));
  a.shareMinBelow30 = double(below30) / mesh.faceCount();
  return a;
}

SurfaceDistance surfaceDistance(const TriMesh& from, const TriMesh& to, Progress progress, int maxThreads,
                                DistanceSamples samples) {
  SurfaceDistance d;
  if (from.vertexCount() == 0 || to.faceCount() == 0) return d;
  CoreMesh target;
  toCoreMesh(to, target);
  // Sample q: vertex q for q < V, then per face its centroid and the midpoints of its three sides
  // (or nothing: the vertices alone).
  const long perFace = samples == DistanceSamples::VerticesMidpointsCentroids ? 4 : 0;
  const long vertices = from.vertexCount(), total = vertices + perFace * from.faceCount();
  // vcglib's default grid has as many cells as faces, most of them empty (a surface fills few
  // cells of a volume), so the occupied ones hold tens of faces each. Sixteen cells per face (at
  // most 2^24 cells, 128 MiB of cell pointers) keeps the faces per occupied cell few, so each
  // query tests few faces.
  vcg::GridStaticPtr<CoreFace, double> grid;
  grid.Set(target.face.begin(), target.face.end(), static_cast<int>(std::min(16L * to.faceCount(), 1L << 24)));
  const double searchRadius = 2.0 * (to.boundingBoxDiagonal() + from.boundingBoxDiagonal());
  const auto samplePoint = [&](long q) -> Vec3 {
    if (q < vertices) return from.positions[q];
    const Tri& t = from.triangles[(q - vertices) / perFace];
    const Vec3 &a = from.positions[t[0]], &b = from.positions[t[1]], &c = from.positions[t[2]];
    switch ((q - vertices) % perFace) {
      case 0: return (a + b + c) / 3.0;
      case 1: return 0.5 * (a + b);
      case 2: return 0.5 * (b + c);
      default: return 0.5 * (c + a);
    }
  };
  constexpr long kBlock = 1 << 14;
  const long blocks = (total + kBlock - 1) / kBlock;
  std::vector<double> blockMax(blocks, 0.0), blockSumSq(blocks, 0.0);
  std::atomic<long> nextBlock{0};
  std::atomic<bool> cancelled{false};
  // Each thread takes the next block until none is left; vcglib's grid is only read (no marks).
  const auto work = [&](bool reports) {
    vcg::face::PointDistanceBaseFunctor<double> pointToFace;
    vcg::tri::EmptyTMark<CoreMesh> marker;
    for (long b = nextBlock++; b < blocks; b = nextBlock++) {
      double mx = 0.0, sumSq = 0.0;
      for (long q = b * kBlock, end = std::min(total, q + kBlock); q < end; ++q) {
        const Vec3 p = samplePoint(q);
        double dist = searchRadius;
        vcg::Point3d closest;
        grid.GetClosest(pointToFace, marker, vcg::Point3d(p.x(), p.y(), p.z()), searchRadius, dist, closest);
        mx = std::max(mx, dist);
        sumSq += dist * dist;
      }
      blockMax[b] = mx;
      blockSumSq[b] = sumSq;
      if (reports && !progress.report(double(b + 1) / blocks, "Surface distance")) {
        cancelled = true;
        nextBlock = blocks;
      }
    }
  };
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const long threads = std::min<long>(blocks, maxThreads > 0 ? maxThreads : hardware);
  std::vector<std::thread> helpers;
  try {
    for (long i = 1; i < threads; ++i) helpers.emplace_back(work, false);
  } catch (const std::system_error&) {
    // No more threads to be had: the ones started and this one share the blocks.
  }
  work(true);
  for (std::thread& t : helpers) t.join();
  double sumSq = 0.0;
  for (long b = 0; b < blocks; ++b) {
    d.max = std::max(d.max, blockMax[b]);
    sumSq += blockSumSq[b];
  }
  d.rms = std::sqrt(sumSq / total);
  d.complete = !cancelled;
  return d;
}

}  // namespace gr
