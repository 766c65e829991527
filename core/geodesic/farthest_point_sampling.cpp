#include "core/geodesic/farthest_point_sampling.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/geodesic/detail/farthest_queue.h"
#include "core/geodesic/fast_marching.h"

namespace gr {
namespace {

/// The point near interior vertex v where the model of the fronts (see the header) is largest,
/// searched on a barycentric lattice of the faces around v and the faces across their outer
/// edges. `samplePosition` holds the position of each cell's sample. Returns v itself when no
/// lattice point beats it; *u receives the model's value at the point.
SurfacePoint farthestPointNear(const FastMarcher& marcher, int v, const std::vector<Vec3>& samplePosition, double* u) {
  const TriMesh& mesh = marcher.mesh();
  const std::vector<double>& U = marcher.distance();
  const std::vector<int>& cell = marcher.cell();
  constexpr int kMaxFaces = 64, kMaxVertices = 64;
  int faces[kMaxFaces], nf = 0;
  int verts[kMaxVertices], nvtx = 0;
  const auto addVertex = [&](int w) {
    for (int i = 0; i < nvtx; ++i)
      if (verts[i] == w) return;
    if (nvtx < kMaxVertices && cell[w] >= 0 && std::isfinite(U[w])) verts[nvtx++] = w;
  };
  for (const int* c = mesh.cornersBegin(v); c != mesh.cornersEnd(v) && nf < kMaxFaces; ++c) {
    faces[nf++] = TriMesh::face(*c);
    const int o = mesh.oppositeCorner[*c];
    if (o >= 0 && nf < kMaxFaces) faces[nf++] = TriMesh::face(o);
  }
  for (int i = 0; i < nf; ++i)
    for (int w : mesh.triangles[faces[i]]) addVertex(w);
  // Per vertex of the neighbourhood: its front's offset U(w) - |w - s_L|.
  double offset[kMaxVertices];
  for (int i = 0; i < nvtx; ++i)
    offset[i] = U[verts[i]] - (mesh.positions[verts[i]] - samplePosition[cell[verts[i]]]).norm();
  const auto model = [&](const Vec3& p) {
    double best = kUnreached;
    for (int i = 0; i < nvtx; ++i) {
      // U_L(p) for w's front; the minimum over all w is the minimum over fronts of their
      // estimate from the nearest-in-value vertex, a safe (low) side of the model.
      best = std::min(best, offset[i] + (p - samplePosition[cell[verts[i]]]).norm());
    }
    return best;
  };
  SurfacePoint bestPoint = SurfacePoint::atVertex(v);
  double bestU = U[v];
  constexpr int kLattice = 4;  // points (i, j, k) / 4: 15 per face
  for (int i = 0; i < nf; ++i) {
    const Tri& t = mesh.triangles[faces[i]];
    const Vec3 &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]], &p2 = mesh.positions[t[2]];
    for (int a = 0; a <= kLattice; ++a)
      for (int b = 0; a + b <= kLattice; ++b) {
        const int c = kLattice - a - b;
        if (a == kLattice || b == kLattice || c == kLattice) continue;  // vertices: U is known there
        const Vec3 bary(double(a) / kLattice, double(b) / kLattice, double(c) / kLattice);
        const double m = model(bary[0] * p0 + bary[1] * p1 + bary[2] * p2);
        if (m > bestU) {
          bestU = m;
          bestPoint = SurfacePoint::inFace(faces[i], bary);
        }
      }
  }
  *u = bestU;
  return bestPoint;
}

/// Vertices in faces: the most samples a mesh can take.
int usableVertexCount(const TriMesh& mesh) { return mesh.vertexCount() - mesh.topology.isolatedVertices; }

