// Fast marching on a triangle mesh: weighted geodesic distance and nearest source (Voronoi).
//
// Paper §2.1–2.2, §3.1; Kimmel & Sethian 1998. Vertices are accepted in increasing distance U
// from a binary heap. When a vertex is accepted, each incident triangle (v, a, b) offers a and b
// the local Eikonal solution (eikonal_update.h) and edge updates. At an obtuse corner X the
// update also comes from the virtual triangles XAR, XRB, where R is found by unfolding across AB
// (acute_split.h). A triangle update smaller than max(U(A), U(B)) is rejected, so the accepted
// values never decrease along the acceptance order (monotone) on any mesh. Around each source,
// the nearby vertices first get the straight-line distance in the unfolded faces (exact where a
// point source is too close for the triangle updates to be causal).
//
// Incremental use (greedy sampling, Lloyd): after a run, add a source and propagate again: the
// new front only enters vertices it improves, U_{n+1} = min(U_n, U_x) (§3.1), and
// acceptedOrder() lists exactly the vertices whose U decreased.
// Cost: O(n log n) for n vertices accepted in a run. Memory: O(V + F) buffers owned by the
// FastMarcher and reused across runs (about 40 bytes per corner and 40 per vertex); no
// allocation per vertex in the loop. Internally vertices are renumbered in breadth-first order
// for memory locality; the API always speaks the mesh's vertex numbers.
#pragma once

#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/geodesic/detail/acute_split.h"
#include "core/geodesic/detail/eikonal_update.h"
#include "core/geodesic/detail/indexed_heap.h"
#include "core/geodesic/detail/marcher_records.h"
#include "core/geodesic/detail/unfold.h"
#include "core/geodesic/metric.h"
#include "core/geodesic/triangulation_quality.h"
#include "core/mesh/face_geometry.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

struct FastMarchingParams {
  /// Stop the front at this distance (mesh units, weighted by P); vertices farther away keep
  /// their previous value (+inf in a first run). +inf (default) = no limit.
  double maxDistance = kUnreached;
  /// Stop as soon as all these vertices are accepted; empty (default) = no such stop.
  std::vector<int> targets;
  /// A region to stay in (none by default): per vertex a label. The front enters any vertex it
  /// reaches but goes on only from vertices labelled `regionLabel`, so it covers the region and
  /// the ring of vertices around it (a Voronoi cell and its margin, for Lloyd's descent).
  const std::vector<int>* region = nullptr;
  int regionLabel = 0;
};

struct FastMarchingResult {
  std::vector<double> distance;    ///< per vertex, U; kUnreached (+inf) if not reached
  std::vector<int> cell;           ///< per vertex, index into the source list; -1 if not reached
  std::vector<int> acceptedOrder;  ///< reached vertices in the order they were accepted
  double maxDistance = 0.0;        ///< largest finite U
  int reachedCount() const { return static_cast<int>(acceptedOrder.size()); }
};

/// The checks every distance entry point makes: at least one source, each a vertex of `mesh`, and a
/// distance limit >= 0 (+inf = none). InvalidInput with the reason otherwise.
Status checkSourcesAndLimit(const TriMesh& mesh, const std::vector<int>& sources, double maxDistance);

/// Reusable fast-marching engine: owns the heap and per-vertex buffers for one mesh and metric.
class FastMarcher {
 public:
  /// `mesh` and `metric` must outlive the marcher; the metric is uniform or has one P per
  /// vertex (checked by Metric's factories). Precomputes the vertex order, the per-vertex star
  /// records (neighbours, edge lengths) and the acute splits: O(V + F).
  FastMarcher(const TriMesh& mesh, const Metric& metric);
  /// The same on a triangulation that carries its own edge lengths (an intrinsic triangulation:
  /// `cornerLength[c]` is the length of the edge facing corner c); the positions are not read.
  /// `cornerLength` must outlive the marcher and have 3 values per face.
  FastMarcher(const TriMesh& mesh, const std::vector<double>& cornerLength, const Metric& metric);

