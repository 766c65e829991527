#include "core/remesh/geodesic_delaunay.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "core/geodesic/fast_marching.h"
#include "core/mesh/face_geometry.h"
#include "core/mesh/self_intersection.h"
#include "core/remesh/delaunay_flips.h"

namespace gr {
namespace {

/// The dual triangles of a cell assignment, and the cells to repair if it is not a valid mesh with
/// the given topology.
struct Dual {
  std::vector<Tri> triangles;
  std::vector<int> badCells;
};

Dual buildDual(const TriMesh& mesh, const std::vector<int>& cell, int cellCount) {
  // Faces in three cells, keyed by their sorted cell triple, sorted so a triple met twice
  // (three cells meeting twice) sits next to its twin.
  using Keyed = std::pair<std::array<int, 3>, int>;  // (sorted cells, face)
  std::vector<Keyed> found;
  std::vector<int> bucketBegin(cellCount + 1, 0);  // counting sort on the smallest cell
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    std::array<int, 3> key = {cell[t[0]], cell[t[1]], cell[t[2]]};
    if (key[0] == key[1] || key[1] == key[2] || key[2] == key[0]) continue;
    if (key[0] < 0 || key[1] < 0 || key[2] < 0) continue;  // a vertex no front reached
    std::sort(key.begin(), key.end());
    found.push_back({key, f});
    ++bucketBegin[key[0] + 1];
  }
  for (int c = 0; c < cellCount; ++c) bucketBegin[c + 1] += bucketBegin[c];
  std::vector<Keyed> keyed(found.size());
  {
    std::vector<int> fill(bucketBegin.begin(), bucketBegin.end() - 1);
    for (const Keyed& k : found) keyed[fill[k.first[0]]++] = k;
  }
  // Each bucket holds the few faces around one cell's Voronoi vertices: sorted in place.
  for (int c = 0; c < cellCount; ++c) std::sort(keyed.begin() + bucketBegin[c], keyed.begin() + bucketBegin[c + 1]);
  Dual d;
  std::vector<char> bad(cellCount, 0);
  for (size_t a = 0; a < keyed.size();) {
    size_t b = a + 1;
    while (b < keyed.size() && keyed[b].first == keyed[a].first) ++b;
    const Tri& t = mesh.triangles[keyed[a].second];
    const int i = cell[t[0]], j = cell[t[1]], k = cell[t[2]];
    if (b - a > 1) {  // three cells meeting twice
      bad[i] = bad[j] = bad[k] = 1;
    } else {
      d.triangles.push_back({i, j, k});  // oriented like the input face
    }
    a = b;
  }
  for (int c = 0; c < cellCount; ++c)
    if (bad[c]) d.badCells.push_back(c);
  return d;
}

/// Cells at the defects of a dual mesh: non-manifold edges and vertices, and boundary edges that
/// do not join two samples lying on the input's boundary (a closed part of the input must give
/// a closed part of the output, and output boundaries must follow input boundaries).
std::vector<int> defectCells(const TriMesh& dual, const std::vector<char>& sampleOnBoundary) {
  std::set<int> cells(dual.topology.nonManifoldVertexList.begin(), dual.topology.nonManifoldVertexList.end());
  for (int c = 0; c < 3 * dual.faceCount(); ++c) {
    const int o = dual.oppositeCorner[c];
    const int a = dual.vertex(TriMesh::next(c)), b = dual.vertex(TriMesh::prev(c));
    if (o == kNonManifold || (o == kBoundary && !(sampleOnBoundary[a] && sampleOnBoundary[b]))) {
      cells.insert(a);
      cells.insert(b);
    }
  }
  return {cells.begin(), cells.end()};
}

Status checkInput(const TriMesh& mesh, const std::vector<SurfacePoint>& samples) {
  if (samples.empty()) return invalidInput("no samples were given");
  for (const SurfacePoint& s : samples) {
    if (s.vertex >= mesh.vertexCount() || (s.vertex < 0 && (s.face < 0 || s.face >= mesh.faceCount())))
      return invalidInput("sample " +
                          (s.vertex >= 0 ? "vertex " + std::to_string(s.vertex) : "face " + std::to_string(s.face)) +
                          " does not exist");
  }
  if (mesh.topology.nonManifoldEdges > 0 || mesh.topology.nonManifoldVertices > 0)
    return nonManifold("the mesh is not manifold (" + std::to_string(mesh.topology.nonManifoldEdges) +
                       " non-manifold edges, " + std::to_string(mesh.topology.nonManifoldVertices) +
                       " non-manifold vertices)");
  // A component whose faces all have zero area (points on a line or at one place) has no
  // surface to triangulate.
  std::vector<double> area(mesh.topology.components, 0.0);
  for (const Tri& t : mesh.triangles) {
    const int c = mesh.topology.componentOfVertex[t[0]];
    if (c >= 0) area[c] += areaNormal(mesh, t).norm();
  }
  for (size_t c = 0; c < area.size(); ++c)
    if (!(area[c] > 0.0))
      return invalidInput("component " + std::to_string(c) +
                          " of the mesh has zero area (all its faces are "
                          "degenerate): there is no surface to remesh");
  // The dual's triangles take the orientation of the input faces they come from.
  if (mesh.topology.inconsistentEdges > 0)
    return invalidInput("the faces of the mesh are not oriented coherently (" +
                        std::to_string(mesh.topology.inconsistentEdges) +
                        " edges have two faces that disagree): orient them first (orientCoherently)");
  return Status::ok();
}

/// A component the samples do not reach (fewer samples than components) gets one at its lowest
/// vertex, as the sampling gives each component its first: counted as added by the repair.
Status sampleUnreachedComponents(FastMarcher& marcher, std::vector<SurfacePoint>& samples) {
  const TriMesh& mesh = marcher.mesh();
  std::vector<char> reached(mesh.topology.components, 0);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (marcher.cell()[v] >= 0 && mesh.topology.componentOfVertex[v] >= 0)
      reached[mesh.topology.componentOfVertex[v]] = 1;
  bool added = false;
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    const int c = mesh.topology.componentOfVertex[v];
    if (c < 0 || reached[c]) continue;
    reached[c] = 1;
    samples.push_back(SurfacePoint::atVertex(v));
    if (Status s = marcher.addSource(v, static_cast<int>(samples.size()) - 1); !s) return s;
    added = true;
  }
  if (added)
    if (Status s = marcher.propagate(); !s) return s;
  return Status::ok();
}

