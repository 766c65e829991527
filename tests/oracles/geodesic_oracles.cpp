#include "tests/oracles/geodesic_oracles.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <vcg/complex/complex.h>
// geodesic.h relies on complex.h being included first.
#include <vcg/complex/algorithms/geodesic.h>

#include <limits>
#include <queue>
#include <stdexcept>

namespace gr::oracle {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using VertexIndex = SurfaceMesh::Vertex_index;

SurfaceMesh toSurfaceMesh(const TriMesh& mesh) {
  SurfaceMesh sm;
  for (const Vec3& p : mesh.positions) sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  for (const Tri& t : mesh.triangles)
    if (sm.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2])) == SurfaceMesh::null_face())
      throw std::runtime_error("CGAL cannot add a face: the mesh is not an oriented 2-manifold");
  return sm;
}

// vcglib mesh with what tri::Geodesic requires (VF adjacency, quality, marks).
class GVertex;
class GFace;
struct GTypes : vcg::UsedTypes<vcg::Use<GVertex>::AsVertexType, vcg::Use<GFace>::AsFaceType> {};
class GVertex : public vcg::Vertex<GTypes, vcg::vertex::Coord3d, vcg::vertex::Qualityd, vcg::vertex::VFAdj,
                                   vcg::vertex::Mark, vcg::vertex::BitFlags> {};
class GFace : public vcg::Face<GTypes, vcg::face::VertexRef, vcg::face::VFAdj, vcg::face::FFAdj, vcg::face::Mark,
                               vcg::face::BitFlags> {};
class GMesh : public vcg::tri::TriMesh<std::vector<GVertex>, std::vector<GFace>> {};

}  // namespace

std::vector<double> exactGeodesic(const TriMesh& mesh, int source) {
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, SurfaceMesh>;
  using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
  SurfaceMesh sm = toSurfaceMesh(mesh);
  ShortestPath sp(sm);
  sp.add_source_point(VertexIndex(source));
  std::vector<double> d(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) d[v] = sp.shortest_distance_to_source_points(VertexIndex(v)).first;
  return d;
}

std::vector<double> dijkstra(const TriMesh& mesh, int source) {
  std::vector<double> d(mesh.vertexCount(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> heap;
  d[source] = 0.0;
  heap.push({0.0, source});
  while (!heap.empty()) {
    const auto [du, u] = heap.top();
    heap.pop();
    if (du > d[u]) continue;
    for (const int* c = mesh.cornersBegin(u); c != mesh.cornersEnd(u); ++c) {
      const int w = mesh.vertex(TriMesh::next(*c));  // each edge is seen from one of its faces at least
      const int w2 = mesh.vertex(TriMesh::prev(*c));
      for (int x : {w, w2}) {
        const double nd = du + (mesh.positions[x] - mesh.positions[u]).norm();
        if (nd < d[x]) {
          d[x] = nd;
          heap.push({nd, x});
        }
      }
    }
  }
  return d;
}

std::vector<double> vcgGeodesic(const TriMesh& mesh, int source) {
  GMesh m;
  auto vi = vcg::tri::Allocator<GMesh>::AddVertices(m, mesh.vertexCount());
  for (const Vec3& p : mesh.positions) (vi++)->P() = vcg::Point3d(p.x(), p.y(), p.z());
  auto fi = vcg::tri::Allocator<GMesh>::AddFaces(m, mesh.faceCount());
  for (const Tri& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
    ++fi;
  }
  vcg::tri::UpdateTopology<GMesh>::VertexFace(m);
  std::vector<GMesh::VertexPointer> seeds = {&m.vert[source]};
  vcg::tri::EuclideanDistance<GMesh> metric;
  vcg::tri::Geodesic<GMesh>::Compute(m, seeds, metric);
  std::vector<double> d(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    const double q = m.vert[v].Q();
    d[v] = q == std::numeric_limits<double>::max() ? std::numeric_limits<double>::infinity() : q;
  }
  return d;
}

struct HeatMethod::Impl {
  using Heat = CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<SurfaceMesh, CGAL::Heat_method_3::Direct>;
  explicit Impl(const TriMesh& mesh) : sm(toSurfaceMesh(mesh)), heat(sm) {}
  SurfaceMesh sm;
  Heat heat;
};

HeatMethod::HeatMethod(const TriMesh& mesh) : impl_(std::make_unique<Impl>(mesh)) {}
HeatMethod::~HeatMethod() = default;

std::vector<double> HeatMethod::query(int source) {
  auto distance = impl_->sm.add_property_map<VertexIndex, double>("v:heat_distance", 0.0).first;
  impl_->heat.clear_sources();
  impl_->heat.add_source(VertexIndex(source));
  impl_->heat.estimate_geodesic_distances(distance);
  std::vector<double> d(impl_->sm.number_of_vertices());
  for (VertexIndex v : impl_->sm.vertices()) d[v.idx()] = distance[v];
  return d;
}

}  // namespace gr::oracle
