#include "tests/oracles/remesh_oracles.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

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
    if (std::abs(obtained / n - 1.0) <= tolerance) break;
    c.edgeLength *= std::sqrt(obtained / n);
  }
  return c;
}

TwoSidedDistance twoSidedDistance(const TriMesh& a, const TriMesh& b) {
  const SurfaceDistance there = surfaceDistance(a, b), back = surfaceDistance(b, a);
  return {std::max(there.max, back.max), std::sqrt(0.5 * (there.rms * there.rms + back.rms * back.rms))};
}

}  // namespace gr::oracle
