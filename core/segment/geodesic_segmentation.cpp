#include "core/segment/geodesic_segmentation.h"

#include "core/segment/boundary_snapping.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <utility>

#include "core/geodesic/farthest_point_sampling.h"
#include "core/mesh/face_geometry.h"
#include "core/mesh/sharp_cut.h"

namespace gr {
namespace {

/// Rounds of giving stray pieces to their neighbours (each round at least halves them in practice).
constexpr int kStrayRounds = 16;
/// The first seeds are chosen in 3D (farthestPointsIn3d), one in kSeedsPerSeedIn3d of them and at
/// most kSeedsIn3d; the geodesic farthest-point sampling goes on from their field. The first fronts
/// of a greedy sampling are its dearest (each covers much of the surface): the subdivided armadillo
/// (1.66M vertices, 1,000 regions, 10 iterations, medians of 3) 20.1 -> 17.2 s, area CV 0.383 ->
/// 0.385, isoperimetric quotient 0.652 -> 0.651. A small share only: where the seeds are few,
/// their layout is the sampling's (fandisk at 50 regions, 16 seeds in 3D: on sharp edges 0.542 ->
/// 0.513).
constexpr int kSeedsPerSeedIn3d = 64;
constexpr int kSeedsIn3d = 16;
/// A piece of the surface cut at its sharp edges smaller than this share of the mean region area
/// is not cut off (frontSurface). A quarter: fandisk's 12 pieces at 20 regions (the smallest is
/// a third of the mean) are kept.
constexpr double kSmallestPiece = 0.25;

/// Faces grouped by region (CSR): faces of region r are order[begin[r] .. begin[r + 1]).
struct FacesByRegion {
  std::vector<int> begin, order;
};

FacesByRegion groupFaces(const std::vector<int>& faceRegion, int regions) {
  FacesByRegion g;
  g.begin.assign(regions + 1, 0);
  for (int r : faceRegion)
    if (r >= 0 && r < regions) ++g.begin[r + 1];
  for (int r = 0; r < regions; ++r) g.begin[r + 1] += g.begin[r];
  g.order.resize(g.begin[regions]);
  std::vector<int> fill(g.begin.begin(), g.begin.end() - 1);
  for (int f = 0; f < static_cast<int>(faceRegion.size()); ++f)
    if (faceRegion[f] >= 0 && faceRegion[f] < regions) g.order[fill[faceRegion[f]]++] = f;
  return g;
}

/// Per face, the edge-connected piece of its region it belongs to (pieces numbered from 0).
std::vector<int> piecesOf(const TriMesh& mesh, const std::vector<int>& faceRegion, int* count) {
  std::vector<int> piece(mesh.faceCount(), -1), stack;
  int pieces = 0;
  for (int f0 = 0; f0 < mesh.faceCount(); ++f0) {
    if (piece[f0] >= 0 || faceRegion[f0] < 0) continue;
    piece[f0] = pieces;
    stack.push_back(f0);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        const int o = mesh.oppositeCorner[c];
        if (o < 0) continue;
        const int g = TriMesh::face(o);
        if (piece[g] < 0 && faceRegion[g] == faceRegion[f]) {
          piece[g] = pieces;
          stack.push_back(g);
        }
      }
    }
    ++pieces;
  }
  *count = pieces;
  return piece;
}

/// The region of each input face: the cell of its vertex nearest its own seed (least U). A face
/// next to a slow band (a sharp edge under the feature-aligned speed) has its far vertex nearer
/// its seed than the vertices on the band, so the region boundary runs along the band's edges.
std::vector<int> labelFaces(const TriMesh& mesh, const std::vector<int>& cell, const std::vector<double>& distance) {
  std::vector<int> label(mesh.faceCount(), -1);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    double best = kUnreached;
    for (int v : mesh.triangles[f])
      if (cell[v] >= 0 && distance[v] < best) {
        best = distance[v];
        label[f] = cell[v];
      }
  }
  return label;
}

