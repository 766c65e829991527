// CGAL's Surface_mesh (Epick kernel), what every CGAL oracle runs on, and the conversions to and
// from the core's TriMesh: vertex i of the TriMesh is vertex i of the Surface_mesh.
#pragma once

#include <memory>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr::oracle {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using SmVertex = SurfaceMesh::Vertex_index;

/// A CGAL copy of a mesh. InvalidInput naming the face when Surface_mesh rejects one (a
/// non-manifold mesh, or faces not oriented coherently).
Expected<std::unique_ptr<SurfaceMesh>> toSurfaceMesh(const TriMesh& mesh);

/// Back to a TriMesh (the Surface_mesh is garbage collected first).
Expected<TriMesh> toTriMesh(SurfaceMesh& mesh);

}  // namespace gr::oracle