/// Cells that reach the input's boundary while their sample is off it (the output's boundary
/// would cut across the surface), appended to `bad`. `sampleOnBoundary` is per cell.
void addCellsWithSampleOffBoundary(const std::vector<int>& cell, const std::vector<char>& onBoundary,
                                   const std::vector<char>& sampleOnBoundary, std::vector<int>& bad) {
  const int cells = static_cast<int>(sampleOnBoundary.size());
  std::vector<char> cellOnBoundary(cells, 0);
  for (size_t v = 0; v < onBoundary.size(); ++v)
    if (onBoundary[v] && cell[v] >= 0) cellOnBoundary[cell[v]] = 1;
  for (int c = 0; c < cells; ++c)
    if (cellOnBoundary[c] && !sampleOnBoundary[c]) bad.push_back(c);
}

/// Whether a dual without defects is the triangulation sought: the input's components, genus and
/// boundary loops, manifold and coherently oriented, and no non-empty cell without a triangle.
bool hasInputTopology(const TriMesh& out, const TriMesh& mesh, const std::vector<int>& cellSize) {
  const Topology& t = out.topology;
  int isolated = 0;
  for (int v = 0; v < out.vertexCount(); ++v) isolated += out.valence(v) == 0 && cellSize[v] > 0;
  return t.components == mesh.topology.components && t.genus == mesh.topology.genus &&
         t.boundaryLoops == mesh.topology.boundaryLoops && isolated == 0 && t.inconsistentEdges == 0 && t.isManifold();
}

