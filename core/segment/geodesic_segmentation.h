// Segmentation into compact, feature-aligned regions that are topological disks: a geodesic
// centroidal tessellation (paper §4.2, conditions C1 and C2), the first stage of the atlas.
//
//   mesh --cutAlongEdges (sharp_cut.h: edges sharper than sharpEdgeAngle cut open, so no front
//          crosses them and region boundaries lie on them exactly)--> the fronts' surface
//        --adaptiveMetric (total curvature or a given field, Attractive: the paper's F2 "edge
//          attractive" speed 1/(1 + mu tau/s), which slows fronts on curved bands)--> metric
//        --prepareGeodesicSurface (the surface as it is, by default)
//        --farthestPointSampling (`regions` seeds; the first regions/64 of them, at most 16,
//          chosen in 3D: farthestPointsIn3d); where the cut leaves several pieces, each piece
//          gets its share of the seeds by area (the centroidal energy's best split)
//        --geodesicLloyd (`iterations`)--> cells
//        --faces labelled by their vertices' cells (the vertex nearest its seed), faces of pieces
//          with no seed given to the regions around them, each label's stray pieces given to the
//          neighbour they share most edges with, so every region is one edge-connected piece
//        --a region that is not a disk (Euler characteristic 1, one boundary loop: a handle, a
//          ring around a tube, an input hole inside it, a whole closed component) gets a seed
//          at its vertex farthest from its own seed, and the Lloyd iteration goes on with one
//          more region; until every region is a disk (`regionsAdded` counts the seeds added)
//        --with mu > 0, boundaries one face beside an edge of 30-60 degrees moved onto it
//          (boundary_snapping.h: regions stay disks)
//
// Regions are counted on the input (faces are the same on the cut surface). With mu = 0 and no
// cut the metric is uniform: plain geodesic Voronoi cells.
// Cost: the cut O(F), the metric O(V k) (curvature balls), Lloyd (geodesic_lloyd.h) about
// (1 + 2 * steps) fronts per iteration, the labelling and the disk check O(V + F) per round.
#pragma once

#include <string>
#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/field/adaptive_metric.h"
#include "core/geodesic/geodesic_lloyd.h"
#include "core/geodesic/geodesic_surface.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Options of the segmentation (Peyré & Cohen 2006, §4.2).
struct SegmentationParams {
  int regions = 50;  ///< seeds of the farthest-point sampling (>= 1, at most the vertices)
  /// The Lloyd iteration (20 iterations; the mass element is the surface's area).
  LloydParams lloyd;
  /// Which field sets the speed: TotalCurvature (feature alignment, default) or VertexQuality
  /// (a given per-vertex field, e.g. MeshLab's vertex quality: paper Fig. 11).
  AdaptiveField speedField = AdaptiveField::TotalCurvature;
  /// mu of the speed F = 1 / (1 + mu q / s) (dimensionless, s the field's 95th percentile);
  /// 0 = uniform metric. It slows the fronts on curved bands that are not sharp edges (those the
  /// surface is cut at: sharpEdgeAngle), so cells are rounder there. 0.5: more compact regions
  /// (bunny00, 100 regions: isoperimetric quotient 0.61 -> 0.79) at a small cost in evenness
  /// (area CV 0.09 -> 0.12); larger values make a scan's regions uneven (8: CV 0.46).
  double featureAlignment = 0.5;
  /// Fronts stop at edges sharper than this, in degrees between the normals of their two faces:
  /// the surface is cut open along them (sharp_cut.h), so region boundaries lie on them exactly and
  /// no region crosses one (but around the end of a crease). 0 = no cut. 60: fandisk's creases,
  /// none of a scan's (bunny00 has no edge over 60 degrees).
  double sharpEdgeAngle = 60.0;
  /// Ball radius of the total curvature (0 = the mean edge length).
  double curvatureRadius = 0.0;
  unsigned seed = 0;  ///< the farthest-point sampling's start: the same seed, the same regions
  /// Rounds of "add a seed to each non-disk region, iterate again" before giving up with
  /// InvalidInput (also when more seeds than vertices would be needed: a mesh too coarse for its
  /// topology, e.g. 3torus.off at 1 region).
  int maxDiskRounds = 64;
  /// Lloyd iterations after each round of added seeds.
  int iterationsAfterAdding = 4;
  /// With feature alignment (featureAlignment > 0), move the region boundaries that run one face
  /// beside a sharp edge onto it, and straighten the others (boundary_snapping.h).
  bool snapToSharpEdges = true;
  /// The surface the fronts run on: the input as it is by default (Off), since regions are
  /// unions of input faces labelled from their vertices; a refinement's inserted points would
  /// make cells finer than the faces that carry them.
  GeodesicSurfaceParams surface = [] {
    GeodesicSurfaceParams p;
    p.refinement = SurfaceRefinement::Off;
    return p;
  }();
};

