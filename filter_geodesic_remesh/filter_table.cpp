#include "filter_geodesic_remesh/adaptive_remesh_filter.h"
#include "filter_geodesic_remesh/atlas_filter.h"
#include "filter_geodesic_remesh/fast_marching_filter.h"
#include "filter_geodesic_remesh/filter_spec.h"
#include "filter_geodesic_remesh/param_filter.h"
#include "filter_geodesic_remesh/segmentation_filter.h"
#include "filter_geodesic_remesh/uniform_remesh_filter.h"

namespace gr::filters {

enum FilterId {
  kFastMarching = 0,
  kUniformRemesh = 1,
  kAdaptiveRemesh = 2,
  kTotalCurvature = 3,
  kSegmentation = 4,
  kTextureAtlas = 5,
  kLleFlattening = 6,
  kSemiRegular = 7,
  kGeodesicBarycentric = 8
};

const auto kQualityAndColorClass =
    MeshFilterInterface::FilterClass(MeshFilterInterface::Quality + MeshFilterInterface::VertexColoring);
constexpr int kWritesQualityAndColor = MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR;

const char* const kSemiRegularInfo =
    "Remeshes the surface with subdivision connectivity: a geodesic remesh of the surface (farthest-point "
    "samples and their geodesic Delaunay triangulation) is the base domain; the surface is cut along paths "
    "between the base vertices into one disk per base triangle, each disk is mapped onto its triangle by "
    "geodesic barycentric coordinates (Heron's formula on geodesic distances; mean value coordinates where "
    "those fold), and each base triangle, subdivided 1-to-4 Levels times, is mapped back onto the surface. "
    "Every vertex that is not a base vertex has valence 6 (4 on a boundary): the input of wavelet "
    "compression and multiresolution editing. A few rounds of tangential relaxation on the surface follow. "
    "The result goes to a new layer with the input's topology.<br>See G. Peyr&eacute; and L. Cohen, "
    "<i>Geodesic Remeshing Using Front Propagation</i>, IJCV 2006, &sect;4.1.";

const char* const kGeodesicBarycentricInfo =
    "Parameterises the surface over a coarse geodesic remesh of it: the surface is cut along paths between "
    "the base vertices into one disk per base triangle, and each disk is mapped onto its triangle by geodesic "
    "barycentric coordinates (Heron's formula on the geodesic distances to the triangle's corners), or by "
    "mean value coordinates where those fold; every map is checked one-to-one and the pieces tile their "
    "triangles. Writes a new layer: the input with the edges the cut needed split, the base triangle of each "
    "vertex in its quality and colour, and per-wedge texture coordinates with one tile of a checkerboard "
    "texture per base triangle.<br>See G. Peyr&eacute; and L. Cohen, <i>Geodesic Remeshing Using Front "
    "Propagation</i>, IJCV 2006, &sect;4.1.";

const std::vector<FilterSpec>& filterTable() {
  static const std::vector<FilterSpec> table = {
      {kFastMarching, "Geodesic Distance: Fast Marching from Selected Vertices",
       "Computes the geodesic distance from the selected vertices to every vertex by fast marching on the "
       "triangles (Kimmel &amp; Sethian 1998), optionally weighted by a speed read from the vertex quality, "
       "and the geodesic Voronoi diagram of the selected vertices (nearest source of each vertex).<br>"
       "Writes the distance into the vertex quality (-1 where not reached) and colors the vertices by distance "
       "or by Voronoi cell.<br>See G. Peyr&eacute; and L. Cohen, <i>Geodesic Remeshing Using Front "
       "Propagation</i>, IJCV 2006, &sect;2.1&ndash;2.2.",
       kQualityAndColorClass, kWritesQualityAndColor, declareFastMarching, applyFastMarching},
      {kUniformRemesh, "Remeshing: Geodesic Uniform",
       "Remeshes the surface with evenly spaced vertices: greedy farthest-point sampling with geodesic "
       "distances from fast marching, then the geodesic Delaunay triangulation of the samples (the dual of "
       "their geodesic Voronoi diagram). Where the samples are too sparse for a valid triangulation, samples "
       "are added until the result is a manifold, consistently oriented mesh with the input's components and "
       "genus and boundary loops (boundaries are sampled first and stay boundaries). Last, a few rounds of "
       "tangential relaxation on the input surface give well-shaped triangles (creases and tips stay). The "
       "result goes to a new layer; vertex colour and quality of the input are carried over.<br>See G. Peyr&eacute; "
       "and L. Cohen, <i>Geodesic "
       "Remeshing Using Front Propagation</i>, IJCV 2006, &sect;3.1&ndash;3.2.",
       MeshFilterInterface::Remeshing, kWritesQualityAndColor, declareUniformRemesh, applyUniformRemesh},
      {kAdaptiveRemesh, "Remeshing: Geodesic Adaptive",
       "Remeshes the surface with a density that follows a per-vertex field: the field sets the front speed F of "
       "the fast marching, so farthest-point samples are spaced proportionally to F. The field is the vertex "
       "quality (any filter that computes quality can drive it), the total curvature |k1|+|k2| from the "
       "Cohen-Steiner&ndash;Morvan tensor, or the gradient of the vertex colour; mappings Attractive (denser where "
       "the field is large, e.g. on sharp edges), Repulsive and Direct. Same guarantees as the uniform filter: "
       "a manifold, oriented mesh with the input's components, genus and boundary loops, on a new layer.<br>See "
       "G. Peyr&eacute; and L. Cohen, <i>Geodesic Remeshing Using Front Propagation</i>, IJCV 2006, "
       "&sect;3.3&ndash;3.4.",
       MeshFilterInterface::Remeshing, kWritesQualityAndColor, declareAdaptiveRemesh, applyAdaptiveRemesh},
      {kTotalCurvature, "Compute Total Curvature (Normal Cycle) into Vertex Quality",
       "Computes the total curvature |k1|+|k2| of every vertex from the Cohen-Steiner&ndash;Morvan normal-cycle "
       "tensor averaged over a ball of the given radius, writes it into the vertex quality and colours the "
       "vertices by it. This is the field the adaptive remeshing uses for curvature; look at it before "
       "remeshing.<br>See D. Cohen-Steiner and J.-M. Morvan, <i>Restricted Delaunay triangulations and normal "
       "cycle</i>, SoCG 2003, and G. Peyr&eacute; and L. Cohen, IJCV 2006, &sect;3.4.",
       kQualityAndColorClass, kWritesQualityAndColor, declareTotalCurvature, applyTotalCurvature},
      {kSegmentation, "Segmentation: Geodesic Centroidal Tessellation",
       "Cuts the surface into compact regions of even area that are topological disks (ready to be flattened): "
       "farthest-point seeds, then geodesic Lloyd iterations that move each seed to the intrinsic centre of mass "
       "of its geodesic Voronoi region. With Feature alignment the fronts slow down on sharp edges (the "
       "edge-attractive speed from the total curvature, or from the vertex quality), so region boundaries follow "
       "them. A region that is not a disk (a handle, a ring around a tube, a closed component) gets another seed "
       "until all are disks. Writes the region index into the face quality and one colour per region into the "
       "face colour, selects the faces on region boundaries, and can put each region on its own layer.<br>See "
       "G. Peyr&eacute; and L. Cohen, <i>Geodesic Remeshing Using Front Propagation</i>, IJCV 2006, &sect;4.2.",
       MeshFilterInterface::FilterClass(MeshFilterInterface::FaceColoring + MeshFilterInterface::Quality),
       MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR | MeshModel::MM_FACEFLAGSELECT, declareSegmentation,
       applySegmentation},
      {kTextureAtlas, "Parametrization: Geodesic Texture Atlas",
       "Builds a texture atlas: the surface is cut into disk regions by the geodesic centroidal tessellation "
       "(boundaries on sharp edges), each region is flattened by geodesic LLE with a Nystr&ouml;m extension, "
       "scaled to one texel density, turned to its smallest bounding rectangle and packed into the unit square "
       "with a gutter. Every chart's map is checked one-to-one; where LLE folds, the chart is mapped by Tutte's "
       "embedding with mean-value weights. Writes per-wedge texture coordinates and a checkerboard texture "
       "(PNG, next to the mesh's file) named in the mesh's texture list.<br>See G. Peyr&eacute; and L. Cohen, "
       "<i>Geodesic Remeshing Using Front Propagation</i>, IJCV 2006, &sect;4.2&ndash;4.3, &sect;5.",
       MeshFilterInterface::FilterClass(MeshFilterInterface::Texture), MeshModel::MM_WEDGTEXCOORD, declareTextureAtlas,
       applyTextureAtlas},
      {kLleFlattening, "Parametrization: Geodesic LLE Flattening",
       "Flattens a mesh that is a topological disk: B farthest-point base points, their geodesic distances by "
       "fast marching, locally linear embedding (Roweis &amp; Saul) of the base points from those distances, then "
       "the Nystr&ouml;m extension to every vertex. Folds are untangled, or the mesh is mapped by Tutte's "
       "embedding (one-to-one). Writes vertex and wedge texture coordinates; optionally a flat layer.<br>See G. "
       "Peyr&eacute; and L. Cohen, <i>Geodesic Remeshing Using Front Propagation</i>, IJCV 2006, &sect;4.3.",
       MeshFilterInterface::FilterClass(MeshFilterInterface::Texture),
       MeshModel::MM_VERTTEXCOORD | MeshModel::MM_WEDGTEXCOORD, declareLleFlattening, applyLleFlattening},
      {kSemiRegular, "Remeshing: Geodesic Semi-Regular", kSemiRegularInfo, MeshFilterInterface::Remeshing,
       kWritesQualityAndColor, declareSemiRegular, applySemiRegular},
      {kGeodesicBarycentric, "Parametrization: Geodesic Barycentric", kGeodesicBarycentricInfo,
       MeshFilterInterface::FilterClass(MeshFilterInterface::Texture),
       kWritesQualityAndColor | MeshModel::MM_WEDGTEXCOORD, declareGeodesicBarycentric, applyGeodesicBarycentric},
  };
  return table;
}

}  // namespace gr::filters