/// The checks of the sampling's parameters, in the order their messages are reported.
Status checkFpsParams(const TriMesh& mesh, const FpsParams& params) {
  if (params.targetCount < 0) return invalidInput("the target sample count must be >= 0");
  if (!(params.minSpacing >= 0.0) || !std::isfinite(params.minSpacing))
    return invalidInput("the sample spacing must be finite and >= 0");
  if (params.targetCount == 0 && params.minSpacing == 0.0)
    return invalidInput("give a target sample count or a spacing (both are 0)");
  const int usable = usableVertexCount(mesh);
  if (params.targetCount > usable)
    return invalidInput("cannot place " + std::to_string(params.targetCount) + " samples on " + std::to_string(usable) +
                        " vertices");
  if (!(params.boundaryPriority >= 1.0) || !std::isfinite(params.boundaryPriority))
    return invalidInput("the boundary priority must be finite and >= 1");
  std::vector<char> taken(mesh.vertexCount(), 0);
  for (int v : params.initialSamples) {
    if (v < 0 || v >= mesh.vertexCount() || mesh.valence(v) == 0)
      return invalidInput("an initial sample (" + std::to_string(v) + ") is not a vertex in a face");
    if (taken[v]++) return invalidInput("the initial sample " + std::to_string(v) + " is given twice");
  }
  if (params.targetCount > 0 && static_cast<int>(params.initialSamples.size()) > params.targetCount)
    return invalidInput(std::to_string(params.initialSamples.size()) + " initial samples for a target of " +
                        std::to_string(params.targetCount));
  return Status::ok();
}

/// The vertex a sampling starts from: `seed` modulo the vertex count, else the next vertex in a face
/// (the mesh has one).
int startVertex(const TriMesh& mesh, unsigned seed) {
  int start = static_cast<int>(seed % static_cast<unsigned>(mesh.vertexCount()));
  while (mesh.valence(start) == 0) start = (start + 1) % mesh.vertexCount();
  return start;
}

/// The first sample: the vertex farthest from a start vertex in a face chosen by `seed`. Leaves
/// the marcher reset.
Expected<int> firstSample(FastMarcher& marcher, unsigned seed) {
  const TriMesh& mesh = marcher.mesh();
  marcher.reset();
  const int start = startVertex(mesh, seed);
  if (Status s = marcher.addSource(start, 0); !s) return s;
  if (Status s = marcher.propagate(); !s) return s;
  int first = start;
  for (int v : marcher.acceptedOrder())
    if (marcher.distance()[v] > marcher.distance()[first]) first = v;
  marcher.reset();
  return first;
}

/// The lowest vertex of each component other than `first`'s, the next one to take at the back.
std::vector<int> firstVerticesOfOtherComponents(const TriMesh& mesh, int first) {
  std::vector<int> firstOfComponent(mesh.topology.components, -1);
  for (int v = mesh.vertexCount() - 1; v >= 0; --v)
    if (mesh.topology.componentOfVertex[v] >= 0) firstOfComponent[mesh.topology.componentOfVertex[v]] = v;
  std::vector<int> pending;
  for (int c = 0; c < mesh.topology.components; ++c)
    if (c != mesh.topology.componentOfVertex[first]) pending.push_back(firstOfComponent[c]);
  std::reverse(pending.begin(), pending.end());
  return pending;
}

/// The lowest vertex of each component with no vertex in `samples`, the next one to take at the back.
std::vector<int> firstVerticesOfUnsampledComponents(const TriMesh& mesh, const std::vector<int>& samples) {
  std::vector<char> sampled(mesh.topology.components, 0);
  for (int v : samples)
    if (mesh.topology.componentOfVertex[v] >= 0) sampled[mesh.topology.componentOfVertex[v]] = 1;
  std::vector<int> firstOfComponent(mesh.topology.components, -1);
  for (int v = mesh.vertexCount() - 1; v >= 0; --v)
    if (mesh.topology.componentOfVertex[v] >= 0) firstOfComponent[mesh.topology.componentOfVertex[v]] = v;
  std::vector<int> pending;
  for (int c = mesh.topology.components - 1; c >= 0; --c)
    if (!sampled[c]) pending.push_back(firstOfComponent[c]);
  return pending;
}

