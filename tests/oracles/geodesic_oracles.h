// Independent references for geodesic distances, used by tests and benchmarks:
// CGAL's exact geodesics (Surface_mesh_shortest_path, Xin-Wang/Chen-Han style), CGAL's heat method,
// vcglib's tri::Geodesic (what MeshLab's geodesic colouring runs), and Dijkstra along edges.
// Never linked into the plugin.
#pragma once

#include <memory>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr::oracle {

/// Exact polyhedral geodesic distance from vertex `source` (CGAL). Slow: seconds on 40k vertices.
std::vector<double> exactGeodesic(const TriMesh& mesh, int source);

/// Shortest paths along edges (the classic upper bound of geodesic distance).
std::vector<double> dijkstra(const TriMesh& mesh, int source);

/// vcglib's tri::Geodesic<>::Compute with EuclideanDistance, as MeshLab runs it.
std::vector<double> vcgGeodesic(const TriMesh& mesh, int source);

/// CGAL's heat method (Crane et al. 2013), direct variant. Factorisation is paid at construction;
/// query() can then be called for any source.
class HeatMethod {
 public:
  explicit HeatMethod(const TriMesh& mesh);
  ~HeatMethod();
  std::vector<double> query(int source);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gr::oracle
