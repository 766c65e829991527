#include "tests/oracles/geodesic_oracles.h"

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <vcg/complex/complex.h>
// geodesic.h relies on complex.h being included first.
#include <vcg/complex/algorithms/geodesic.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>

#include "tests/oracles/vcg_copy.h"

namespace gr::oracle {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// vcglib mesh with what tri::Geodesic requires (VF adjacency, quality, mark, flags), in float (as
// MeshLab's CMeshO) or double.
template <class Scalar>
struct ScalarComponents {
  static constexpr bool kFloat = std::is_same_v<Scalar, float>;
  template <class T>
  using Coord = std::conditional_t<kFloat, vcg::vertex::Coord3f<T>, vcg::vertex::Coord3d<T>>;
  template <class T>
  using Quality = std::conditional_t<kFloat, vcg::vertex::Qualityf<T>, vcg::vertex::Qualityd<T>>;
};
template <class Scalar>
class GVertex;
template <class Scalar>
class GFace;
template <class Scalar>
struct GTypes
    : vcg::UsedTypes<vcg::Use<GVertex<Scalar>>::template AsVertexType, vcg::Use<GFace<Scalar>>::template AsFaceType> {};
template <class Scalar>
class GVertex
    : public vcg::Vertex<GTypes<Scalar>, ScalarComponents<Scalar>::template Coord, vcg::vertex::VFAdj,
                         ScalarComponents<Scalar>::template Quality, vcg::vertex::Mark, vcg::vertex::BitFlags> {};
template <class Scalar>
class GFace
    : public vcg::Face<GTypes<Scalar>, vcg::face::VertexRef, vcg::face::VFAdj, vcg::face::Mark, vcg::face::BitFlags> {};
template <class Scalar>
class GMesh : public vcg::tri::TriMesh<std::vector<GVertex<Scalar>>, std::vector<GFace<Scalar>>> {};

}  // namespace

std::vector<double> exactGeodesic(const TriMesh& mesh, int source) {
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, SurfaceMesh>;
  using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
  Expected<std::unique_ptr<SurfaceMesh>> sm = toSurfaceMesh(mesh);
  if (!sm) throw std::runtime_error(sm.status().message);
  ShortestPath sp(**sm);
  sp.add_source_point(SmVertex(source));
  std::vector<double> d(mesh.vertexCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) d[v] = sp.shortest_distance_to_source_points(SmVertex(v)).first;
  return d;
}

namespace {

/// A SurfacePoint as CGAL's face location: coordinates in the order source(halfedge(f)),
/// target(halfedge(f)), target(next(halfedge(f))).
template <class ShortestPath>
typename ShortestPath::Face_location cgalLocation(const TriMesh& mesh, const SurfaceMesh& sm, const SurfacePoint& p) {
  if (p.vertex >= 0) return ShortestPath::face_location(SmVertex(p.vertex), sm);
  const SurfaceMesh::Face_index f(static_cast<SurfaceMesh::size_type>(p.face));
  const auto h = sm.halfedge(f);
  const std::array<SmVertex, 3> w = {sm.source(h), sm.target(h), sm.target(sm.next(h))};
  typename ShortestPath::Barycentric_coordinates b{};
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k)
      if (static_cast<int>(w[j].idx()) == mesh.triangles[p.face][k]) b[j] = p.bary[k];
  return {f, b};
}

}  // namespace

std::vector<double> exactGeodesicBetween(const TriMesh& mesh, const SurfacePoint& source,
                                         const std::vector<SurfacePoint>& targets) {
  using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, SurfaceMesh>;
  using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
  Expected<std::unique_ptr<SurfaceMesh>> sm = toSurfaceMesh(mesh);
  if (!sm) throw std::runtime_error(sm.status().message);
  ShortestPath sp(**sm);
  sp.add_source_point(cgalLocation<ShortestPath>(mesh, **sm, source));
  std::vector<double> d;
  d.reserve(targets.size());
  for (const SurfacePoint& t : targets) {
    const auto loc = cgalLocation<ShortestPath>(mesh, **sm, t);
    d.push_back(sp.shortest_distance_to_source_points(loc.first, loc.second).first);
  }
  return d;
}

// ------------------------------------------------------------------------------------------------
// Dijkstra

