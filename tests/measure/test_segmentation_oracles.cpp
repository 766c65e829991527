// The segmentation's competitors (tests/oracles/segmentation_oracles.h), CGAL's VSA and face-centroid
// k-means, on bunny00 and fandisk: one label per face, every label in range and used, and the
// shape figures the segmentation is compared with, printed as anchors (regions that are not
// edge-connected topological disks, area coefficient of variation, mean isoperimetric quotient).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "tests/oracles/segmentation_oracles.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

double faceArea(const TriMesh& m, int f) {
  const Tri& t = m.triangles[f];
  return 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
}

/// Shape of a partition of the faces: per region its faces, edge-connected pieces (faces joined
/// across an edge, TriMesh::oppositeCorner), Euler characteristic V - E + F of its faces, boundary
/// loops (connected components of its boundary edges: edges whose other face is in another region
/// or absent, so the mesh boundary included), area and perimeter (length of those edges).
struct RegionShape {
  int regions = 0;
  int nonDisks = 0;        ///< regions that are not 1 piece with chi = 1 and 1 boundary loop
  int disconnected = 0;    ///< regions of two or more pieces
  double totalArea = 0.0;  ///< sum of the regions' areas
  double areaCv = 0.0;     ///< standard deviation / mean of the regions' areas
  double meanIq = 0.0;     ///< mean over regions of 4 pi A / P^2
  int smallestRegion = 0;  ///< fewest faces in a region
};

struct PerRegion {
  std::vector<int> faces, pieces, vertices, boundaryEdges, loops;
  std::vector<double> interiorHalfEdges, area, perimeter;
  explicit PerRegion(int n)
      : faces(n), pieces(n), vertices(n), boundaryEdges(n), loops(n), interiorHalfEdges(n), area(n), perimeter(n) {}
};

/// Fills faces, pieces, area, perimeter, edge counts of each region; returns the boundary edges as
/// (region, vertex) pairs of their ends.
std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>> countFacesAndEdges(const TriMesh& m,
                                                                                    const std::vector<int>& label,
                                                                                    PerRegion& r) {
  std::vector<std::pair<std::pair<int, int>, std::pair<int, int>>> boundary;
  UnionFind faces(m.faceCount());
  for (int c = 0; c < 3 * m.faceCount(); ++c) {
    const int f = TriMesh::face(c), region = label[f], opp = m.oppositeCorner[c];
    const int a = m.vertex(TriMesh::next(c)), b = m.vertex(TriMesh::prev(c));
    if (opp >= 0 && label[TriMesh::face(opp)] == region) {
      r.interiorHalfEdges[region] += 1.0;
      faces.unite(f, TriMesh::face(opp));
      continue;
    }
    ++r.boundaryEdges[region];
    r.perimeter[region] += (m.positions[a] - m.positions[b]).norm();
    boundary.push_back({{region, a}, {region, b}});
  }
  for (int f = 0; f < m.faceCount(); ++f) {
    ++r.faces[label[f]];
    r.area[label[f]] += faceArea(m, f);
    if (faces.find(f) == f) ++r.pieces[label[f]];
  }
  return boundary;
}

RegionShape regionShape(const TriMesh& m, const std::vector<int>& label) {
  RegionShape s;
  s.regions = *std::max_element(label.begin(), label.end()) + 1;
  PerRegion r(s.regions);
  const auto boundary = countFacesAndEdges(m, label, r);
  // Vertices of each region: the distinct (region, vertex) pairs; boundary loops by union-find on them.
  std::vector<std::pair<int, int>> corners;
  for (int c = 0; c < 3 * m.faceCount(); ++c) corners.push_back({label[TriMesh::face(c)], m.vertex(c)});
  std::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  for (const auto& rv : corners) ++r.vertices[rv.first];
  const auto index = [&](const std::pair<int, int>& rv) {
    return static_cast<int>(std::lower_bound(corners.begin(), corners.end(), rv) - corners.begin());
  };
  UnionFind loops(static_cast<int>(corners.size()));
  std::vector<char> onBoundary(corners.size(), 0);
  for (const auto& [a, b] : boundary) {
    loops.unite(index(a), index(b));
    onBoundary[index(a)] = onBoundary[index(b)] = 1;
  }
  for (int i = 0; i < static_cast<int>(corners.size()); ++i)
    if (onBoundary[i] && loops.find(i) == i) ++r.loops[corners[i].first];
  double sum = 0.0, sum2 = 0.0, iq = 0.0;
  s.smallestRegion = m.faceCount();
  for (int k = 0; k < s.regions; ++k) {
    const int edges = static_cast<int>(std::lround(r.interiorHalfEdges[k] / 2.0)) + r.boundaryEdges[k];
    const int chi = r.vertices[k] - edges + r.faces[k];
    s.nonDisks += r.pieces[k] != 1 || chi != 1 || r.loops[k] != 1;
    s.disconnected += r.pieces[k] > 1;
    s.smallestRegion = std::min(s.smallestRegion, r.faces[k]);
    sum += r.area[k];
    sum2 += r.area[k] * r.area[k];
    if (r.perimeter[k] > 0.0) iq += 4.0 * M_PI * r.area[k] / (r.perimeter[k] * r.perimeter[k]);
  }
  const double mean = sum / s.regions;
  s.totalArea = sum;
  s.areaCv = std::sqrt(std::max(0.0, sum2 / s.regions - mean * mean)) / mean;
  s.meanIq = iq / s.regions;
  return s;
}

