#include "core/remesh/remesh_surface.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <utility>

#include "core/base/math.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_lloyd.h"
#include "core/geodesic/geodesic_surface.h"
#include "core/mesh/face_geometry.h"
#include "core/mesh/orientation.h"
#include "core/mesh/self_intersection.h"
#include "core/mesh/subdivide.h"
#include "core/remesh/edge_collapse.h"
#include "core/remesh/remesh_distance.h"

namespace gr {
namespace {

/// Whether the remesh's cells are still the Voronoi cells of its vertices (remeshDistances'
/// voronoiCells): edge collapses and removed ears merge cells.
bool cellsAreVoronoi(const SurfaceRemeshResult& r) {
  return r.collapsedVertices == 0 && r.removedEars == 0 && r.splitVertices == 0;
}

/// Seconds since `start`, and restarts it.
double lap(std::chrono::steady_clock::time_point& start) {
  const auto now = std::chrono::steady_clock::now();
  const double seconds = std::chrono::duration<double>(now - start).count();
  start = now;
  return seconds;
}

/// Refuses what no stage can work with, before any work: non-manifold input, parameters out of range.
Status checkRemeshInput(const TriMesh& input, const SurfaceRemeshParams& params) {
  const Topology& topology = input.topology;
  if (!topology.isManifold())
    return nonManifold("the mesh has " + topology.nonManifoldCounts() +
                       "; repair them first (Cleaning and Repairing menu)");
  if (params.refinement < 0 || params.refinement > SurfaceRemeshParams::kMaxRefinement)
    return invalidInput("Refinement must be 0 to " + std::to_string(SurfaceRemeshParams::kMaxRefinement) + ", got " +
                        std::to_string(params.refinement));
  // The target is bounded by the input's vertices in faces, also when the fronts run on a refined
  // surface with more vertices (the output never has more vertices than the input offers).
  int usable = 0;
  for (int v = 0; v < input.vertexCount(); ++v) usable += input.valence(v) > 0;
  if (params.sampling.targetCount > usable)
    return invalidInput("cannot place " + std::to_string(params.sampling.targetCount) + " samples on " +
                        std::to_string(usable) + " vertices");
  const int rounds = params.relaxation.iterations;
  if (rounds < 0 || rounds > SurfaceRemeshParams::kMaxRelaxationRounds)
    return invalidInput("Relaxation must be 0 to " + std::to_string(SurfaceRemeshParams::kMaxRelaxationRounds) +
                        " rounds, got " + std::to_string(rounds));
  if (params.centroidalIterations < 0 || params.centroidalIterations > SurfaceRemeshParams::kMaxCentroidalIterations)
    return invalidInput("CentroidalIterations must be 0 to " +
                        std::to_string(SurfaceRemeshParams::kMaxCentroidalIterations) + ", got " +
                        std::to_string(params.centroidalIterations));
  if (!(params.countTolerance >= 0.0) || !std::isfinite(params.countTolerance))
    return invalidInput("the count tolerance must be finite and >= 0, got " + std::to_string(params.countTolerance));
  return Status::ok();
}

/// The surface the work runs on: a coherently oriented copy when some faces run against their
/// neighbours (the output takes its orientation from the faces), else nothing (use the input).
struct OrientedSurface {
  std::optional<TriMesh> copy;
  std::vector<char> flipped;  ///< per face, 1 if the copy swapped its corners 1 and 2
};
Expected<OrientedSurface> orientedSurface(const TriMesh& input) {
  OrientedSurface s;
  if (input.topology.inconsistentEdges == 0) return s;
  Expected<TriMesh> oriented = orientCoherently(input, &s.flipped);
  if (!oriented) return oriented.status();
  s.copy = std::move(oriented).value();
  return s;
}

/// The mesh the fronts run on: the oriented input's intrinsic Delaunay refinement (`geodesic`
/// refined), or the oriented input subdivided `params.refinement` times (`fine`).
struct FrontSurface {
  GeodesicSurface geodesic;
  std::optional<Subdivision> fine;        ///< when not refined
  Metric fineMetric;                      ///< on fine's vertices
  const Metric* surfaceMetric = nullptr;  ///< on the surface's vertices (the caller's)

