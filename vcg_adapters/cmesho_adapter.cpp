#include "vcg_adapters/cmesho_adapter.h"

#include <cmath>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

namespace gr::adapters {

Expected<CoreView> toCore(const CMeshO& m) {
  CoreView view;
  Expected<TriMesh> mesh = toTriMesh(m, &view.map);
  if (!mesh) return mesh.status();
  view.mesh = std::move(mesh).value();
  return view;
}

std::vector<int> selectedVertices(const CMeshO& m, const CoreView& view) {
  std::vector<int> selected;
  for (int v = 0; v < view.mesh.vertexCount(); ++v)
    if (m.vert[view.map.vcgOfCoreVertex[v]].IsS()) selected.push_back(v);
  return selected;
}

std::vector<double> vertexQuality(const CMeshO& m, const CoreView& view) {
  std::vector<double> q(view.mesh.vertexCount());
  for (int v = 0; v < view.mesh.vertexCount(); ++v) q[v] = m.vert[view.map.vcgOfCoreVertex[v]].cQ();
  return q;
}

void writeVertexQuality(CMeshO& m, const CoreView& view, const std::vector<double>& values, double missing) {
  for (int v = 0; v < view.mesh.vertexCount(); ++v)
    m.vert[view.map.vcgOfCoreVertex[v]].Q() = std::isfinite(values[v]) ? values[v] : missing;
}

void colorByRamp(CMeshO& m, const CoreView& view, const std::vector<double>& values, double lo, double hi,
                 vcg::Color4b missingColor) {
  for (int v = 0; v < view.mesh.vertexCount(); ++v) {
    vcg::Color4b& c = m.vert[view.map.vcgOfCoreVertex[v]].C();
    if (!std::isfinite(values[v])) {
      c = missingColor;
    } else {
      c.SetColorRamp(float(lo), float(hi > lo ? hi : lo + 1.0), float(values[v]));
    }
  }
}

void colorByLabel(CMeshO& m, const CoreView& view, const std::vector<int>& labels, int labelCount,
                  vcg::Color4b missingColor) {
  for (int v = 0; v < view.mesh.vertexCount(); ++v)
    m.vert[view.map.vcgOfCoreVertex[v]].C() =
        labels[v] < 0 ? missingColor : vcg::Color4b::Scatter(std::max(labelCount, 1), labels[v]);
}

void writeMesh(const TriMesh& mesh, CMeshO& out, const CMeshO& in, const CoreView& view,
               const std::vector<int>& inputVertexOf, bool copyColor, bool copyQuality) {
  out.Clear();
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(out, mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v, ++vi) {
    const Vec3& p = mesh.positions[v];
    vi->P() = CMeshO::CoordType(Scalarm(p.x()), Scalarm(p.y()), Scalarm(p.z()));
    const CVertexO& source = in.vert[view.map.vcgOfCoreVertex[inputVertexOf[v]]];
    if (copyColor) vi->C() = source.cC();
    if (copyQuality) vi->Q() = source.cQ();
  }
  if (mesh.faceCount() > 0) {
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(out, mesh.faceCount());
    for (const Tri& t : mesh.triangles) {
      for (int k = 0; k < 3; ++k) fi->V(k) = &out.vert[t[k]];
      ++fi;
    }
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(out);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalizedPerFaceNormalized(out);
}

}  // namespace gr::adapters
