#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numeric>
#include <random>
#include <set>

#include "core/base/math.h"
#include "core/mesh/vcg_mesh.h"

namespace gr::test {

std::string meshPath(const std::string& name) { return std::string(GR_MESH_DIR) + "/" + name; }

std::vector<std::string> dataSetMeshFiles() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(GR_MESH_DIR, error)) {
    const std::string name = entry.path().filename().string(), ext = entry.path().extension().string();
    if ((ext == ".off" || ext == ".ply" || ext == ".stl" || ext == ".obj") && name != "prim.off") names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  if (names.empty()) names.push_back("(no mesh found in " + std::string(GR_MESH_DIR) + ": run scripts/setup.sh)");
  return names;
}

std::string testNameOfFile(const std::string& file) {
  std::string n;
  for (char ch : file) n += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
  return n;
}

void expectValidWithTopologyOf(const Recount& out, const Recount& in) {
  EXPECT_TRUE(out.manifoldEdges && out.manifoldVertices && out.oriented);
  EXPECT_EQ(out.isolated, 0);
  EXPECT_EQ(out.components, in.components);
  EXPECT_EQ(out.genusSum, in.genusSum);
  EXPECT_EQ(out.boundaryLoops, in.boundaryLoops);
}

TriMesh loadRealMesh(const std::string& name) {
  Expected<TriMesh> m = loadTriMesh(meshPath(name));
  if (!m) {
    ADD_FAILURE() << "cannot load " << name << ": " << m.status().message
                  << " (run scripts/setup.sh to fetch the test meshes)";
    return {};
  }
  return std::move(m).value();
}

TriMesh planeGrid(int n, double size, double jitter, unsigned seed) {
  std::vector<Vec3> pos;
  std::vector<Tri> tris;
  const double h = size / n;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      Vec3 p(i * h, j * h, 0.0);
      if (jitter > 0 && i > 0 && j > 0 && i < n && j < n) p += Vec3(u(rng), u(rng), 0.0) * jitter * h;
      pos.push_back(p);
    }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return std::move(buildTriMesh(std::move(pos), std::move(tris))).value();
}

TriMesh gridsMeetingAtACorner(int n) {
  const TriMesh grid = planeGrid(n);
  const int count = grid.vertexCount(), corner = count - 1;  // the grid's vertex at (1, 1)
  std::vector<Vec3> positions = grid.positions;
  for (const Vec3& p : grid.positions) positions.push_back(Vec3(2, 2, 0) - p);
  std::vector<Tri> triangles = grid.triangles;
  for (Tri t : grid.triangles) {
    for (int& v : t) v = v == corner ? corner : v + count;
    triangles.push_back(t);
  }
  return std::move(buildTriMesh(std::move(positions), std::move(triangles))).value();
}

TriMesh unitCube() {
  std::vector<Vec3> p;
  for (int i = 0; i < 8; ++i) p.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  std::vector<Tri> t = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                        {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return std::move(buildTriMesh(std::move(p), std::move(t))).value();
}

TriMesh icosphere(int level, double r) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> pos = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  std::vector<Tri> tris = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                           {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                           {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (Vec3& p : pos) p.normalize();
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      pos.push_back((pos[a] + pos[b]).normalized());
      return mid[key] = static_cast<int>(pos.size()) - 1;
    };
    std::vector<Tri> next;
    for (const Tri& f : tris) {
      const int a = midpoint(f[0], f[1]), b = midpoint(f[1], f[2]), c = midpoint(f[2], f[0]);
      next.push_back({f[0], a, c});
      next.push_back({f[1], b, a});
      next.push_back({f[2], c, b});
      next.push_back({a, b, c});
    }
    tris.swap(next);
  }
  for (Vec3& p : pos) p *= r;
  return std::move(buildTriMesh(std::move(pos), std::move(tris))).value();
}

}  // namespace gr::test

namespace gr::test {

TriMesh cylinder(int nTheta, int nZ, double r, double h) {
  std::vector<Vec3> pos;
  std::vector<Tri> tris;
  for (int j = 0; j <= nZ; ++j)
    for (int i = 0; i < nTheta; ++i) {
      const double t = 2.0 * kPi * i / nTheta;
      pos.emplace_back(r * std::cos(t), r * std::sin(t), h * j / nZ);
    }
  auto id = [nTheta](int i, int j) { return j * nTheta + (i % nTheta); };
  for (int j = 0; j < nZ; ++j)
    for (int i = 0; i < nTheta; ++i) {
      tris.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return std::move(buildTriMesh(std::move(pos), std::move(tris))).value();
}

TriMesh moebiusStrip(int n) {
  std::vector<Vec3> pos;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * i / n, half = t / 2;
    const Vec3 centre(std::cos(t), std::sin(t), 0.0);
    const Vec3 across = 0.3 * (std::cos(half) * Vec3(std::cos(t), std::sin(t), 0.0) + std::sin(half) * Vec3(0, 0, 1));
    pos.push_back(centre - across);
    pos.push_back(centre + across);
  }
  std::vector<Tri> t;
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    // The last quad joins side a of the last section to side b of the first one (the twist).
    const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    t.push_back({a, c, b});
    t.push_back({b, c, d});
  }
  return std::move(buildTriMesh(std::move(pos), std::move(t))).value();
}