/// The initial samples, each the source of its own cell, and their field: one front from all.
Status addInitialSamples(FastMarcher& marcher, const std::vector<int>& samples, FpsResult& r,
                         std::vector<Vec3>& samplePosition) {
  marcher.reset();
  for (int v : samples) {
    r.samples.push_back(v);
    r.origin.push_back(SurfacePoint::atVertex(v));
    samplePosition.push_back(marcher.mesh().positions[v]);
    r.insertionDistance.push_back(kUnreached);
    if (Status s = marcher.addSource(v, static_cast<int>(r.samples.size()) - 1); !s) return s;
  }
  return marcher.propagate();
}

/// U at the top of a queue; 0 when it is empty.
double topU(FarthestQueue& queue, const std::vector<double>& U) {
  const int v = queue.top();
  return v < 0 ? 0.0 : U[v];
}

/// Adds the sample chosen at vertex `next` (U_n = nextU there) to `r` and to the marcher, at the
/// farthest point near it if asked, and propagates its front.
Status addSample(FastMarcher& marcher, const FpsParams& params, const std::vector<char>& onBoundary, int next,
                 double nextU, FpsResult& r, std::vector<Vec3>& samplePosition) {
  const TriMesh& mesh = marcher.mesh();
  SurfacePoint point = SurfacePoint::atVertex(next);
  if (params.subVertexPlacement && std::isfinite(nextU) && !onBoundary[next])
    point = farthestPointNear(marcher, next, samplePosition, &nextU);
  r.samples.push_back(next);
  r.origin.push_back(point);
  samplePosition.push_back(point.position(mesh));
  r.insertionDistance.push_back(nextU);
  if (Status s = marcher.addSource(point, static_cast<int>(r.samples.size()) - 1); !s) return s;
  if (Status s = marcher.propagate(); !s) return s;
  if (point.vertex < 0 && marcher.acceptedOrder().empty()) {
    // A point that is nearest to no vertex would have an empty Voronoi cell, and no place in
    // the triangulation: the sample goes back to the farthest vertex (the field is unchanged).
    r.origin.back() = SurfacePoint::atVertex(next);
    samplePosition.back() = mesh.positions[next];
    if (Status s = marcher.addSource(next, static_cast<int>(r.samples.size()) - 1); !s) return s;
    if (Status s = marcher.propagate(); !s) return s;
  }
  return Status::ok();
}

/// Picks the next sample, the farthest interior or (with priority) boundary vertex, into `next`
/// and `nextU`; false when sampling should stop (every vertex is a sample, or the spacing is reached).
bool pickFarthest(const std::vector<double>& U, const FpsParams& params, FarthestQueue& farthest,
                  FarthestQueue& farthestOnBoundary, int& next, double& nextU) {
  const double interiorU = topU(farthest, U), boundaryU = topU(farthestOnBoundary, U);
  if (std::max(interiorU, boundaryU) <= 0.0) return false;  // every vertex is a sample
  if (params.minSpacing > 0.0 && std::max(interiorU, boundaryU) < params.minSpacing) return false;
  const bool boundaryFirst = boundaryU > 0.0 && boundaryU * params.boundaryPriority >= interiorU;
  next = boundaryFirst ? farthestOnBoundary.top() : farthest.top();
  nextU = boundaryFirst ? boundaryU : interiorU;
  return true;
}

}  // namespace

Expected<FpsResult> farthestPointSampling(const TriMesh& mesh, const Metric& metric, const FpsParams& params,
                                          Progress progress) {
  if (!metric.isUniform() && static_cast<int>(metric.P.size()) != mesh.vertexCount())
    return invalidInput("the metric does not have one value per vertex");
  FastMarcher marcher(mesh, metric);
  return farthestPointSampling(marcher, params, std::move(progress));
}

