#include "core/mesh/vcg_mesh.h"

#include <wrap/io_trimesh/export.h>
#include <wrap/io_trimesh/import.h>

#include <vcg/complex/algorithms/update/normal.h>

#include "core/mesh/vcg_convert.h"

namespace gr {

Status loadMesh(const std::string& path, CoreMesh& m, LoadedAttributes* attributes) {
  m.Clear();
  int mask = 0;
  const int err = vcg::tri::io::Importer<CoreMesh>::Open(m, path.c_str(), mask);
  if (err != 0 && vcg::tri::io::Importer<CoreMesh>::ErrorCritical(err))
    return invalidInput("cannot read '" + path + "': " + vcg::tri::io::Importer<CoreMesh>::ErrorMsg(err));
  if (attributes) {
    attributes->vertexQuality = (mask & vcg::tri::io::Mask::IOM_VERTQUALITY) != 0;
    attributes->vertexColor = (mask & vcg::tri::io::Mask::IOM_VERTCOLOR) != 0;
  }
  return Status::ok();
}

Status saveMesh(const CoreMesh& m, const std::string& path, bool withQuality, bool withColor) {
  int mask = 0;
  if (withQuality) mask |= vcg::tri::io::Mask::IOM_VERTQUALITY;
  if (withColor) mask |= vcg::tri::io::Mask::IOM_VERTCOLOR;
  // vcglib's exporter takes a non-const mesh but does not modify it.
  const int err = vcg::tri::io::Exporter<CoreMesh>::Save(const_cast<CoreMesh&>(m), path.c_str(), mask);
  if (err != 0) return invalidInput("cannot write '" + path + "': " + vcg::tri::io::Exporter<CoreMesh>::ErrorMsg(err));
  return Status::ok();
}

Expected<TriMesh> loadTriMesh(const std::string& path) {
  CoreMesh m;
  if (Status s = loadMesh(path, m); !s) return s;
  return toTriMesh(m);
}

void toCoreMesh(const TriMesh& mesh, CoreMesh& m) {
  m.Clear();
  auto vi = vcg::tri::Allocator<CoreMesh>::AddVertices(m, mesh.vertexCount());
  for (const Vec3& p : mesh.positions) (vi++)->P() = vcg::Point3d(p.x(), p.y(), p.z());
  auto fi = vcg::tri::Allocator<CoreMesh>::AddFaces(m, mesh.faceCount());
  for (const Tri& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
    ++fi;
  }
  vcg::tri::UpdateNormal<CoreMesh>::PerFaceNormalized(m);
}

}  // namespace gr