struct SegmentationResult {
  std::vector<int> faceRegion;  ///< per input face, its region in [0, regions)
  int regions = 0;              ///< regions got: regionsAsked + regionsAdded
  int regionsAsked = 0;
  int regionsAdded = 0;     ///< seeds added to split regions that were not disks
  int nonDiskRegions = 0;   ///< regions not disks in the last round (0: a result has none)
  int strayFacesMoved = 0;  ///< faces given to a neighbouring region to keep regions connected
  /// Regions cut open around a hole of the input (a boundary loop all in one region, which no cell
  /// splits when the hole is a few edges): the faces of a path from the hole to another region go
  /// to that region (counted in strayFacesMoved), in the last round.
  int holesOpened = 0;
  int snappedFaces = 0;            ///< faces moved to put boundaries on sharp edges (snapToSharpEdges)
  int iterations = 0;              ///< Lloyd iterations accepted, over all rounds
  int reseeded = 0;                ///< seeds re-placed because their cell vanished
  double energyStart = 0.0;        ///< the Lloyd energy of the farthest-point samples
  double energyEnd = 0.0;          ///< of the final seeds
  std::vector<Vec3> seedPosition;  ///< per region, its seed in 3D
  int sharpEdges = 0;              ///< edges the fronts did not cross (sharpEdgeAngle)
  int surfacePieces = 0;           ///< connected pieces of the surface the fronts ran on
  /// Non-manifold vertices of the input, split into one vertex per fan for the fronts; regions
  /// are disks on the input itself (none holds two fans of such a vertex).
  int splitVertices = 0;
  bool refined = false;  ///< the fronts ran on the intrinsic refinement of the input
  int insertedPoints = 0;
  double curvatureRadius = 0.0;  ///< the ball radius used (featureAlignment > 0, TotalCurvature)
  std::string speedFallback;     ///< the speed mapping's fallback, if it took one (for the log)
};

/// Region topology counted from a face labelling: per region, its faces, edge-connected pieces,
/// Euler characteristic V - E + F and boundary loops (edges with one face in the region).
struct RegionTopology {
  int faces = 0, pieces = 0, euler = 0, boundaryLoops = 0;
  bool isDisk() const { return faces > 0 && pieces == 1 && euler == 1 && boundaryLoops == 1; }
};
std::vector<RegionTopology> regionTopology(const TriMesh& mesh, const std::vector<int>& faceRegion, int regions);

/// The same for one region at a time (`faces`: the faces labelled r), in time linear in its
/// faces: the per-vertex scratch is kept between calls.
class RegionTopologyCounter {
 public:
  explicit RegionTopologyCounter(const TriMesh& mesh);
  RegionTopology count(const std::vector<int>& faceRegion, const std::vector<int>& faces, int r);

 private:
  int pieces(const std::vector<int>& faceRegion, const std::vector<int>& faces, int r, int mark);
  const TriMesh& mesh_;
  std::vector<int> vertexStamp_, faceStamp_, parent_, boundaryDegree_, loopSeen_, boundary_, stack_;
  int mark_ = 0;
};

/// Segments `mesh` (no non-manifold edge, with faces; a non-manifold vertex is split for the
/// fronts, SegmentationResult::splitVertices). `values` is the per-vertex field when speedField is
/// VertexQuality (not read otherwise). Fails with InvalidInput (no faces, regions < 1 or more
/// than the vertices, iterations < 0, a negative or non-finite strength, a field of the wrong
/// size or with a NaN; regions that cannot all be made disks, see maxDiskRounds), NonManifold
/// (an edge of three or more faces),
/// Cancelled.
Expected<SegmentationResult> segmentSurface(const TriMesh& mesh, const std::vector<double>& values,
                                            const SegmentationParams& params = {}, Progress progress = {});

}  // namespace gr
