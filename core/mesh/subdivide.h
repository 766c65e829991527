// 1-to-4 midpoint subdivision that remembers where each new vertex lies on the original mesh.
//
// Each face is split into four at its edge midpoints; the surface does not change (midpoints
// lie in the original faces), the topology does not change, and the vertex count grows about 4x
// per level. Computing Voronoi cells on the finer mesh gives sample positions and cell
// boundaries at a finer resolution than the input's vertices.
// Cost: O(F) per level.
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

struct Subdivision {
  TriMesh mesh;
  /// Per vertex of `mesh`: the point of the original mesh it sits on (a vertex, or a face with
  /// barycentric coordinates). Original vertices keep their indices and come first.
  std::vector<SurfacePoint> origin;
  /// Per face of `mesh`: the face of the original mesh it lies in.
  std::vector<int> originalFace;

  /// A point of `mesh` as a point of the original mesh (`original` is the mesh subdivided).
  SurfacePoint originOf(const TriMesh& original, const SurfacePoint& p) const;
};

/// levels >= 0 (0 returns a copy). Fails with InvalidInput on a negative level count, and
/// NonManifold on non-manifold edges. New vertices are numbered by corner, level by level.
Expected<Subdivision> subdivideMidpoint(const TriMesh& mesh, int levels);

}  // namespace gr