/// Gives every stray piece of a region (not its largest) to the neighbouring region it shares the
/// most edges with. Returns the faces moved; pieces with no neighbouring region (a component of
/// the mesh all in one region, or unlabelled faces) are left and listed in `isolated` (a face of each).
int mergeStrayPieces(const TriMesh& mesh, std::vector<int>& faceRegion, int regions, std::vector<int>* isolated) {
  int moved = 0;
  for (int round = 0; round < kStrayRounds; ++round) {
    int pieces = 0;
    const std::vector<int> piece = piecesOf(mesh, faceRegion, &pieces);
    std::vector<int> size(pieces, 0), largest(regions, -1);
    for (int f = 0; f < mesh.faceCount(); ++f)
      if (piece[f] >= 0) ++size[piece[f]];
    for (int f = 0; f < mesh.faceCount(); ++f) {
      const int r = faceRegion[f];
      if (r >= 0 && (largest[r] < 0 || size[piece[f]] > size[largest[r]])) largest[r] = piece[f];
    }
    // Per stray piece, the neighbouring region it shares the most edges with.
    std::vector<std::vector<std::pair<int, int>>> shared(pieces);  // (region, edges)
    for (int f = 0; f < mesh.faceCount(); ++f) {
      if (piece[f] < 0 || largest[faceRegion[f]] == piece[f]) continue;
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        const int o = mesh.oppositeCorner[c];
        if (o < 0) continue;
        const int r = faceRegion[TriMesh::face(o)];
        if (r < 0 || r == faceRegion[f]) continue;
        auto& list = shared[piece[f]];
        auto it = std::find_if(list.begin(), list.end(), [r](const auto& e) { return e.first == r; });
        if (it == list.end())
          list.emplace_back(r, 1);
        else
          ++it->second;
      }
    }
    std::vector<int> target(pieces, -1);
    for (int p = 0; p < pieces; ++p)
      if (!shared[p].empty())
        target[p] = std::max_element(shared[p].begin(), shared[p].end(), [](const auto& x, const auto& y) {
                      return x.second < y.second || (x.second == y.second && x.first > y.first);
                    })->first;
    int movedNow = 0;
    for (int f = 0; f < mesh.faceCount(); ++f)
      if (piece[f] >= 0 && largest[faceRegion[f]] != piece[f] && target[piece[f]] >= 0) {
        faceRegion[f] = target[piece[f]];
        ++movedNow;
      }
    moved += movedNow;
    if (movedNow == 0) {
      isolated->clear();
      std::vector<char> listed(pieces, 0);
      for (int f = 0; f < mesh.faceCount(); ++f)
        if (piece[f] >= 0 && largest[faceRegion[f]] != piece[f] && !listed[piece[f]]) {
          listed[piece[f]] = 1;
          isolated->push_back(f);
        }
      break;
    }
  }
  // Faces no front reached (a piece of the cut surface or a component of the input with no seed):
  // one face of each edge-connected piece of them.
  std::vector<int> unlabelled(faceRegion.size());
  for (int f = 0; f < mesh.faceCount(); ++f) unlabelled[f] = faceRegion[f] < 0 ? 0 : -1;
  int pieces = 0;
  const std::vector<int> piece = piecesOf(mesh, unlabelled, &pieces);
  std::vector<char> listed(pieces, 0);
  for (int f = 0; f < mesh.faceCount(); ++f)
    if (faceRegion[f] < 0 && !listed[piece[f]]) {
      listed[piece[f]] = 1;
      isolated->push_back(f);
    }
  return moved;
}