  const TriMesh& mesh() const { return geodesic.refined ? geodesic.refinement.mesh : fine->mesh; }
};
Expected<FrontSurface> frontSurface(const TriMesh& surface, const Metric& metric, const SurfaceRemeshParams& params,
                                    Progress progress) {
  FrontSurface f;
  f.surfaceMetric = &metric;
  // A triangle soup is neither refined nor subdivided: each face comes back as it was (with
  // points inside it, the repair's samples on its sides split it into 2-4 triangles).
  const bool soup = TriMesh::looksLikeTriangleSoup(surface.looseFaceCount(), surface.faceCount());
  GeodesicSurfaceParams surfaceParams = params.surface;
  if (soup) surfaceParams.refinement = SurfaceRefinement::Off;
  Expected<GeodesicSurface> geodesic = prepareGeodesicSurface(surface, metric, surfaceParams, std::move(progress));
  if (!geodesic) return geodesic.status();
  f.geodesic = std::move(*geodesic);
  if (f.geodesic.refined) return f;
  Expected<Subdivision> fine = subdivideMidpoint(surface, soup ? 0 : params.refinement);
  if (!fine) return fine.status();
  Expected<Metric> fineMetric = transferMetric(metric, surface, fine->origin);
  if (!fineMetric) return fineMetric.status();
  f.fine = std::move(*fine);
  f.fineMetric = std::move(*fineMetric);
  return f;
}

/// Points of the refined surface as points of the oriented input: its vertices' origins. Samples
/// inside refined faces do not occur (sub-vertex placement is off there); one would be a bug.
Status originsOnSurface(const GeodesicSurface& geodesic, std::vector<SurfacePoint>& points) {
  for (SurfacePoint& p : points) {
    if (p.vertex < 0)
      return internalError("a sample inside a face of the refined surface (sub-vertex placement is off)");
    p = geodesic.origin(p.vertex);
  }
  return Status::ok();
}

/// The relaxation, on the subdivision (unrefined) or on the oriented input `surface` (refined: the
/// triangulation's origins are mapped to it first; the refined mesh's faces are chords, not the
/// surface), `guard` constraining some output vertices.
Status relaxDual(const FrontSurface& front, const TriMesh& surface, const SurfaceRemeshParams& params,
                 DelaunayResult& triangulation, RelaxationResult& result, RemeshStageTimes& times,
                 const RelaxationGuard& guard) {
  auto clock = std::chrono::steady_clock::now();
  if (front.geodesic.refined)
    if (Status s = originsOnSurface(front.geodesic, triangulation.origin); !s) return s;
  const TriMesh& relaxOn = front.geodesic.refined ? surface : front.fine->mesh;
  RelaxationParams relaxation = params.relaxation;
  // A non-uniform metric's density is kept: the metric on the mesh relaxed on.
  const Metric& metric = front.geodesic.refined ? *front.surfaceMetric : front.fineMetric;
  if (!metric.isUniform()) relaxation.density = &metric.P;
  Expected<RelaxationResult> relaxed =
      relaxOnSurface(triangulation.mesh, triangulation.origin, relaxOn, relaxation, guard);
  if (!relaxed) return relaxed.status();
  result = *relaxed;
  times.relaxation += lap(clock);
  return Status::ok();
}

/// A sampling, the triangulation of its Voronoi diagram, relaxed, and whether that has crossing
/// faces (selfIntersectingFaces).
struct SampledDual {
  FpsResult sampling;
  int lloydIterations = 0;        ///< centroidal iterations accepted
  double lloydEnergyRatio = 1.0;  ///< their energy at the end over the samples'
  DelaunayResult dual;
  RelaxationResult relaxation;
  int requested = 0;
  int crossingPairs = 0;      ///< pairs of crossing faces of the output (relaxWithoutCrossing counts them)
  int crossingPairsAway = 0;  ///< of them, those away from the input's own crossings
};

/// The crossing pairs of `dual`'s output away from where the input crosses itself
/// (crossingsAwayFromInput with DelaunayParams::mayCross, which remeshSurface always sets): only
/// those are worth watching in the relaxation or the triangulation's repair.
std::vector<std::pair<int, int>> awayFromInputCrossings(const SurfaceRemeshParams& params, const DelaunayResult& dual,
                                                        std::vector<std::pair<int, int>> pairs) {
  if (pairs.empty() || !params.triangulation.mayCross) return pairs;
  return crossingsAwayFromInput(dual.mesh, dual.cell, params.triangulation.mayCross(), std::move(pairs));
}

/// Flags (one per vertex of `mesh`) the corners of the faces in `pairs` and, with `ring`, their
/// neighbours: the vertices a relaxation that made those faces cross watches or pins next
/// (RelaxationGuard).
void flagCrossingCorners(const TriMesh& mesh, const std::vector<std::pair<int, int>>& pairs, bool ring,
                         std::vector<char>& flags) {
  flags.resize(mesh.vertexCount(), 0);
  for (const auto& [f, g] : pairs)
    for (int face : {f, g})
      for (int v : mesh.triangles[face]) {
        flags[v] = 1;
        if (ring)
          for (const int* c = mesh.cornersBegin(v); c != mesh.cornersEnd(v); ++c)
            flags[mesh.vertex(TriMesh::next(*c))] = 1;
      }
}

/// The relaxation of d's dual, kept from making its faces cross: a relaxed output with crossing
/// pairs (selfIntersectingFaces, away from the input's own crossings: awayFromInputCrossings) is
/// relaxed again from the triangulation, the corners of its
/// crossing faces and their neighbours watched (their moves refused where faces would cross:
/// RelaxationGuard), up to kWatchRounds times; then with those corners pinned, up to kPinRounds
/// times; then not at all. The first output without crossing pairs is kept, else the one with the
/// fewest (the first of equals); a guarded relaxation with no more pairs than the triangulation
/// itself ends the rounds (those are the triangulation's to repair). Past kMaxWatchedPairs pairs
/// after the first relaxation (an input through itself), the relaxed output is kept if it has no
/// more pairs than the triangulation, else the triangulation is. On a thin plate a vertex moved over the plate's rim folds a face
/// onto the other side (the CAD gear of tests/support/cad_meshes.h at 104 centroidal samples: 3
/// crossing faces); at 30% of a scan a vertex slides over a fold of the surface (bunny00: 2
/// pairs). Pinning alone kept the triangulation's slivers there (bunny00: 0.5 degrees).
Status relaxWithoutCrossing(const FrontSurface& front, const TriMesh& surface, const SurfaceRemeshParams& params,
                            SampledDual& d, RemeshStageTimes& times) {
  constexpr int kWatchRounds = 2, kPinRounds = 4;
  constexpr size_t kMaxWatchedPairs = 64;  // beyond: no watching, the relaxation kept if no worse
  const DelaunayResult unrelaxed = d.dual;
  RelaxationGuard guard;
  std::optional<SampledDual> best;
  std::optional<size_t> before;  // crossing pairs of the triangulation, counted when needed
  SurfaceRemeshParams none = params;
  none.relaxation.iterations = 0;
  for (int round = 0; round <= kPinRounds + 1; ++round) {
    const bool relax = round <= kPinRounds && params.relaxation.iterations > 0;
    if (Status s = relaxDual(front, surface, relax ? params : none, d.dual, d.relaxation, times, guard); !s) return s;
    const std::vector<std::pair<int, int>> all = selfIntersectingFaces(d.dual.mesh);
    const std::vector<std::pair<int, int>> pairs = awayFromInputCrossings(params, d.dual, all);
    d.crossingPairs = static_cast<int>(all.size());
    d.crossingPairsAway = static_cast<int>(pairs.size());
    if (!best || d.crossingPairsAway < best->crossingPairsAway) best = d;
    if (pairs.empty() || !relax) break;
    if (!before) before = awayFromInputCrossings(params, unrelaxed, selfIntersectingFaces(unrelaxed.mesh)).size();
    if (round > 0 && pairs.size() <= *before) break;      // what is left the triangulation has itself
    if (round == 0 && pairs.size() > kMaxWatchedPairs) {  // an input that crosses itself, as boeing.off
      if (pairs.size() > *before) {
        d.dual = unrelaxed;  // the relaxation made it worse: not relaxed
        round = kPinRounds;
        continue;
      }
      break;
    }
    flagCrossingCorners(d.dual.mesh, pairs, round < kWatchRounds, round < kWatchRounds ? guard.watched : guard.pinned);
    d.dual = unrelaxed;
  }
  d = std::move(*best);
  return Status::ok();
}

/// The triangulation of d's samples (the marcher holds their field) and its relaxation. The
/// triangulation's crossing repair (DelaunayParams::maxCrossingRounds) comes second: first
/// without it, since the relaxation undoes most crossings of a dual (the CAD gear at 104 samples:
/// none left, where refining the crossing cells first added samples and the count search then
/// landed at 87); only if the relaxed output still crosses away from where the input crosses
/// itself are the triangulation's samples (the repair's included) triangulated again, their field
/// restored by one front, with the repair of crossing triangles, and relaxed.
Status triangulateAndRelax(FastMarcher& marcher, const FrontSurface& front, const TriMesh& surface,
                           const SurfaceRemeshParams& params, SampledDual& d, Progress progress,
                           RemeshStageTimes& times) {
  DelaunayParams triangulation = params.triangulation;
  triangulation.maxCrossingRounds = 0;
  auto clock = std::chrono::steady_clock::now();
  Expected<DelaunayResult> dual = geodesicDelaunay(marcher, d.sampling.origin, triangulation, progress.sub(0.0, 0.4));
  if (!dual) return dual.status();
  std::vector<SurfacePoint> triangulated = dual->origin;  // on the front mesh (relaxDual maps them)
  d.dual = std::move(*dual);
  times.triangulation += lap(clock);
  if (!progress.report(0.4, "Relaxation")) return cancelled();
  if (Status s = relaxWithoutCrossing(front, surface, params, d, times); !s) return s;
  if (d.crossingPairsAway == 0 || params.triangulation.maxCrossingRounds == 0) return Status::ok();
  // The valid triangulation's samples again (their field by one front), now with the repair of
  // crossing triangles: no validity repair to redo.
  marcher.reset();
  for (size_t i = 0; i < triangulated.size(); ++i)
    if (Status s = marcher.addSource(triangulated[i], static_cast<int>(i)); !s) return s;
  if (Status s = marcher.propagate(); !s) return s;
  const int added = d.dual.addedSamples, dropped = d.dual.droppedSamples, rounds = d.dual.repairRounds;
  dual = geodesicDelaunay(marcher, std::move(triangulated), params.triangulation, progress.sub(0.5, 0.9));
  if (!dual) return dual.status();
  d.dual = std::move(*dual);
  d.dual.addedSamples += added;
  d.dual.droppedSamples += dropped;
  d.dual.repairRounds += rounds;
  times.triangulation += lap(clock);
  if (!progress.report(0.9, "Relaxation")) return cancelled();
  return relaxWithoutCrossing(front, surface, params, d, times);
}

/// One sampling of `request` samples, the triangulation of its Voronoi diagram on the same engine
/// (the sampling resets it; the triangulation goes on from the sampling's field), relaxed. When
/// `longest` (the longest farthest-point sampling so far, same parameters) has at least `request`
/// samples, its first `request` are taken (samplingPrefix: one front instead of a sampling);
/// otherwise the new sampling becomes `longest`.
Expected<SampledDual> sampleAndTriangulate(FastMarcher& marcher, const FrontSurface& front, const TriMesh& surface,
                                           const SurfaceRemeshParams& params, int request, Progress progress,
                                           RemeshStageTimes& times, std::optional<FpsResult>& longest) {
  auto clock = std::chrono::steady_clock::now();
  SampledDual d;
  d.requested = request;
  FpsParams fpsParams = params.sampling;
  fpsParams.targetCount = request;
  if (front.geodesic.refined) fpsParams.subVertexPlacement = false;  // no exact origin on the input inside a face
  const double lloydShare = params.centroidalIterations > 0 ? 0.35 : 0.0;
  const bool prefix = longest && request > 0 && request <= static_cast<int>(longest->samples.size());
  Expected<FpsResult> fps = prefix ? samplingPrefix(marcher, *longest, request)
                                   : farthestPointSampling(marcher, fpsParams, progress.sub(0.0, 0.7 - lloydShare));
  if (!fps) return fps.status();
  if (!prefix) longest = *fps;
  d.sampling = std::move(*fps);
  if (params.centroidalIterations > 0) {
    LloydParams lloyd;
    lloyd.iterations = params.centroidalIterations;
    lloyd.metricArea = true;
    lloyd.keepBoundarySeeds = true;
    lloyd.vertexSeeds = front.geodesic.refined;  // a point inside a refined face has no exact origin on the input
    const Metric& metric = front.geodesic.refined ? front.geodesic.metric : front.fineMetric;
    Expected<LloydResult> relaxed =
        geodesicLloyd(front.mesh(), metric, marcher, d.sampling.origin, lloyd, progress.sub(0.7 - lloydShare, 0.7));
    if (!relaxed) return relaxed.status();
    d.sampling.origin = std::move(relaxed->seeds);  // the marcher holds their cells, 0..n-1 in order
    d.lloydIterations = relaxed->iterations;
    if (relaxed->energy.front() > 0.0) d.lloydEnergyRatio = relaxed->energy.back() / relaxed->energy.front();
  }
  times.sampling += lap(clock);
  if (Status s = triangulateAndRelax(marcher, front, surface, params, d, progress.sub(0.7, 1.0), times); !s) return s;
  return d;
}

/// The next count to ask the sampling for, or 0 to stop: the last request less the surplus (or
/// plus the shortfall), kept strictly between the largest request that gave too few vertices
/// (`below`) and the smallest that gave too many (`above`), else halfway between them.
int nextRequest(int request, int got, int target, int below, int above) {
  int next = request - (got - target);
  if (next <= below || next >= above) next = below + (above - below) / 2;
  next = std::max(next, 1);
  return next <= below || next >= above || next == request ? 0 : next;
}

/// How far a valid triangulation is from what is asked: crossing faces first (an output that is
/// not embedded, as thin plates give when sampled too sparsely: cad_gear at 100-102 samples), then the
/// distance to the count. Smaller is better.
std::pair<bool, int> miss(const SampledDual& d, int target) {
  const int got = d.dual.mesh.vertexCount();
  return {d.crossingPairs > 0, std::abs(got - target)};
}

/// Whether a first sampling that missed the count is worth a centroidal one at the same count:
/// the repair added more than SurfaceRemeshParams::kRescueShare of the count, or, on a surface whose triangles were
/// poor (refined: CAD exports, thin plates), the output crosses itself. There the Voronoi cells of
/// farthest points wrap around the plates' rims (the gear of tests/support/cad_meshes.h: 104
/// asked, about 110 added, or 105 with crossing faces from another first vertex); Lloyd's cells
/// do not. On scans crossing faces come from the relaxation at sharp creases, which Lloyd does
/// not cure: armadillo at 30% and the 1.66M armadillo would pay 5x (2.6 s more; 81 s more) for no
/// better count. Only when the caller asked for no centroidal iterations (else the first sampling
/// was centroidal already).
bool rescuable(const SurfaceRemeshParams& params, bool refined, bool crossing, int got, int target) {
  return params.centroidalIterations == 0 && target > 0 &&
         (got - target > SurfaceRemeshParams::kRescueShare * target || (refined && crossing));
}

/// Issue 20: when the repair of the triangulation added samples, the sampling is redone with
/// fewer so that the output lands at the count asked for, at most kMaxSamplingRounds samplings in
/// all; of the valid results the one closest to the count without crossing faces is kept (the
/// first of equals; with crossings only if all have some). Before any count is cut, a first
/// sampling that calls for it (rescuable) is redone at the same count with centroidal (Lloyd)
/// iterations, which move samples instead of adding them (one of the kMaxSamplingRounds
/// samplings, kept on only if closer). A redo that fails (the repair does not converge from too few samples) ends the search with the best so far; so does an output with no
/// crossing faces at the count or above it by at most countTolerance. Without a count (spacing
/// only), or when the first sampling lands on it, one sampling.
Expected<SampledDual> sampleToCount(FastMarcher& marcher, const FrontSurface& front, const TriMesh& surface,
                                    const SurfaceRemeshParams& params, Progress progress, SurfaceRemeshResult& r) {
  const int target = params.sampling.targetCount;
  r.countAsked = target;
  std::optional<SampledDual> best;
  std::optional<FpsResult> longest;
  std::pair<bool, int> bestMiss;
  SurfaceRemeshParams roundParams = params;
  std::pair<bool, int> firstMiss;  // of the first sampling, when the rescue round follows it
  int firstGot = 0;
  int request = target, below = 0, above = std::numeric_limits<int>::max();
  for (int round = 0; round < SurfaceRemeshParams::kMaxSamplingRounds && (round == 0 || request > 0); ++round) {
    const double from = 1.0 - std::pow(0.5, round), to = 1.0 - std::pow(0.5, round + 1);
    Expected<SampledDual> run =
        sampleAndTriangulate(marcher, front, surface, roundParams, request, progress.sub(from, to), r.times, longest);
    if (!run && (!best || run.status().code == StatusCode::Cancelled)) return run.status();
    if (!run) break;
    ++r.samplingRounds;
    int got = run->dual.mesh.vertexCount();
    if (target <= 0 || (round == 0 && got == target && run->crossingPairs == 0)) {
      r.fewestCount = got;
      return std::move(*run);
    }
    const std::pair<bool, int> runMiss = miss(*run, target);
    if (!runMiss.first) r.fewestCount = r.fewestCount > 0 ? std::min(r.fewestCount, got) : got;
    if (!best || runMiss < bestMiss) {
      best = std::move(*run);
      bestMiss = runMiss;
    }
    if (!runMiss.first && got >= target && got - target <= params.countTolerance * target) break;
    if (round == 0 && rescuable(params, front.geodesic.refined, runMiss.first, got, target)) {
      // Samples moved rather than added: the same count again, centroidal.
      roundParams.centroidalIterations = SurfaceRemeshParams::kRescueCentroidalIterations;
      r.centroidalRescue = true;
      firstMiss = runMiss;
      firstGot = got;
      continue;
    }
    if (round == 1 && r.centroidalRescue && !(runMiss < firstMiss)) {
      // No better: the search goes on from the first sampling, with farthest points again.
      roundParams = params;
      r.centroidalRescue = false;
      got = firstGot;
    }
    if (got > target) above = std::min(above, request);
    if (got < target) below = std::max(below, request);
    request = nextRequest(request, got, target, below, above);
  }
  return std::move(*best);
}

/// Angles of the output and its distance to the input both ways (remesh_distance.h: the remesh's
/// cells and origins find each sample's nearest point without a grid over the input).
Status measureOutput(const TriMesh& input, bool distances, SurfaceRemeshResult& r, Progress progress) {
  r.measures.angles = angleStatistics(r.mesh);
  if (!distances) return Status::ok();
  const RemeshDistances d = remeshDistances(input, r.mesh, r.cell, r.origin, cellsAreVoronoi(r));
  r.measures.toInput = d.toInput;
  r.measures.fromInput = d.fromInput;
  r.measures.inputDiagonal = input.boundingBoxDiagonal();
  r.measures.distances = true;
  if (!progress.report(1.0, "Surface distance")) return cancelled();
  return Status::ok();
}

/// Each output vertex's point on the input: through the subdivision when not refined (points on
/// a refined surface are already on the oriented input), then with the orientation flip of its
/// face undone.
std::vector<SurfacePoint> originsOnInput(const std::vector<SurfacePoint>& onFront, const FrontSurface& front,
                                         const TriMesh& surface, const std::vector<char>& flipped) {
  std::vector<SurfacePoint> origin(onFront.size());
  for (size_t i = 0; i < origin.size(); ++i) {
    origin[i] = front.fine ? front.fine->originOf(surface, onFront[i]) : onFront[i];
    if (origin[i].face >= 0 && !flipped.empty() && flipped[origin[i].face])
      std::swap(origin[i].bary[1], origin[i].bary[2]);
  }
  return origin;
}

/// DelaunayParams::mayCross for the front mesh: on the subdivided input, its own crossing
/// vertices; on the intrinsic refinement, its vertices on a crossing face of the input (the
/// refinement's own straight triangles may cross where the input's do not). Computed once, on the
/// first call, and kept for the samplings after it.
std::function<std::vector<char>()> inputCrossings(const TriMesh& surface, const FrontSurface& front) {
  auto cached = std::make_shared<std::vector<char>>();
  return [&surface, &front, cached]() {
    if (!cached->empty()) return *cached;
    if (!front.geodesic.refined) {  // the subdivision has the input's geometry
      *cached = crossingVertices(front.mesh());
      return *cached;
    }
    std::vector<char> crossingFace(surface.faceCount(), 0), crossingVertex(surface.vertexCount(), 0);
    for (const auto& [f, g] : selfIntersectingFaces(surface))
      for (int face : {f, g}) {
        crossingFace[face] = 1;
        for (int v : surface.triangles[face]) crossingVertex[v] = 1;
      }
    const int n = front.mesh().vertexCount();
    cached->assign(n, 0);
    for (int v = 0; v < n; ++v) {
      const SurfacePoint p = front.geodesic.origin(v);
      (*cached)[v] = p.vertex >= 0 ? crossingVertex[p.vertex] : crossingFace[p.face];
    }
    return *cached;
  };
}

/// What every remesh of one call shares: the oriented input, the surface the fronts run on, one
/// engine on it (each sampling resets it) and the input's crossings. They depend on the input,
/// the metric, `surface` and `refinement` only, never on what the starts, the angle rescue or
/// the count search's samplings change (seed, relaxation, centroidal iterations, count): built
/// once per call (prepareRemesh), not once per remesh (corner_with_hole at 30%, refined to
/// 10,511 vertices: about 100 of a start's 160 ms). Built in place and never moved: the front
/// surface points into `oriented`, the engine into `front`.
struct Prepared {
  Prepared() = default;
  Prepared(const Prepared&) = delete;
  Prepared& operator=(const Prepared&) = delete;