/// The cells that break the closed ball property as regions of the front mesh (a cell is its
/// vertices, the edges and faces between them): a cell that is not one disk (Euler characteristic
/// other than 1: a ring around a handle or a hole, two pieces), and both cells of a pair of disks
/// whose union is not a disk (they meet along two arcs). Counted in one pass over the edges and
/// faces: chi(i u j) = chi(i) + chi(j) - (edges from i to j) + (faces with corners in i and j only).
std::vector<int> cellsNotClosedBalls(const TriMesh& mesh, const std::vector<int>& cell, int cells) {
  std::vector<int> chi(cells, 0);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (cell[v] >= 0) ++chi[cell[v]];
  std::map<std::pair<int, int>, int> pairChi;  // per adjacent pair: faces in the pair - edges across it
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int o = mesh.oppositeCorner[c];
    if (o >= 0 && o < c) continue;  // each edge once
    const int a = cell[mesh.vertex(TriMesh::next(c))], b = cell[mesh.vertex(TriMesh::prev(c))];
    if (a < 0 || b < 0) continue;
    if (a == b)
      --chi[a];
    else
      --pairChi[std::minmax(a, b)];
  }
  for (const Tri& t : mesh.triangles) {
    std::array<int, 3> k = {cell[t[0]], cell[t[1]], cell[t[2]]};
    if (k[0] < 0 || k[1] < 0 || k[2] < 0) continue;
    std::sort(k.begin(), k.end());
    if (k[0] == k[2])
      ++chi[k[0]];
    else if (k[0] == k[1] || k[1] == k[2])
      ++pairChi[std::minmax(k[0], k[2])];
  }
  std::vector<int> bad;
  for (int c = 0; c < cells; ++c)
    if (chi[c] != 1) bad.push_back(c);
  for (const auto& [pair, faceMinusEdge] : pairChi)
    if (chi[pair.first] == 1 && chi[pair.second] == 1 && 2 + faceMinusEdge != 1) {
      bad.push_back(pair.first);
      bad.push_back(pair.second);
    }
  return bad;
}

/// Cells to refine when the dual is valid locally but not of the input's topology (e.g. a handle
/// not captured, a component with too few cells): the non-empty cells without a triangle, else
/// the cells that are not closed balls (cellsNotClosedBalls: where the handle is), else the tenth
/// of the cells with the largest distance to their sample (at least one).
std::vector<int> cellsToRefineForTopology(const FastMarcher& marcher, const TriMesh& out,
                                          const std::vector<int>& cellSize) {
  const std::vector<int>& cell = marcher.cell();
  const int cells = static_cast<int>(cellSize.size());
  std::vector<int> bad;
  for (int v = 0; v < out.vertexCount(); ++v)
    if (out.valence(v) == 0 && cellSize[v] > 0) bad.push_back(v);
  if (bad.empty()) {
    bad = cellsNotClosedBalls(marcher.mesh(), cell, cells);
    for (int& c : bad)
      if (cellSize[c] == 0) c = -1;
    bad.erase(std::remove(bad.begin(), bad.end(), -1), bad.end());
  }
  if (bad.empty()) {
    std::vector<double> far(cells, 0.0);
    for (int v = 0; v < marcher.mesh().vertexCount(); ++v)
      if (cell[v] >= 0) far[cell[v]] = std::max(far[cell[v]], marcher.distance()[v]);
    std::vector<int> order(cells);
    for (int c = 0; c < cells; ++c) order[c] = c;
    std::sort(order.begin(), order.end(), [&](int a, int b) { return far[a] > far[b]; });
    bad.assign(order.begin(), order.begin() + std::max(1, cells / 10));
  }
  return bad;
}

/// The cells to refine where the straight triangles of a valid dual cross each other (an output
/// that is not embedded: on thin plates a triangle of the top cells cuts through the bottom; at
/// 30% of a scan a sliver dual triangle folds over its neighbour): the cells of both faces of each
/// crossing pair away from the input's own crossings (crossingsAwayFromInput, with
/// DelaunayParams::mayCross read on first use into `inputCrossing`).
std::vector<int> crossingCells(const TriMesh& out, const TriMesh& mesh, const std::vector<int>& cell,
                               const DelaunayParams& params, std::vector<char>& inputCrossing) {
  std::vector<std::pair<int, int>> pairs = selfIntersectingFaces(out);
  if (pairs.empty()) return {};
  if (inputCrossing.empty()) inputCrossing = params.mayCross ? params.mayCross() : crossingVertices(mesh);
  std::vector<int> bad;
  for (const auto& [f, g] : crossingsAwayFromInput(out, cell, inputCrossing, std::move(pairs))) {
    bad.insert(bad.end(), out.triangles[f].begin(), out.triangles[f].end());
    bad.insert(bad.end(), out.triangles[g].begin(), out.triangles[g].end());
  }
  return bad;
}

