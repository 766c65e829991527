// Fast marching on a triangle mesh: weighted geodesic distance and nearest source (Voronoi).
//
// Paper §2.1–2.2; Kimmel & Sethian 1998. Vertices are accepted in increasing distance U from a
// binary heap. When a vertex is accepted, each incident triangle (v, a, b) updates a and b:
//
//            S   virtual source, unfolded across AB so that |SA| = U(A)/P, |SB| = U(B)/P
//            |
//      A ----+-------- B       U(X) = P * |SX| if the segment SX crosses AB (upwind),
//        \     |     /         else U(X) = min(U(A) + P|XA|, U(B) + P|XB|) (edge updates).
//          \   |   /
//              X
//
// At an obtuse corner X the update also comes from virtual triangles XAR, XRB, where R is found
// by unfolding across AB (acute_split.h). A triangle update smaller than max(U(A), U(B)) is
// rejected, so the accepted values never decrease along the acceptance order (monotone).
// Cost: O(n log n) for n reached vertices; memory: O(V) buffers owned by the FastMarcher and
// reused across runs (no allocation per vertex in the loop).
#pragma once

#include <limits>
#include <vector>

#include "core/acute_split.h"
#include "core/metric.h"
#include "core/progress.h"
#include "core/status.h"
#include "core/tri_mesh.h"

namespace gr {

constexpr double kUnreached = std::numeric_limits<double>::infinity();

struct FastMarchingParams {
  /// Stop the front at this distance (mesh units, weighted by P); vertices farther away are left
  /// unreached. +inf (default) = no limit.
  double maxDistance = kUnreached;
};

struct FastMarchingResult {
  std::vector<double> distance;    ///< per vertex, U; kUnreached (+inf) if not reached
  std::vector<int> nearestSource;  ///< per vertex, index into the source list; -1 if not reached
  std::vector<int> acceptedOrder;  ///< reached vertices in the order they were accepted
  double maxDistance = 0.0;        ///< largest finite U
  int reachedCount() const { return static_cast<int>(acceptedOrder.size()); }
};

/// Reusable fast-marching engine: owns the heap and per-vertex buffers for one mesh and metric.
/// reset() costs O(vertices touched by the last run).
class FastMarcher {
 public:
  /// `mesh` and `metric` must outlive the marcher. The metric must be uniform or have one P
  /// per vertex (checked by Metric's factories).
  FastMarcher(const TriMesh& mesh, const Metric& metric);

  /// Forgets all sources and distances.
  void reset();
  /// Adds vertex `v` as a source with distance 0 and the given label. InvalidInput if v is out
  /// of range. A vertex given twice keeps its first label.
  Status addSource(int v, int label);
  /// Runs the front until the heap is empty or the next distance exceeds params.maxDistance.
  /// Cancelled if `progress` says so (the state is then partial).
  Status propagate(const FastMarchingParams& params = {}, Progress progress = {});

  const std::vector<double>& distance() const { return U_; }
  const std::vector<int>& label() const { return label_; }
  const std::vector<int>& acceptedOrder() const { return accepted_; }

 private:
  struct HeapEntry {
    double u;
    int v;
  };
  void push(int v, double u, int label);
  /// Offers x the value u (edge update) with the given label.
  void relax(int x, double u, int label);
  /// Offers x the update of the (possibly virtual) triangle x, s, t; s and t are frozen.
  void relax(int x, int s, int t, double lxs, double lxt, double lst);

  const TriMesh& mesh_;
  AcuteSplits splits_;             ///< obtuse corners and their unfolded acute splits
  std::vector<double> P_;          ///< per vertex; all ones for a uniform metric
  std::vector<double> edgeLength_; ///< per corner: length of the opposite edge
  std::vector<double> U_;
  std::vector<int> label_;
  std::vector<char> frozen_;
  std::vector<int> touched_;       ///< vertices with a finite tentative value since reset()
  std::vector<int> accepted_;
  std::vector<HeapEntry> heap_;
};

/// One-shot multi-source fast marching. Fails on an empty or out-of-range source list, or a
/// metric whose size does not match the mesh. On a connected mesh with no distance limit every
/// vertex is reached.
Expected<FastMarchingResult> fastMarching(const TriMesh& mesh, const Metric& metric,
                                          const std::vector<int>& sources,
                                          const FastMarchingParams& params = {}, Progress progress = {});

}  // namespace gr
