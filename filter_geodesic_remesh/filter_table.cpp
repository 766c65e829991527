#include "filter_geodesic_remesh/fast_marching_filter.h"
#include "filter_geodesic_remesh/filter_spec.h"

namespace gr::filters {

enum FilterId { kFastMarching = 0 };

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
  };
  return table;
}

}  // namespace gr::filters