/// Renumbers a valid dual without its isolated vertices (the samples of empty cells), in the
/// mesh, in r.origin and in r.cell (the input vertices' cells).
Status dropEmptyCells(TriMesh& out, const std::vector<Vec3>& positions, const std::vector<SurfacePoint>& samples,
                      const std::vector<int>& cell, DelaunayResult& r) {
  const int cells = static_cast<int>(samples.size());
  std::vector<int> index(cells, -1);
  std::vector<Vec3> kept;
  for (int c = 0; c < cells; ++c)
    if (out.valence(c) > 0) {
      index[c] = static_cast<int>(kept.size());
      kept.push_back(positions[c]);
      r.origin.push_back(samples[c]);
    }
  std::vector<Tri> tris = out.triangles;
  for (Tri& tri : tris)
    for (int& v : tri) v = index[v];
  Expected<TriMesh> renumbered = buildTriMesh(std::move(kept), std::move(tris));
  if (!renumbered) return renumbered.status();
  out = std::move(renumbered).value();
  r.cell = cell;
  for (int& l : r.cell)
    if (l >= 0) l = index[l];
  return Status::ok();
}

/// The result from a valid dual: samples of empty cells left out, then the Delaunay flips.
Expected<DelaunayResult> finishValidDual(TriMesh out, const std::vector<Vec3>& positions,
                                         const std::vector<SurfacePoint>& samples, const std::vector<int>& cell,
                                         const DelaunayParams& params, int initialCount, int round) {
  DelaunayResult r;
  const int cells = static_cast<int>(samples.size());
  if (out.topology.isolatedVertices > 0) {  // drop the empty cells' samples, renumber the rest
    if (Status s = dropEmptyCells(out, positions, samples, cell, r); !s) return s;
    r.droppedSamples = cells - out.vertexCount();
  } else {
    r.origin = samples;
    r.cell = cell;
  }
  if (params.delaunayFlips) {
    Expected<DelaunayFlipResult> flipped = flipToDelaunay(out, params.flips);
    if (!flipped) return flipped.status();
    r.flippedEdges = flipped->flips;
  }
  r.mesh = std::move(out);
  r.addedSamples = cells - initialCount;
  r.repairRounds = round;
  return r;
}

/// Per cell, the vertex to add as a sample if the cell is refined: its vertex farthest from the
/// samples, or its farthest boundary vertex if it reaches the boundary (so that boundaries are
/// sampled on the boundary); -1 for a cell without vertices.
std::vector<int> farthestVertexPerCell(const FastMarcher& marcher, const std::vector<char>& onBoundary, int cells) {
  const std::vector<int>& cell = marcher.cell();
  std::vector<int> farthest(cells, -1), farthestOnBoundary(cells, -1);
  for (int v = 0; v < marcher.mesh().vertexCount(); ++v) {
    const int c = cell[v];
    if (c < 0) continue;
    const double u = marcher.distance()[v];
    if (farthest[c] < 0 || u > marcher.distance()[farthest[c]]) farthest[c] = v;
    if (onBoundary[v] && (farthestOnBoundary[c] < 0 || u > marcher.distance()[farthestOnBoundary[c]]))
      farthestOnBoundary[c] = v;
  }
  for (int c = 0; c < cells; ++c)
    if (farthestOnBoundary[c] >= 0 && marcher.distance()[farthestOnBoundary[c]] > 0.0)
      farthest[c] = farthestOnBoundary[c];
  return farthest;
}

