#include "tests/oracles/curvature_oracles.h"

#include <cmath>

// vcglib's algorithm headers need complex.h first: a block of its own keeps it there.
#include <vcg/complex/complex.h>

#include <vcg/complex/algorithms/update/curvature.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include "tests/oracles/vcg_copy.h"

namespace gr::oracle {
namespace {

// What PrincipalDirections and PrincipalDirectionsNormalCycle need (FF and VF adjacency, normals,
// curvature and its directions), float like MeshLab's CMeshO.
class CVertex;
class CFace;
struct CUsedTypes : public vcg::UsedTypes<vcg::Use<CVertex>::AsVertexType, vcg::Use<CFace>::AsFaceType> {};
class CVertex : public vcg::Vertex<CUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::VFAdj,
                                   vcg::vertex::Curvaturef, vcg::vertex::CurvatureDirf, vcg::vertex::BitFlags> {};
class CFace : public vcg::Face<CUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::FFAdj,
                               vcg::face::VFAdj, vcg::face::BitFlags> {};
class CMesh : public vcg::tri::TriMesh<std::vector<CVertex>, std::vector<CFace>> {};

}  // namespace

struct VcgCurvature::Impl {
  CMesh m;
};

VcgCurvature::VcgCurvature(const TriMesh& mesh) : impl_(std::make_unique<Impl>()) {
  CMesh& m = impl_->m;
  copyToVcg(mesh, m);
  vcg::tri::UpdateTopology<CMesh>::FaceFace(m);
  vcg::tri::UpdateTopology<CMesh>::VertexFace(m);
  vcg::tri::UpdateNormal<CMesh>::PerVertexNormalizedPerFace(m);
}

VcgCurvature::~VcgCurvature() = default;

void VcgCurvature::normalCycle() { vcg::tri::UpdateCurvature<CMesh>::PrincipalDirectionsNormalCycle(impl_->m); }

void VcgCurvature::taubin() { vcg::tri::UpdateCurvature<CMesh>::PrincipalDirections(impl_->m); }

double VcgCurvature::k1(int vertex) const { return impl_->m.vert[vertex].cK1(); }

std::vector<double> VcgCurvature::totalCurvature() const {
  std::vector<double> tau;
  tau.reserve(impl_->m.vert.size());
  for (const CVertex& v : impl_->m.vert) tau.push_back(std::abs(double(v.cK1())) + std::abs(double(v.cK2())));
  return tau;
}

}  // namespace gr::oracle
