// toTriMesh: builds the core's compact TriMesh from any vcglib triangle mesh.
//
// A template over the mesh type, so the core (CoreMesh, in tests and benchmarks) and the MeshLab
// adapters (CMeshO) share one conversion. Deleted vertices and faces are skipped; the index map
// ties core indices back to positions in the vcg containers, so results can be written back.
// Cost: O(V + F) plus buildTriMesh().
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Core <-> vcg index correspondence of a conversion.
struct VcgIndexMap {
  std::vector<int> coreOfVcgVertex;  ///< per vcg vertex slot; -1 for deleted vertices
  std::vector<int> vcgOfCoreVertex;  ///< per core vertex
  std::vector<int> vcgOfCoreFace;    ///< per core face
};

template <class VcgMesh>
Expected<TriMesh> toTriMesh(const VcgMesh& m, VcgIndexMap* map = nullptr) {
  VcgIndexMap local;
  VcgIndexMap& idx = map ? *map : local;
  idx = VcgIndexMap{};
  idx.coreOfVcgVertex.assign(m.vert.size(), -1);
  std::vector<Vec3> positions;
  positions.reserve(m.vn);
  for (size_t i = 0; i < m.vert.size(); ++i) {
    const auto& v = m.vert[i];
    if (v.IsD()) continue;
    idx.coreOfVcgVertex[i] = static_cast<int>(positions.size());
    idx.vcgOfCoreVertex.push_back(static_cast<int>(i));
    positions.emplace_back(double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2]));
  }
  std::vector<Tri> triangles;
  triangles.reserve(m.fn);
  for (size_t i = 0; i < m.face.size(); ++i) {
    const auto& f = m.face[i];
    if (f.IsD()) continue;
    Tri t;
    for (int k = 0; k < 3; ++k) {
      const auto* vp = f.cV(k);
      const long slot = vp == nullptr || m.vert.empty() ? -1 : long(vp - &m.vert[0]);
      if (slot < 0 || slot >= long(m.vert.size()) || idx.coreOfVcgVertex[slot] < 0)
        return invalidInput("face " + std::to_string(i) + " references a deleted or missing vertex");
      t[k] = idx.coreOfVcgVertex[slot];
    }
    triangles.push_back(t);
    idx.vcgOfCoreFace.push_back(static_cast<int>(i));
  }
  return buildTriMesh(std::move(positions), std::move(triangles));
}

}  // namespace gr
