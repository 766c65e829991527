// What the benchmarks share: the test meshes (optionally subdivided), CGAL's
// Surface_mesh to and from a TriMesh, CGAL's isotropic remeshing, and the surface distance both
// ways. Never timed themselves unless a benchmark says so.
#pragma once

#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr::bench {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using SmVertex = SurfaceMesh::Vertex_index;

/// A mesh of GR_MESH_DIR ("bunny00.off"), after `subdivisions` 1-to-4 midpoint subdivisions.
Expected<TriMesh> loadBenchMesh(const std::string& file, int subdivisions = 0);

/// A CGAL copy of a mesh (fails, naming the face, when Surface_mesh rejects one).
Expected<std::unique_ptr<SurfaceMesh>> toSurfaceMesh(const TriMesh& mesh);
/// `slot`, filled with toSurfaceMesh(mesh) on first use (never timed); nullptr after marking the
/// benchmark skipped when CGAL rejects the mesh.
SurfaceMesh* cachedSurfaceMesh(benchmark::State& state, const TriMesh& mesh, std::unique_ptr<SurfaceMesh>& slot);
/// Back to a TriMesh (garbage collected first).
Expected<TriMesh> toTriMesh(SurfaceMesh& mesh);

/// CGAL's isotropic remeshing of the whole mesh in place, without protected constraints.
void cgalIsotropicRemeshing(SurfaceMesh& mesh, double edgeLength, int iterations);

/// The target edge length for which CGAL's isotropic remeshing gives about `n` vertices: from
/// L = sqrt(2 A / (sqrt(3) n)) (equilateral triangles of area A / (2n)), then up to `maxRuns`
/// untimed runs, each followed by L *= sqrt(n_obtained / n), stopping within `tolerance`.
struct CgalCalibration {
  double edgeLength = 0.0;
  int runs = 0;
};
CgalCalibration calibrateCgalEdgeLength(const SurfaceMesh& input, double n, int iterations, int maxRuns,
                                        double tolerance);

/// Two-sided distance between surfaces (gr::surfaceDistance both ways): the larger maximum, and
/// the RMS over both directions' samples.
struct TwoSidedDistance {
  double max = 0.0;
  double rms = 0.0;
};
TwoSidedDistance twoSidedDistance(const TriMesh& a, const TriMesh& b);

}  // namespace gr::bench