/// EXPECTs one label per face in [0, asked), the labels used being [0, p) with p >= minShare * asked.
void expectLabelsCover(const TriMesh& m, const std::vector<int>& label, int asked, double minShare) {
  ASSERT_EQ(static_cast<int>(label.size()), m.faceCount());
  std::vector<int> count(asked, 0);
  for (int l : label) {
    ASSERT_GE(l, 0);
    ASSERT_LT(l, asked);
    ++count[l];
  }
  const int used = static_cast<int>(std::count_if(count.begin(), count.end(), [](int c) { return c > 0; }));
  const int p = *std::max_element(label.begin(), label.end()) + 1;
  EXPECT_EQ(used, p) << "labels not contiguous";
  EXPECT_GE(used, static_cast<int>(std::ceil(minShare * asked)));
}

double meshArea(const TriMesh& m) {
  double a = 0.0;
  for (int f = 0; f < m.faceCount(); ++f) a += faceArea(m, f);
  return a;
}

void print(const char* mesh, const char* method, int asked, const RegionShape& s, double seconds) {
  std::printf(
      "%-8s %-6s asked %4d got %4d | non-disk %3d (disconnected %3d) | area CV %.3f | mean IQ %.3f | "
      "smallest %4d faces | %.2f s\n",
      mesh, method, asked, s.regions, s.nonDisks, s.disconnected, s.areaCv, s.meanIq, s.smallestRegion, seconds);
}

template <typename F>
std::pair<std::vector<int>, double> timed(F&& run) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<int> label = run();
  return {std::move(label), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
}

void checkAndReport(const std::string& name, const std::vector<int>& counts) {
  const TriMesh m = test::loadRealMesh(name);
  ASSERT_GT(m.faceCount(), 0);
  const double area = meshArea(m);
  for (int n : counts) {
    SCOPED_TRACE(name + " at " + std::to_string(n) + " regions");
    const auto [vsa, vsaSeconds] = timed([&] { return oracle::cgalVsaSegmentation(m, n); });
    ASSERT_FALSE(vsa.empty()) << "CGAL VSA failed";
    expectLabelsCover(m, vsa, n, 0.9);
    const RegionShape v = regionShape(m, vsa);
    // CGAL grows each proxy from its seed over face adjacency: a proxy that is not edge-connected
    // (on a one-component mesh) would mean the labels were read back in the wrong face order.
    if (m.topology.components == 1) {
      EXPECT_EQ(v.disconnected, 0);
    }
    print(name.c_str(), "VSA", n, v, vsaSeconds);

    const auto [km, kmSeconds] = timed([&] { return oracle::kmeansFaceCentroids(m, n); });
    expectLabelsCover(m, km, n, 1.0);
    const RegionShape k = regionShape(m, km);
    EXPECT_NEAR(k.totalArea, area, 1e-9 * area);
    print(name.c_str(), "kmeans", n, k, kmSeconds);
  }
}

TEST(SegmentationOracles, Bunny00) { checkAndReport("bunny00.off", {100, 500}); }

TEST(SegmentationOracles, Fandisk) { checkAndReport("fandisk.off", {20, 50}); }

TEST(SegmentationOracles, KmeansIsDeterministicAndRefusesBadCounts) {
  const TriMesh m = test::icosphere(2);
  EXPECT_EQ(oracle::kmeansFaceCentroids(m, 12, 7), oracle::kmeansFaceCentroids(m, 12, 7));
  EXPECT_TRUE(oracle::kmeansFaceCentroids(m, 0).empty());
  EXPECT_TRUE(oracle::kmeansFaceCentroids(m, m.faceCount() + 1).empty());
  // Every face its own cluster: all labels used.
  std::vector<int> all = oracle::kmeansFaceCentroids(m, m.faceCount());
  std::sort(all.begin(), all.end());
  EXPECT_EQ(std::unique(all.begin(), all.end()) - all.begin(), m.faceCount());
  EXPECT_TRUE(oracle::cgalVsaSegmentation(m, m.faceCount() / 3).empty());
}

}  // namespace
}  // namespace gr
