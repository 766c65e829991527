// Edge flips that make a surface triangulation locally Delaunay, keeping its shape and topology.
//
// The dual of a Voronoi diagram computed at the resolution of the input's vertices picks, where
// four samples are nearly cocircular, whichever diagonal the discrete fronts happened to favour;
// some output triangles then have the wrong diagonal (a small angle where the other diagonal
// gives two good triangles). This pass corrects that with the Delaunay criterion on the output:
//
//          x                      x
//         / \                    /|\        interior edge (a, b) is flipped to (x, y) when the
//        /   \                  / | \       angles facing it sum to more than 180 degrees
//       a-----b      ->        a  |  b      (not locally Delaunay), the quad is nearly flat
//        \   /                  \ | /       (no sharp feature is cut), both new faces keep the
//         \ /                    \|/        orientation, and (x, y) is not already an edge.
//          y                      y
//
// Caps are flipped away too: a face whose angle facing the edge is over 170 degrees (three
// samples on one straight line of the input, off it only by rounding; or an ear on a boundary
// folded over its neighbour) has no normal that says anything about a crease, so the crease test
// ignores it; the flip keeps the line as the path a - x - b, or unfolds the ear.
// Flips never change the vertices, the number of faces, the components, genus or boundaries.
// Edges to check are kept in a work list; each flip re-queues the quad's four outer edges.
// Cost: O(F) plus O(valence) per flip (the new diagonal is looked up around its vertex); at most
// maxFlipsPerFace * F flips. The adjacency is updated flip by flip, the vertex lists once at the end.
#pragma once

#include <functional>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct DelaunayFlipParams {
  /// Largest angle between the normals of the two faces of an edge (before and after the flip)
  /// for the edge to be flipped, in degrees: edges on sharper creases are features and stay.
  double featureAngleDegrees = 30.0;
  /// A flip must lower the larger of the two facing angles' sum by at least this (degrees), so
  /// nearly cocircular quads do not flip back and forth.
  double toleranceDegrees = 1e-6;
  int maxFlipsPerFace = 10;  ///< safety bound on the total number of flips
};

struct DelaunayFlipResult {
  int flips = 0;
};

/// Flips edges of a manifold, consistently oriented mesh in place (positions unchanged) and
/// rebuilds its adjacency. Fails, leaving the mesh as it is, with NonManifold (a non-manifold edge
/// or vertex) or InvalidInput (no faces, or faces not oriented coherently: see orientCoherently in
/// mesh/orientation.h).
Expected<DelaunayFlipResult> flipToDelaunay(TriMesh& mesh, const DelaunayFlipParams& params = {});

/// Flips toward valence 6 (4 on the boundary), as isotropic remeshing does (Botsch & Kobbelt
/// 2004): an interior edge (a, b) becomes (x, y) when that lowers the sum of squared valence
/// excesses of a, b, x, y, keeps the surface (the same crease and orientation checks as above)
/// and leaves no angle of the two new faces under minAngleDegrees. The result is no longer
/// Delaunay everywhere: evener valences for evener angles after a relaxation. Fails as above.
struct ValenceFlipParams {
  double minAngleDegrees = 30.0;      ///< no new face with a smaller angle
  double featureAngleDegrees = 30.0;  ///< as DelaunayFlipParams::featureAngleDegrees
  int passes = 5;                     ///< sweeps over the edges at most
  /// Asked last, with the corner facing the edge (the mesh's faces and adjacency as they are, its
  /// vertex lists not updated during the sweeps): the flip is made only if it returns true.
  /// Empty: every flip the rules above allow. The polish checks the input surface with it.
  std::function<bool(int corner)> accept;
};
Expected<DelaunayFlipResult> flipTowardValenceSix(TriMesh& mesh, const ValenceFlipParams& params = {});

/// Flips toward better angles (the polish, surface_relaxation.h): an interior edge (a, b) becomes
/// (x, y) when fewer of the two faces have an angle under 30 degrees after, or as many and their
/// smallest angle rises, keeping the surface (the crease and orientation checks above) and leaving
/// no angle of the new faces under minAngleDegrees. The smallest angle of the mesh never falls
/// below minAngleDegrees and the faces under 30 degrees never grow in number. Delaunay flips
/// maximise the pair's smallest angle in the plane only, and may leave two faces of 28 degrees
/// where the other diagonal gives one of 25 and one of 35. Fails as above.
struct AngleFlipParams {
  double minAngleDegrees = 0.0;       ///< no new face with a smaller angle (the mesh's smallest: never lowered)
  double featureAngleDegrees = 30.0;  ///< as DelaunayFlipParams::featureAngleDegrees
  int passes = 5;                     ///< sweeps over the edges at most
};
Expected<DelaunayFlipResult> flipToBetterAngles(TriMesh& mesh, const AngleFlipParams& params = {});

/// Flips the interior edge facing `corner` of a manifold, coherently oriented mesh if that keeps
/// the surface (the crease and orientation checks above, creases up to featureAngleDegrees;
/// negative: no check, to undo a flip) and rebuilds the vertex lists. Returns the corner facing the
/// new edge (flipOneEdge on it restores the two faces), or -1 if the edge was not flipped.
int flipOneEdge(TriMesh& mesh, int corner, double featureAngleDegrees);

}  // namespace gr
