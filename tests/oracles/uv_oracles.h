// The judge of texture atlases, sharing no code with core/flatten or core/atlas: per-corner UV
// triangles counted as flipped or of zero area, and pairs of triangles whose interiors overlap,
// with CGAL's exact predicates (Exact_predicates_inexact_constructions_kernel).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "core/mesh/tri_mesh.h"

namespace gr::oracle {

struct UvAtlasCheck {
  int flipped = 0;            ///< clockwise UV triangles (exact orientation)
  int zeroArea = 0;           ///< collinear UV corners (exact orientation)
  long overlaps = 0;          ///< pairs of triangles whose interiors meet
  int outsideUnitSquare = 0;  ///< corners with a coordinate outside [0, 1]
};

/// `triangles[i]` = the three UV corners of face i, in the face's vertex order. Overlap: two
/// triangles overlap when their interiors share a point, decided exactly: an edge of one crosses
/// an edge of the other properly, a corner of one lies strictly inside the other, or they
/// coincide; triangles that only share edges or corners do not overlap. Broad phase: a uniform
/// grid on the bounding boxes. Flipped and zero-area triangles are left out of the overlap count.
UvAtlasCheck checkUvAtlas(const std::vector<std::array<Eigen::Vector2d, 3>>& triangles);

/// CGAL 5.5's least-squares conformal map (Lévy et al. 2002, Surface_mesh_parameterization::
/// LSCM_parameterizer_3, two pinned vertices on the longest border) of a topological disk: one UV
/// per vertex of `patch`, or empty if CGAL refuses or fails. The anchor of the atlas's per-chart
/// conformal distortion (issue 19).
std::vector<Eigen::Vector2d> cgalLscm(const TriMesh& patch);

}  // namespace gr::oracle