/// Per cell, 1 if it is refined: the bad cells, and the cells around a bad cell that is only its
/// sample (it cannot be refined itself).
std::vector<char> cellsToRefine(const FastMarcher& marcher, const std::vector<SurfacePoint>& samples,
                                const std::vector<int>& bad, const std::vector<int>& farthest) {
  const TriMesh& mesh = marcher.mesh();
  const std::vector<int>& cell = marcher.cell();
  std::vector<char> isBad(samples.size(), 0);
  for (int c : bad) isBad[c] = 1;
  for (int c : bad)
    if (farthest[c] < 0 || marcher.distance()[farthest[c]] <= 0.0) {
      const SurfacePoint& p = samples[c];
      const Tri around = p.vertex >= 0 ? Tri{p.vertex, p.vertex, p.vertex} : mesh.triangles[p.face];
      for (int x : around)
        for (const int* k = mesh.cornersBegin(x); k != mesh.cornersEnd(x); ++k)
          for (int w : {mesh.vertex(TriMesh::next(*k)), mesh.vertex(TriMesh::prev(*k))})
            if (cell[w] >= 0) isBad[cell[w]] = 1;
    }
  return isBad;
}

/// Adds the new samples of a round of repair and returns how many: in each bad cell its farthest
/// vertex (farthestVertexPerCell). Farthest first, as the sampling would; a candidate nearer to a
/// sample added in this round than to the existing ones is left for the next round (adjacent bad
/// cells have their farthest vertices around the same Voronoi vertex: adding all of them would
/// cluster). The fronts are not propagated.
Expected<int> addRefinementSamples(FastMarcher& marcher, std::vector<SurfacePoint>& samples, std::vector<int> bad,
                                   const std::vector<char>& onBoundary) {
  const int cells = static_cast<int>(samples.size());
  std::sort(bad.begin(), bad.end());
  bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
  const std::vector<int> farthest = farthestVertexPerCell(marcher, onBoundary, cells);
  const std::vector<char> isBad = cellsToRefine(marcher, samples, bad, farthest);
  std::vector<int> candidates;
  for (int c = 0; c < cells; ++c)
    if (isBad[c] && farthest[c] >= 0 && marcher.distance()[farthest[c]] > 0.0) candidates.push_back(farthest[c]);
  std::sort(candidates.begin(), candidates.end(),
            [&](int a, int b) { return marcher.distance()[a] > marcher.distance()[b]; });
  std::vector<Vec3> addedPositions;
  int added = 0;
  for (int v : candidates) {
    const Vec3& p = marcher.mesh().positions[v];
    const double u = marcher.distance()[v];
    bool covered = false;
    for (const Vec3& q : addedPositions) covered = covered || (p - q).squaredNorm() < u * u;
    if (covered) continue;
    addedPositions.push_back(p);
    samples.push_back(SurfacePoint::atVertex(v));
    if (Status s = marcher.addSource(v, static_cast<int>(samples.size()) - 1); !s) return s;
    ++added;
  }
  return added;
}

}  // namespace

std::vector<std::pair<int, int>> crossingsAwayFromInput(const TriMesh& out, const std::vector<int>& cell,
                                                        const std::vector<char>& inputCrossing,
                                                        std::vector<std::pair<int, int>> pairs) {
  if (pairs.empty()) return pairs;
  if (inputCrossing.size() != cell.size()) return {};  // not known: every crossing may be the input's
  std::vector<char> excused(out.vertexCount(), 0);
  for (size_t v = 0; v < cell.size(); ++v)
    if (inputCrossing[v] && cell[v] >= 0) excused[cell[v]] = 1;
  const auto nearInput = [&](const std::pair<int, int>& p) {
    for (int face : {p.first, p.second})
      for (int v : out.triangles[face])
        if (excused[v]) return true;
    return false;
  };
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(), nearInput), pairs.end());
  return pairs;
}

Expected<DelaunayResult> geodesicDelaunay(const TriMesh& mesh, const Metric& metric, std::vector<int> vertices,
                                          const DelaunayParams& params, Progress progress) {
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::vector<SurfacePoint> samples;
  for (int v : vertices) samples.push_back(SurfacePoint::atVertex(v));
  if (Status s = checkInput(mesh, samples); !s) return s;
  FastMarcher marcher(mesh, metric);
  for (size_t i = 0; i < samples.size(); ++i)
    if (Status s = marcher.addSource(samples[i], static_cast<int>(i)); !s) return s;
  if (Status s = marcher.propagate(); !s) return s;
  return geodesicDelaunay(marcher, std::move(samples), params, std::move(progress));
}

