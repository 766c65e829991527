// Internal to gr_oracles: a TriMesh copied into a vcglib mesh type of an oracle (vertex i is
// vertex i, face f is face f), coordinates converted to the mesh's scalar. Adjacency is left to
// the caller (each vcglib algorithm needs its own).
#pragma once

#include <vcg/complex/complex.h>

#include "core/mesh/tri_mesh.h"

namespace gr::oracle {

template <class VcgMesh>
void copyToVcg(const TriMesh& t, VcgMesh& m) {
  using Scalar = typename VcgMesh::ScalarType;
  vcg::tri::Allocator<VcgMesh>::AddVertices(m, t.vertexCount());
  for (int v = 0; v < t.vertexCount(); ++v)
    m.vert[v].P() =
        vcg::Point3<Scalar>(Scalar(t.positions[v].x()), Scalar(t.positions[v].y()), Scalar(t.positions[v].z()));
  vcg::tri::Allocator<VcgMesh>::AddFaces(m, t.faceCount());
  for (int f = 0; f < t.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) m.face[f].V(k) = &m.vert[t.triangles[f][k]];
}

}  // namespace gr::oracle
