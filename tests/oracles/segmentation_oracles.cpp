#include "tests/oracles/segmentation_oracles.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <random>

#include <CGAL/Surface_mesh_approximation/approximate_triangle_mesh.h>

#include "tests/oracles/cgal_mesh.h"

namespace gr::oracle {
namespace {

using Face = SurfaceMesh::Face_index;

/// True if Face_index f of `sm` has the vertices of triangle f of `mesh`, in the same cyclic order:
/// the faces were added in order to an empty Surface_mesh, nothing removed, so this holds; checked
/// all the same, since the labels are read back by index.
bool sameFaceOrder(const TriMesh& mesh, const SurfaceMesh& sm) {
  if (static_cast<int>(sm.number_of_faces()) != mesh.faceCount()) return false;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const auto h = sm.halfedge(Face(static_cast<SurfaceMesh::size_type>(f)));
    const int a = static_cast<int>(sm.source(h).idx()), b = static_cast<int>(sm.target(h).idx());
    const Tri& t = mesh.triangles[f];
    int k = 0;
    while (k < 3 && t[k] != a) ++k;
    if (k == 3 || t[(k + 1) % 3] != b) return false;
  }
  return true;
}

}  // namespace

std::vector<int> cgalVsaSegmentation(const TriMesh& mesh, int regions, int iterations) {
  // CGAL honours max_number_of_proxies only below faceCount / 3 (else it uses its own error drop).
  if (regions < 1 || iterations < 0 || regions >= mesh.faceCount() / 3) return {};
  Expected<std::unique_ptr<SurfaceMesh>> copy = toSurfaceMesh(mesh);
  if (!copy) return {};
  SurfaceMesh& sm = **copy;
  if (!sameFaceOrder(mesh, sm)) return {};
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  auto proxyOf = sm.add_property_map<Face, std::size_t>("f:gr_vsa_proxy", kNone).first;
  namespace VSA = CGAL::Surface_mesh_approximation;
  try {
    // The return value says whether the extracted approximating mesh is manifold; no mesh is
    // extracted here (no anchors or triangles asked), so it is false and means nothing.
    VSA::approximate_triangle_mesh(sm, CGAL::parameters::seeding_method(VSA::HIERARCHICAL)
                                           .max_number_of_proxies(static_cast<std::size_t>(regions))
                                           .number_of_iterations(static_cast<std::size_t>(iterations))
                                           .face_proxy_map(proxyOf));
  } catch (...) {
    return {};
  }
  std::vector<int> label(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const std::size_t p = proxyOf[Face(static_cast<SurfaceMesh::size_type>(f))];
    if (p >= static_cast<std::size_t>(regions)) return {};
    label[f] = static_cast<int>(p);
  }
  return label;
}

namespace {

struct WeightedPoints {
  std::vector<Vec3> x;       ///< face centroids
  std::vector<double> area;  ///< face areas
};

WeightedPoints faceCentroids(const TriMesh& mesh) {
  WeightedPoints w;
  w.x.reserve(mesh.faceCount());
  w.area.reserve(mesh.faceCount());
  for (const Tri& t : mesh.triangles) {
    const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
    w.x.push_back((a + b + c) / 3.0);
    w.area.push_back(0.5 * (b - a).cross(c - a).norm());
  }
  return w;
}

/// An index drawn with probability weight[i] / sum, from the generator's raw 32-bit output (not a
/// std distribution, whose algorithm each standard library chooses). -1 if every weight is 0.
int drawIndex(const std::vector<double>& weight, std::mt19937& rng) {
  double total = 0.0;
  for (double v : weight) total += v;
  if (!(total > 0.0)) return -1;
  const double u = (static_cast<double>(rng()) + 0.5) / 4294967296.0 * total;
  double sum = 0.0;
  int last = -1;
  for (int i = 0; i < static_cast<int>(weight.size()); ++i) {
    if (weight[i] <= 0.0) continue;
    sum += weight[i];
    last = i;
    if (sum > u) return i;
  }
  return last;  // rounding: u beyond the accumulated sum
}

/// Area-weighted k-means++: k distinct faces' centroids.
std::vector<Vec3> kmeansPlusPlus(const WeightedPoints& w, int k, std::mt19937& rng) {
  const int n = static_cast<int>(w.x.size());
  std::vector<Vec3> centres;
  std::vector<char> chosen(n, 0);
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity()), weight(w.area);
  while (static_cast<int>(centres.size()) < k) {
    int pick = drawIndex(weight, rng);
    if (pick < 0) pick = static_cast<int>(std::find(chosen.begin(), chosen.end(), 0) - chosen.begin());
    chosen[pick] = 1;
    centres.push_back(w.x[pick]);
    for (int i = 0; i < n; ++i) {
      nearest[i] = std::min(nearest[i], (w.x[i] - w.x[pick]).squaredNorm());
      weight[i] = chosen[i] ? 0.0 : w.area[i] * nearest[i];
    }
  }
  return centres;
}