  OrientedSurface oriented;
  FrontSurface front;
  std::optional<FastMarcher> marcher;
  std::function<std::vector<char>()> mayCross;  ///< DelaunayParams::mayCross: the input's crossings
  double prepareSeconds = 0.0, engineSeconds = 0.0;
  const TriMesh* input = nullptr;

  /// The oriented input (the input itself when no face runs against its neighbours).
  const TriMesh& surface() const { return oriented.copy ? *oriented.copy : *input; }
};

Status prepareRemesh(const TriMesh& input, const Metric& metric, const SurfaceRemeshParams& params, Progress progress,
                     Prepared& out) {
  auto clock = std::chrono::steady_clock::now();
  out.input = &input;
  Expected<OrientedSurface> oriented = orientedSurface(input);
  if (!oriented) return oriented.status();
  out.oriented = std::move(*oriented);
  Expected<FrontSurface> front = frontSurface(out.surface(), metric, params, std::move(progress));
  if (!front) return front.status();
  out.front = std::move(*front);
  out.prepareSeconds = lap(clock);
  const FrontSurface& f = out.front;
  if (f.geodesic.refined)
    out.marcher.emplace(f.geodesic.makeMarcher());
  else
    out.marcher.emplace(f.fine->mesh, f.fineMetric);
  out.engineSeconds = lap(clock);
  out.mayCross = inputCrossings(out.surface(), out.front);
  return Status::ok();
}

}  // namespace

int SurfaceRemeshParams::defaultTargetCount(int vertexCount) {
  return std::max(kMinDefaultTarget, static_cast<int>(kDefaultTargetFraction * vertexCount));
}

int SurfaceRemeshParams::restartsFor(int outputVertices) const {
  if (restarts <= 0) return 0;
  const int scaled = restarts * kRestartVertices / std::max(1, outputVertices);
  return std::max(restarts, std::min(kMaxRestarts, scaled));
}

SurfaceRemeshParams SurfaceRemeshParams::adaptive() {
  SurfaceRemeshParams p;
  p.relaxation.iterations = 0;
  p.restarts = 0;
  return p;
}

namespace {

/// Origins on the input <-> on its oriented copy: the barycentric coordinates of a flipped face
/// swap their last two (as originsOnInput undoes the orientation).
void swapFlipped(std::vector<SurfacePoint>& points, const std::vector<char>& flipped) {
  for (SurfacePoint& p : points)
    if (p.face >= 0 && !flipped.empty() && flipped[p.face]) std::swap(p.bary[1], p.bary[2]);
}

/// The collapsed output relaxed on the oriented input as the triangulation was (its angles: cow at
/// 5% 6.9 -> 20.9 degrees), kept from making more faces cross than before as relaxWithoutCrossing
/// keeps the triangulation's relaxation: plain, then with the corners of the crossing faces and
/// their neighbours watched (twice), then those corners pinned (twice); the first with no more
/// crossing pairs than the unrelaxed output is kept, else the unrelaxed one.
void relaxCollapsed(const TriMesh& surface, const std::vector<char>& flipped, const Metric& metric,
                    const SurfaceRemeshParams& params, SurfaceRemeshResult& r) {
  constexpr int kWatchRounds = 2, kRounds = 4;
  RelaxationParams relaxation = params.relaxation;
  if (!metric.isUniform()) relaxation.density = &metric.P;  // the surface is the oriented input
  RelaxationGuard guard;
  for (int round = 0; round <= kRounds; ++round) {
    TriMesh relaxed = r.mesh;
    std::vector<SurfacePoint> points = r.origin;
    swapFlipped(points, flipped);
    const Expected<RelaxationResult> done = relaxOnSurface(relaxed, points, surface, relaxation, guard);
    if (!done) return;
    const std::vector<std::pair<int, int>> pairs = selfIntersectingFaces(relaxed);
    if (static_cast<int>(pairs.size()) <= r.crossingPairs) {
      swapFlipped(points, flipped);
      r.mesh = std::move(relaxed);
      r.origin = std::move(points);
      r.crossingPairs = static_cast<int>(pairs.size());
      r.relaxation.moves += done->moves;
      r.relaxation.flips += done->flips;
      return;
    }
    flagCrossingCorners(relaxed, pairs, round < kWatchRounds, round < kWatchRounds ? guard.watched : guard.pinned);
  }
}

/// The metric at the output's vertices (P at their origins; 1 when uniform): the collapses' weights.
std::vector<double> outputWeights(const TriMesh& input, const Metric& metric, const SurfaceRemeshResult& r) {
  if (!metric.isUniform())
    if (Expected<Metric> atOutput = transferMetric(metric, input, r.origin); atOutput && !atOutput->isUniform())
      return atOutput->P;
  return std::vector<double>(r.mesh.vertexCount(), 1.0);
}

/// Issue 20: an output whose faces still cross away from where the input crosses itself (the
/// triangulation's crossing repair ran out; armadillo, adaptive, at 30%: 6 pairs) loses those
/// crossing faces by edge collapses (collapseCrossingFaces), then is relaxed as a collapsed one.
/// The input's crossing vertices (`mayCross`, per vertex of the mesh the fronts ran on, whose
/// first vertices are the input's) excuse the output vertices of their cells.
void collapseCrossings(const TriMesh& input, const TriMesh& surface, const std::vector<char>& flipped,
                       const Metric& metric, const SurfaceRemeshParams& params,
                       const std::function<std::vector<char>()>& mayCross, SurfaceRemeshResult& r) {
  if (r.crossingPairs == 0 || !mayCross) return;
  std::vector<char> inputCrossing = mayCross();
  inputCrossing.resize(input.vertexCount(), 0);
  const CrossingPairs away = [&inputCrossing](const TriMesh& mesh, const std::vector<int>& cell) {
    return crossingsAwayFromInput(mesh, cell, inputCrossing, selfIntersectingFaces(mesh));
  };
  std::vector<double> weight = outputWeights(input, metric, r);
  const CollapseResult collapsed = collapseCrossingFaces(r.mesh, r.origin, weight, r.cell, away);
  if (collapsed.collapsed == 0) return;
  r.collapsedVertices += collapsed.collapsed;
  r.crossingPairs = static_cast<int>(selfIntersectingFaces(r.mesh).size());
  if (params.relaxation.iterations > 0) relaxCollapsed(surface, flipped, metric, params, r);
}

/// Per output vertex of `r`, whether it lies at one of the input's vertices `at` (its origin that
/// vertex, or a corner of a face with all its weight); empty when `at` is.
std::vector<char> atSamples(const TriMesh& input, const std::vector<int>& at, const SurfaceRemeshResult& r) {
  if (at.empty()) return {};
  std::vector<char> is(input.vertexCount(), 0), out(r.origin.size(), 0);
  for (int v : at) is[v] = 1;
  for (size_t i = 0; i < r.origin.size(); ++i) {
    const SurfacePoint& p = r.origin[i];
    if (p.vertex >= 0) out[i] = is[p.vertex];
    for (int k = 0; k < 3 && p.face >= 0; ++k)
      if (p.bary[k] == 1.0) out[i] = is[input.triangles[p.face][k]];
  }
  return out;
}

/// Whether `r` has an output vertex at each of the input's vertices `at` (none when `at` is empty).
bool holdsEvery(const TriMesh& input, const std::vector<int>& at, const SurfaceRemeshResult& r) {
  const std::vector<char> is = atSamples(input, at, r);
  return !at.empty() && static_cast<size_t>(std::count(is.begin(), is.end(), 1)) >= at.size();
}

/// Issue 20: an output still above the count asked for (by more than countTolerance) after the
/// count search, as thin parts at low counts give, is brought down to it by edge collapses
/// (edge_collapse.h), weighted by the metric, then relaxed on the oriented input as the
/// triangulation was (when the parameters relax: not the adaptive preset); the relaxed one is kept
/// unless more of its faces cross.
void collapseToAsked(const TriMesh& input, const TriMesh& surface, const std::vector<char>& flipped,
                     const Metric& metric, const SurfaceRemeshParams& params, SurfaceRemeshResult& r) {
  const int target = params.sampling.targetCount;
  if (target <= 0 || r.mesh.vertexCount() <= (1.0 + params.countTolerance) * target) return;
  std::vector<double> weight = outputWeights(input, metric, r);
  const CollapseResult collapsed =
      collapseToCount(r.mesh, r.origin, weight, r.cell, target, atSamples(input, params.sampling.initialSamples, r));
  r.collapsedVertices = collapsed.collapsed;
  if (collapsed.collapsed == 0) return;
  r.crossingPairs = static_cast<int>(selfIntersectingFaces(r.mesh).size());
  if (params.relaxation.iterations > 0) relaxCollapsed(surface, flipped, metric, params, r);
}

/// collapseToAsked, collapseCrossings, and the fewest vertices reached without crossing faces
/// updated with the output.
void collapseToAskedAndCount(const TriMesh& input, const TriMesh& surface, const std::vector<char>& flipped,
                             const Metric& metric, const SurfaceRemeshParams& params,
                             const std::function<std::vector<char>()>& mayCross, SurfaceRemeshResult& r) {
  collapseToAsked(input, surface, flipped, metric, params, r);
  collapseCrossings(input, surface, flipped, metric, params, mayCross, r);
  if (r.collapsedVertices > 0 && r.crossingPairs == 0)
    r.fewestCount = r.fewestCount > 0 ? std::min(r.fewestCount, r.mesh.vertexCount()) : r.mesh.vertexCount();
}

/// One count search on the prepared surface: remeshSurface without the angle rescue, the polish,
/// the other starts and the measures.
Expected<SurfaceRemeshResult> remeshOnce(const TriMesh& input, const Metric& metric, Prepared& prepared,
                                         const SurfaceRemeshParams& params, double remeshShare, Progress progress) {
  auto clock = std::chrono::steady_clock::now();
  SurfaceRemeshResult r;
  const std::vector<char>& flipped = prepared.oriented.flipped;
  const TriMesh& surface = prepared.surface();
  const FrontSurface& front = prepared.front;
  // One engine: the triangulation goes on from the sampling's field.
  FastMarcher& marcher = *prepared.marcher;

  const Progress remeshing = progress.sub(front.geodesic.refined ? 0.1 * remeshShare : 0.0, remeshShare);
  SurfaceRemeshParams searchParams = params;
  searchParams.triangulation.mayCross = prepared.mayCross;
  Expected<SampledDual> sampled = sampleToCount(marcher, front, surface, searchParams, remeshing, r);
  if (!sampled) return sampled.status();
  const FpsResult& sampling = sampled->sampling;
  DelaunayResult& dual = sampled->dual;
  r.sampledAsked = sampled->requested;
  r.lloydIterations = sampled->lloydIterations;
  r.lloydEnergyRatio = sampled->lloydEnergyRatio;
  r.relaxation = sampled->relaxation;
  r.mesh = std::move(dual.mesh);
  r.origin = originsOnInput(dual.origin, front, surface, flipped);
  r.cell.assign(dual.cell.begin(), dual.cell.begin() + input.vertexCount());  // input vertices come first
  r.frontVertices = front.mesh().vertexCount();
  r.refinedSurface = front.geodesic.refined;
  r.refinedPoints = front.geodesic.insertedPoints();
  r.sampledCount = static_cast<int>(sampling.samples.size());
  r.coveringRadius = sampling.coveringRadius;
  r.addedSamples = dual.addedSamples;
  r.droppedSamples = dual.droppedSamples;
  r.repairRounds = dual.repairRounds;
  r.crossingRounds = dual.crossingRounds;
  r.crossingPairs = sampled->crossingPairs;
  r.flippedEdges = dual.flippedEdges;
  r.reorientedFaces = static_cast<int>(std::count(flipped.begin(), flipped.end(), 1));
  r.looseFaces = input.looseFaceCount();
  r.looksLikeTriangleSoup = TriMesh::looksLikeTriangleSoup(r.looseFaces, input.faceCount());
  lap(clock);
  collapseToAskedAndCount(input, surface, flipped, metric, params, searchParams.triangulation.mayCross, r);
  r.times.triangulation += lap(clock);
  return r;
}

void addTimes(RemeshStageTimes& to, const RemeshStageTimes& from) {
  to.prepare += from.prepare;
  to.engine += from.engine;
  to.sampling += from.sampling;
  to.triangulation += from.triangulation;
  to.relaxation += from.relaxation;
}

/// The angle rescue (SurfaceRemeshParams::kRescueAngleDegrees): `r` is replaced by the centroidal
/// output if that one is better. Fails only when cancelled.
Status rescueAngles(const TriMesh& input, const Metric& metric, Prepared& prepared, const SurfaceRemeshParams& params,
                    double remeshShare, Progress progress, SurfaceRemeshResult& r) {
  if (params.relaxation.iterations <= 0 || params.centroidalIterations > 0 || r.looksLikeTriangleSoup) return {};
  const double first = angleStatistics(r.mesh).minDegrees;
  if (!(first < SurfaceRemeshParams::kRescueAngleDegrees)) return {};
  SurfaceRemeshParams again = params;
  again.centroidalIterations = SurfaceRemeshParams::kRescueCentroidalIterations;
  Expected<SurfaceRemeshResult> second = remeshOnce(input, metric, prepared, again, remeshShare, progress);
  if (!second) return second.status().code == StatusCode::Cancelled ? second.status() : Status::ok();
  // No farther from the count asked for than the first output (give or take 1%).
  const auto miss = [&](const SurfaceRemeshResult& x) { return std::abs(x.mesh.vertexCount() - x.countAsked); };
  const bool better = angleStatistics(second->mesh).minDegrees > first && second->crossingPairs <= r.crossingPairs &&
                      miss(*second) <= miss(r) + 0.01 * r.countAsked;
  if (better) {
    addTimes(second->times, r.times);
    r = std::move(*second);
  } else {
    addTimes(r.times, second->times);
  }
  r.angleRescueTried = true;
  r.angleRescued = better;
  r.firstSmallestAngle = first;
  return {};
}

/// Per face of `after` (the same vertices and face count as `before`), 1 if its corners or their
/// positions differ from before's.
std::vector<char> changedFaces(const TriMesh& before, const TriMesh& after) {
  std::vector<char> changed(after.faceCount(), 0);
  for (int f = 0; f < after.faceCount(); ++f) {
    const Tri& t = after.triangles[f];
    changed[f] = t != before.triangles[f];
    for (int k = 0; k < 3 && !changed[f]; ++k) changed[f] = after.positions[t[k]] != before.positions[t[k]];
  }
  return changed;
}

/// Flat ears off the final output's boundary (removeFlatEars), where the relaxation runs. Removing
/// faces makes none cross: an output without crossing faces is one with fewer vertices.
void removeEars(const SurfaceRemeshParams& params, SurfaceRemeshResult& r) {
  if (params.relaxation.iterations <= 0 || r.looksLikeTriangleSoup) return;
  const double height = RelaxationParams::kEarHeight * params.relaxation.maxDeviation;
  r.removedEars = removeFlatEars(r.mesh, r.origin, r.cell, height).collapsed;
  if (r.removedEars > 0 && r.crossingPairs == 0 && r.fewestCount > 0)
    r.fewestCount = std::min(r.fewestCount, r.mesh.vertexCount());
}

/// `a` better than `b`: fewer faces under 30 degrees, or as many and a larger smallest angle.
bool betterAngles(const AngleStatistics& a, const AngleStatistics& b) {
  return a.shareMinBelow30 < b.shareMinBelow30 ||
         (a.shareMinBelow30 == b.shareMinBelow30 && a.minDegrees > b.minDegrees);
}

/// `a` worse than `b` in either figure.
bool worseAngles(const AngleStatistics& a, const AngleStatistics& b) {
  return a.shareMinBelow30 > b.shareMinBelow30 || a.minDegrees < b.minDegrees;
}

/// `mesh` (with its points on the input, `origin`) polished (polishOnSurface) on the oriented
/// input. A polish that makes more of its faces cross than `crossingPairs` is done again with the
/// corners of the crossing faces and their neighbours pinned, up to `pinRounds` times, else
/// not kept. Returns the polish kept, if any.
std::optional<RelaxationResult> polishWithoutCrossing(const Prepared& prepared, const RelaxationParams& relaxation,
                                                      PolishGuard guard, int crossingPairs, TriMesh& mesh,
                                                      std::vector<SurfacePoint>& origin, int pinRounds = 2) {
  const std::vector<char>& flipped = prepared.oriented.flipped;
  for (int round = 0; round <= pinRounds; ++round) {
    TriMesh polished = mesh;
    std::vector<SurfacePoint> points = origin;
    swapFlipped(points, flipped);
    const Expected<RelaxationResult> done = polishOnSurface(polished, points, prepared.surface(), relaxation, guard);
    if (!done || done->polishMoves == 0) return std::nullopt;
    // Without crossings before, only faces the polish changed can cross now.
    const std::vector<std::pair<int, int>> pairs =
        crossingPairs == 0 ? crossingsOfFaces(polished, changedFaces(mesh, polished)) : selfIntersectingFaces(polished);
    if (static_cast<int>(pairs.size()) <= crossingPairs) {
      swapFlipped(points, flipped);
      mesh = std::move(polished);
      origin = std::move(points);
      return *done;
    }
    flagCrossingCorners(polished, pairs, true, guard.pinned);
  }
  return std::nullopt;
}

/// The crossing pairs of `split`, r's mesh with edges split (splitWideFaces: its first faces are
/// r's, some changed, then the new ones): when r's faces cross nowhere, only those the split
/// changed can (crossingsOfFaces), else all are counted (selfIntersectingFaces).
std::vector<std::pair<int, int>> crossingsAfterSplit(const SurfaceRemeshResult& r, const TriMesh& split) {
  if (r.crossingPairs > 0) return selfIntersectingFaces(split);
  std::vector<char> changed(split.faceCount(), 1);
  for (int f = 0; f < r.mesh.faceCount(); ++f) changed[f] = split.triangles[f] != r.mesh.triangles[f];
  return crossingsOfFaces(split, changed);
}

/// Up to SurfaceRemeshParams::splitRounds rounds of splits of the edges of kind `edges` facing
/// the wide angles of faces under 30 degrees (splitWideFaces), each polished
/// (polishWithoutCrossing) and kept only if the share of faces under 30 degrees falls, or stays
/// and the smallest angle rises, neither getting worse against `before` (r's angles, updated),
/// with no more crossing pairs; at most `most` split vertices in all. Faces split in a round not
/// kept are not tried again until one is kept.
void runSplitRounds(const Prepared& prepared, const SurfaceRemeshParams& params, SplitEdges edges, int most,
                    AngleStatistics& before, SurfaceRemeshResult& r) {
  const RelaxationParams& relaxation = params.relaxation;
  const std::vector<char>& flipped = prepared.oriented.flipped;
  std::vector<char> refused;  // per face of r.mesh: split in a round not kept
  for (int round = 0; round < params.splitRounds && before.shareMinBelow30 > 0 && r.splitVertices < most; ++round) {
    TriMesh mesh = r.mesh;
    std::vector<SurfacePoint> points = r.origin;
    swapFlipped(points, flipped);
    const Expected<int> n =
        splitWideFaces(mesh, points, prepared.surface(), relaxation, most - r.splitVertices, refused, edges);
    if (!n || *n == 0) break;
    const auto refuse = [&] {
      refused.resize(r.mesh.faceCount(), 0);
      for (int f = 0; f < r.mesh.faceCount(); ++f) refused[f] |= mesh.triangles[f] != r.mesh.triangles[f];
    };
    swapFlipped(points, flipped);
    PolishGuard guard;
    guard.voronoiCells = false;
    if (mesh.vertexCount() <= params.measuredPolishVertices) guard.cell = &r.cell;
    const int splitPairs = static_cast<int>(crossingsAfterSplit(r, mesh).size());
    const std::optional<RelaxationResult> polished =
        polishWithoutCrossing(prepared, relaxation, guard, std::max(splitPairs, r.crossingPairs), mesh, points);
    const AngleStatistics a = angleStatistics(mesh);
    // The polish keeps the pairs at most max(splitPairs, r.crossingPairs): counted again only
    // when the split made more.
    const bool moreCross =
        splitPairs > r.crossingPairs && static_cast<int>(selfIntersectingFaces(mesh).size()) > r.crossingPairs;
    if (!betterAngles(a, before) || worseAngles(a, before) || moreCross) {
      refuse();
      continue;
    }
    refused.clear();
    before = a;
    r.mesh = std::move(mesh);
    r.origin = std::move(points);
    r.splitVertices += *n;
    ++r.splitRounds;
    if (polished) {
      r.relaxation.polishMoves += polished->polishMoves;
      r.relaxation.flips += polished->flips;
    }
  }
}

/// The splits of faces under 30 degrees held by a wide angle (SurfaceRemeshParams::splitRounds):
/// rounds of inner edges' splits (runSplitRounds), then rounds of boundary edges' splits, which
/// start from what the inner ones reached, so that they only ever improve on it. At most
/// kSplitShare of the count asked in all. As the first polish, no check of the distance to the
/// input beyond the polish's own (RelaxationParams::maxDeviation).
void splitAndPolish(const Prepared& prepared, const SurfaceRemeshParams& params, SurfaceRemeshResult& r) {
  const RelaxationParams& relaxation = params.relaxation;
  if (params.splitRounds <= 0 || relaxation.iterations <= 0 || !relaxation.raiseSmallestAngle ||
      relaxation.polishMarginDegrees < 0 || r.looksLikeTriangleSoup || r.inputKept)
    return;
  auto clock = std::chrono::steady_clock::now();
  const int count = r.countAsked > 0 ? r.countAsked : r.mesh.vertexCount();
  const int most = static_cast<int>(SurfaceRemeshParams::kSplitShare * count);
  AngleStatistics before = angleStatistics(r.mesh);
  const int splitBefore = r.splitVertices;
  for (const SplitEdges edges : {SplitEdges::Inner, SplitEdges::Boundary})
    runSplitRounds(prepared, params, edges, most, before, r);
  // splitWideFaces builds the adjacency alone: the topology, which the log reports, is counted
  // once here. (Without it, lion and cylinder_locally_refined at 30% logged 0 components.)
  if (r.splitVertices != splitBefore) countTopology(r.mesh);
  r.times.relaxation += lap(clock);
}

/// The final output polished (polishWithoutCrossing). Only after the rescues: their choices are
/// made on the relaxed outputs.
void polishOutput(const Prepared& prepared, const SurfaceRemeshParams& params, SurfaceRemeshResult& r) {
  const RelaxationParams& relaxation = params.relaxation;
  if (relaxation.iterations <= 0 || !relaxation.raiseSmallestAngle || relaxation.polishMarginDegrees < 0 ||
      r.looksLikeTriangleSoup)
    return;
  auto clock = std::chrono::steady_clock::now();
  PolishGuard guard;  // the cells let the polish measure its distance to the input
  if (r.mesh.vertexCount() <= params.measuredPolishVertices) guard.cell = &r.cell;
  guard.voronoiCells = cellsAreVoronoi(r);
  const std::optional<RelaxationResult> done =
      polishWithoutCrossing(prepared, relaxation, guard, r.crossingPairs, r.mesh, r.origin);
  if (done) {
    r.relaxation.polishMoves = done->polishMoves;
    r.relaxation.flips += done->flips;
  }
  r.times.relaxation += lap(clock);
}

/// The two-sided distance between the output and the input at remeshDistances' samples, the
/// input's face centroids and side midpoints too: the judge of the starts, the last polishes and
/// the ears' cuts. (At the input's vertices alone it let a start and polishes be kept that the
/// oracle finds farther: spool at 10% 6.78 -> 6.90%, triceratops at 30% 1.282 -> 1.346% of the
/// diagonal.)
double outputDistance(const TriMesh& input, const SurfaceRemeshResult& r) {
  const RemeshDistances d =
      remeshDistances(input, r.mesh, r.cell, r.origin, cellsAreVoronoi(r), DistanceSamples::VerticesMidpointsCentroids);
  return std::max(d.toInput.max, d.fromInput.max);
}

/// The last steps' judge of the distance to the input (outputDistance): the output's distance
/// once measured, and the first one measured, which the thin ears' cuts may exceed by
/// SurfaceRemeshParams::earSlack.
struct LastDistance {
  double slack = 0.0;
  double current = -1.0;    ///< the output's, once measured; negative: to be measured
  double reference = -1.0;  ///< the first measured
  /// r's distance (the output's), measured if not known yet.
  double of(const TriMesh& input, const SurfaceRemeshResult& r) {
    if (current < 0) current = outputDistance(input, r);
    if (reference < 0) reference = current;
    return current;
  }
  /// Whether an output at distance d is no farther than the one measured (`of` called first).
  bool noFarther(double d) const { return d <= current; }
  /// Whether an output at distance d is no farther than the one measured or than the first one
  /// with the slack (`of` called first).
  bool withinSlack(double d) const { return d <= std::max(current, (1.0 + slack) * reference); }
};

/// Whether `other`, r changed, is to be kept: better angles than `before` (r's; betterAngles),
/// neither figure worse, and a distance to the input `distance` allows. If so, `before` and
/// `distance` become other's.
bool betterAndNoFarther(const TriMesh& input, const SurfaceRemeshResult& r, const SurfaceRemeshResult& other,
                        AngleStatistics& before, LastDistance& distance) {
  const AngleStatistics after = angleStatistics(other.mesh);
  if (!betterAngles(after, before) || worseAngles(after, before)) return false;
  distance.of(input, r);
  const double d = outputDistance(input, other);
  if (!distance.noFarther(d)) return false;
  distance.current = d;
  before = after;
  return true;
}

/// The last polishes (SurfaceRemeshParams::lastPolishVertices): r polished again from where it
/// stands with the relaxation's deviation limit, then with restartDeviation's, each kept only if
/// its angles are better and neither worse, with no more crossing pairs and no farther from the
/// input (outputDistance, the input's centroids and midpoints measured too; `distance`, the last
/// steps' judge: r's measured if not yet known; updated).
void polishAgain(const TriMesh& input, const Prepared& prepared, const SurfaceRemeshParams& params,
                 SurfaceRemeshResult& r, LastDistance& distance) {
  if (r.mesh.vertexCount() > params.lastPolishVertices || r.inputKept) return;
  AngleStatistics before = angleStatistics(r.mesh);  // r's, taken once
  if (!(before.minDegrees < SurfaceRemeshParams::kLastPolishBelowDegrees)) return;
  auto clock = std::chrono::steady_clock::now();
  const double relaxation = r.times.relaxation;  // the polishes' own laps are counted in this one's
  for (const double deviation : {params.relaxation.maxDeviation, params.restartDeviation}) {
    if (!(deviation > 0)) continue;
    SurfaceRemeshResult polished = r;
    SurfaceRemeshParams looser = params;
    looser.relaxation.maxDeviation = deviation;
    polished.relaxation.polishMoves = 0;  // this polish's, then added to r's
    polishOutput(prepared, looser, polished);
    polished.relaxation.polishMoves += r.relaxation.polishMoves;
    if (polished.crossingPairs > r.crossingPairs || !betterAndNoFarther(input, r, polished, before, distance)) continue;
    r = std::move(polished);
    ++r.lastPolishes;
  }
  r.times.relaxation = relaxation + lap(clock);
}

/// The thin ears (thinEars in edge_collapse.h) of an output the relaxation ran on, cut thinnest
/// first, each kept only if the distance to the input (outputDistance, the input's centroids and
/// midpoints too) does not grow beyond the larger of the output's and the first one measured
/// raised by earSlack (LastDistance::withinSlack); kEarRounds tried at most. That judge bounds
/// how deep an ear may be: no point of the input may end much farther from the output than the
/// farthest one already is.
/// (A bound of one mean output edge besides, the first version's, held ALSTOM_TEST4's ear of
/// 2.15 edges at 10%: 6.9 degrees, cut 18.6, the distance the same.) A cut takes a face under 30
/// degrees away and changes no other: no angle falls, nothing new crosses. `distance` as
/// polishAgain's.
void cutThinEars(const TriMesh& input, const SurfaceRemeshParams& params, SurfaceRemeshResult& r,
                 LastDistance& distance) {
  if (!params.cutThinEars || params.relaxation.iterations <= 0 || r.looksLikeTriangleSoup || r.inputKept) return;
  auto clock = std::chrono::steady_clock::now();
  for (int tried = 0, cut = 1; cut && tried < kEarRounds;) {
    cut = 0;
    for (const int face : thinEars(r.mesh, std::numeric_limits<double>::infinity())) {
      if (tried++ == kEarRounds) break;
      SurfaceRemeshResult without = r;
      if (!removeEar(without.mesh, without.origin, without.cell, face)) continue;
      distance.of(input, r);
      const double d = outputDistance(input, without);
      if (!distance.withinSlack(d)) continue;
      distance.current = d;
      r = std::move(without);
      ++r.removedEars;
      ++r.thinEars;
      cut = 1;
      break;  // the faces are numbered anew
    }
  }
  if (r.thinEars > 0 && r.crossingPairs > 0)  // a cut face may have crossed
    r.crossingPairs = static_cast<int>(selfIntersectingFaces(r.mesh).size());
  if (r.thinEars > 0 && r.crossingPairs == 0 && r.fewestCount > 0)
    r.fewestCount = std::min(r.fewestCount, r.mesh.vertexCount());
  r.times.relaxation += lap(clock);
}

/// The joint climbs (climbJointly in surface_relaxation.h) of the final output, up to
/// SurfaceRemeshParams::jointClimbVertices and under kLastPolishBelowDegrees, kept if the
/// distance to the input (outputDistance; `distance` as polishAgain's) does not grow; the
/// relaxation's outputs only.
void climbJointlyAtLast(const TriMesh& input, const Prepared& prepared, const SurfaceRemeshParams& params,
                        SurfaceRemeshResult& r, LastDistance& distance) {
  const RelaxationParams& relaxation = params.relaxation;
  if (r.mesh.vertexCount() > params.jointClimbVertices || relaxation.iterations <= 0 ||
      !relaxation.raiseSmallestAngle || relaxation.polishMarginDegrees < 0 || r.looksLikeTriangleSoup || r.inputKept)
    return;
  // As for the last polishes: above it the climbs and the distances cost most and bring least.
  if (!(angleStatistics(r.mesh).minDegrees < SurfaceRemeshParams::kLastPolishBelowDegrees)) return;
  auto clock = std::chrono::steady_clock::now();
  SurfaceRemeshResult climbed = r;
  const std::vector<char>& flipped = prepared.oriented.flipped;
  swapFlipped(climbed.origin, flipped);
  const Expected<int> moves = climbJointly(climbed.mesh, climbed.origin, prepared.surface(), relaxation);
  swapFlipped(climbed.origin, flipped);
  if (moves && *moves > 0) {
    distance.of(input, r);
    const double after = outputDistance(input, climbed);
    if (distance.noFarther(after)) {
      distance.current = after;
      r = std::move(climbed);
      r.jointMoves = *moves;
    }
  }
  r.times.relaxation += lap(clock);
}

/// Whether a face with the smallest angle of `mesh` (`smallestDegrees`) is a thin ear
/// (thinEars): only then can a cut raise that angle.
bool smallestIsAThinEar(const TriMesh& mesh, double smallestDegrees) {
  const std::vector<int> ears = thinEars(mesh, std::numeric_limits<double>::infinity());
  if (ears.empty()) return false;
  const Tri& t = mesh.triangles[ears.front()];  // the thinnest
  const double degrees = smallestAngle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]) * 180.0 / kPi;
  return degrees <= smallestDegrees + 1e-6;  // angleStatistics measures by acos, angleAt by atan2
}

