#include "tests/oracles/cgal_mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace gr::oracle {

Expected<std::unique_ptr<SurfaceMesh>> toSurfaceMesh(const TriMesh& mesh) {
  auto m = std::make_unique<SurfaceMesh>();
  m->reserve(mesh.vertexCount(), 3 * mesh.faceCount() / 2 + mesh.topology.boundaryEdges, mesh.faceCount());
  for (const Vec3& p : mesh.positions) m->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    if (m->add_face(SmVertex(t[0]), SmVertex(t[1]), SmVertex(t[2])) == SurfaceMesh::null_face())
      return invalidInput("CGAL Surface_mesh rejects face " + std::to_string(f));
  }
  return m;
}

Expected<TriMesh> toTriMesh(SurfaceMesh& m) {
  m.collect_garbage();
  std::vector<Vec3> positions;
  positions.reserve(m.number_of_vertices());
  for (SmVertex v : m.vertices()) {
    const Kernel::Point_3& p = m.point(v);
    positions.emplace_back(p.x(), p.y(), p.z());
  }
  std::vector<Tri> triangles;
  triangles.reserve(m.number_of_faces());
  for (auto f : m.faces()) {
    Tri t{};
    int k = 0;
    for (SmVertex v : CGAL::vertices_around_face(m.halfedge(f), m)) t[k++ % 3] = static_cast<int>(v.idx());
    triangles.push_back(t);
  }
  return buildTriMesh(std::move(positions), std::move(triangles));
}

}  // namespace gr::oracle
