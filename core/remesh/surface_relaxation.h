// Tangential relaxation of a remeshed surface on the input surface: better angles, same mesh.
//
// The geodesic Delaunay triangulation of farthest-point samples has no angle under 30 degrees in
// the limit of a fine input, but its samples sit on input vertices (or are resolved by fronts
// between vertices), so at 10-30% of the input's vertex count its circumradii exceed the covering
// radius by up to ~50% and some angles fall to a few degrees. This pass moves each free output
// vertex toward the mean of its neighbours in its tangent plane and puts it back on the input
// surface, then flips edges back to Delaunay (delaunay_flips.h), a few times over:
//
//        n                         q = p + (c - p) minus its component along the normal n,
//        |  c (mean of the ring)   then its closest point on the input, found by walking from
//        | /                       the face p lies in to neighbouring faces while the distance
//   -----p-----  output vertex     to q decreases; the walk never crosses a sharp input edge
//
// A move is kept only if no incident face turns over (unless it then faces the way the input
// does: an unfolding), the smallest angle of the incident faces does not fall ("smart"
// Laplacian; in the centroidal mode, not below 30 degrees), and the point the vertex leaves stays
// within maxDeviation of the new faces (tips and ridges, where farthest-point samples sit, are
// kept). Then steps in eight tangent directions are tried and the one that most raises the
// smallest angle is kept, within twice that deviation, or with no limit while an angle under 30
// degrees remains (raiseSmallestAngle).
// The input's feature curves (chains of boundary edges and of creases sharper than the feature
// angle, through vertices with exactly two such edges; crease chains shorter than an output edge,
// the noise of scans, are not features: minCreaseLength) hold the vertices on them: such a vertex
// moves only along its curve, by the step (up to 0.4 of its edges' length, both ways) that most
// raises the smallest angle, while no point of the curve near it ends farther from its faces
// than maxDeviation (or than before). Vertices where three or more feature edges meet, one ends,
// or the curve turns by more than the feature angle do not move; nor do output boundary vertices
// the input's boundary does not hold.
// A polish (polishOnSurface, below) then raises the smallest angles where they are: the worst
// rings' vertices climb by steepest ascent of their smallest angle.
// Tiny holes: an output boundary loop far shorter than an output edge is a point at the output's
// resolution; the faces on its edges are slivers whatever the ring around does, and widening them
// draws the ring in, into a cluster of faces under 30 degrees. The angles facing such a loop's
// edges do not count in a vertex's ring, for its moves and the polish's climbs
// (RelaxationParams::tinyLoopLength).
// Connectivity changes only by the flips: vertices, components, genus and boundaries are kept, and
// every vertex stays on the input surface (its SurfacePoint is updated).
// Cost: O(iterations * F_out * (valence + walk length)), and one pass over the input's faces per
// call for its crease chains (O(F_in); none with minCreaseLength 0 or a density).
#pragma once

#include <algorithm>
#include <vector>

#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"
#include "core/remesh/delaunay_flips.h"