TriMesh uvSphere(int nLat, int nLon, double r) {
  std::vector<Vec3> pos;
  std::vector<Tri> tris;
  pos.emplace_back(0, 0, r);  // north pole: 0
  for (int j = 1; j < nLat; ++j)
    for (int i = 0; i < nLon; ++i) {
      const double th = kPi * j / nLat, ph = 2.0 * kPi * i / nLon;
      pos.emplace_back(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
  pos.emplace_back(0, 0, -r);  // south pole
  const int south = static_cast<int>(pos.size()) - 1;
  auto id = [nLon](int i, int j) { return 1 + (j - 1) * nLon + (i % nLon); };
  for (int i = 0; i < nLon; ++i) {
    tris.push_back({0, id(i, 1), id(i + 1, 1)});
    tris.push_back({south, id(i + 1, nLat - 1), id(i, nLat - 1)});
  }
  for (int j = 1; j < nLat - 1; ++j)
    for (int i = 0; i < nLon; ++i) {
      tris.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      tris.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  return std::move(buildTriMesh(std::move(pos), std::move(tris))).value();
}

}  // namespace gr::test

namespace gr::test {

namespace {

using EdgeCounts = std::map<std::pair<int, int>, int>;

/// Edges: undirected ones by their number of faces (boundary, non-manifold), directed ones for the
/// orientation (every directed edge once; a two-face edge run the same way by both faces).
void recountEdges(const EdgeCounts& undirected, const EdgeCounts& directed, Recount& r) {
  for (const auto& [e, n] : directed)
    if (n > 1) r.oriented = false;
  for (const auto& [e, n] : undirected) {
    if (n != 2) r.closedManifoldEdges = false;
    if (n > 2) r.manifoldEdges = false;
    r.boundaryEdges += n == 1;
    r.nonManifoldEdges += n > 2;
    if (n == 2) {
      const auto ab = directed.find(e);
      if (ab == directed.end() || ab->second != 1) ++r.inconsistentEdges;
    }
  }
}

/// True if the link of a vertex (the edges opposite to it) is one cycle (interior vertex) or one
/// path (boundary vertex): connected, degrees <= 2, and zero or two ends.
bool linkIsOneCycleOrPath(const std::vector<std::pair<int, int>>& link) {
  std::map<int, std::vector<int>> adj;
  for (const auto& [a, b] : link) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  bool ok = true;
  int ends = 0;
  for (const auto& [a, n] : adj) {
    ok = ok && n.size() <= 2;
    ends += n.size() == 1;
  }
  ok = ok && (ends == 0 || ends == 2);
  std::set<int> seen = {adj.begin()->first};
  std::vector<int> stack = {adj.begin()->first};
  while (!stack.empty()) {
    const int a = stack.back();
    stack.pop_back();
    for (int b : adj[a])
      if (seen.insert(b).second) stack.push_back(b);
  }
  return ok && seen.size() == adj.size();
}

/// Union-find with path halving over `parent`.
int findRoot(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

/// The boundary (edges with one face) is a disjoint union of simple loops: every vertex starts as
/// many boundary half-edges as it ends, at most one.
bool boundaryIsSimpleLoops(const EdgeCounts& undirected, const EdgeCounts& directed) {
  std::map<int, int> out, in;
  for (const auto& [d, n] : directed)
    if (undirected.at(std::minmax(d.first, d.second)) == 1) {
      out[d.first] += n;
      in[d.second] += n;
    }
  for (const auto& [v, n] : out)
    if (n != 1 || in[v] != 1) return false;
  for (const auto& [v, n] : in)
    if (n != 1 || out[v] != 1) return false;
  return true;
}

}  // namespace

Recount recount(const std::vector<Tri>& tris, int nv) {
  Recount r;
  EdgeCounts undirected, directed;
  for (const Tri& t : tris)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      ++undirected[std::minmax(a, b)];
      ++directed[{a, b}];
    }
  recountEdges(undirected, directed, r);
  r.simpleBoundary = boundaryIsSimpleLoops(undirected, directed);
  // Link of each vertex: the edges opposite to it.
  std::vector<std::vector<std::pair<int, int>>> link(nv);
  for (const Tri& t : tris)
    for (int k = 0; k < 3; ++k) link[t[k]].push_back({t[(k + 1) % 3], t[(k + 2) % 3]});
  for (int v = 0; v < nv; ++v) {
    if (link[v].empty()) {
      ++r.isolated;
    } else if (!linkIsOneCycleOrPath(link[v])) {
      r.manifoldVertices = false;
      ++r.nonManifoldVertices;
    }
  }
  // Components (union-find over faces' vertices) and genus from chi = V - E + F = 2 - 2g.
  std::vector<int> parent(nv);
  std::iota(parent.begin(), parent.end(), 0);
  for (const Tri& t : tris) {
    parent[findRoot(parent, t[0])] = findRoot(parent, t[1]);
    parent[findRoot(parent, t[1])] = findRoot(parent, t[2]);
  }
  std::map<int, long> chi;
  for (int v = 0; v < nv; ++v)
    if (!link[v].empty()) ++chi[findRoot(parent, v)];
  for (const auto& [e, n] : undirected) chi[findRoot(parent, e.first)] -= 1;
  for (const Tri& t : tris) chi[findRoot(parent, t[0])] += 1;
  // Boundary loops: boundary edges joined at shared endpoints (union-find of their own).
  std::vector<int> loop(nv);
  std::iota(loop.begin(), loop.end(), 0);
  std::set<int> boundaryVertices;
  std::map<int, int> loopsOfComponent;
  for (const auto& [e, n] : undirected)
    if (n == 1) {
      loop[findRoot(loop, e.first)] = findRoot(loop, e.second);
      boundaryVertices.insert(e.first);
      boundaryVertices.insert(e.second);
    }
  std::set<int> loopRoots;
  for (int v : boundaryVertices)
    if (loopRoots.insert(findRoot(loop, v)).second) ++loopsOfComponent[findRoot(parent, v)];
  r.boundaryLoops = static_cast<int>(loopRoots.size());
  r.components = static_cast<int>(chi.size());
  for (const auto& [root, c] : chi) {
    r.eulerCharacteristic += static_cast<int>(c);
    r.genusSum += static_cast<int>((2 - c - loopsOfComponent[root]) / 2);
  }
  // Component labels: the rank of the component's root among the roots.
  std::map<int, int> labelOfRoot;
  for (const auto& [root, c] : chi) labelOfRoot.emplace(root, static_cast<int>(labelOfRoot.size()));
  r.componentOfVertex.assign(nv, -1);
  for (int v = 0; v < nv; ++v)
    if (!link[v].empty()) r.componentOfVertex[v] = labelOfRoot.at(findRoot(parent, v));
  return r;
}

}  // namespace gr::test

namespace gr::test {

int numberBefore(const std::string& log, const std::string& words) {
  const size_t at = log.find(words);
  if (at == std::string::npos || at < 2) return -1000;
  size_t start = log.rfind(' ', at - 2);
  start = start == std::string::npos ? 0 : start + 1;
  return std::atoi(log.substr(start, at - start).c_str());
}

TriMesh withBadTriangles(const TriMesh& m, int* zeroAreaFaces) {
  std::vector<Vec3> pos = m.positions;
  std::vector<Tri> tris = m.triangles;
  std::vector<char> used(m.faceCount(), 0);
  *zeroAreaFaces = 0;
  bool needle = true;
  for (int c = 0; c < 3 * m.faceCount(); c += 12 * 3 + 1) {
    const int o = m.oppositeCorner[c];
    const int f = TriMesh::face(c);
    if (o < 0 || used[f] || used[TriMesh::face(o)]) continue;
    used[f] = used[TriMesh::face(o)] = 1;
    const int C = m.vertex(c), a = m.vertex(TriMesh::next(c)), b = m.vertex(TriMesh::prev(c)), D = m.vertex(o);
    const int mid = static_cast<int>(pos.size());
    if (needle) {
      pos.push_back(m.positions[a] + 0.002 * (m.positions[b] - m.positions[a]));
      tris[f] = {C, a, mid};
      tris.push_back({C, mid, b});
      tris[TriMesh::face(o)] = {D, b, mid};
      tris.push_back({D, mid, a});
    } else {
      pos.push_back(0.5 * (m.positions[a] + m.positions[b]));
      tris[TriMesh::face(o)] = {b, a, mid};  // zero area
      tris.push_back({b, mid, D});
      tris.push_back({mid, a, D});
      ++*zeroAreaFaces;
    }
    needle = !needle;
  }
  return std::move(buildTriMesh(pos, tris)).value();
}

AngleRecount recountAngles(const TriMesh& mesh) {
  AngleRecount r;
  int below30 = 0;
  for (const Tri& t : mesh.triangles) {
    double minAngle = 180.0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = mesh.positions[t[(k + 1) % 3]] - mesh.positions[t[k]];
      const Vec3 w = mesh.positions[t[(k + 2) % 3]] - mesh.positions[t[k]];
      const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / kPi;
      minAngle = std::min(minAngle, angle);
      r.largestDegrees = std::max(r.largestDegrees, angle);
    }
    r.smallestDegrees = std::min(r.smallestDegrees, minAngle);
    below30 += minAngle < 30.0;
  }
  r.shareBelow30 = mesh.faceCount() > 0 ? double(below30) / mesh.faceCount() : 0.0;
  return r;
}

}  // namespace gr::test
