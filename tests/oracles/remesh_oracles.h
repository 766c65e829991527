// Independent references for remeshing: CGAL's isotropic remeshing (the competitor of the uniform
// and adaptive remeshers, at an equal vertex count), the two-sided surface distance every
// remeshing comparison measures its outputs with, and CGAL's self-intersection test (the judge of
// output and generated triangles).
#pragma once

#include <utility>
#include <vector>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"
#include "tests/oracles/cgal_mesh.h"

namespace gr::oracle {

/// CGAL::Polygon_mesh_processing::isotropic_remeshing of the whole mesh in place, without
/// protected constraints, `iterations` rounds towards the target edge length.
void cgalIsotropicRemeshing(SurfaceMesh& mesh, double edgeLength, int iterations);

/// The target edge length for which CGAL's isotropic remeshing gives about `n` vertices: from
/// L = sqrt(2 A / (sqrt(3) n)) (equilateral triangles of area A / (2n)), then up to `maxRuns`
/// runs on copies of `input`, each followed by L *= sqrt(n_obtained / n), stopping within
/// `tolerance` (relative). edgeLength is the last estimate (run or not); closestEdgeLength the
/// length of the run whose count, closestVertices, came nearest n (on small outputs the estimates
/// swing round n: ellipsoid.off at 8 vertices gave 10, 6, ... before 8).
struct CgalCalibration {
  double edgeLength = 0.0;
  int runs = 0;
  double closestEdgeLength = 0.0;
  int closestVertices = 0;
};
CgalCalibration calibrateCgalEdgeLength(const SurfaceMesh& input, double n, int iterations, int maxRuns,
                                        double tolerance);

/// Two-sided distance between surfaces (gr::surfaceDistance both ways): the larger maximum, and
/// the RMS over both directions' samples, sqrt((rms_ab^2 + rms_ba^2) / 2).
struct TwoSidedDistance {
  double max = 0.0;
  double rms = 0.0;
};
TwoSidedDistance twoSidedDistance(const TriMesh& a, const TriMesh& b);

/// The largest distance from samples of `from` to the surface of `to`, each exact (CGAL's AABB
/// tree, squared_distance to every triangle it cannot rule out): at the samples of
/// gr::surfaceDistance (`from`'s vertices, then with `midpointsAndCentroids` its faces' centroids
/// and side midpoints). vcglib's grid, which surfaceDistance queries, misses the nearest point by
/// 1.3e-4 of the distance near an input's slivers (cheese.off at 10%). Fails as toSurfaceMesh on `to`.
Expected<double> largestDistanceAtSamples(const TriMesh& from, const TriMesh& to, bool midpointsAndCentroids);

/// The pairs of faces (indices of `mesh`, smaller first, sorted) that intersect other than in
/// their shared vertex or edge: CGAL::Polygon_mesh_processing::self_intersections, exact
/// predicates. Fails as toSurfaceMesh (a non-manifold or incoherently oriented mesh).
Expected<std::vector<std::pair<int, int>>> selfIntersections(const TriMesh& mesh);

}  // namespace gr::oracle