Expected<DelaunayResult> geodesicDelaunay(FastMarcher& marcher, std::vector<SurfacePoint> samples,
                                          const DelaunayParams& params, Progress progress) {
  const TriMesh& mesh = marcher.mesh();
  if (Status s = checkInput(mesh, samples); !s) return s;
  const std::vector<char> onBoundary = boundaryVertexFlags(mesh);
  const int initialCount = static_cast<int>(samples.size());
  if (Status s = sampleUnreachedComponents(marcher, samples); !s) return s;
  int crossingRounds = 0;
  std::vector<char> inputCrossing;  // crossingCells: per vertex of `mesh`, where the input crosses itself
  for (int round = 0;; ++round) {
    const std::vector<int>& cell = marcher.cell();
    const int cells = static_cast<int>(samples.size());
    Dual dual = buildDual(mesh, cell, cells);
    std::vector<int> bad = dual.badCells;
    std::vector<Vec3> positions(cells);
    for (int c = 0; c < cells; ++c) positions[c] = samples[c].position(mesh);
    // Components without any triangle (one cell covers a whole component) are defects too.
    Expected<TriMesh> out = dual.triangles.empty() ? Expected<TriMesh>(invalidInput("no triangle"))
                                                   : buildTriMesh(positions, dual.triangles);
    bool valid = false;  // a mesh of the input's topology, which may still cross itself
    const auto finishValid = [&]() -> Expected<DelaunayResult> {
      Expected<DelaunayResult> r =
          finishValidDual(std::move(out).value(), positions, samples, marcher.cell(), params, initialCount, round);
      if (r) r->crossingRounds = crossingRounds;
      return r;
    };
    // A cell that reaches the input's boundary must have its sample on it.
    std::vector<char> sampleOnBoundary(cells, 0);
    for (int c = 0; c < cells; ++c) sampleOnBoundary[c] = samples[c].vertex >= 0 && onBoundary[samples[c].vertex];
    addCellsWithSampleOffBoundary(cell, onBoundary, sampleOnBoundary, bad);
    if (out) {
      const std::vector<int> defects = defectCells(*out, sampleOnBoundary);
      bad.insert(bad.end(), defects.begin(), defects.end());
      // A sample inside a face may end up nearest to no vertex (another sample took its cell):
      // it is left out of the output rather than repaired.
      std::vector<int> cellSize(cells, 0);
      for (int v = 0; v < mesh.vertexCount(); ++v)
        if (cell[v] >= 0) ++cellSize[cell[v]];
      valid = bad.empty() && hasInputTopology(*out, mesh, cellSize);
      if (valid && crossingRounds < params.maxCrossingRounds)
        bad = crossingCells(*out, mesh, cell, params, inputCrossing);
      if (valid && (bad.empty() || round >= params.maxRepairRounds)) return finishValid();
      if (valid) ++crossingRounds;
      if (bad.empty()) bad = cellsToRefineForTopology(marcher, *out, cellSize);
    } else {
      for (int c = 0; c < cells; ++c) bad.push_back(c);
    }
    if (round >= params.maxRepairRounds)
      return Status{StatusCode::NotConverged, "the geodesic Delaunay triangulation is still invalid after " +
                                                  std::to_string(round) + " rounds of sample insertion"};
    // How many rounds a mesh needs is not known ahead (1 to a few hundred): the bar moves by
    // a tenth of what is left each round.
    if (!progress.report(1.0 - std::pow(0.9, round + 1), "Geodesic Delaunay repair")) return cancelled();
    const Expected<int> added = addRefinementSamples(marcher, samples, std::move(bad), onBoundary);
    if (!added) return added.status();
    if (*added == 0 && valid) return finishValid();  // crossing cells that cannot be refined: kept as they are
    if (*added == 0)
      return Status{StatusCode::NotConverged,
                    "the geodesic Delaunay triangulation is invalid and no cell can be refined"};
    if (Status s = marcher.propagate(); !s) return s;
  }
}

}  // namespace gr
