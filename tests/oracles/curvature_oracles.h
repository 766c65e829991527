// Independent references for per-vertex curvature: vcglib's two 1-ring estimators, the ones
// MeshLab's "Compute curvature principal directions" offers. Never linked into the plugin.
#pragma once

#include <memory>
#include <vector>

#include "core/mesh/tri_mesh.h"

namespace gr::oracle {

/// vcglib's curvature on a float copy of the mesh (as MeshLab's CMeshO), with FF and VF adjacency
/// and per-vertex normals (normalised per-face normals) built once by the constructor; each call
/// then estimates every vertex's principal curvatures and directions again.
class VcgCurvature {
 public:
  explicit VcgCurvature(const TriMesh& mesh);
  ~VcgCurvature();
  /// UpdateCurvature<M>::PrincipalDirectionsNormalCycle: the normal-cycle tensor over the edges at
  /// each vertex (1-ring, no area normalisation, beta = asin, so |beta| <= 90 degrees); MeshLab's
  /// "Normal Cycles" option.
  void normalCycle();
  /// UpdateCurvature<M>::PrincipalDirections: Taubin 1995 over the 1-ring (with its own per-vertex
  /// normal update); MeshLab's default option.
  void taubin();
  /// Principal curvature k1 of a vertex, from the last estimate.
  double k1(int vertex) const;
  /// Per vertex, |k1| + |k2| of the last estimate (the total curvature tau of gr::totalCurvature).
  std::vector<double> totalCurvature() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace gr::oracle
