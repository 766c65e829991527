// Geodesic Delaunay triangulation of surface samples, as the dual of their geodesic Voronoi
// diagram (paper §3.2), with automatic repair until the result is a valid mesh of the input's
// topology.
//
// Each input face whose three vertices lie in three different Voronoi cells (i, j, k) gives the
// output triangle (i, j, k), oriented like that face:
//
//      cell i  \   cell j          input face (a, b, c), cells (i, j, k)
//               \ /                   -> output triangle (sample i, sample j, sample k)
//                *   <- three fronts meet
//                |
//             cell k
//
// The dual is a valid triangulation when the samples are dense enough (closed ball property:
// every cell a disk, two cells meeting along one arc, three cells at one point). Where it is not
// (an output edge with three or more triangles, a non-manifold vertex, a triangle twice, a
// topology other than the input's), the vertex farthest from the samples inside the offending
// cells becomes a new sample, the Voronoi diagram is updated incrementally, and the dual is
// rebuilt; the number of added samples is reported. When the dual is a manifold of another
// topology (a handle missed), the offending cells are the ones that are not closed balls, counted
// by Euler characteristic (a cell that is not one disk, two cells whose union is not one); only
// if there are none, the tenth of the cells with the largest radius. Last, edges that are not locally Delaunay
// are flipped (delaunay_flips.h) where that keeps features, orientation and topology.
// Boundaries: output boundary edges must join samples lying on input boundaries, and a cell
// that reaches a boundary must have its sample on it (else its farthest boundary vertex is
// added); the output then has the input's boundary loops. A valid dual whose straight triangles
// cross each other (thin plates, slivers at fine densities) gets the same insertion in the cells
// of the crossing triangles, up to maxCrossingRounds rounds.
// Cost: one incremental front per added sample plus O(F) per round.
#pragma once

#include <functional>
#include <utility>
#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/metric.h"
#include "core/mesh/tri_mesh.h"
#include "core/remesh/delaunay_flips.h"

namespace gr {

struct DelaunayParams {
  /// Rounds of sample insertion before giving up (NotConverged). Each round adds at least one
  /// sample, so the repair ends within V rounds anyway; the cap bounds its time. A mesh with many
  /// small holes needs many (elephant-with-holes.off, 106 boundary loops: 176 rounds from 50 samples).
  int maxRepairRounds = 1000;
  /// Rounds of the same insertion, once the dual is valid, in the cells of output triangles that
  /// cross each other (selfIntersectingFaces; not next to a crossing of the input itself): an
  /// output that cuts through itself where the input does not (thin plates: the rotor of the
  /// data set at 10%, 0 -> 12 crossing pairs). 0 = a crossing dual is returned as it is.
  int maxCrossingRounds = 8;
  /// Per vertex of the mesh the fronts run on, 1 where the input itself crosses (output crossings
  /// there are not repaired); called once, only if a dual crosses. Unset: the crossings of that
  /// mesh (crossingVertices). A caller whose front mesh is not the input's geometry (an intrinsic
  /// refinement, whose straight triangles may cross where the input's do not) maps the input's.
  std::function<std::vector<char>()> mayCross;
  /// Last, flip edges of the valid dual that are not locally Delaunay (delaunay_flips.h): the
  /// discrete Voronoi diagram picks the diagonal of nearly cocircular samples at random.
  bool delaunayFlips = true;
  DelaunayFlipParams flips;  ///< feature angle and tolerance of those flips
};

struct DelaunayResult {
  TriMesh mesh;                      ///< output: one vertex per sample, at the sample's position
  std::vector<SurfacePoint> origin;  ///< per output vertex, the point of the input it sits on
  int addedSamples = 0;              ///< samples inserted by the repair
  int droppedSamples = 0;            ///< samples inside faces left out: nearest to no vertex
  int repairRounds = 0;
  int crossingRounds = 0;  ///< of repairRounds, those for crossing triangles (maxCrossingRounds)
  int flippedEdges = 0;    ///< edges flipped to make the result locally Delaunay
  std::vector<int> cell;   ///< per input vertex, its Voronoi cell: an output vertex
};

/// Fails with InvalidInput (no samples, a sample out of range, faces not oriented coherently: see
/// orientCoherently in mesh/orientation.h, a component of zero area), NonManifold (a non-manifold
/// edge or vertex), NotConverged (still invalid after maxRepairRounds) or Cancelled.
Expected<DelaunayResult> geodesicDelaunay(const TriMesh& mesh, const Metric& metric, std::vector<int> samples,
                                          const DelaunayParams& params = {}, Progress progress = {});

/// The same on an engine that already holds the field of `samples` with cells 0..n-1 in that
/// order (as farthestPointSampling leaves it, with FpsResult::origin): no propagation from
/// scratch. Samples may lie inside faces; the ones the repair adds are vertices.
Expected<DelaunayResult> geodesicDelaunay(FastMarcher& marcher, std::vector<SurfacePoint> samples,
                                          const DelaunayParams& params = {}, Progress progress = {});

/// Of `pairs`, crossing faces of a dual `out` (selfIntersectingFaces), those away from where the
/// input crosses itself: no corner's cell holds a vertex flagged in `inputCrossing` (one flag per
/// vertex of the mesh the fronts ran on, as DelaunayParams::mayCross gives; `cell` maps those
/// vertices to output vertices, as DelaunayResult::cell). Flags of another size: none is away.
std::vector<std::pair<int, int>> crossingsAwayFromInput(const TriMesh& out, const std::vector<int>& cell,
                                                        const std::vector<char>& inputCrossing,
                                                        std::vector<std::pair<int, int>> pairs);

}  // namespace gr
