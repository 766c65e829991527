#include "tests/oracles/remesh_oracles.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include "core/measure/evaluation.h"

namespace gr::oracle {

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
    if (c.closestVertices == 0 || std::abs(obtained - n) < std::abs(c.closestVertices - n)) {
      c.closestEdgeLength = c.edgeLength;
      c.closestVertices = static_cast<int>(obtained);
    }
    if (std::abs(obtained / n - 1.0) <= tolerance) break;
    c.edgeLength *= std::sqrt(obtained / n);
  }
  return c;
}

TwoSidedDistance twoSidedDistance(const TriMesh& a, const TriMesh& b) {
  const SurfaceDistance there = surfaceDistance(a, b), back = surfaceDistance(b, a);
  return {std::max(there.max, back.max), std::sqrt(0.5 * (there.rms * there.rms + back.rms * back.rms))};
}

Expected<double> largestDistanceAtSamples(const TriMesh& from, const TriMesh& to, bool midpointsAndCentroids) {
  Expected<std::unique_ptr<SurfaceMesh>> sm = toSurfaceMesh(to);
  if (!sm) return sm.status();
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>>>;
  Tree tree(faces(**sm).first, faces(**sm).second, **sm);
  tree.accelerate_distance_queries();
  double largest = 0.0;
  const auto measure = [&](const Vec3& p) {
    largest = std::max(largest, std::sqrt(tree.squared_distance(Kernel::Point_3(p.x(), p.y(), p.z()))));
  };
  for (const Vec3& p : from.positions) measure(p);
  if (midpointsAndCentroids)
    for (const Tri& t : from.triangles) {
      const Vec3 &a = from.positions[t[0]], &b = from.positions[t[1]], &c = from.positions[t[2]];
      for (const Vec3& p : {Vec3((a + b + c) / 3.0), Vec3(0.5 * (a + b)), Vec3(0.5 * (b + c)), Vec3(0.5 * (c + a))})
        measure(p);
    }
  return largest;
}

Expected<std::vector<std::pair<int, int>>> selfIntersections(const TriMesh& mesh) {
  Expected<std::unique_ptr<SurfaceMesh>> sm = toSurfaceMesh(mesh);
  if (!sm) return sm.status();
  using Face = SurfaceMesh::Face_index;
  std::vector<std::pair<Face, Face>> found;
  CGAL::Polygon_mesh_processing::self_intersections(**sm, std::back_inserter(found));
  // Faces were added in order to an empty Surface_mesh: face f of the mesh is Face_index f.
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [f, g] : found) pairs.push_back(std::minmax(static_cast<int>(f.idx()), static_cast<int>(g.idx())));
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace gr::oracle