Expected<FpsResult> farthestPointSampling(FastMarcher& marcher, const FpsParams& params, Progress progress) {
  const TriMesh& mesh = marcher.mesh();
  if (Status s = checkFpsParams(mesh, params); !s) return s;
  const int usable = usableVertexCount(mesh);
  const std::vector<char> onBoundary = boundaryVertexFlags(mesh);
  const bool initial = !params.initialSamples.empty();
  const Expected<int> first =
      initial ? Expected<int>(params.initialSamples.front()) : firstSample(marcher, params.seed);
  if (!first) return first.status();
  // Components with no sample yet have U = +inf: each gets a first sample (its lowest vertex)
  // before any component gets a second one.
  std::vector<int> pending = initial ? firstVerticesOfUnsampledComponents(mesh, params.initialSamples)
                                     : firstVerticesOfOtherComponents(mesh, *first);

  FpsResult r;
  const std::vector<double>& U = marcher.distance();
  // The farthest interior and boundary vertices. Values below the floor are still ordered
  // exactly, only scanned more slowly (farthest_queue.h).
  const double floor = std::max(1e-9 * mesh.boundingBoxDiagonal(), 1e-300);
  FarthestQueue farthest(U, floor), farthestOnBoundary(U, floor);
  const int cap = params.targetCount > 0 ? params.targetCount : usable;
  int next = *first;
  double nextU = kUnreached;
  std::vector<Vec3> samplePosition;
  if (initial)
    if (Status s = addInitialSamples(marcher, params.initialSamples, r, samplePosition); !s) return s;
  for (bool added = initial;; added = false) {  // the initial samples are in: their front is the first
    if (!added)
      if (Status s = addSample(marcher, params, onBoundary, next, nextU, r, samplePosition); !s) return s;
    for (int v : marcher.acceptedOrder()) (onBoundary[v] ? farthestOnBoundary : farthest).update(v);
    if (static_cast<int>(r.samples.size()) >= cap) break;
    if (!progress.report(double(r.samples.size()) / cap, "Farthest point sampling")) return cancelled();
    if (!pending.empty()) {
      next = pending.back();
      pending.pop_back();
      nextU = kUnreached;
      continue;
    }
    if (!pickFarthest(U, params, farthest, farthestOnBoundary, next, nextU)) break;
  }
  r.coveringRadius = std::max(topU(farthest, U), topU(farthestOnBoundary, U));
  r.distance = U;
  r.cell = marcher.cell();
  return r;
}

std::vector<int> farthestPointsIn3d(const TriMesh& mesh, int count, unsigned seed) {
  const int n = mesh.vertexCount();
  if (count <= 0 || usableVertexCount(mesh) == 0) return {};
  const int start = startVertex(mesh, seed);
  std::vector<double> d2(n, kUnreached);  // squared distance to the nearest chosen vertex
  const auto farthestFrom = [&](const Vec3& p) {
    int far = -1;
    for (int v = 0; v < n; ++v) {
      if (mesh.valence(v) == 0) continue;
      d2[v] = std::min(d2[v], (mesh.positions[v] - p).squaredNorm());
      if (far < 0 || d2[v] > d2[far]) far = v;
    }
    return far;
  };
  int next = farthestFrom(mesh.positions[start]);
  std::fill(d2.begin(), d2.end(), kUnreached);
  std::vector<int> chosen;
  while (static_cast<int>(chosen.size()) < count && next >= 0 && d2[next] > 0.0) {
    chosen.push_back(next);
    next = farthestFrom(mesh.positions[next]);
  }
  return chosen;
}

Expected<FpsResult> samplingPrefix(FastMarcher& marcher, const FpsResult& longer, int count) {
  if (count < 1 || count > static_cast<int>(longer.samples.size()))
    return invalidInput("a prefix of " + std::to_string(count) + " samples of a sampling of " +
                        std::to_string(longer.samples.size()));
  FpsResult r;
  r.samples.assign(longer.samples.begin(), longer.samples.begin() + count);
  r.origin.assign(longer.origin.begin(), longer.origin.begin() + count);
  r.insertionDistance.assign(longer.insertionDistance.begin(), longer.insertionDistance.begin() + count);
  marcher.reset();
  for (int i = 0; i < count; ++i)
    if (Status s = marcher.addSource(r.origin[i], i); !s) return s;
  if (Status s = marcher.propagate(); !s) return s;
  r.distance = marcher.distance();
  r.cell = marcher.cell();
  for (int v : marcher.acceptedOrder()) r.coveringRadius = std::max(r.coveringRadius, r.distance[v]);
  return r;
}

}  // namespace gr
