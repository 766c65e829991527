// Geodesic barycentric parameterisation over a base domain (paper §4.1): every point of the
// input gets a base triangle and its coordinates there.
//
//   input --orient, buildBaseDomain, cutIntoBasePieces (base_pieces.h)--> one disk per base
//           triangle, its sides paths of edges between the corners
//         --per base vertex: one front over its pieces--> d(x, corner) for the pieces' vertices,
//           and the base edges' geodesic lengths: each base triangle becomes a planar triangle
//           with those side lengths (its parameter domain)
//         --per piece: sides pinned by arc length; inside, Heron's coordinates from the three
//           distances (geodesic_barycentric.h); if a face of the piece then flips (near the
//           sides, where the fronts' distances and the paths disagree), the piece is mapped by
//           mean value coordinates instead (Floater 2003: one-to-one, since no edge inside a
//           piece joins two points of one side)--> per corner (u, v)
//
// The pieces tile each base triangle: their sides are its sides, shared with the neighbouring
// piece point for point (the same edges, the same arc length), and the map is one-to-one inside.
// Cost: the cut (base_pieces.h), one front per base vertex over about its star, and per repaired
// piece a sparse LU of its interior vertices.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"
#include "core/param/base_pieces.h"

namespace gr {

using Vec2 = Eigen::Vector2d;

struct ParameterizationParams {
  BaseDomainParams base;  ///< base vertices, centroidal iterations, seed
};

struct Parameterization {
  TriMesh input;              ///< the input, its faces oriented coherently (orientCoherently)
  std::vector<char> flipped;  ///< per input face, 1 if that swapped its corners 1 and 2
  BaseDomain base;            ///< over `input`
  BasePieces pieces;          ///< the input cut into one disk per base triangle
  /// Per corner of pieces.mesh, its point in its base triangle (pieces.triangle of its face) as
  /// the coordinates (u, v) of that triangle's corners 1 and 2 (corner 0 weighs 1 - u - v).
  std::vector<Vec2> cornerUv;
  std::vector<double> edgeLength;  ///< per base edge (pieces.edges), its geodesic length on the input
  int heronPieces = 0;             ///< pieces mapped by Heron's coordinates
  int smoothedPieces = 0;          ///< by Heron's, but for a band around the faces those folded (mean value)
  int repairedPieces = 0;          ///< pieces where those flipped a face, mapped by mean value coordinates
};

/// Fails with InvalidInput (no faces, a triangle soup: TriMesh::looksLikeTriangleSoup, a component
/// of zero area), NonManifold, as
/// buildBaseDomain and cutIntoBasePieces do, or with Degenerate if a piece is still folded after
/// the mean value and Tutte maps (degenerate faces: degtri_sliding.off of the data set).
Expected<Parameterization> parameterizeOverBase(const TriMesh& input, const ParameterizationParams& params = {},
                                                Progress progress = {});

/// The domain of a base triangle with sides (c0c1, c1c2, c2c0) = `l01`, `l12`, `l20`: corner 0 at
/// the origin, corner 1 on the x axis, corner 2 above. Lengths that break the triangle inequality
/// or a flat triangle (shape quality under 0.05) give the equilateral triangle of their mean side.
std::array<Vec2, 3> triangleDomain(double l01, double l12, double l20);

/// The margin of tiledUv's tiles, a fraction of the tile.
constexpr double kTileMargin = 0.05;

/// The parameterisation as one texture: base triangle t in square tile (t mod g, t div g) of a
/// g x g grid (g = ceil(sqrt(triangles))), its corners 0, 1, 2 at the tile's lower left, lower
/// right and upper left, kTileMargin inside. Per corner of pieces.mesh, in [0, 1]^2: a
/// checkerboard shows each piece's map, one tile per base triangle. Every face is counter-clockwise
/// there also once the coordinates are rounded to float, as MeshLab holds them (the maps are
/// judged so).
std::vector<Vec2> tiledUv(const Parameterization& par);

/// Per vertex of pieces.mesh, the point of the input as given (not its oriented copy) it lies on:
/// the input's own vertices first (isolated ones included), then the points the cut added.
std::vector<SurfacePoint> cutVertexOrigins(const Parameterization& par);

/// Per vertex of pieces.mesh, the base triangle of one of its faces (-1 for a vertex in no face).
std::vector<int> baseTriangleOfVertex(const Parameterization& par);

}  // namespace gr