/// Gives the faces no front reached (the pieces of a cut surface that got no seed) to the labelled
/// regions around them, nearest first (a breadth-first search over the input's faces). Returns
/// the faces given.
/// Regions around a hole: a boundary loop of the input whose faces all lie in one region makes
/// that region a ring, and no Voronoi cell can split a hole of a few edges (ogre.obj has holes of
/// 4 to 6 edges; a seed on the rim owns all of it). The faces of the shortest path of faces from
/// the rim to a face next to another region are given to that region: the ring is cut open and
/// the other region grows a strip, both disks. Returns the holes so opened; `facesMoved` gets the
/// faces given away.
int cutRingsAroundHoles(const TriMesh& mesh, std::vector<int>& faceRegion, int* facesMoved) {
  if (mesh.topology.boundaryEdges == 0) return 0;
  std::vector<int> parent(mesh.vertexCount());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    if (mesh.oppositeCorner[c] < 0) parent[root(mesh.vertex(TriMesh::next(c)))] = root(mesh.vertex(TriMesh::prev(c)));
  constexpr int kNone = -1, kMixed = -2;
  std::vector<int> loopRegion(mesh.vertexCount(), kNone);  // per loop (its root): the one region along it
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    if (mesh.oppositeCorner[c] >= 0) continue;
    int& r = loopRegion[root(mesh.vertex(TriMesh::next(c)))];
    const int here = faceRegion[TriMesh::face(c)];
    r = r == kNone ? here : (r == here ? r : kMixed);
  }
  std::vector<std::pair<int, int>> rim;  // (loop, face) for the loops inside one region
  for (int c = 0; c < 3 * mesh.faceCount(); ++c)
    if (mesh.oppositeCorner[c] < 0 && loopRegion[root(mesh.vertex(TriMesh::next(c)))] >= 0)
      rim.push_back({root(mesh.vertex(TriMesh::next(c))), TriMesh::face(c)});
  std::sort(rim.begin(), rim.end());
  int opened = 0;
  *facesMoved = 0;
  std::vector<int> from(mesh.faceCount(), -2), queue;
  for (size_t first = 0, last = 0; first < rim.size(); first = last) {
    const int r = loopRegion[rim[first].first];
    // Faces of r from the loop's rim outward, until a face with a neighbour in another region.
    queue.clear();
    for (last = first; last < rim.size() && rim[last].first == rim[first].first; ++last)
      if (from[rim[last].second] == -2) {
        from[rim[last].second] = -1;
        queue.push_back(rim[last].second);
      }
    int end = -1, other = -1;
    for (size_t head = 0; head < queue.size() && end < 0; ++head) {
      const int f = queue[head];
      for (int c = 3 * f; c < 3 * f + 3 && end < 0; ++c) {
        const int o = mesh.oppositeCorner[c];
        if (o < 0) continue;
        const int g = TriMesh::face(o);
        if (faceRegion[g] != r && faceRegion[g] >= 0) {
          end = f;
          other = faceRegion[g];
        } else if (from[g] == -2) {
          from[g] = f;
          queue.push_back(g);
        }
      }
    }
    if (end >= 0) {
      ++opened;
      for (int f = end; f >= 0; f = from[f]) {
        faceRegion[f] = other;
        ++*facesMoved;
      }
    }
    for (int f : queue) from[f] = -2;
  }
  return opened;
}

int fillUnlabelled(const TriMesh& mesh, std::vector<int>& faceRegion) {
  std::vector<int> queue;
  for (int f = 0; f < mesh.faceCount(); ++f)
    if (faceRegion[f] >= 0) queue.push_back(f);
  int given = 0;
  for (size_t head = 0; head < queue.size(); ++head) {
    const int f = queue[head];
    for (int c = 3 * f; c < 3 * f + 3; ++c) {
      const int o = mesh.oppositeCorner[c];
      if (o < 0 || faceRegion[TriMesh::face(o)] >= 0) continue;
      faceRegion[TriMesh::face(o)] = faceRegion[f];
      queue.push_back(TriMesh::face(o));
      ++given;
    }
  }
  return given;
}