/// The splits (splitAndPolish) from r as it stands and, where the face with r's smallest angle is
/// a thin ear the cuts' judge (cutThinEars) lets be cut, from r with its thin ears cut too: the
/// better angles kept (betterAngles; r's own splits when the other's are not better), as
/// SurfaceRemeshParams::earsBeforeSplits says. `distance` as polishAgain's; unknown again where a
/// split was kept.
void splitWithAndWithoutEars(const TriMesh& input, const Prepared& prepared, const SurfaceRemeshParams& params,
                             SurfaceRemeshResult& r, LastDistance& distance) {
  const double relaxation = r.times.relaxation;  // each branch adds its laps to its own
  const double smallest = angleStatistics(r.mesh).minDegrees;
  std::optional<SurfaceRemeshResult> cut;
  LastDistance cutDistance = distance;
  if (params.cutThinEars && params.earsBeforeSplits && smallestIsAThinEar(r.mesh, smallest)) {
    cut = r;
    cutThinEars(input, params, *cut, cutDistance);
    if (!(angleStatistics(cut->mesh).minDegrees > smallest)) {
      r.times.relaxation += cut->times.relaxation - relaxation;
      cut.reset();
    }
  }
  const auto split = [&](SurfaceRemeshResult& s, LastDistance& d) {
    const int rounds = s.splitRounds;
    splitAndPolish(prepared, params, s);
    if (s.splitRounds != rounds) d.current = -1.0;
  };
  split(r, distance);
  if (!cut) return;
  split(*cut, cutDistance);
  if (!betterAngles(angleStatistics(cut->mesh), angleStatistics(r.mesh))) {
    r.times.relaxation += cut->times.relaxation - relaxation;
    return;
  }
  cut->times.relaxation += r.times.relaxation - relaxation;
  r = std::move(*cut);
  distance = cutDistance;
}

