#include "vcg_adapters/cmesho_adapter.h"

#include <algorithm>
#include <cmath>

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include "core/field/color_gradient.h"

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

std::vector<double> vertexColorIntensity(const CMeshO& m, const CoreView& view) {
  std::vector<double> intensity(view.mesh.vertexCount());
  for (int v = 0; v < view.mesh.vertexCount(); ++v) {
    const vcg::Color4b& c = m.vert[view.map.vcgOfCoreVertex[v]].cC();
    intensity[v] = rgbIntensity(c[0], c[1], c[2]);
  }
  return intensity;
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
               const std::vector<SurfacePoint>& originOf, bool copyColor, bool copyQuality) {
  out.Clear();
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(out, mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v, ++vi) {
    const Vec3& p = mesh.positions[v];
    vi->P() = CMeshO::CoordType(Scalarm(p.x()), Scalarm(p.y()), Scalarm(p.z()));
    // The input vertices (and weights) the output vertex lies between.
    const SurfacePoint& o = originOf[v];
    int corner[3] = {o.vertex, -1, -1};
    double weight[3] = {1.0, 0.0, 0.0};
    if (o.vertex < 0)
      for (int k = 0; k < 3; ++k) {
        corner[k] = view.mesh.triangles[o.face][k];
        weight[k] = o.bary[k];
      }
    double q = 0.0, rgba[4] = {0, 0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      if (corner[k] < 0) continue;
      const CVertexO& source = in.vert[view.map.vcgOfCoreVertex[corner[k]]];
      q += weight[k] * source.cQ();
      for (int c = 0; c < 4; ++c) rgba[c] += weight[k] * source.cC()[c];
    }
    if (copyQuality) vi->Q() = Scalarm(q);
    if (copyColor)
      for (int c = 0; c < 4; ++c) vi->C()[c] = static_cast<unsigned char>(std::lround(std::clamp(rgba[c], 0.0, 255.0)));
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