Status checkSegmentationInput(const TriMesh& mesh, const std::vector<double>& values, const SegmentationParams& p) {
  if (mesh.faceCount() == 0) return invalidInput("segmentation: the mesh has no faces");
  if (mesh.topology.nonManifoldEdges > 0)
    return nonManifold("segmentation: the mesh has " + std::to_string(mesh.topology.nonManifoldEdges) +
                       " non-manifold edges (three or more faces on an edge): regions could not be disks; clean it "
                       "first (Filters > Cleaning and Repairing)");
  const int inFaces = mesh.vertexCount() - mesh.topology.isolatedVertices;
  if (p.regions < 1 || p.regions > std::min(inFaces, mesh.faceCount()))
    return invalidInput(
        "segmentation: Regions must be between 1 and " + std::to_string(std::min(inFaces, mesh.faceCount())) +
        " (a region needs a face and a vertex of its own: the mesh has " + std::to_string(inFaces) + " vertices in " +
        std::to_string(mesh.faceCount()) + " faces; asked " + std::to_string(p.regions) + ")");
  if (p.lloyd.iterations < 0 || p.iterationsAfterAdding < 0 || p.maxDiskRounds < 0)
    return invalidInput("segmentation: Iterations must be >= 0");
  if (!std::isfinite(p.featureAlignment) || p.featureAlignment < 0.0)
    return invalidInput("segmentation: the feature alignment must be finite and >= 0");
  if (!(p.sharpEdgeAngle >= 0.0 && p.sharpEdgeAngle <= 180.0))
    return invalidInput("segmentation: the sharp edge angle must be between 0 and 180 degrees");
  if (p.featureAlignment > 0.0 && p.speedField == AdaptiveField::VertexQuality &&
      static_cast<int>(values.size()) != mesh.vertexCount())
    return invalidInput("segmentation: the speed field needs one value per vertex");
  return Status::ok();
}

/// The metric of the segmentation: uniform (mu = 0) or the Attractive speed of the field.
Expected<Metric> segmentationMetric(const TriMesh& mesh, const std::vector<double>& values, const SegmentationParams& p,
                                    SegmentationResult* out, Progress progress) {
  if (p.featureAlignment == 0.0) return Metric::uniform();
  AdaptiveMetricParams a;
  a.field = p.speedField;
  a.speed.mapping = SpeedMapping::Attractive;
  a.speed.strength = p.featureAlignment;
  a.curvature.radius = p.curvatureRadius;
  Expected<AdaptiveMetricResult> m = adaptiveMetric(mesh, values, a, progress);
  if (!m) return m.status();
  out->curvatureRadius = m->curvatureRadius;
  out->speedFallback = m->speed.fallback;
  return m->speed.metric;
}

/// Seeds to add after a labelling: one per region that is not a disk (at its vertex farthest from
/// the seeds) and one per isolated piece; the seeds of empty regions re-placed. Returns the seeds
/// added; *nonDisk receives the regions that are not disks.
/// Regions are counted on `mesh`, seeds placed on the fronts' surface `fronts` (the same faces;
/// `distance` per vertex of `fronts`).
/// Per region, a vertex of `fronts` whose input vertex the region also holds through another copy
/// (two fans of a non-manifold vertex, split for the fronts), the farther of the two from the
/// seeds; -1 where there is none. A seed there parts the two fans, where a seed at the region's
/// farthest vertex may not (ogre.obj, 3 such vertices, 50 regions: without it one region was still
/// not a disk after 65 rounds).
std::vector<int> secondCopies(const TriMesh& mesh, const TriMesh& fronts, const std::vector<int>& faceRegion,
                              const std::vector<double>& distance, int regions) {
  std::vector<int> second(regions, -1);
  if (mesh.topology.nonManifoldVertices == 0) return second;
  std::vector<char> copied(mesh.vertexCount(), 0);
  for (int f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) copied[mesh.triangles[f][k]] |= fronts.triangles[f][k] != mesh.triangles[f][k];
  std::unordered_map<long long, int> seen;  // (region, input vertex) -> the first copy met
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const int r = faceRegion[f];
    for (int k = 0; k < 3 && r >= 0; ++k) {
      const int v = mesh.triangles[f][k], w = fronts.triangles[f][k];
      if (!copied[v]) continue;
      const auto [it, first] = seen.emplace(static_cast<long long>(r) * mesh.vertexCount() + v, w);
      if (first || it->second == w) continue;
      const int far = distance[w] > distance[it->second] ? w : it->second;
      if (second[r] < 0 || distance[far] > distance[second[r]]) second[r] = far;
    }
  }
  return second;
}