  /// Forgets all sources and distances. Cost: O(vertices ever reached since the last reset).
  void reset();
  /// Forgets all sources and distances, then starts from upper bounds: every vertex gets
  /// U = bound[v] in cell[v] (vertex numbers) as if an earlier run had accepted it (+inf: not
  /// reached). Sources added then propagate only where they go below these values, so the field
  /// of sources that moved a little from those of a known field (Lloyd's from one iteration to
  /// the next) costs their cells and the band where the bound is loose, one compact front at a
  /// time, instead of one front over the whole mesh from all of them at once. Where a bound is
  /// below the new sources' field it stays. InvalidInput on sizes that differ from the mesh's or
  /// a negative or NaN bound.
  Status startFromBound(const std::vector<double>& bound, const std::vector<int>& cell);
  /// Adds vertex `v` as a source (U = 0) in Voronoi cell `cell`. InvalidInput if v is out of range. A
  /// vertex that already has U = 0 keeps its cell.
  Status addSource(int v, int cell);
  /// Adds a surface point (vertex, or face + barycentric) as a source; the vertices of the
  /// faces around it, up to three rings, get straight-line distances in the unfolding.
  Status addSource(const SurfacePoint& point, int cell);
  /// Saddle seeding (off by default): a vertex whose angle sum is above 2 pi (a saddle) or that
  /// lies on the boundary, when accepted, offers the vertices across its star's outer edges the
  /// straight line from it in the unfolding, as a source does (addSource(int)). Geodesics bend
  /// only at such vertices, where the front restarts as from a point; the triangle updates alone
  /// smear that restart over the faces around (cheese.off refined: 1.4% -> 0.9% mean error).
  /// About +50% per accepted vertex on a scan; geodesic_surface.h turns it on for refined
  /// surfaces only. O(V + F) to turn on (the angle sums). `boundaryOnly`: at boundary vertices
  /// only (a few per mesh: no measurable cost), for unrefined surfaces.
  void setSaddleSeeding(bool on, bool boundaryOnly = false);
  /// Chord bound (off by default; uniform metric only): the mesh's positions are points of the
  /// surface the lengths describe, and no vertex is accepted below the straight-line distance to
  /// the vertex source of its cell (cells of face sources, or of several sources, are not
  /// bounded). The triangle updates of a virtual source can undershoot: behind a convex cone
  /// (a box's corner, refined surfaces with few vertices per feature) and on the virtual
  /// triangles of acute splits unfolded over curved faces (bull.off vertex 54, 0.06% below);
  /// a vertex found below its bound goes back into the heap at the bound, so the acceptance
  /// order stays monotone. O(1) per accepted vertex (a square root); O(V) to turn on.
  void setChordBound(bool on);
  /// Path edges (none by default): straight segments on the surface that are not (or no longer)
  /// edges of this mesh, each with its length; an accepted end offers the other end U plus the
  /// segment's cost (mean P of the ends times the length), an upper bound that is exact along
  /// the segment. For a refined surface: the input's edges, which the intrinsic flips may have
  /// removed, and along which the exact geodesic runs on polygonal meshes (a star-shaped plate:
  /// its reflex corners; a cube: its edges). O(edges) to set; O(1) per edge per run.
  void setPathEdges(const std::vector<std::array<int, 2>>& edges, const std::vector<double>& lengths);
  /// Runs the front from the sources added since the last run, entering only vertices it
  /// improves. Cancelled if `progress` says so (the field is then partial).
  Status propagate(const FastMarchingParams& params = {}, Progress progress = {});

  /// U and nearest-source cell per vertex, as of the end of the last propagate().
  const std::vector<double>& distance() const { return U_; }
  const std::vector<int>& cell() const { return cell_; }
  /// Vertices accepted by the last propagate(), in order: all reached vertices for a first
  /// run, the improved ones for an incremental run.
  const std::vector<int>& acceptedOrder() const { return acceptedVertices_; }
  const TriMesh& mesh() const { return mesh_; }
  /// assessTriangulation(mesh()), measured while the engine was built (one pass over the faces
  /// for both); null for an engine on a triangulation with its own lengths.
  const TriangulationQuality* triangulationQuality() const { return quality_.faces > 0 ? &quality_ : nullptr; }

 private:
  using Candidate = detail::Candidate;
  using Saved = detail::Saved;
  using StarFace = detail::StarFace;
  using NearSplit = detail::NearSplit;
  using StarCost = detail::StarCost;
  using FarSplit = detail::FarSplit;
  using Node = detail::Node;

  // Construction, in this order (all O(V + F)):
  /// Numbers the vertices into slots (slotOf_, vertexOf_) breadth-first from each unnumbered vertex.
  void orderSlotsBreadthFirst();
  /// Fills each slot's star records (starBegin_, star_): neighbours, edge lengths, acute split.
  void buildStars(const AcuteSplits& splits);
  /// Fills the per-record metric costs (starCost_) of a non-uniform metric from P_ and the stars.
  void buildStarCosts();
  /// Fills the acute splits' records: per split, what a star face reads (nearSplits_), and per
  /// slot, the splits whose far vertex R it is (farSplitBegin_, farSplits_).
  void buildSplitRecords(const AcuteSplits& splits);

