// A texture atlas: the surface cut into disk regions, each flattened and packed into the unit
// square (Peyré & Cohen 2006, §4.2-4.3 and §5: segmentation, then flattening per region).
//
//   mesh --segmentSurface (geodesic centroidal tessellation, boundaries on sharp edges)--> regions
//        --per region: its faces as a patch, flattenChart (geodesic LLE + Nyström, relaxed by
//          ARAP; Tutte's embedding, relaxed likewise, when LLE folds; the faces laid out one by one
//          when even that fails)--> UVs
//        --per chart: scaled so that UV area / 3D area is the same for all (one texel density),
//          turned to its minimal bounding rectangle (chart_packing.h)--> rectangles
//        --packCharts, a gutter of `gutter` texels at `textureSize`--> UVs in [0, 1]^2
//        --> per corner (wedge) texture coordinates, chart of each face, the figures for the log
//
// Guarantees: every chart's map is one-to-one (checkUvInjectivity: positive triangles, no
// branch point, a simple boundary), charts lie in disjoint rectangles at least 2 gutters apart,
// all UVs in [0, 1]^2. Cost: the segmentation, plus per chart B fronts over its V_c vertices
// (geodesic_lle.h; the charts run on all cores, with the same output), plus the packing.
#pragma once

#include <vector>

#include "core/atlas/chart_packing.h"
#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/flatten/geodesic_lle.h"
#include "core/flatten/uv_map_quality.h"
#include "core/mesh/tri_mesh.h"
#include "core/segment/geodesic_segmentation.h"

namespace gr {

struct AtlasParams {
  /// Regions and Lloyd iterations of the segmentation (30 regions, 10 iterations; charts end at
  /// sharp edges, sharpEdgeAngle as the segmentation's). Feature alignment 8, stronger than the
  /// segmentation's 0.5: chart boundaries drawn to curved bands flatten with less distortion, and
  /// fewer charts need a seed added to be disks (bunny00: 30 charts, conformal distortion 1.036,
  /// 0.60 s of CPU; with 0.5, 33 charts, 1.050, 0.83 s; its 603k-vertex subdivision 11.3 s
  /// against 15.7 s).
  SegmentationParams segmentation = [] {
    SegmentationParams p;
    p.regions = 30;
    p.lloyd.iterations = 10;
    p.featureAlignment = 8.0;
    return p;
  }();
  /// B and K of each chart's LLE, B the most a chart gets: a chart of V vertices gets at most
  /// V / 5 and at most max(25, V / 50) (its ARAP relaxation does the rest); K < B.
  LleFlatteningParams flattening;
  /// A mesh of F faces gets at most max(1, F / kFacesPerChart) charts, whatever was asked: more
  /// regions than that leave some without faces or not disks (a cube's 12 faces at the default 30
  /// regions were refused; they now get 3 charts, and the atlas logs that it lowered the count).
  static constexpr int kFacesPerChart = 4;
  int textureSize = 1024;  ///< texels per side of the (square) texture, >= 16
  int gutter = 4;          ///< empty texels around each chart, >= 0
};

struct AtlasChart {
  int faces = 0, vertices = 0;
  bool tutte = false;       ///< mapped by Tutte's embedding (LLE folded or its boundary crossed)
  int splits = 0;           ///< times the region (or a part of it) was cut in smaller ones for want of a map
  bool facesApart = false;  ///< even Tutte's was not one-to-one in floating point: faces laid out apart
  int foldedBeforeRepair = 0;
};

struct AtlasResult {
  std::vector<Vec2> cornerUv;  ///< per corner 3 f + k of the input: its texture coordinate
  std::vector<int> faceChart;  ///< per face, its chart
  std::vector<AtlasChart> charts;
  int regionsAsked = 0;     ///< AtlasParams' regions; segmentation.regionsAsked is what was used (kFacesPerChart)
  int repairedCharts = 0;   ///< charts whose LLE map was repaired (untangled, Tutte's, cut or faces apart)
  int pieces = 0;           ///< pieces packed into the texture: a chart cut or laid out apart gives several
  UvDistortion distortion;  ///< of the whole atlas
  double packing = 0.0;     ///< UV area of the charts / area of the unit square
  SegmentationResult segmentation;
};

/// Builds the atlas of `mesh` (manifold, coherently oriented; any genus, boundaries, components:
/// the segmentation makes every region a disk). Fails as segmentSurface, with InvalidInput on
/// textureSize < 16, gutter < 0, faces not coherently oriented, or charts that cannot fit with that
/// gutter, NonManifold, Degenerate (a face too small for the texture's float precision even laid
/// out alone), and Cancelled.
Expected<AtlasResult> buildTextureAtlas(const TriMesh& mesh, const AtlasParams& params = {}, Progress progress = {});

/// One chart's map: `patch` (a topological disk) flattened by geodesic LLE with B and K capped to
/// its size, checked with checkUvInjectivity, compact (>= 5% of its bounding rectangle) and with an
/// L2 stretch <= 4, else Tutte's embedding with the same checks (each relaxed by ARAP first,
/// arap_relaxation.h, and taken as it was if the relaxed map fails them); UV area = 3D area,
/// counter-clockwise. Empty uv if neither passes (the caller lays the faces apart).
struct ChartMap {
  std::vector<Vec2> uv;
  bool tutte = false;
  int foldedBeforeRepair = 0;
};
Expected<ChartMap> flattenChart(const TriMesh& patch, const LleFlatteningParams& params, Progress progress = {});

}  // namespace gr
