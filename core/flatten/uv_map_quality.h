// Whether a map of a disk to the plane is one-to-one, and how far it is from an isometry.
//
// Injectivity of a piecewise-linear map of a topological disk: every UV triangle has positive
// area (no fold, none degenerate), the UV angles around each interior vertex sum to 2 pi (no
// branch point: positive triangles can wind twice round a vertex) and to less than 2 pi at each
// boundary vertex, and the boundary loop is a simple polygon. Together these make the map a
// local homeomorphism that is one-to-one on the boundary, hence one-to-one (a disk's covering
// of the region inside a simple curve has one sheet).
//
// Distortion (Sander et al. 2001), per face from the Jacobian J of UV -> 3D with singular values
// G >= g: L2 stretch sqrt((G^2 + g^2) / 2), conformal distortion G / g. The atlas's figures are
// area-weighted over the faces after one global scale that makes the UV area the 3D area (the
// L2 stretch is then 1 exactly for an isometry).
// Cost: O(F) plus the boundary test, O(b) expected with a uniform grid over b boundary edges.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "core/mesh/tri_mesh.h"

namespace gr {

using Vec2 = Eigen::Vector2d;

struct UvInjectivity {
  int nonPositiveFaces = 0;   ///< UV area <= 1e-12 of the mean |area|, or negative
  int windingVertices = 0;    ///< interior vertices whose UV angles do not sum to 2 pi
  int boundaryCrossings = 0;  ///< pairs of non-adjacent boundary edges that meet
  bool injective() const { return nonPositiveFaces == 0 && windingVertices == 0 && boundaryCrossings == 0; }
};

/// The checks above for `patch` (a topological disk) mapped to `uv` (one per vertex).
UvInjectivity checkUvInjectivity(const TriMesh& patch, const std::vector<Vec2>& uv);

/// The same without the interior vertices' windings, for a map reached from a one-to-one map by a
/// continuous path on which every face stays positive: an interior vertex's winding number is then
/// an integer that varies continuously, so it stays 1; only the boundary can run over itself.
/// Boundary edges closer than `clearance` count as crossing (a boundary that nearly touches
/// itself would cross once its UVs are rounded to float).
UvInjectivity checkUvAlongPositivePath(const TriMesh& patch, const std::vector<Vec2>& uv, double clearance = 0.0);

/// Pairs of boundary edges without a common vertex that meet or come closer than `clearance`.
int boundaryContacts(const TriMesh& patch, const std::vector<Vec2>& uv, double clearance);

struct UvDistortion {
  double stretchL2 = 1.0;      ///< Sander's L2 stretch over the whole map (1 = isometry up to scale)
  double conformalMean = 1.0;  ///< area-weighted mean of G / g
  double conformalMax = 1.0;
  double area3d = 0.0, areaUv = 0.0;
};

/// Distortion of a map given per corner (`cornerUv[3 f + k]`, e.g. wedge texture coordinates):
/// faces of zero 3D area are skipped; a face of zero UV area makes the figures infinite.
UvDistortion measureUvDistortion(const TriMesh& mesh, const std::vector<Vec2>& cornerUv);

}  // namespace gr