int seedsForNonDisks(const TriMesh& mesh, const TriMesh& fronts, const std::vector<int>& faceRegion,
                     const std::vector<double>& distance, const std::vector<int>& isolated,
                     std::vector<SurfacePoint>& seeds, int* nonDisk, int* replaced) {
  const int regions = static_cast<int>(seeds.size());
  const std::vector<RegionTopology> topo = regionTopology(mesh, faceRegion, regions);
  std::vector<int> farthest(regions, -1);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const int r = faceRegion[f];
    if (r < 0) continue;
    for (int v : fronts.triangles[f])
      if (farthest[r] < 0 || distance[v] > distance[farthest[r]]) farthest[r] = v;
  }
  const std::vector<int> second = secondCopies(mesh, fronts, faceRegion, distance, regions);
  int added = 0;
  *nonDisk = 0;
  // Regions that lost all their faces to their neighbours: their seeds go to the vertices
  // farthest from all seeds, one each (the vertices sorted only when some region is empty).
  const int empty =
      static_cast<int>(std::count_if(topo.begin(), topo.end(), [](const RegionTopology& t) { return t.faces == 0; }));
  std::vector<int> farthestFirst(empty > 0 ? distance.size() : 0);
  std::iota(farthestFirst.begin(), farthestFirst.end(), 0);
  const auto finiteOrLow = [&](int v) { return std::isfinite(distance[v]) ? distance[v] : -1.0; };
  std::partial_sort(farthestFirst.begin(), farthestFirst.begin() + std::min<size_t>(empty, farthestFirst.size()),
                    farthestFirst.end(), [&](int a, int b) { return finiteOrLow(a) > finiteOrLow(b); });
  size_t nextFarthest = 0;
  for (int r = 0; r < regions; ++r) {
    if (topo[r].faces == 0) {
      if (nextFarthest < farthestFirst.size()) seeds[r] = SurfacePoint::atVertex(farthestFirst[nextFarthest++]);
      ++*replaced;
    } else if (!topo[r].isDisk()) {
      ++*nonDisk;
      seeds.push_back(SurfacePoint::atVertex(second[r] >= 0 ? second[r] : farthest[r]));
      ++added;
    }
  }
  for (int f : isolated) {
    seeds.push_back(SurfacePoint::atVertex(fronts.triangles[f][0]));
    ++added;
  }
  return added;
}

/// Seeds per connected piece of the fronts' surface (a piece's fronts never leave it, so Lloyd
/// keeps its count): one for each of the `seeds` heaviest pieces, then each further seed where it
/// lowers the centroidal energy most. Cells of even size in a piece of mass M cost about
/// c M^2 / n for n cells, so the next seed goes to the piece with the largest M^2 / (n (n + 1)),
/// at most `available[k]` in piece k. With one piece: all the seeds.
std::vector<int> seedsPerPiece(const std::vector<double>& mass, const std::vector<int>& available, int seeds) {
  const int pieces = static_cast<int>(mass.size());
  std::vector<int> order(pieces), count(pieces, 0);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return mass[a] > mass[b]; });
  int given = 0;
  for (int k : order)
    if (given < seeds && available[k] > 0) {
      count[k] = 1;
      ++given;
    }
  for (; given < seeds; ++given) {
    int best = -1;
    double gain = -1.0;
    for (int k = 0; k < pieces; ++k) {
      if (count[k] == 0 || count[k] >= available[k]) continue;
      const double g = mass[k] * mass[k] / (double(count[k]) * (count[k] + 1));
      if (g > gain) {
        gain = g;
        best = k;
      }
    }
    if (best < 0) break;
    ++count[best];
  }
  return count;
}

