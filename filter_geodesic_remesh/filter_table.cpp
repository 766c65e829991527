#include "filter_geodesic_remesh/fast_marching_filter.h"
#include "filter_geodesic_remesh/filter_spec.h"
#include "filter_geodesic_remesh/uniform_remesh_filter.h"

namespace gr::filters {

enum FilterId { kFastMarching = 0, kUniformRemesh = 1 };

const std::vector<FilterSpec>& filterTable() {
  static const std::vector<FilterSpec> table = {
      {kFastMarching, "Geodesic Distance: Fast Marching from Selected Vertices",
       "Computes the geodesic distance from the selected vertices to every vertex by fast marching on the "
       "triangles (Kimmel &amp; Sethian 1998), optionally weighted by a speed read from the vertex quality, "
       "and the geodesic Voronoi diagram of the selected vertices (nearest source of each vertex).<br>"
       "Writes the distance into the vertex quality (-1 where not reached) and colors the vertices by distance "
       "or by Voronoi region.<br>See G. Peyr&eacute; and L. Cohen, <i>Geodesic Remeshing Using Front "
       "Propagation</i>, IJCV 2006, &sect;2.1&ndash;2.2.",
       MeshFilterInterface::FilterClass(MeshFilterInterface::Quality + MeshFilterInterface::VertexColoring),
       MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR, declareFastMarching, applyFastMarching},
      {kUniformRemesh, "Remeshing: Geodesic Uniform",
       "Remeshes the surface with evenly spaced vertices: greedy farthest-point sampling with geodesic "
       "distances from fast marching, then the geodesic Delaunay triangulation of the samples (the dual of "
       "their geodesic Voronoi diagram). Where the samples are too sparse for a valid triangulation, samples "
       "are added until the result is a manifold, consistently oriented mesh with the input's components and "
       "genus and boundary loops (boundaries are sampled first and stay boundaries). The result goes to a new "
       "layer; vertex colour and quality of the input are carried over.<br>See G. Peyr&eacute; and L. Cohen, <i>Geodesic "
       "Remeshing Using Front Propagation</i>, IJCV 2006, &sect;3.1&ndash;3.2.",
       MeshFilterInterface::Remeshing, MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR, declareUniformRemesh,
       applyUniformRemesh},
  };
  return table;
}

}  // namespace gr::filters