/// The face of `mesh` with the smallest angle.
int worstFace(const TriMesh& mesh) {
  int worst = 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    const double angle = smallestAngle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
    if (angle < smallest) smallest = angle, worst = f;
  }
  return worst;
}

/// The vertex of `face` inside the surface with three faces (no boundary edge around it), or -1. Its faces split the triangle of its neighbours in three, so one of them has an
/// angle of at most half that triangle's smallest: 30 degrees at best.
int innerVertexOfThreeFaces(const TriMesh& mesh, int face) {
  for (const int v : mesh.triangles[face]) {
    if (mesh.valence(v) != 3) continue;
    bool inner = true;
    for (const int* c = mesh.cornersBegin(v); c != mesh.cornersEnd(v); ++c)
      inner &= mesh.oppositeCorner[TriMesh::next(*c)] >= 0 && mesh.oppositeCorner[TriMesh::prev(*c)] >= 0;
    if (inner) return v;
  }
  return -1;
}

/// The collapses at the face with the smallest angle (SurfaceRemeshParams::worstFaceCollapses):
/// of any of its vertices on an output above the count asked for, of its vertex with three
/// faces (innerVertexOfThreeFaces) on one within the count's tolerance below it too.
/// `distance` as polishAgain's.
void collapseWorstFaces(const TriMesh& input, const Metric& metric, const SurfaceRemeshParams& params,
                        SurfaceRemeshResult& r, LastDistance& distance) {
  const RelaxationParams& relaxation = params.relaxation;
  if (params.worstFaceCollapses <= 0 || r.countAsked <= 0 || relaxation.iterations <= 0 || r.looksLikeTriangleSoup ||
      r.inputKept)
    return;
  const double above = (1.0 + params.countTolerance) * r.countAsked;  // collapseToAsked's bound
  const double below = (1.0 - params.countTolerance) * r.countAsked;
  const auto aboveTheCount = [&](int n) { return n > above && n <= params.jointClimbVertices; };
  const auto allowed = [&](int n, int three) {
    return aboveTheCount(n) || (three >= 0 && n > below && n <= params.floorVertices);
  };
  AngleStatistics before = angleStatistics(r.mesh);
  if (!(before.minDegrees < SurfaceRemeshParams::kLastPolishBelowDegrees) ||
      !allowed(r.mesh.vertexCount(), innerVertexOfThreeFaces(r.mesh, worstFace(r.mesh))))
    return;
  auto clock = std::chrono::steady_clock::now();
  std::vector<double> weight = outputWeights(input, metric, r);  // compacted with the vertices kept
  for (int k = 0; k < params.worstFaceCollapses && before.minDegrees < SurfaceRemeshParams::kLastPolishBelowDegrees;
       ++k) {
    const int worst = worstFace(r.mesh), three = innerVertexOfThreeFaces(r.mesh, worst);
    const int n = r.mesh.vertexCount();
    if (!allowed(n, three)) break;
    std::vector<char> keep(n, 1);  // every vertex but the worst face's, or but its vertex with three faces
    if (three >= 0 && !aboveTheCount(n))
      keep[three] = 0;
    else
      for (const int v : r.mesh.triangles[worst]) keep[v] = 0;
    SurfaceRemeshResult collapsed = r;
    std::vector<double> collapsedWeight = weight;
    if (collapseToCount(collapsed.mesh, collapsed.origin, collapsedWeight, collapsed.cell, n - 1, keep).collapsed == 0)
      break;
    ++collapsed.collapsedVertices;  // before its distance: its cells are no longer Voronoi cells
    ++collapsed.worstFaceCollapses;
    if (!betterAndNoFarther(input, r, collapsed, before, distance)) break;
    r = std::move(collapsed);
    weight = std::move(collapsedWeight);
  }
  if (r.worstFaceCollapses > 0 && r.crossingPairs > 0)  // a face gone may have crossed
    r.crossingPairs = static_cast<int>(selfIntersectingFaces(r.mesh).size());
  if (r.worstFaceCollapses > 0 && r.crossingPairs == 0 && r.fewestCount > 0)
    r.fewestCount = std::min(r.fewestCount, r.mesh.vertexCount());
  r.times.relaxation += lap(clock);
}