/// The first seeds: a farthest-point sampling of the fronts' surface and, where that surface is
/// in several pieces, of each piece its share (seedsPerPiece). Greedy sampling chosen over the
/// whole surface, read piece by piece, is each piece's own greedy sampling, so a longer sampling
/// gives every piece its first samples; it is made longer (doubled) until each piece has its
/// share. *holdsField: the engine holds the field of exactly the seeds returned.
Expected<std::vector<SurfacePoint>> initialSeeds(FastMarcher& marcher, const std::vector<double>& mass,
                                                 const SegmentationParams& params, bool* holdsField,
                                                 Progress progress) {
  const TriMesh& mesh = marcher.mesh();
  const Topology& topo = mesh.topology;
  FpsParams fps;
  fps.targetCount = params.regions;
  fps.seed = params.seed;
  fps.boundaryPriority = 1.0;  // seeds are cell centres, not outline samples
  fps.initialSamples = farthestPointsIn3d(mesh, std::min(kSeedsIn3d, params.regions / kSeedsPerSeedIn3d), params.seed);
  std::vector<double> pieceMass(std::max(topo.components, 1), 0.0);
  std::vector<int> available(pieceMass.size(), 0);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (topo.componentOfVertex[v] >= 0) {
      pieceMass[topo.componentOfVertex[v]] += mass[v];
      ++available[topo.componentOfVertex[v]];
    }
  const std::vector<int> share = seedsPerPiece(pieceMass, available, params.regions);
  const int inFaces = mesh.vertexCount() - topo.isolatedVertices;
  for (;;) {
    Expected<FpsResult> sampled = farthestPointSampling(marcher, fps, progress);
    if (!sampled) return sampled.status();
    std::vector<int> taken(share.size(), 0);
    std::vector<SurfacePoint> seeds;
    for (size_t i = 0; i < sampled->samples.size(); ++i) {
      const int k = topo.componentOfVertex[sampled->samples[i]];
      if (taken[k] < share[k]) {
        ++taken[k];
        seeds.push_back(sampled->origin[i]);
      }
    }
    if (taken == share || fps.targetCount >= inFaces) {
      *holdsField = seeds.size() == sampled->samples.size();
      return seeds;
    }
    fps.targetCount = std::min(2 * fps.targetCount, inFaces);
  }
}

/// Per face, the connected piece of the cut surface it lies in, and each piece's area.
std::vector<double> pieceAreas(const TriMesh& cut, std::vector<int>* pieceOfFace) {
  std::vector<double> area(std::max(cut.topology.components, 1), 0.0);
  pieceOfFace->resize(cut.faceCount());
  for (int f = 0; f < cut.faceCount(); ++f) {
    const int k = cut.topology.componentOfVertex[cut.triangles[f][0]];
    (*pieceOfFace)[f] = k;
    area[k] += 0.5 * areaNormal(cut, f).norm();
  }
  return area;
}

/// The surface the fronts run on: `mesh` cut open along its sharp edges (sharpEdgeAngle > 0 and
/// some edge that sharp), else `mesh` itself (`cut` left empty). A piece the cut would leave
/// smaller than kSmallestPiece of a region's mean area (a scan's noise: armadillo has 125 edges
/// over 60 degrees, around specks of a few faces) is not cut off: it could not be a region, and
/// regions would have to be rings around it. A non-manifold vertex (fans of faces meeting at it)
/// is always split, one copy per fan (cutAlongEdges does that by itself): fronts need a manifold.
Expected<const TriMesh*> frontSurface(const TriMesh& mesh, const SegmentationParams& p, CutSurface* cut,
                                      SegmentationResult* out) {
  const bool pinched = mesh.topology.nonManifoldVertices > 0;
  if (p.sharpEdgeAngle <= 0.0) {
    if (!pinched) return &mesh;
    Expected<CutSurface> c = splitNonManifoldVertices(mesh);
    if (!c) return c.status();
    *cut = std::move(*c);
    return &cut->mesh;
  }
  std::vector<char> sharp = sharpEdgeCorners(mesh, p.sharpEdgeAngle);
  for (;;) {
    Expected<CutSurface> c = cutAlongEdges(mesh, sharp);
    if (!c) return c.status();
    out->sharpEdges = c->sharpEdges;
    if (c->sharpEdges == 0 && !pinched) return &mesh;
    std::vector<int> piece;
    const std::vector<double> area = pieceAreas(c->mesh, &piece);
    const double smallest = kSmallestPiece * std::accumulate(area.begin(), area.end(), 0.0) / p.regions;
    bool merged = false;
    for (int corner = 0; corner < 3 * mesh.faceCount(); ++corner) {
      const int o = mesh.oppositeCorner[corner];
      if (o < 0 || !(sharp[corner] || sharp[o])) continue;
      if (area[piece[corner / 3]] < smallest || area[piece[o / 3]] < smallest) {
        sharp[corner] = sharp[o] = 0;
        merged = true;
      }
    }
    if (!merged) {
      *cut = std::move(*c);
      return &cut->mesh;
    }
  }
}

}  // namespace

