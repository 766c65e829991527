// The input cut into one disk per triangle of a base domain (paper §4.1): the pieces that the
// geodesic barycentric parameterisation maps onto their base triangles.
//
//   input --farthest-point samples (+ Lloyd), the dual of their geodesic Voronoi diagram on the
//           input itself, no flips--> base triangles over input vertices, and each input
//           vertex's Voronoi cell (buildBaseDomain)
//         --the stars of the base vertices split (room for one path per base edge at each)-->
//         --per base edge (i, j): a path of edges from i to j, vertex-disjoint from the paths
//           already cut, leaving i and reaching j between the paths of its neighbours in the
//           base's cyclic order, and dearer outside cells i and j (the Voronoi diagram says
//           where it belongs); base edges on the boundary follow the boundary-->
//         --faces joined across uncut edges: one piece per base triangle, checked (a disk whose
//           boundary meets the triangle's three corners in its order)-->
//         --"chords" split: an edge inside a piece whose ends lie on one side of it would be
//           squashed onto that side by any map that pins the sides-->  BasePieces
//
// Why paths of edges and not the base triangles' geodesic triangles: the pieces are then sets
// of whole faces, cut only where an edge is split, their sides are shared exactly by the two
// triangles of a base edge, and a map that pins the sides by arc length tiles each base triangle
// (Floater 2003: a convex-combination map of a disk onto a convex polygon is one-to-one when no
// interior edge joins two points of one side). Why the Voronoi cells: the dual's triangles are
// where its three cells meet, so a path through cells i and j runs where the base edge (i, j)
// is, and the cyclic order of the paths at a base vertex is that of its cell's neighbours.
// Cost: one bounded Dijkstra per base edge (about the two cells it crosses), O(F) per rebuild.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct BaseDomainParams {
  int baseVertices = 500;        ///< farthest-point samples asked for (>= 4); the repair may add some
  int centroidalIterations = 0;  ///< geodesic Lloyd iterations on the samples before the dual (>= 0)
  unsigned seed = 0;             ///< the sampling's start: the same seed gives the same base
  /// Base vertices denser where the surface bends: the speed mu of the total curvature's
  /// Attractive metric (adaptive_metric.h; curvature read over half the base spacing, at most 3
  /// input edges), 0 =
  /// evenly spaced. A base triangle over a bump leaves its top between the points its
  /// subdivision puts on the base edges; denser base vertices there keep it. 500 base vertices,
  /// one level (about 2,000 vertices), two-sided Hausdorff against 0: bunny00 1.22 -> 0.82% of
  /// the diagonal, armadillo 1.37 -> 1.31%, fandisk 1.91 -> 1.06% (our uniform remesh at the same
  /// count: 0.94, 1.15, 1.35%).
  double curvatureStrength = 1.0;
};

struct BaseDomain {
  std::vector<Tri> triangles;   ///< base triangles over base vertices, oriented like the input
  std::vector<int> baseVertex;  ///< per base vertex, the input vertex it is
  std::vector<int> cell;        ///< per input vertex, its Voronoi cell: a base vertex
  int addedSamples = 0;         ///< samples the dual's repair added to the ones asked for
};

/// The base domain of `input` (a manifold, coherently oriented mesh). Fails as
/// farthestPointSampling, geodesicLloyd and geodesicDelaunay do (geodesic/, remesh/), and with
/// InvalidInput on fewer than 4 base vertices asked for.
Expected<BaseDomain> buildBaseDomain(const TriMesh& input, const BaseDomainParams& params, Progress progress = {});

struct BasePieces {
  TriMesh mesh;                            ///< the input with some edges split (its first vertices are the input's)
  std::vector<int> originalFace;           ///< per face of `mesh`, the input face it lies in
  std::vector<Vec3> cornerBary;            ///< per corner of `mesh`, its barycentric coordinates in that face
  std::vector<int> triangle;               ///< per face of `mesh`, its piece: a base triangle
  std::vector<char> onCut;                 ///< per corner: the edge facing it lies on a path (or the boundary)
  std::vector<std::pair<int, int>> edges;  ///< base edges, as (lower, higher) base vertex
  std::vector<std::array<int, 3>> triangleEdge;  ///< per base triangle, per corner k, the edge facing it
  std::vector<std::vector<int>> path;            ///< per base edge, its vertices of `mesh`, from lower to higher
  int splitEdges = 0;                            ///< edges split (stars of base vertices, chords)
};

/// Cuts `input` (manifold, coherently oriented, the mesh `base` was built on) along paths of
/// edges into one disk per base triangle. Fails with InvalidInput on a base that does not fit
/// the input (sizes, a corner out of range), and with NotConverged naming the base edge when a
/// path finds no way between the paths already cut, the splits that make room for the paths would
/// take the surface past 32 times the input's faces (a mesh too coarse for its base), or a piece
/// is not the disk of one base triangle; Cancelled if asked.
Expected<BasePieces> cutIntoBasePieces(const TriMesh& input, const BaseDomain& base, Progress progress = {});

}  // namespace gr