namespace gr {

struct RelaxationParams {
  int iterations = 5;  ///< rounds of (move every free vertex, then flip to Delaunay); 0 = off
  /// Input edges whose faces' normals differ by more than this (degrees) are creases: vertices on
  /// them stay, and walks do not cross them. 60 keeps the creases of CAD parts (fandisk) and lets
  /// the vertices of scans (armadillo: thousands of edges over 30 degrees) move.
  double featureAngleDegrees = 60.0;
  /// Crease chains of the input (its crease edges joined through vertices with exactly two of
  /// them, where the chain turns by less than the feature angle) shorter than this times the
  /// output's mean edge length are not creases: no output edge could follow them, and on scans
  /// they are noise (femur: 14% of its edges over 60 degrees, in 1,095 chains, none longer than
  /// two output edges at 10%) that holds vertices in place. Boundaries always hold. 0 = every
  /// crease holds; so does a relaxation with a density (an adaptive spacing is not one length).
  double minCreaseLength = 1.0;
  /// A move is refused when the point the vertex leaves ends farther than this times the mean
  /// length of its edges from the new faces around it: tips and ridges, where the farthest-point
  /// samples sit, are not smoothed away (the surface error stays that of the triangulation).
  double maxDeviation = 0.05;
  /// Output vertices on a feature curve of the input (a chain of boundary or crease edges through
  /// vertices with exactly two of them) move along it, to raise the smallest angle of their faces;
  /// off, they stay where they are.
  bool slideAlongFeatures = true;
  /// On: a move never lowers the smallest angle around the vertex, and after the move toward the
  /// ring's mean, tangent steps that raise it are tried (max-min angles: bunny00 and knot2 reach
  /// CGAL's isotropic remeshing). Off: the mean may lower it as long as it stays at least 30
  /// degrees, and steps are tried only under 30 degrees (evener angles, for the centroidal mode).
  bool raiseSmallestAngle = true;
  /// Per vertex of the surface relaxed on, the metric P of an adaptive remesh (whose density goes
  /// as P^2), or null (uniform). The move toward the ring's mean weights each neighbour by P
  /// there: in 1D a vertex between a neighbour at spacing h and one at 2h (P twice as large at
  /// the first) stays put, where the plain mean moves it toward the sparse side. fandisk adaptive
  /// at 10% (the main command's script, 5 rounds): two-sided Hausdorff 1.61% -> 1.51% of the
  /// diagonal; two speed zones 2x apart: density ratio 3.96 -> 4.47 (4 expected; the weights pull
  /// toward the dense zone at the interface).
  const std::vector<double>* density = nullptr;
  /// Output boundary loops shorter than this times the output's mean edge length are tiny: the
  /// angle facing each of their edges does not count in the smallest angle of a vertex's ring, so
  /// no move or climb draws the ring in to widen the loop's slivers. ChineseDragon-10kv's two
  /// holes (triangles of 0.004 to 0.04 mean edges round at 5-30%) drew their rings into 8 to 12
  /// faces under 30 degrees each; left where they are, each has its 3 slivers only. Longer loops
  /// count in full: the data set's next shortest, pig's at 5% (0.22 edges round), are better drawn
  /// in (smallest angle 5.8 degrees; 1.9 left out, CGAL's 2.0). 0 = every angle counts.
  double tinyLoopLength = 0.1;
  /// The polish (polishOnSurface): the free vertices whose ring's smallest angle is under
  /// max(30 degrees, the smallest of all + this margin) climb, worst first. Negative = off.
  double polishMarginDegrees = 3.0;
  DelaunayFlipParams flips;  ///< the flips after each round
  /// After the Delaunay flips of each round, flips toward valence 6 (flipTowardValenceSix): evener
  /// angles, no longer Delaunay everywhere. Off by default; the remeshes' centroidal relaxation
  /// turns it on (regularised(), below).
  bool valenceFlips = false;
  ValenceFlipParams valence;