RegionTopologyCounter::RegionTopologyCounter(const TriMesh& mesh)
    : mesh_(mesh),
      vertexStamp_(mesh.vertexCount(), -1),
      faceStamp_(mesh.faceCount(), -1),
      parent_(mesh.vertexCount()),
      boundaryDegree_(mesh.vertexCount(), 0),
      loopSeen_(mesh.vertexCount(), -1) {}

RegionTopology RegionTopologyCounter::count(const std::vector<int>& faceRegion, const std::vector<int>& faces, int r) {
  const int mark = ++mark_;
  RegionTopology t;
  int vertices = 0, edges = 0;
  boundary_.clear();
  const auto root = [&](int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  };
  for (int f : faces) {
    ++t.faces;
    for (int v : mesh_.triangles[f])
      if (vertexStamp_[v] != mark) {
        vertexStamp_[v] = mark;
        parent_[v] = v;
        boundaryDegree_[v] = 0;
        ++vertices;
      }
    for (int c = 3 * f; c < 3 * f + 3; ++c) {
      const int o = mesh_.oppositeCorner[c];
      const bool inside = o >= 0 && faceRegion[TriMesh::face(o)] == r;
      if (inside && o < c) continue;  // counted from the other side
      ++edges;
      if (inside) continue;
      const int a = mesh_.vertex(TriMesh::next(c)), b = mesh_.vertex(TriMesh::prev(c));
      ++boundaryDegree_[a];
      ++boundaryDegree_[b];
      boundary_.push_back(a);
      boundary_.push_back(b);
      parent_[root(a)] = root(b);
    }
  }
  t.euler = vertices - edges + t.faces;
  t.pieces = pieces(faceRegion, faces, r, mark);
  int loops = 0;
  bool pinched = false;
  for (int v : boundary_) {
    pinched = pinched || boundaryDegree_[v] != 2;
    const int top = root(v);
    if (loopSeen_[top] != mark) {
      loopSeen_[top] = mark;
      ++loops;
    }
  }
  t.boundaryLoops = pinched ? -1 : loops;
  return t;
}

int RegionTopologyCounter::pieces(const std::vector<int>& faceRegion, const std::vector<int>& faces, int r, int mark) {
  int count = 0;
  for (int f0 : faces) {
    if (faceStamp_[f0] == mark) continue;
    ++count;
    faceStamp_[f0] = mark;
    stack_.assign(1, f0);
    while (!stack_.empty()) {
      const int f = stack_.back();
      stack_.pop_back();
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        const int o = mesh_.oppositeCorner[c];
        if (o < 0) continue;
        const int g = TriMesh::face(o);
        if (faceStamp_[g] != mark && faceRegion[g] == r) {
          faceStamp_[g] = mark;
          stack_.push_back(g);
        }
      }
    }
  }
  return count;
}

std::vector<RegionTopology> regionTopology(const TriMesh& mesh, const std::vector<int>& faceRegion, int regions) {
  std::vector<RegionTopology> topo(regions);
  const FacesByRegion g = groupFaces(faceRegion, regions);
  RegionTopologyCounter counter(mesh);
  std::vector<int> faces;
  for (int r = 0; r < regions; ++r) {
    faces.assign(g.order.begin() + g.begin[r], g.order.begin() + g.begin[r + 1]);
    topo[r] = counter.count(faceRegion, faces, r);
  }
  return topo;
}