DijkstraSolver::EdgeGraph DijkstraSolver::buildEdgeGraph(const TriMesh& m) {
  EdgeGraph g;
  const int nv = m.vertexCount();
  g.begin.assign(nv + 1, 0);
  g.neighbour.reserve(m.vertexCorners.size() + nv);
  g.length.reserve(m.vertexCorners.size() + nv);
  std::vector<int> ring;
  for (int v = 0; v < nv; ++v) {
    ring.clear();
    for (const int* it = m.cornersBegin(v); it != m.cornersEnd(v); ++it) {
      ring.push_back(m.vertex(TriMesh::next(*it)));
      ring.push_back(m.vertex(TriMesh::prev(*it)));
    }
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    for (int w : ring) {
      g.neighbour.push_back(w);
      g.length.push_back((m.positions[v] - m.positions[w]).norm());
    }
    g.begin[v + 1] = static_cast<int>(g.neighbour.size());
  }
  return g;
}

DijkstraSolver::DijkstraSolver(const TriMesh& mesh) : g_(buildEdgeGraph(mesh)), d_(g_.vertexCount(), kInf) {
  heap_.reserve(g_.vertexCount());
  touched_.reserve(g_.vertexCount());
}

void DijkstraSolver::reset() {
  for (int v : touched_) d_[v] = kInf;
  touched_.clear();
  heap_.clear();
}

int DijkstraSolver::run(const std::vector<int>& sources) {
  for (int s : sources)
    if (d_[s] != 0.0) set(s, 0.0);
  int reached = 0;
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const Entry e = heap_.back();
    heap_.pop_back();
    if (e.d != d_[e.v]) continue;  // stale
    ++reached;
    relax(e.v, e.d, nullptr);
  }
  return reached;
}

int DijkstraSolver::addSourceIncremental(int s, std::vector<std::pair<int, double>>* undo) {
  if (d_[s] == 0.0) return 0;
  undo->push_back({s, d_[s]});
  set(s, 0.0);
  while (!heap_.empty()) {
    std::pop_heap(heap_.begin(), heap_.end(), Later{});
    const Entry e = heap_.back();
    heap_.pop_back();
    if (e.d != d_[e.v]) continue;
    relax(e.v, e.d, undo);
  }
  return static_cast<int>(undo->size());
}

void DijkstraSolver::undo(const std::vector<std::pair<int, double>>& changes) {
  for (auto it = changes.rbegin(); it != changes.rend(); ++it) d_[it->first] = it->second;
}

void DijkstraSolver::set(int v, double d) {
  if (d_[v] == kInf) touched_.push_back(v);
  d_[v] = d;
  heap_.push_back({d, v});
  std::push_heap(heap_.begin(), heap_.end(), Later{});
}

void DijkstraSolver::relax(int v, double dv, std::vector<std::pair<int, double>>* undo) {
  for (int k = g_.begin[v]; k < g_.begin[v + 1]; ++k) {
    const int w = g_.neighbour[k];
    const double dw = dv + g_.length[k];
    if (dw < d_[w]) {
      if (undo) undo->push_back({w, d_[w]});
      set(w, dw);
    }
  }
}

std::vector<double> dijkstra(const TriMesh& mesh, int source) {
  DijkstraSolver solver(mesh);
  solver.run({source});
  return solver.distance();
}

// ------------------------------------------------------------------------------------------------
// vcglib

template <class Scalar>
struct VcgGeodesic<Scalar>::Impl {
  using Mesh = GMesh<Scalar>;
  Mesh m;
  std::vector<typename Mesh::VertexPointer> seeds;
  vcg::tri::EuclideanDistance<Mesh> metric;
};

template <class Scalar>
VcgGeodesic<Scalar>::VcgGeodesic(const TriMesh& mesh) : impl_(std::make_unique<Impl>()) {
  copyToVcg(mesh, impl_->m);
  vcg::tri::UpdateTopology<typename Impl::Mesh>::VertexFace(impl_->m);
}

template <class Scalar>
VcgGeodesic<Scalar>::~VcgGeodesic() = default;

template <class Scalar>
void VcgGeodesic<Scalar>::setSources(const std::vector<int>& sources) {
  impl_->seeds.clear();
  for (int s : sources) impl_->seeds.push_back(&impl_->m.vert[s]);
}