/// The floor polishes (SurfaceRemeshParams::floorVertices): polishes from where r stands, one
/// after the other with the margins kFloorMargins (the first's aim at most
/// kFloorFirstAimDegrees), the vertices on the input's feature curves
/// held; the one with the best angles (betterAngles, none worse than r's) no farther from the
/// input than r (outputDistance) and with no more crossing pairs is kept. `distance` as
/// polishAgain's.
void polishTheFloor(const TriMesh& input, const Prepared& prepared, const SurfaceRemeshParams& params,
                    SurfaceRemeshResult& r, LastDistance& distance) {
  const RelaxationParams& relaxation = params.relaxation;
  if (r.mesh.vertexCount() > params.floorVertices || relaxation.iterations <= 0 || !relaxation.raiseSmallestAngle ||
      relaxation.polishMarginDegrees < 0 || r.looksLikeTriangleSoup || r.inputKept)
    return;
  const AngleStatistics first = angleStatistics(r.mesh);
  if (!(first.minDegrees < SurfaceRemeshParams::kLastPolishBelowDegrees)) return;
  auto clock = std::chrono::steady_clock::now();
  const double relaxationSeconds = r.times.relaxation;
  RelaxationParams held = relaxation;
  held.slideAlongFeatures = false;
  AngleStatistics best = first;
  SurfaceRemeshResult polished = r;
  polished.relaxation.polishMoves = 0;  // the floor polishes', then added to r's
  std::optional<SurfaceRemeshResult> kept;
  double keptDistance = distance.current;
  for (const double margin : SurfaceRemeshParams::kFloorMargins) {
    // The first aims at most at kFloorFirstAimDegrees: above it nearly every ring climbs.
    held.polishMarginDegrees = polished.floorPolishes == 0
                                   ? std::min(margin, SurfaceRemeshParams::kFloorFirstAimDegrees - first.minDegrees)
                                   : margin;
    const std::optional<RelaxationResult> done =
        polishWithoutCrossing(prepared, held, PolishGuard{}, r.crossingPairs, polished.mesh, polished.origin, 0);
    if (!done) break;  // nothing moved (or every try crossed): the next margins start from here too
    polished.relaxation.polishMoves += done->polishMoves;
    polished.relaxation.flips += done->flips;
    ++polished.floorPolishes;
    const AngleStatistics a = angleStatistics(polished.mesh);
    if (!betterAngles(a, best) || worseAngles(a, first)) continue;
    if (distance.current < 0) keptDistance = distance.of(input, r);
    const double d = outputDistance(input, polished);
    if (!distance.noFarther(d)) continue;
    best = a;
    keptDistance = d;
    kept = polished;
  }
  if (kept) {
    kept->relaxation.polishMoves += r.relaxation.polishMoves;
    r = std::move(*kept);
    distance.current = keptDistance;
  }
  r.times.relaxation = relaxationSeconds + lap(clock);
}

