#include "bench/bench_support.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include "core/measure/evaluation.h"
#include "core/mesh/subdivide.h"
#include "core/mesh/vcg_mesh.h"

namespace gr::bench {

Expected<TriMesh> loadBenchMesh(const std::string& file, int subdivisions) {
  Expected<TriMesh> m = loadTriMesh(std::string(GR_MESH_DIR) + "/" + file);
  if (!m || subdivisions == 0) return m;
  Expected<Subdivision> fine = subdivideMidpoint(*m, subdivisions);  // old vertices keep their indices
  if (!fine) return fine.status();
  return std::move(fine->mesh);
}

Expected<std::unique_ptr<SurfaceMesh>> toSurfaceMesh(const TriMesh& mesh) {
  auto m = std::make_unique<SurfaceMesh>();
  for (const Vec3& p : mesh.positions) m->add_vertex(Kernel::Point_3(p.x(), p.y(), p.z()));
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Tri& t = mesh.triangles[f];
    if (m->add_face(SmVertex(t[0]), SmVertex(t[1]), SmVertex(t[2])) == SurfaceMesh::null_face())
      return invalidInput("CGAL Surface_mesh rejects face " + std::to_string(f));
  }
  return m;
}

SurfaceMesh* cachedSurfaceMesh(benchmark::State& state, const TriMesh& mesh, std::unique_ptr<SurfaceMesh>& slot) {
  if (slot) return slot.get();
  Expected<std::unique_ptr<SurfaceMesh>> m = toSurfaceMesh(mesh);
  if (!m) {
    state.SkipWithError(m.status().message.c_str());
    return nullptr;
  }
  slot = std::move(*m);
  return slot.get();
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

void cgalIsotropicRemeshing(SurfaceMesh& mesh, double edgeLength, int iterations) {
  CGAL::Polygon_mesh_processing::isotropic_remeshing(
      faces(mesh), edgeLength, mesh, CGAL::parameters::number_of_iterations(iterations).protect_constraints(false));
}

CgalCalibration calibrateCgalEdgeLength(const SurfaceMesh& input, double n, int iterations, int maxRuns,
                                        double tolerance) {
  CgalCalibration c;
  c.edgeLength = std::sqrt(2.0 * CGAL::Polygon_mesh_processing::area(input) / (std::sqrt(3.0) * n));
  while (c.runs < maxRuns) {
    SurfaceMesh m = input;
    cgalIsotropicRemeshing(m, c.edgeLength, iterations);
    ++c.runs;
    const double obtained = m.number_of_vertices();
    if (std::abs(obtained / n - 1.0) <= tolerance) break;
    c.edgeLength *= std::sqrt(obtained / n);
  }
  return c;
}

TwoSidedDistance twoSidedDistance(const TriMesh& a, const TriMesh& b) {
  const SurfaceDistance there = surfaceDistance(a, b), back = surfaceDistance(b, a);
  return {std::max(there.max, back.max), std::sqrt(0.5 * (there.rms * there.rms + back.rms * back.rms))};
}

}  // namespace gr::bench
