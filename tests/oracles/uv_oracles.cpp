#include "tests/oracles/uv_oracles.h"

#include "tests/oracles/cgal_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace gr::oracle {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;

P2 point(const Eigen::Vector2d& p) { return P2(p.x(), p.y()); }

/// Segments ab and cd cross at one point interior to both.
bool properCrossing(const P2& a, const P2& b, const P2& c, const P2& d) {
  const auto o1 = CGAL::orientation(a, b, c), o2 = CGAL::orientation(a, b, d);
  const auto o3 = CGAL::orientation(c, d, a), o4 = CGAL::orientation(c, d, b);
  return o1 != CGAL::COLLINEAR && o2 != CGAL::COLLINEAR && o1 != o2 && o3 != CGAL::COLLINEAR && o4 != CGAL::COLLINEAR &&
         o3 != o4;
}

/// p strictly inside the counter-clockwise triangle t.
bool strictlyInside(const P2& p, const std::array<P2, 3>& t) {
  for (int k = 0; k < 3; ++k)
    if (CGAL::orientation(t[k], t[(k + 1) % 3], p) != CGAL::LEFT_TURN) return false;
  return true;
}

/// The centroid test catches two equal triangles (no proper crossing, no corner strictly inside).
bool interiorsMeet(const std::array<P2, 3>& s, const std::array<P2, 3>& t) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (properCrossing(s[i], s[(i + 1) % 3], t[j], t[(j + 1) % 3])) return true;
  for (int k = 0; k < 3; ++k)
    if (strictlyInside(s[k], t) || strictlyInside(t[k], s)) return true;
  const P2 cs = CGAL::centroid(s[0], s[1], s[2]), ct = CGAL::centroid(t[0], t[1], t[2]);
  return strictlyInside(cs, t) || strictlyInside(ct, s);
}

}  // namespace

UvAtlasCheck checkUvAtlas(const std::vector<std::array<Eigen::Vector2d, 3>>& triangles) {
  UvAtlasCheck r;
  std::vector<std::array<P2, 3>> valid;
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  double size = 0.0;
  for (const auto& t : triangles) {
    for (const auto& q : t) r.outsideUnitSquare += !(q.x() >= 0.0 && q.x() <= 1.0 && q.y() >= 0.0 && q.y() <= 1.0);
    const std::array<P2, 3> p = {point(t[0]), point(t[1]), point(t[2])};
    const auto o = CGAL::orientation(p[0], p[1], p[2]);
    if (o == CGAL::COLLINEAR) {
      ++r.zeroArea;
    } else if (o == CGAL::RIGHT_TURN) {
      ++r.flipped;
    } else {
      valid.push_back(p);
      for (const auto& q : t) {
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
      }
      size += (t[1] - t[0]).norm();
    }
  }
  if (valid.size() < 2) return r;
  const double cell = std::max({size / valid.size(), (hi.x() - lo.x()) / 8192.0, (hi.y() - lo.y()) / 8192.0});
  std::unordered_map<long long, std::vector<int>> grid;
  for (int i = 0; i < static_cast<int>(valid.size()); ++i) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const P2& q : valid[i]) {
      x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x()), y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
    }
    std::vector<int> tested;
    for (long a = static_cast<long>((x0 - lo.x()) / cell); a <= static_cast<long>((x1 - lo.x()) / cell); ++a)
      for (long b = static_cast<long>((y0 - lo.y()) / cell); b <= static_cast<long>((y1 - lo.y()) / cell); ++b) {
        std::vector<int>& bucket = grid[a * 1000003LL + b];
        for (int j : bucket) {
          if (std::find(tested.begin(), tested.end(), j) != tested.end()) continue;
          tested.push_back(j);
          r.overlaps += interiorsMeet(valid[i], valid[j]);
        }
        bucket.push_back(i);
      }
  }
  return r;
}

std::vector<Eigen::Vector2d> cgalLscm(const TriMesh& patch) {
  namespace SMP = CGAL::Surface_mesh_parameterization;
  Expected<std::unique_ptr<SurfaceMesh>> sm = toSurfaceMesh(patch);
  if (!sm) return {};
  SurfaceMesh& mesh = **sm;
  const auto border = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  if (border == SurfaceMesh::null_halfedge()) return {};
  auto uvMap = mesh.add_property_map<SmVertex, K::Point_2>("v:gr_uv").first;
  using Parameterizer = SMP::LSCM_parameterizer_3<SurfaceMesh>;
  try {
    if (SMP::parameterize(mesh, Parameterizer(), border, uvMap) != SMP::OK) return {};
  } catch (...) {
    return {};
  }
  std::vector<Eigen::Vector2d> uv(patch.vertexCount());
  for (SmVertex v : mesh.vertices()) uv[v.idx()] = Eigen::Vector2d(uvMap[v].x(), uvMap[v].y());
  return uv;
}

}  // namespace gr::oracle