/// Assigns every point to its nearest centre (the lower index on a tie); returns whether a label
/// changed. dist2 receives each point's squared distance to its centre.
bool assignNearest(const WeightedPoints& w, const std::vector<Vec3>& centres, std::vector<int>& label,
                   std::vector<double>& dist2) {
  bool changed = false;
  for (std::size_t i = 0; i < w.x.size(); ++i) {
    int best = 0;
    double bestD = std::numeric_limits<double>::infinity();
    for (int c = 0; c < static_cast<int>(centres.size()); ++c) {
      const double d = (w.x[i] - centres[c]).squaredNorm();
      if (d < bestD) bestD = d, best = c;
    }
    changed |= label[i] != best;
    label[i] = best;
    dist2[i] = bestD;
  }
  return changed;
}

/// Moves, for each empty cluster, the point of largest area * squared distance (in a cluster of
/// two or more points) into it. Returns whether any cluster was empty.
bool refillEmptyClusters(const WeightedPoints& w, int k, std::vector<int>& label, std::vector<double>& dist2) {
  std::vector<int> count(k, 0);
  for (int l : label) ++count[l];
  bool any = false;
  for (int c = 0; c < k; ++c) {
    if (count[c] > 0) continue;
    int far = -1;
    for (std::size_t i = 0; i < label.size(); ++i)
      if (count[label[i]] > 1 && (far < 0 || w.area[i] * dist2[i] > w.area[far] * dist2[far]))
        far = static_cast<int>(i);
    --count[label[far]];  // k <= points, so some cluster has two or more points
    label[far] = c;
    count[c] = 1;
    dist2[far] = 0.0;
    any = true;
  }
  return any;
}

/// Each centre moved to the area-weighted mean of its cluster (kept if the cluster has no area).
void updateCentres(const WeightedPoints& w, const std::vector<int>& label, std::vector<Vec3>& centres) {
  std::vector<Vec3> sum(centres.size(), Vec3::Zero());
  std::vector<double> mass(centres.size(), 0.0);
  for (std::size_t i = 0; i < label.size(); ++i) {
    sum[label[i]] += w.area[i] * w.x[i];
    mass[label[i]] += w.area[i];
  }
  for (std::size_t c = 0; c < centres.size(); ++c)
    if (mass[c] > 0.0) centres[c] = sum[c] / mass[c];
}

}  // namespace

std::vector<int> kmeansFaceCentroids(const TriMesh& mesh, int k, unsigned seed, int iterations) {
  if (k < 1 || k > mesh.faceCount()) return {};
  const WeightedPoints w = faceCentroids(mesh);
  std::mt19937 rng(seed);
  std::vector<Vec3> centres = kmeansPlusPlus(w, k, rng);
  std::vector<int> label(mesh.faceCount(), -1);
  std::vector<double> dist2(mesh.faceCount(), 0.0);
  for (int it = 0; it < std::max(iterations, 1); ++it) {
    bool changed = assignNearest(w, centres, label, dist2);
    changed |= refillEmptyClusters(w, k, label, dist2);
    if (!changed) break;
    updateCentres(w, label, centres);
  }
  return label;
}

}  // namespace gr::oracle