Expected<SegmentationResult> segmentSurface(const TriMesh& mesh, const std::vector<double>& values,
                                            const SegmentationParams& params, Progress progress) {
  if (Status s = checkSegmentationInput(mesh, values, params); !s) return s;
  SegmentationResult out;
  out.regionsAsked = params.regions;
  CutSurface cut;
  Expected<const TriMesh*> cutOrInput = frontSurface(mesh, params, &cut, &out);
  if (!cutOrInput) return cutOrInput.status();
  const TriMesh& work = **cutOrInput;  // the input, or the input cut open at its sharp edges
  out.surfacePieces = work.topology.components;
  out.splitVertices = mesh.topology.nonManifoldVertices;
  std::vector<double> workValues;  // the field on the cut surface's vertices, from their origins
  if (!cut.origin.empty() && params.speedField == AdaptiveField::VertexQuality && !values.empty())
    for (int v : cut.origin) workValues.push_back(values[v]);
  Expected<Metric> metric =
      segmentationMetric(work, cut.origin.empty() ? values : workValues, params, &out, progress.sub(0.0, 0.05));
  if (!metric) return metric.status();
  Expected<GeodesicSurface> surface = prepareGeodesicSurface(work, *metric, params.surface, progress.sub(0.05, 0.1));
  if (!surface) return surface.status();
  out.refined = surface->refined;
  out.insertedPoints = surface->insertedPoints();
  FastMarcher marcher = surface->makeMarcher();
  LloydParams lloyd = params.lloyd;
  Expected<std::vector<SurfacePoint>> first =
      initialSeeds(marcher, lloydVertexMass(surface->mesh(), surface->metric, lloyd.metricArea), params,
                   &lloyd.marcherHoldsSeedsField, progress.sub(0.1, 0.15));
  if (!first) return first.status();
  std::vector<SurfacePoint> seeds = std::move(*first);
  // A seed on a vertex (U = 0 there) owns every face around it in the labelling: no region is
  // left without a face.
  lloyd.vertexSeeds = true;
  std::vector<int> cell;  // of the fronts' vertices, in the last round
  for (int round = 0;; ++round) {
    Expected<LloydResult> relaxed = geodesicLloyd(
        surface->mesh(), surface->metric, marcher, seeds, lloyd,
        progress.sub(0.15 + 0.8 * (1.0 - std::pow(0.5, round)), 0.15 + 0.8 * (1.0 - std::pow(0.5, round + 1))));
    if (!relaxed) return relaxed.status();
    if (round == 0) out.energyStart = relaxed->energy.front();
    out.energyEnd = relaxed->energy.back();
    out.iterations += relaxed->iterations;
    out.reseeded += relaxed->reseeded;
    seeds = relaxed->seeds;
    // The fronts' surface's first vertices are `work`'s: their cells label its faces, the input's.
    cell.assign(relaxed->cell.begin(), relaxed->cell.begin() + work.vertexCount());
    const std::vector<double> distance(relaxed->distance.begin(), relaxed->distance.begin() + work.vertexCount());
    out.faceRegion = labelFaces(work, cell, distance);
    std::vector<int> isolated;
    out.strayFacesMoved += fillUnlabelled(mesh, out.faceRegion);
    int ringFaces = 0;
    out.holesOpened = cutRingsAroundHoles(mesh, out.faceRegion, &ringFaces);
    out.strayFacesMoved += ringFaces;
    out.strayFacesMoved += mergeStrayPieces(mesh, out.faceRegion, static_cast<int>(seeds.size()), &isolated);
    int replaced = 0;
    const int added =
        seedsForNonDisks(mesh, work, out.faceRegion, distance, isolated, seeds, &out.nonDiskRegions, &replaced);
    out.reseeded += replaced;
    if (added == 0 && replaced == 0) break;
    if (round == params.maxDiskRounds || static_cast<int>(seeds.size()) > mesh.vertexCount())
      return invalidInput("segmentation: the mesh could not be cut into regions that are all topological disks (" +
                          std::to_string(out.nonDiskRegions + replaced) + " of " + std::to_string(seeds.size()) +
                          " regions still not disks after " + std::to_string(round + 1) +
                          " rounds); it may be too coarse for its topology: ask for more regions");
    out.regionsAdded += added;
    lloyd.marcherHoldsSeedsField = false;
    lloyd.iterations = std::max(params.iterationsAfterAdding, 1);
  }
  out.regions = static_cast<int>(seeds.size());
  cell.resize(mesh.vertexCount());  // a cut vertex's first copy keeps its number
  if (params.featureAlignment > 0.0 && params.snapToSharpEdges)
    out.snappedFaces = snapBoundariesToSharpEdges(mesh, cell, out.faceRegion, out.regions);
  out.seedPosition.resize(seeds.size());
  for (size_t i = 0; i < seeds.size(); ++i) out.seedPosition[i] = seeds[i].position(surface->mesh());
  return out;
}

}  // namespace gr