  /// These options with regular triangles as the aim: valence flips on (no new angle under 30
  /// degrees, creases as the Delaunay flips see them) and moves up to 0.1 of the ring's edge
  /// length off the surface. bunny00 at 10%, 10 rounds, with 10 centroidal iterations against
  /// none: angle standard deviation 10.7 -> 7.0 degrees (CGAL's isotropic remeshing 7.2),
  /// smallest angle 30 degrees, two-sided Hausdorff 0.64 -> 0.85% of the diagonal (CGAL 1.03%;
  /// tests/remesh/test_remesh_quality.cpp).
  RelaxationParams regularised() const {
    RelaxationParams p = *this;
    p.valenceFlips = true;
    p.raiseSmallestAngle = false;
    p.valence.featureAngleDegrees = flips.featureAngleDegrees;
    p.maxDeviation = std::max(maxDeviation, kRegularMaxDeviation);
    return p;
  }
  static constexpr double kRegularMaxDeviation = 0.1;
  /// The remeshes remove flat ears off their boundary (removeFlatEars in edge_collapse.h) whose
  /// tip lies within this times maxDeviation times their base of it: the deviation the tangent
  /// steps allow.
  static constexpr double kEarHeight = 2.0;
};

struct RelaxationResult {
  int iterations = 0;       ///< rounds done
  int moves = 0;            ///< vertex moves kept, over all rounds
  int fixedVertices = 0;    ///< vertices that never move (corners of the input's feature curves)
  int slidingVertices = 0;  ///< vertices that move along the input's feature curves
  int pinnedVertices = 0;   ///< of the others, those the caller pinned (RelaxationGuard)
  int watchedVertices = 0;  ///< and those it watched
  int refusedCrossing = 0;  ///< moves of watched vertices refused because faces would cross
  int flips = 0;            ///< edges flipped over all rounds and the polish
  int polishMoves = 0;      ///< moves of the polish (polishOnSurface)
};

/// Output vertices the caller constrains (each vector empty, or one flag per output vertex): the
/// remeshing's answer to a relaxation that made faces cross (remesh_surface.cpp).
struct RelaxationGuard {
  std::vector<char> pinned;  ///< does not move
  /// Moves only where its faces then cross none of the faces around watched vertices
  /// (facesCross in mesh/self_intersection.h).
  std::vector<char> watched;
};

/// What the polish (polishOnSurface) is given beyond the meshes.
struct PolishGuard {
  std::vector<char> pinned;  ///< empty, or per output vertex: does not move
  /// Null, or per vertex of the input its output vertex (SurfaceRemeshResult::cell). Given, the
  /// polish also tries the valence batches that move the surface more, kept only where the
  /// two-sided distance to the input (remeshDistances in remesh_distance.h) does not grow.
  const std::vector<int>* cell = nullptr;
  bool voronoiCells = true;  ///< remeshDistances' voronoiCells
};

/// Relaxes `output` in place on the surface of `input`. `points[i]` is where output vertex i lies
/// on the input (as DelaunayResult::origin) and is updated with it; `guard` constrains some. Fails, changing nothing, with
/// NonManifold if either mesh is not manifold, or InvalidInput if the sizes disagree, a point is
/// out of range, the output has no faces or its faces are not oriented coherently (orient them
/// first: orientCoherently in mesh/orientation.h).
Expected<RelaxationResult> relaxOnSurface(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                                          const RelaxationParams& params = {}, const RelaxationGuard& guard = {});

/// The polish of a relaxed output (RelaxationParams::polishMarginDegrees; the remeshes run it once
/// on their final output): the free vertices whose ring's smallest angle is under max(30 degrees,
/// the smallest of all + the margin) are taken worst first. Each climbs by steepest ascent of that
/// angle (the direction that raises every angle near the smallest; along its curve for a vertex
/// on a feature curve), by at least 0.05 degrees a step and never adding a face under 30 degrees,
/// the point it started from kept within maxDeviation of its faces; a vertex is taken again when
/// a neighbour moves. Then Delaunay flips, and again while both change something (3 times at
/// most). Then the worst face's edges are flipped, each followed by climbs of the vertices
/// around it, kept where the smallest angle there rises (the input staying near the faces), else
/// undone, again from the new worst face while one is kept. Then batches: edges flip toward
/// valence 6 (the input staying near the faces), the vertices climb and the worst face's edges
/// flip again, all kept only if the smallest angle rises, no more faces are under 30 degrees and
/// no changed face crosses another; the first keeps the new faces near the smallest angle, and
/// with `guard.cell` two more follow (flips with no bound on the angles, undone at once if they
/// leave a face under 5 degrees; flips, then two rounds of moves toward the rings' means), each
/// kept only if the two-sided distance to the input does not grow either. Then, up to 3 times: edges flip
/// toward fewer faces under 30 degrees (flipToBetterAngles in delaunay_flips.h, across creases
/// up to featureAngleDegrees; a round of flips that makes faces cross is undone), and each free
/// vertex off the feature curves whose ring has faces under 30 degrees moves to where (of 16
/// directions at 4 lengths) its ring has the fewest, never below the mesh's smallest angle, and
/// the edges of the faces still under 30 degrees are flipped with climbs as above, kept where the
/// faces under 30 degrees around fall in number and none crosses another face. No flips if
/// flips.maxFlipsPerFace is 0. The smallest angle never falls and the faces under 30
/// degrees never grow in number.
/// `guard.pinned` (empty, or one flag per output vertex) holds vertices in place. Fails as
/// relaxOnSurface, or with InvalidInput if `pinned` or `cell` has the wrong size or a cell is
/// neither -1 nor an output vertex.
Expected<RelaxationResult> polishOnSurface(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                                           const RelaxationParams& params = {}, const PolishGuard& guard = {});

/// Joint climbs of a polished output (the remeshes' last step): the free vertices of the face with
/// the smallest angle move together, two or three at once (each along its feature curve or on the
/// input in eight directions, steps of 0.2 of its mean edge halved down to 0.00625), to the best
/// combination that raises the smallest angle of the faces around them, without more faces under
/// 30 degrees, a face turned over or crossing another, or (from 30 degrees up) a vertex's starting
/// point farther than maxDeviation from its faces, or the farthest point of its feature curve
/// nearby farther than both maxDeviation and before (the polish's moves of one vertex hold each
/// point of the curve; patch-13 at 5%: 31.3 -> 35.3 degrees, CGAL 31.9); then again from the new
/// worst face, 64 times at most. The one-vertex climbs of the polish stop where two faces hold the
/// smallest angle and each move of one vertex lowers one of them. `pinned`: empty, or per output
/// vertex whether it stays. Returns the moves kept; fails as polishOnSurface does.
/// Cost per move: O(F) to find the worst face, and up to 9^3 combinations at each of 6 steps
/// (bunny00 at 10%, 3,775 vertices: 64 moves in 57 ms).
Expected<int> climbJointly(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                           const RelaxationParams& params = {}, const std::vector<char>& pinned = {});

/// The corners of the input's feature curves as the relaxation sees them (boundaries, and creases
/// sharper than params.featureAngleDegrees, every crease held): the input vertices on a feature
/// edge where not exactly two of them meet (one ends, or three or more meet) or where the curve
/// turns by more than the feature angle (the four corners of a rectangle). No output vertex there
/// ever moves, so a sampling that leaves one out cuts it off with a chord for good; the small
/// outputs' starts include one sampled from them (SurfaceRemeshParams::restarts). In vertex order.
/// Cost: O(F) (every vertex's corners once).
std::vector<int> featureCorners(const TriMesh& input, const RelaxationParams& params = {});

/// A face under 30 degrees whose widest angle is at least this (degrees) is one that moves and
/// flips could not mend: a corner of the input's feature curves or a vertex on a boundary holds its
/// wide angle (mech-holes-shark at 5%: 5.2 degrees at a hole's rim). Splitting the edge facing the
/// angle halves it.
constexpr double kSplitWideAngleDegrees = 100.0;

/// Which edges splitWideFaces splits: inner edges, or edges of the output's boundary.
enum class SplitEdges { Inner, Boundary };

/// Splits the edge facing the widest angle of each face under 30 degrees whose widest angle is at
/// least kSplitWideAngleDegrees and whose edge there is of the kind `edges`, worst faces (smallest
/// angle) first, up to `maxSplits`, no face split twice, none flagged in `skip` (empty, or per
/// face of `output`). The new vertex goes at one of five points of the edge (0.3 to 0.7 of it), the
/// one whose new faces have the largest smallest angle, taken on the input: an inner edge's point
/// is the input's point nearest it by a walk from its first vertex's point, not across the input's
/// creases (as the relaxation's); a boundary edge's is the point of the input's boundary the same
/// arc length along it from the first vertex's point (none if that is not within a quarter of the
/// edge of it: the face is left as it is). The vertex is appended to `output` and `points`; an
/// inner edge's two faces become four, a boundary edge's one face two (the first `output` faces
/// keep their places, the new ones follow). Vertices, faces and edges grow by one, two and three
/// per inner split, by one, one and two per boundary split: components, genus and boundary loops
/// are kept. The faces are not otherwise changed: a polish (polishOnSurface) then moves the new
/// vertices. Returns how many edges were split. Fails as relaxOnSurface.
/// Cost: O(F_out log F_out) and five walks (or slides along the boundary) per split.
Expected<int> splitWideFaces(TriMesh& output, std::vector<SurfacePoint>& points, const TriMesh& input,
                             const RelaxationParams& params, int maxSplits, const std::vector<char>& skip = {},
                             SplitEdges edges = SplitEdges::Inner);

}  // namespace gr