  void beginRun();
  void push(int v, double u, int cell);
  bool known(int v) const { return node_[v].run != 0; }
  /// Offers x the value u (edge update) with the given cell.
  void relax(int x, double u, int cell);
  /// Offers x the update of the (possibly virtual) triangle x, s, t; s and t are known. `p` is
  /// the triangle's mean P (unused with a uniform metric).
  template <bool kUniform>
  void offerTriangle(Candidate& best, int x, int s, int t, double lxs, double lxt, double lst, double p) const;
  /// Updates the neighbours of the newly accepted vertex v.
  template <bool kUniform>
  void scatter(int v);
  /// Offers the vertices of the faces around a source the length of straight segments from the
  /// source point in the unfolding of those faces (kSeedDepth rings): exact values where a point
  /// source is too close for the triangle updates to be causal.
  void seedByUnfolding(const Vec2& p, double pAtSource, int face, const std::array<Vec2, 3>& layout, int enteredThrough,
                       int depth, int cell);
  void endRun();
  /// Offers the vertices across the outer edges of slot sv's star U(sv) plus the straight line
  /// from sv in the unfolding of the two faces, where that line crosses the edge.
  void seedAcrossStar(int sv, int cell);
  /// Records where cell `cell`'s source is for the chord bound (a vertex's slot, or -1 for a
  /// point inside a face: that cell is not bounded).
  void noteSourceOfCell(int cell, int slot);
  /// Whether slot v's value is below its chord bound (false when its cell is not bounded).
  /// Squared lengths: no square root unless it is; a relative slack of 1e-12 so that a value set
  /// to the bound (a rounded square root) is never found below it again.
  bool belowChord(int v) const {
    const int cell = node_[v].cell;
    if (cell < 0 || cell >= static_cast<int>(sourceSlotOfCell_.size())) return false;
    const int s = sourceSlotOfCell_[cell];
    const double u = node_[v].u;
    return s >= 0 && u * u < (chordPosition_[v] - chordPosition_[s]).squaredNorm() * (1.0 - 1e-12);
  }

  /// The constructors' common body; `cornerLength` is null for lengths from the positions.
  FastMarcher(const TriMesh& mesh, const std::vector<double>* cornerLength, const Metric& metric);

  const TriMesh& mesh_;
  CornerLengths length_;  ///< per corner, the length of the edge it faces
  bool uniform_;
  std::vector<double> P_;  ///< per slot; all ones for a uniform metric
  // The hot loop works on slots: vertices renumbered in breadth-first order for memory
  // locality; the public arrays and the API use the mesh's vertex numbers.
  std::vector<int> slotOf_;     ///< per vertex
  std::vector<int> vertexOf_;   ///< per slot
  std::vector<int> starBegin_;  ///< per slot, into star_
  std::vector<StarFace> star_;  ///< the faces around each slot (a, b are slots)
  std::vector<StarCost> starCost_;
  std::vector<NearSplit> nearSplits_;  ///< per acute split
  std::vector<int> farSplitBegin_;
  std::vector<FarSplit> farSplits_;
  std::vector<Node> node_;
  std::vector<double> U_;  ///< public copies of node_.u and node_.cell, updated at the
  std::vector<int> cell_;  ///< end of each run for the vertices it changed
  int run_ = 0;
  bool runOpen_ = false;
  std::vector<int> touched_;           ///< slots given a finite value since reset()
  std::vector<int> accepted_;          ///< slots accepted by the current or last run
  std::vector<int> acceptedVertices_;  ///< the same as vertices, published by endRun()
  std::vector<Saved> saved_;
  IndexedHeap heap_;
  std::vector<std::pair<Vec2, Vec2>> seedChain_;  ///< edges crossed by the current unfolding
  std::vector<char> saddle_;    ///< per slot, 1 if saddle seeding restarts the front there; empty = off
  std::vector<int> pathBegin_;  ///< per slot, into pathEdges_ (CSR); empty = no path edges
  struct PathEdge {
    int to;  ///< slot
    double length;
  };
  std::vector<PathEdge> pathEdges_;
  std::vector<Vec3> chordPosition_;  ///< per slot, for the chord bound; empty = off
  TriangulationQuality quality_;     ///< see triangulationQuality()
  /// Per cell, the slot of its one vertex source; -1 not bounded, -2 no source yet.
  std::vector<int> sourceSlotOfCell_;
};

/// One-shot multi-source fast marching. Fails on an empty or out-of-range source list, a metric
/// whose size does not match the mesh, or a negative distance limit. On a connected mesh with no
/// limit every vertex is reached.
Expected<FastMarchingResult> fastMarching(const TriMesh& mesh, const Metric& metric, const std::vector<int>& sources,
                                          const FastMarchingParams& params = {}, Progress progress = {});

/// The same with a per-vertex front speed F (P = 1/F, Metric::fromSpeed); an empty `speed` is
/// F = 1. Fails also (InvalidInput) when a speed is not finite and > 0, naming the vertex.
Expected<FastMarchingResult> fastMarchingWithSpeed(const TriMesh& mesh, const std::vector<double>& speed,
                                                   const std::vector<int>& sources,
                                                   const FastMarchingParams& params = {}, Progress progress = {});

}  // namespace gr
