// Exact geodesic distance on a triangle mesh by window propagation (Chen & Han 1990, with the
// vertex filter of Xin & Wang 2009, "Improving Chen and Han's algorithm on the discrete geodesic
// problem"): the polyhedral distance itself, not an approximation of it, on any triangulation.
//
// A window is an interval of an edge whose points are reached by straight lines (in the
// unfolding of the faces crossed) from one image of a source or of a pseudo-source: a source, a
// saddle vertex (angle sum above 2 pi) or a boundary vertex, where shortest paths may bend. Windows
// are taken from a queue in increasing distance and cross the face beyond their edge, giving at
// most two children on its other edges; the vertex they see gets the straight-line distance. A
// child is dropped when every point of it is reached more cheaply through an end of its edge
// (d(end) plus the length along the edge, an upper bound that a real path achieves), which is what
// keeps the count of windows low on real meshes. Vertices are also relaxed along their edges, so
// every vertex of a source's component gets a value (the edge path) even where rounding hides it
// from the windows; the windows give the exact one.
//
// Where fast marching is wrong (CAD slivers, caps, vertices only on outlines; issue 17) this is
// exact, and on small poor meshes faster than refining them for fast marching. It is used by
// geodesicDistance (geodesic_surface.h) for such meshes with a uniform metric; a window budget
// bounds the work, and a run that exceeds it says so (the caller then refines instead).
//
// Cost: O(W log W) for W windows, W between O(V) and O(V^2) (in practice about V^1.5 on scans, a
// few per edge on CAD meshes); memory O(W + V + F).
#pragma once

#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/geodesic/fast_marching.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct ExactGeodesicParams {
  /// Vertices farther than this stay unreached (kUnreached, cell -1). +inf (default) = no limit.
  double maxDistance = kUnreached;
  /// The windows a run may create before it gives up (result.budgetExhausted); 0 (default) =
  /// 2,000 per vertex plus 100,000, at most 30 million (about 7 s).
  long long maxWindows = 0;
};

struct ExactGeodesicResult {
  /// Distance and nearest source per vertex (index into the sources), accepted order, largest
  /// distance; the same layout as fast marching's.
  FastMarchingResult field;
  long long windows = 0;         ///< windows created
  bool budgetExhausted = false;  ///< stopped at maxWindows: `field` is then not complete
};

/// Exact multi-source geodesic distance from the given vertices. The mesh must be manifold (edges
/// and vertices; NonManifold otherwise) with no edge of zero length (InvalidInput); orientation
/// does not matter. Fails with InvalidInput (no source, a source out of range, a negative limit),
/// OutOfMemory, Cancelled if `progress` says so.
Expected<ExactGeodesicResult> exactGeodesicDistance(const TriMesh& mesh, const std::vector<int>& sources,
                                                    const ExactGeodesicParams& params = {}, Progress progress = {});

}  // namespace gr
