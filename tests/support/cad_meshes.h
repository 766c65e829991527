// CAD-like test solids, triangulated as a CAD exporter writes them (issue 17's acceptance meshes).
//
// Each is a closed, oriented (outward normals), manifold solid made by extruding a planar profile
// (an outline and holes) along z. Vertices lie only on the feature outlines: the profile's
// polygon at z = 0 and at z = height, nothing inside a flat face. The flat faces are
// triangulated by ear clipping with fans (each ear clipped from the vertex before: long slivers
// across the face), holes joined to the outline by bridge edges; the sides are one quad per
// profile edge from bottom to top, split in two (long strips where the profile is fine):
//
//      top    t0 ---- t1          a flat face (ear clipping):   3 _____ 2
//              |    / |                                          /  .-'  \      .
//              |  /   |  side quad                             4 .-'  _.-' 1
//              |/     |                                          \ _.-'    /
//      bottom b0 ---- b1                                           0 -----'
//
// Vertex numbering: the bottom ring (outline, then each hole), then the top ring in the same
// order; vertex 0 is the outline's first point at z = 0. Deterministic (no random numbers).
// Cost: O(n^2) in the profile's point count n (ear clipping), milliseconds at the defaults.
#pragma once

#include <Eigen/Core>

#include <string>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr::test {

/// A closed polygon in the xy plane (the last point joins the first, not repeated).
using Polygon2 = std::vector<Eigen::Vector2d>;

/// The triangles of a polygon with holes, by ear clipping (Eberly's bridges for the holes).
/// `outline` is counter-clockwise, each hole clockwise, holes strictly inside and disjoint.
/// Indices number the outline's points, then each hole's points, in order. Clipping starts at the
/// outline's point size / 2; after each clipped ear the next ear is tried at the vertex after it,
/// so convex runs become fans from one vertex (the vertex before; for a convex outline of n points,
/// the fan of point n / 2 - 1, across from point 0).
/// Throws std::runtime_error if no ear is found (a profile that is not a simple polygon).
std::vector<Tri> earClip(const Polygon2& outline, const std::vector<Polygon2>& holes);

/// The solid between z = 0 and z = height whose cross-section is `outline` minus `holes`
/// (orientations as for earClip): caps by earClip, one quad split in two per profile edge.
TriMesh extrudeProfile(const Polygon2& outline, const std::vector<Polygon2>& holes, double height);

/// (a) A thin spur gear plate, the worst case of issue 17: a star-shaped outline of 13 points a
/// tooth (root arc, flanks, tip arc), ear-clipped across the whole plate.
struct CadGearParams {
  int teeth = 40;
  double diameter = 100.0;            ///< tip diameter (mesh units)
  double toothDepthFraction = 0.054;  ///< tip radius - root radius, over the diameter (2.25 modules)
  double thicknessFraction = 0.02;    ///< plate thickness over the diameter
  double boreFraction = 0.0;          ///< centre bore diameter over the diameter; 0 = none (genus 0),
                                      ///< > 0: a round bore of boreSegments points (genus 1)
  int boreSegments = 48;
};
TriMesh cadGear(const CadGearParams& params = {});

/// (b) A rectangular plate with a grid of round holes through it (genus columns * rows).
struct CadHolePlateParams {
  double length = 100.0, width = 50.0, thickness = 2.0;  ///< mesh units
  int holeColumns = 5, holeRows = 4;                     ///< holes on a regular grid, centred in their cells
  double holeRadius = 3.0;
  int holeSegments = 32;  ///< points on each hole's circle
};
TriMesh cadHolePlate(const CadHolePlateParams& params = {});

/// (c) A closed cylinder around the z axis: caps fanned from one rim vertex, sides one long quad
/// (split in two) per rim segment.
struct CadCylinderParams {
  double radius = 5.0, height = 40.0;  ///< mesh units
  int segments = 64;                   ///< points on each rim
};
TriMesh cadCylinder(const CadCylinderParams& params = {});

/// (d) An L-bracket: an L profile (two legs of the given length and thickness, outer corner at
/// the origin) extruded by `depth`, with a round fillet at the inner corner whose segments become
/// long thin strips along the extrusion.
struct CadBracketParams {
  double legLength = 40.0, thickness = 4.0, filletRadius = 4.0, depth = 40.0;  ///< mesh units
  int filletSegments = 16;  ///< segments of the quarter-circle fillet
};
TriMesh cadBracket(const CadBracketParams& params = {});

/// The four acceptance meshes with their default parameters, their names ("cad_gear",
/// "cad_hole_plate", "cad_cylinder", "cad_bracket") and their genus (0, 20, 0, 0).
struct CadMesh {
  std::string name;
  TriMesh mesh;
  int genus = 0;
};
std::vector<CadMesh> cadMeshes();

/// Writes `mesh` as an OFF file with 17 significant digits (the doubles round-trip exactly).
/// False if the file cannot be written.
bool writeOff(const TriMesh& mesh, const std::string& path);

}  // namespace gr::test
