// Independent references for geodesic distances, used by tests and benchmarks:
// CGAL's exact geodesics (Surface_mesh_shortest_path, Xin-Wang/Chen-Han style), CGAL's heat method,
// vcglib's tri::Geodesic (what MeshLab's geodesic colouring runs), and Dijkstra along edges.
// Each competitor is an object built once per mesh that answers queries (what the benchmarks
// time), with a one-call function over it for the tests. Never linked into the plugin.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"
#include "tests/oracles/cgal_mesh.h"

namespace gr::oracle {

/// Exact polyhedral geodesic distance from vertex `source` (CGAL). Slow: seconds on 40k vertices.
std::vector<double> exactGeodesic(const TriMesh& mesh, int source);

/// Exact polyhedral geodesic distance from the surface point `source` to each of `targets`
/// (CGAL, with face locations: the barycentric coordinates are reordered to CGAL's corners).
std::vector<double> exactGeodesicBetween(const TriMesh& mesh, const SurfacePoint& source,
                                         const std::vector<SurfacePoint>& targets);

/// How many vertices a field reached, and the largest distance among them.
struct Reached {
  int count = 0;
  double maxDistance = 0.0;
};

// ------------------------------------------------------------------------------------------------
// Dijkstra along edges

/// Shortest paths along edges (the classic upper bound of geodesic distance): binary heap with
/// lazy deletion on a CSR graph of the edges and their lengths, built once; the buffers are reused
/// across runs like FastMarcher's. A source can also be added to a computed field incrementally
/// (U <- min(U, U_s), visiting only the improved vertices), with an undo log.
class DijkstraSolver {
 public:
  explicit DijkstraSolver(const TriMesh& mesh);

  /// Back to no field (cost: the vertices reached since the last reset).
  void reset();
  /// A full multi-source run on a reset solver; returns the number of reached vertices.
  int run(const std::vector<int>& sources);
  /// Adds a source to the current field, visiting only the improved vertices. Every change is
  /// appended to `undo` as (vertex, old value), oldest first. Returns the size of `undo`.
  int addSourceIncremental(int source, std::vector<std::pair<int, double>>* undo);
  /// Reverts the changes recorded by addSourceIncremental.
  void undo(const std::vector<std::pair<int, double>>& changes);

  /// Per vertex; infinity where not reached.
  const std::vector<double>& distance() const { return d_; }

 private:
  /// Vertex -> neighbour adjacency in CSR form with edge lengths, from the corners.
  struct EdgeGraph {
    std::vector<int> begin;  ///< size n + 1
    std::vector<int> neighbour;
    std::vector<double> length;
    int vertexCount() const { return static_cast<int>(begin.size()) - 1; }
  };
  struct Entry {
    double d;
    int v;
  };
  struct Later {
    bool operator()(const Entry& x, const Entry& y) const { return x.d > y.d; }
  };

  static EdgeGraph buildEdgeGraph(const TriMesh& m);
  void set(int v, double d);
  void relax(int v, double dv, std::vector<std::pair<int, double>>* undo);

  EdgeGraph g_;
  std::vector<double> d_;
  std::vector<Entry> heap_;
  std::vector<int> touched_;
};

/// One DijkstraSolver run from vertex `source`.
std::vector<double> dijkstra(const TriMesh& mesh, int source);

// ------------------------------------------------------------------------------------------------
// vcglib's tri::Geodesic

/// vcglib's tri::Geodesic<>::Compute with EuclideanDistance and no distance limit, the call
/// MeshLab's "Colorize by geodesic distance" makes, on a vcglib copy of the mesh built once
/// (VF adjacency, quality, mark, flags). Scalar float is MeshLab's CMeshO (MESHLAB_SCALAR = float),
/// what the benchmarks run; double is the tests' accuracy reference.
template <class Scalar>
class VcgGeodesic {
 public:
  explicit VcgGeodesic(const TriMesh& mesh);
  ~VcgGeodesic();
  /// The seeds of the next compute().
  void setSources(const std::vector<int>& sources);
  /// One Compute from the seeds: each vertex's quality becomes its distance.
  void compute();
  /// Per vertex; infinity where not reached (vcglib leaves the scalar's max there).
  std::vector<double> distance() const;
  Reached reached() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};
extern template class VcgGeodesic<float>;
extern template class VcgGeodesic<double>;

/// VcgGeodesic<double> from vertex `source`.
std::vector<double> vcgGeodesic(const TriMesh& mesh, int source);

// ------------------------------------------------------------------------------------------------
// CGAL's heat method

/// A CGAL copy of a mesh for the heat method, with the per-vertex distance its solvers write.
struct HeatMesh {
  std::unique_ptr<SurfaceMesh> mesh;
  SurfaceMesh::Property_map<SmVertex, double> distance;
  /// Per vertex, as the last solve wrote them: CGAL leaves max-double or NaN where its solve
  /// failed, e.g. where the heat underflowed to 0 far from the source on a fine mesh.
  std::vector<double> distances() const;
  /// The vertices of a finite distance below max-double, and the largest such distance.
  Reached reached() const;
};
/// Fails as toSurfaceMesh.
Expected<HeatMesh> toHeatMesh(const TriMesh& mesh);

/// Direct: the heat method on the input triangulation; IntrinsicDelaunay: on its intrinsic
/// Delaunay triangulation (more robust on bad triangles, slower to build).
enum class HeatVariant { Direct, IntrinsicDelaunay };

/// CGAL's heat method (Crane et al. 2013, Heat_method_3::Surface_mesh_geodesic_distances_3). The
/// constructor pays the set-up (mass and cotan matrices, time step, factorisation of M + tL and
/// of L); each solve() is then one query for the current sources (two back-substitutions, the
/// gradient and its divergence) into `mesh.distance`. `mesh` must outlive the solver.
class HeatSolver {
 public:
  HeatSolver(HeatMesh& mesh, HeatVariant variant);
  ~HeatSolver();
  void clearSources();
  /// Marks the sources changed, so the next solve() computes again.
  void addSource(int vertex);
  void solve();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A mesh and its solver, for the tests: factorised once, then query() for any source.
/// Throws std::runtime_error when CGAL rejects the mesh.
class HeatMethod {
 public:
  explicit HeatMethod(const TriMesh& mesh, HeatVariant variant = HeatVariant::Direct);
  ~HeatMethod();
  std::vector<double> query(int source);

 private:
  HeatMesh mesh_;
  std::unique_ptr<HeatSolver> solver_;
};

}  // namespace gr::oracle