template <class Scalar>
void VcgGeodesic<Scalar>::compute() {
  vcg::tri::Geodesic<typename Impl::Mesh>::Compute(impl_->m, impl_->seeds, impl_->metric,
                                                   std::numeric_limits<Scalar>::max());
}

template <class Scalar>
std::vector<double> VcgGeodesic<Scalar>::distance() const {
  std::vector<double> d(impl_->m.vert.size());
  for (size_t v = 0; v < d.size(); ++v) {
    const Scalar q = impl_->m.vert[v].cQ();
    d[v] = q == std::numeric_limits<Scalar>::max() ? kInf : double(q);
  }
  return d;
}

template <class Scalar>
Reached VcgGeodesic<Scalar>::reached() const {
  Reached r;
  for (const auto& v : impl_->m.vert)
    if (v.cQ() < std::numeric_limits<Scalar>::max()) {
      ++r.count;
      r.maxDistance = std::max(r.maxDistance, double(v.cQ()));
    }
  return r;
}

template class VcgGeodesic<float>;
template class VcgGeodesic<double>;

std::vector<double> vcgGeodesic(const TriMesh& mesh, int source) {
  VcgGeodesic<double> geodesic(mesh);
  geodesic.setSources({source});
  geodesic.compute();
  return geodesic.distance();
}

// ------------------------------------------------------------------------------------------------
// CGAL heat method

std::vector<double> HeatMesh::distances() const {
  std::vector<double> d(mesh->number_of_vertices());
  for (SmVertex v : mesh->vertices()) d[v.idx()] = distance[v];
  return d;
}

Reached HeatMesh::reached() const {
  Reached r;
  for (SmVertex v : mesh->vertices()) {
    const double d = distance[v];
    if (std::isfinite(d) && d < std::numeric_limits<double>::max()) {
      ++r.count;
      r.maxDistance = std::max(r.maxDistance, d);
    }
  }
  return r;
}

Expected<HeatMesh> toHeatMesh(const TriMesh& mesh) {
  Expected<std::unique_ptr<SurfaceMesh>> sm = toSurfaceMesh(mesh);
  if (!sm) return sm.status();
  HeatMesh h;
  h.mesh = std::move(*sm);
  h.distance = h.mesh->add_property_map<SmVertex, double>("v:gr_distance", 0.0).first;
  return h;
}

struct HeatSolver::Impl {
  using Direct = CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<SurfaceMesh, CGAL::Heat_method_3::Direct>;
  using Idt =
      CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<SurfaceMesh, CGAL::Heat_method_3::Intrinsic_Delaunay>;
  HeatMesh& mesh;
  std::unique_ptr<Direct> direct;  ///< one of the two
  std::unique_ptr<Idt> idt;
  template <class F>
  void visit(F f) {
    if (direct)
      f(*direct);
    else
      f(*idt);
  }
};

HeatSolver::HeatSolver(HeatMesh& mesh, HeatVariant variant) : impl_(std::make_unique<Impl>(Impl{mesh, {}, {}})) {
  if (variant == HeatVariant::Direct)
    impl_->direct = std::make_unique<Impl::Direct>(*mesh.mesh);
  else
    impl_->idt = std::make_unique<Impl::Idt>(*mesh.mesh);
}

HeatSolver::~HeatSolver() = default;

void HeatSolver::clearSources() {
  impl_->visit([](auto& heat) { heat.clear_sources(); });
}

void HeatSolver::addSource(int vertex) {
  impl_->visit([vertex](auto& heat) { heat.add_source(SmVertex(vertex)); });
}

void HeatSolver::solve() {
  impl_->visit([this](auto& heat) { heat.estimate_geodesic_distances(impl_->mesh.distance); });
}

HeatMethod::HeatMethod(const TriMesh& mesh, HeatVariant variant) {
  Expected<HeatMesh> m = toHeatMesh(mesh);
  if (!m) throw std::runtime_error(m.status().message);
  mesh_ = std::move(*m);
  solver_ = std::make_unique<HeatSolver>(mesh_, variant);
}

HeatMethod::~HeatMethod() = default;

std::vector<double> HeatMethod::query(int source) {
  solver_->clearSources();
  solver_->addSource(source);
  solver_->solve();
  return mesh_.distances();
}

}  // namespace gr::oracle