/// The shakes' random numbers: uniform in [0, 1), the same sequence for a seed on every platform.
class ShakeDraws {
 public:
  explicit ShakeDraws(unsigned seed) : generator_(seed) {}
  double unit() { return static_cast<double>(generator_() >> 8) / static_cast<double>(1u << 24); }
  double in(double low, double high) { return low + (high - low) * unit(); }

 private:
  std::mt19937 generator_;
};

/// One shake (SurfaceRemeshParams::shakes) of `mesh`: each vertex inside an input face moved, with
/// a chance of kShakeShare, to a random point of an input face whose centroid (`centroids`) lies
/// within `radius` of it. Returns how many moved.
int shakeInnerVertices(const TriMesh& input, const std::vector<Vec3>& centroids, double radius, ShakeDraws& draws,
                       TriMesh& mesh, std::vector<SurfacePoint>& origin) {
  int moved = 0;
  std::vector<int> near;
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    const SurfacePoint& at = origin[v];
    if (at.vertex >= 0 || draws.unit() > SurfaceRemeshParams::kShakeShare || !(at.bary.minCoeff() > 0)) continue;
    near.clear();
    for (int f = 0; f < input.faceCount(); ++f)
      if ((centroids[f] - mesh.positions[v]).norm() < radius) near.push_back(f);
    if (near.empty()) continue;
    const int face = near[std::min(static_cast<int>(near.size()) - 1, static_cast<int>(draws.unit() * near.size()))];
    const double u = draws.in(0.05, 0.9), w = draws.in(0.05, 0.95 - u);
    origin[v] = SurfacePoint::inFace(face, Vec3(u, w, 1 - u - w));
    mesh.positions[v] = origin[v].position(input);
    ++moved;
  }
  return moved;
}

/// The shakes of a small output (SurfaceRemeshParams::shakes), each from the best output so far,
/// polished (polishWithoutCrossing), kept where betterAndNoFarther and with no more crossing
/// pairs. `distance` as polishAgain's.
void shakeSmallOutput(const TriMesh& input, const Prepared& prepared, const SurfaceRemeshParams& params,
                      SurfaceRemeshResult& r, LastDistance& distance) {
  const RelaxationParams& relaxation = params.relaxation;
  if (params.shakes <= 0 || r.mesh.vertexCount() > SurfaceRemeshParams::kRestartVertices ||
      input.vertexCount() > SurfaceRemeshParams::kRestartInputVertices || relaxation.iterations <= 0 ||
      !relaxation.raiseSmallestAngle || relaxation.polishMarginDegrees < 0 || r.looksLikeTriangleSoup || r.inputKept)
    return;
  auto clock = std::chrono::steady_clock::now();
  std::vector<Vec3> centroids(input.faceCount());
  for (int f = 0; f < input.faceCount(); ++f) {
    const Tri& t = input.triangles[f];
    centroids[f] = (input.positions[t[0]] + input.positions[t[1]] + input.positions[t[2]]) / 3.0;
  }
  const double radius = SurfaceRemeshParams::kShakeRadius * r.mesh.meanEdgeLength();
  AngleStatistics before = angleStatistics(r.mesh);
  ShakeDraws draws(params.sampling.seed);
  distance.of(input, r);
  const LastDistance start = distance;
  r.shakesRun = std::min(params.shakes, SurfaceRemeshParams::kShakeWork / r.mesh.vertexCount());
  for (int k = 0; k < r.shakesRun; ++k) {
    SurfaceRemeshResult shaken = r;
    if (shakeInnerVertices(input, centroids, radius, draws, shaken.mesh, shaken.origin) == 0) continue;
    if (!polishWithoutCrossing(prepared, relaxation, PolishGuard{}, r.crossingPairs, shaken.mesh, shaken.origin, 0))
      continue;
    // The shake itself may have made faces cross, which the polish's own check does not see.
    if (static_cast<int>(selfIntersectingFaces(shaken.mesh).size()) > r.crossingPairs) continue;
    LastDistance judge = start;  // no farther than before the shakes
    if (!betterAndNoFarther(input, r, shaken, before, judge)) continue;
    distance.current = judge.current;
    r = std::move(shaken);
    ++r.shakesKept;
  }
  r.times.relaxation += lap(clock);
}

/// An output with more vertices than the input is no remesh (many components and boundary loops
/// at a small count: boeing.off at 10% needs 5,549 vertices for its 2,741): the input, oriented
/// (the prepared copy), is kept instead, each vertex its own cell. Not for an input with isolated vertices, which an
/// output never has.
void keepInputIfSmaller(const TriMesh& input, const Prepared& prepared, SurfaceRemeshResult& r) {
  if (r.mesh.vertexCount() <= input.vertexCount() || input.topology.isolatedVertices > 0) return;
  const std::vector<char>& flipped = prepared.oriented.flipped;
  r.remeshedCount = r.mesh.vertexCount();
  r.mesh = prepared.surface();
  r.origin.resize(input.vertexCount());
  r.cell.resize(input.vertexCount());
  for (int v = 0; v < input.vertexCount(); ++v) {
    r.origin[v] = SurfacePoint::atVertex(v);
    r.cell[v] = v;
  }
  r.crossingPairs = static_cast<int>(selfIntersectingFaces(r.mesh).size());
  r.reorientedFaces = static_cast<int>(std::count(flipped.begin(), flipped.end(), 1));
  r.inputKept = true;
}

/// One whole remesh: the count search (remeshOnce), the angle rescue, the ears, the polish, and
/// the input kept where the remesh would be larger.
Expected<SurfaceRemeshResult> remeshWhole(const TriMesh& input, const Metric& metric, Prepared& prepared,
                                          const SurfaceRemeshParams& p, double remeshShare, Progress progress) {
  Expected<SurfaceRemeshResult> r = remeshOnce(input, metric, prepared, p, remeshShare, progress);
  if (!r) return r.status();
  if (Status s = rescueAngles(input, metric, prepared, p, remeshShare, progress, *r); !s) return s;
  removeEars(p, *r);
  polishOutput(prepared, p, *r);
  keepInputIfSmaller(input, prepared, *r);
  return r;
}

/// The starts of an output of n vertices other than the first, in the order they are judged: the
/// seeds sampling.seed + 1 .. + restarts, then the seeds from the first to + restartsFor(n) with
/// the looser relaxation (restartDeviation), where the other starts of the smallest outputs were
/// kept; without it, the seeds up to + restartsFor(n).
std::vector<SurfaceRemeshParams> otherStarts(const SurfaceRemeshParams& p, int n) {
  const int seeds = p.restartsFor(n);
  const bool looser = p.restartDeviation > p.relaxation.maxDeviation;
  std::vector<SurfaceRemeshParams> starts;
  for (int k = 1; k <= (looser ? p.restarts : seeds); ++k) {
    starts.push_back(p);
    starts.back().sampling.seed = p.sampling.seed + static_cast<unsigned>(k);
  }
  if (looser)
    for (int k = 0; k <= seeds; ++k) {
      starts.push_back(p);
      starts.back().sampling.seed = p.sampling.seed + static_cast<unsigned>(k);
      starts.back().relaxation.maxDeviation = p.restartDeviation;
    }
  return starts;
}

/// The starts sampled from the corners of the input's feature curves (featureCorners: the
/// relaxation never moves a vertex there), appended to `starts`: with the relaxation of `held`
/// and, where it is looser, restartDeviation's. The seeds' samplings may leave corners out, and the
/// output's boundary then cuts them with chords (patch-23, a 100 x 33 rectangle, at 10%: two of
/// its four corners). None when there are no corners or not fewer than the samples asked for;
/// restartSmallOutput passes each over where the output kept so far has a vertex at every corner
/// (the looser one too, once the first is kept).
void cornerStarts(const Prepared& prepared, const SurfaceRemeshParams& held, std::vector<SurfaceRemeshParams>& starts) {
  if (!held.cornerStarts) return;
  std::vector<int> corners = featureCorners(prepared.surface(), held.relaxation);
  if (corners.empty() || static_cast<int>(corners.size()) >= held.sampling.targetCount) return;
  starts.push_back(held);
  starts.back().sampling.initialSamples = std::move(corners);
  if (held.restartDeviation > held.relaxation.maxDeviation) {
    starts.push_back(starts.back());
    starts.back().relaxation.maxDeviation = held.restartDeviation;
  }
}

/// The starts with the boundaries sampled less densely (SurfaceRemeshParams::boundaryStartPriority),
/// appended to `starts`: with the relaxation of `held` and, where it is looser, restartDeviation's.
/// None for an input without boundaries.
void boundaryStarts(const TriMesh& input, const SurfaceRemeshParams& held, std::vector<SurfaceRemeshParams>& starts) {
  if (!(held.boundaryStartPriority >= 1.0) || held.boundaryStartPriority == held.sampling.boundaryPriority ||
      input.topology.boundaryLoops == 0)
    return;
  starts.push_back(held);
  starts.back().sampling.boundaryPriority = held.boundaryStartPriority;
  if (held.restartDeviation > held.relaxation.maxDeviation) {
    starts.push_back(starts.back());
    starts.back().relaxation.maxDeviation = held.restartDeviation;
  }
}

/// A small output's first start with every crease held (RelaxationParams::minCreaseLength 0),
/// when short creases are not: it replaces `r` as the first start, and `r` is returned, to be
/// judged as the last of the others (the other seeds hold every crease too). Nothing if it fails (`r`
/// stays first). Fails only when cancelled.
Expected<std::optional<SurfaceRemeshResult>> holdEveryCrease(const TriMesh& input, const Metric& metric,
                                                             Prepared& prepared, const SurfaceRemeshParams& p,
                                                             SurfaceRemeshResult& r) {
  if (!(p.relaxation.minCreaseLength > 0)) return std::optional<SurfaceRemeshResult>{};
  SurfaceRemeshParams held = p;
  held.relaxation.minCreaseLength = 0;
  Expected<SurfaceRemeshResult> first = remeshWhole(input, metric, prepared, held, 1.0, Progress{});
  if (!first) {
    if (first.status().code == StatusCode::Cancelled) return first.status();
    return std::optional<SurfaceRemeshResult>{};
  }
  std::swap(r, *first);
  r.keptSeed = first->keptSeed;
  r.keptDeviation = first->keptDeviation;
  r.keptCreasesHeld = true;
  return std::optional<SurfaceRemeshResult>(std::move(*first));
}

/// The other starts of a small output (SurfaceRemeshParams::restarts, restartDeviation): the first
/// and the other seeds hold every crease (holdEveryCrease; the output with short creases free is
/// then the last of the others), and `r` is replaced by the best of the others where one is
/// better and no worse in any figure than the first, its distance to the input included; a start
/// with the looser relaxation or from the corners (cornerStarts) must also be no farther from the
/// input than the output kept so far.
/// A start that fails is passed over; fails only when cancelled. times.restarts is the wall time
/// of the starts other than the one kept.
Status restartSmallOutput(const TriMesh& input, const Metric& metric, Prepared& prepared, const SurfaceRemeshParams& p,
                          Progress progress, SurfaceRemeshResult& r) {
  r.keptSeed = p.sampling.seed;
  r.keptDeviation = p.relaxation.maxDeviation;
  r.keptBoundaryPriority = p.sampling.boundaryPriority;
  if (p.restarts <= 0 || r.mesh.vertexCount() > SurfaceRemeshParams::kRestartVertices ||
      input.vertexCount() > SurfaceRemeshParams::kRestartInputVertices || r.inputKept || r.looksLikeTriangleSoup)
    return {};
  auto clock = std::chrono::steady_clock::now();
  Expected<std::optional<SurfaceRemeshResult>> freeCreases = holdEveryCrease(input, metric, prepared, p, r);
  if (!freeCreases) return freeCreases.status();
  const AngleStatistics first = angleStatistics(r.mesh);
  AngleStatistics best = first;
  const double firstDistance = outputDistance(input, r);
  double keptDistance = firstDistance;
  std::optional<SurfaceRemeshResult> kept;
  SurfaceRemeshParams held = p;  // the other seeds hold every crease as the first does
  if (*freeCreases) held.relaxation.minCreaseLength = 0;
  std::vector<SurfaceRemeshParams> starts = otherStarts(held, r.mesh.vertexCount());
  cornerStarts(prepared, held, starts);
  boundaryStarts(input, held, starts);
  if (*freeCreases) starts.push_back(p);  // judged last: r's own start, short creases free
  // A swap made the held start's stages the first's, and the free one's among the others.
  double others = *freeCreases ? (*freeCreases)->times.remesh() - r.times.remesh() : 0.0;
  int passedOver = 0;  // starts from the corners not run
  for (size_t k = 0; k < starts.size(); ++k) {
    const SurfaceRemeshParams& start = starts[k];
    if (!progress.report(1.0, "Other starts")) return cancelled();             // at the remesh's end: a check only
    if (holdsEvery(input, start.sampling.initialSamples, kept ? *kept : r)) {  // no corner to win back
      ++passedOver;
      continue;
    }
    Expected<SurfaceRemeshResult> other = *freeCreases && k + 1 == starts.size()
                                              ? Expected<SurfaceRemeshResult>(std::move(**freeCreases))
                                              : remeshWhole(input, metric, prepared, start, 1.0, Progress{});
    if (!other) continue;
    const AngleStatistics a = angleStatistics(other->mesh);
    // A looser relaxation's start, or one from the corners, no farther than the output kept so far.
    const bool nearer =
        start.relaxation.maxDeviation > p.relaxation.maxDeviation || !start.sampling.initialSamples.empty();
    if (!betterAngles(a, best) || other->mesh.vertexCount() != r.mesh.vertexCount() ||
        other->crossingPairs > r.crossingPairs || worseAngles(a, first))
      continue;
    const double d = outputDistance(input, *other);
    if (d > (nearer ? keptDistance : firstDistance)) continue;
    best = a;
    keptDistance = d;
    kept = std::move(*other);
    kept->keptStart = static_cast<int>(k) + 1 - passedOver;
    kept->keptSeed = start.sampling.seed;
    kept->keptCorners = static_cast<int>(start.sampling.initialSamples.size());
    kept->keptDeviation = start.relaxation.maxDeviation;
    kept->keptBoundaryPriority = start.sampling.boundaryPriority;
    kept->keptCreasesHeld = !(start.relaxation.minCreaseLength > 0);
  }
  others += lap(clock);
  if (kept) {  // the first's stages are now among the others, the kept one's no longer
    others += r.times.remesh() - kept->times.remesh();
    r = std::move(*kept);
  }
  r.starts = 1 + static_cast<int>(starts.size()) - passedOver;
  r.cornerStarts =
      static_cast<int>(std::count_if(starts.begin(), starts.end(),
                                     [](const SurfaceRemeshParams& s) { return !s.sampling.initialSamples.empty(); })) -
      passedOver;
  r.boundaryStarts = static_cast<int>(std::count_if(starts.begin(), starts.end(), [&](const SurfaceRemeshParams& s) {
    return s.sampling.boundaryPriority != p.sampling.boundaryPriority;
  }));
  r.times.restarts = std::max(0.0, others);
  return {};
}

}  // namespace

Expected<SurfaceRemeshResult> remeshSurface(const TriMesh& input, const Metric& metric,
                                            const SurfaceRemeshParams& params, Progress progress) {
  if (Status s = checkRemeshInput(input, params); !s) return s;
  // Centroidal iterations asked for: the relaxation aims at regular triangles too. (The rescues'
  // centroidal iterations keep the relaxation that raises the smallest angle.)
  SurfaceRemeshParams p = params;
  if (p.centroidalIterations > 0) p.relaxation = p.relaxation.regularised();
  const double remeshShare = params.measure ? 0.9 : 1.0;
  Prepared prepared;
  if (Status s = prepareRemesh(input, metric, p, progress.sub(0.0, 0.1 * remeshShare), prepared); !s) return s;
  Expected<SurfaceRemeshResult> r = remeshWhole(input, metric, prepared, p, remeshShare, progress);
  if (!r) return r.status();
  if (Status s = restartSmallOutput(input, metric, prepared, p, progress.sub(0.0, remeshShare), *r); !s) return s;
  LastDistance distance{p.earSlack};  // the last steps' judge of the distance to the input
  splitWithAndWithoutEars(input, prepared, p, *r, distance);
  polishAgain(input, prepared, p, *r, distance);
  cutThinEars(input, p, *r, distance);
  climbJointlyAtLast(input, prepared, p, *r, distance);
  collapseWorstFaces(input, metric, p, *r, distance);
  polishTheFloor(input, prepared, p, *r, distance);
  shakeSmallOutput(input, prepared, p, *r, distance);
  r->times.prepare += prepared.prepareSeconds;  // once for the call, whatever start was kept
  r->times.engine += prepared.engineSeconds;
  auto clock = std::chrono::steady_clock::now();
  if (params.measure)
    if (Status s = measureOutput(input, params.measureDistance, *r, progress.sub(remeshShare, 1.0)); !s) return s;
  r->times.measure = lap(clock);
  return r;
}

double targetSpacing(const TriMesh& mesh, const FpsParams& sampling, const Metric& metric) {
  if (sampling.targetCount <= 0) return std::sqrt(3.0) * sampling.minSpacing;
  double area = 0.0;
  for (const Tri& t : mesh.triangles) {
    double p2 = 1.0;  // the mean P^2 of the face's corners
    if (!metric.isUniform()) {
      p2 = 0.0;
      for (int v : t) p2 += metric.P[v] * metric.P[v] / 3.0;
    }
    area += 0.5 * areaNormal(mesh, t).norm() * p2;
  }
  return std::sqrt(2.0 * area / (std::sqrt(3.0) * sampling.targetCount));
}

Expected<AdaptiveRemeshResult> remeshAdaptive(const TriMesh& input, const std::vector<double>& values,
                                              const AdaptiveRemeshParams& params, Progress progress) {
  if (!(params.gradation >= 0.0) || !std::isfinite(params.gradation))
    return invalidInput("the gradation must be finite and >= 0");
  AdaptiveRemeshResult r;
  AdaptiveMetricParams metricParams = params.metric;
  r.automaticRadius = metricParams.field == AdaptiveField::TotalCurvature && metricParams.curvature.radius == 0.0 &&
                      params.radiusInSpacings > 0.0;
  if (r.automaticRadius)
    metricParams.curvature.radius = params.radiusInSpacings * targetSpacing(input, params.remesh.sampling);
  Expected<AdaptiveMetricResult> metric = adaptiveMetric(input, values, metricParams, progress.sub(0.0, 0.1));
  if (!metric) return metric.status();
  r.metric = std::move(*metric);
  if (params.gradation > 0.0 && !r.metric.speed.metric.isUniform())
    r.gradedVertices = limitSpeedGrowth(
        input, params.gradation / targetSpacing(input, params.remesh.sampling, r.metric.speed.metric), r.metric.speed);
  Expected<SurfaceRemeshResult> remeshed =
      remeshSurface(input, r.metric.speed.metric, params.remesh, progress.sub(0.1, 1.0));
  if (!remeshed) return remeshed.status();
  r.remesh = std::move(*remeshed);
  return r;
}

}  // namespace gr
