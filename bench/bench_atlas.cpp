// Texture atlas benchmarks (issue 19):
//   Atlas/<mesh>            gr::buildTextureAtlas with the defaults (what the filter runs): the
//                           segmentation, per-chart geodesic LLE, packing. Process CPU time.
//   MeshLabVoronoiAtlas/<mesh>  MeshLab 2020.09's "Parametrization: Voronoi Atlas" through the system
//                           meshlabserver (xvfb-run, wall time of the whole process: start, plugin
//                           loading, reading and writing included), regionNum = our chart count;
//                           its atlas is a new layer, saved once the input layer is deleted.
//   BlenderSmartUv/<mesh>   Blender 3.4's Smart UV Project with its defaults (system blender -b,
//                           bench/blender_smart_uv.py): wall time of the whole process, and the
//                           operator's own time as the counter `operator_s`; skipped when blender
//                           is not installed. Its charts are counted on the output (faces joined
//                           across an edge whose two ends keep their UVs).
// Meshes: fandisk, bunny00, and bunny00 subdivided twice (1-to-4 midpoint, 602,690 vertices; one
// iteration). Counters, for both, measured the same way on the output's per-corner UVs: charts,
// L2 stretch and mean conformal distortion (gr::measureUvDistortion), packing (UV area / unit
// square), and the oracle's flipped and overlapping triangles (tests/oracles/uv_oracles.h); for
// ours also, per chart, the conformal distortion over CGAL's LSCM's on the same chart.
#include <benchmark/benchmark.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_support.h"
#include "core/atlas/texture_atlas.h"
#include "tests/oracles/uv_oracles.h"

namespace {

struct Case {
  const char* name;
  const char* file;
  int subdivisions;
};

const Case kCases[] = {
    {"fandisk", "fandisk.off", 0}, {"bunny00", "bunny00.off", 0}, {"bunny00_sub2", "bunny00.off", 2}};

void setUvCounters(benchmark::State& state, const gr::TriMesh& mesh, const std::vector<gr::Vec2>& cornerUv,
                   int charts) {
  const gr::UvDistortion d = gr::measureUvDistortion(mesh, cornerUv);
  std::vector<std::array<Eigen::Vector2d, 3>> triangles(mesh.faceCount());
  double area = 0.0;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    for (int k = 0; k < 3; ++k) triangles[f][k] = cornerUv[3 * f + k];
    const Eigen::Vector2d a = triangles[f][1] - triangles[f][0], b = triangles[f][2] - triangles[f][0];
    area += 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
  }
  const gr::oracle::UvAtlasCheck c = gr::oracle::checkUvAtlas(triangles);
  state.counters["vertices"] = mesh.vertexCount();
  state.counters["charts"] = charts;
  state.counters["stretch"] = d.stretchL2;
  state.counters["conformal"] = d.conformalMean;
  state.counters["packing"] = area;
  state.counters["flipped"] = c.flipped + c.zeroArea;
  state.counters["overlaps"] = static_cast<double>(c.overlaps);
}

int lastCharts(const std::string& name, int charts = -1) {
  static std::map<std::string, int> count;
  if (charts >= 0) count[name] = charts;
  return count.count(name) ? count[name] : 60;
}

/// Per chart (untimed): our conformal distortion over CGAL's LSCM's on the same chart. Counters
/// `lscm_worst` (the largest ratio) and `lscm_within_1_5` (share of charts at most 1.5x LSCM's).
void compareWithLscm(benchmark::State& state, const gr::TriMesh& mesh, const gr::AtlasResult& r) {
  std::vector<std::vector<int>> facesOf(r.charts.size());
  for (int f = 0; f < mesh.faceCount(); ++f) facesOf[r.faceChart[f]].push_back(f);
  std::vector<int> local(mesh.vertexCount(), -1);
  double worst = 0.0;
  int within = 0, compared = 0;
  for (const std::vector<int>& faces : facesOf) {
    std::vector<gr::Vec3> positions;
    std::vector<gr::Tri> tris;
    std::vector<int> used;
    for (int f : faces) {
      gr::Tri t;
      for (int k = 0; k < 3; ++k) {
        const int v = mesh.triangles[f][k];
        if (local[v] < 0) {
          local[v] = static_cast<int>(positions.size());
          positions.push_back(mesh.positions[v]);
          used.push_back(v);
        }
        t[k] = local[v];
      }
      tris.push_back(t);
    }
    for (int v : used) local[v] = -1;
    gr::Expected<gr::TriMesh> patch = gr::buildTriMesh(positions, tris);
    if (!patch) continue;
    const std::vector<Eigen::Vector2d> lscm = gr::oracle::cgalLscm(*patch);
    if (lscm.empty()) continue;
    std::vector<gr::Vec2> ours(3 * faces.size()), theirs(3 * faces.size());
    for (size_t j = 0; j < faces.size(); ++j)
      for (int k = 0; k < 3; ++k) {
        ours[3 * j + k] = r.cornerUv[3 * faces[j] + k];
        theirs[3 * j + k] = lscm[tris[j][k]];
      }
    const double ratio =
        gr::measureUvDistortion(*patch, ours).conformalMean / gr::measureUvDistortion(*patch, theirs).conformalMean;
    worst = std::max(worst, ratio);
    within += ratio <= 1.5;
    ++compared;
  }
  state.counters["lscm_worst"] = worst;
  state.counters["lscm_within_1_5"] = compared > 0 ? double(within) / compared : 0.0;
}

void BM_Atlas(benchmark::State& state, const Case& c) {
  const gr::TriMesh* mesh = gr::bench::cachedMesh<gr::TriMesh>(state, c.name, c.file, c.subdivisions);
  if (!mesh) return;
  gr::Expected<gr::AtlasResult> r = gr::internalError("not run");
  for (auto _ : state) r = gr::buildTextureAtlas(*mesh);
  if (!r) return state.SkipWithError(r.status().message.c_str());
  lastCharts(c.name, static_cast<int>(r->charts.size()));
  setUvCounters(state, *mesh, r->cornerUv, static_cast<int>(r->charts.size()));
  state.counters["repaired"] = r->repairedCharts;
  compareWithLscm(state, *mesh, *r);
}

/// MeshLab's OBJ (v, vt, f v/vt): the faces with their positions and per-corner UVs.
bool readObj(const std::string& path, gr::TriMesh& mesh, std::vector<gr::Vec2>& cornerUv) {
  std::ifstream in(path);
  std::vector<gr::Vec3> v;
  std::vector<gr::Vec2> vt;
  std::vector<gr::Tri> tris;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::string key;
    ss >> key;
    if (key == "v") {
      double x, y, z;
      ss >> x >> y >> z;
      v.emplace_back(x, y, z);
    } else if (key == "vt") {
      double a, b;
      ss >> a >> b;
      vt.emplace_back(a, b);
    } else if (key == "f") {
      gr::Tri t;
      for (int k = 0; k < 3; ++k) {
        std::string ref;
        ss >> ref;
        const size_t slash = ref.find('/');
        if (slash == std::string::npos) return false;
        t[k] = std::stoi(ref) - 1;
        cornerUv.push_back(vt.at(std::stoi(ref.substr(slash + 1)) - 1));
      }
      tris.push_back(t);
    }
  }
  gr::Expected<gr::TriMesh> m = gr::buildTriMesh(std::move(v), std::move(tris));
  if (!m) return false;
  mesh = std::move(*m);
  return true;
}

/// The case's mesh written to `path` as OFF (obj = false) or OBJ; false if it cannot be had.
bool writeCaseMesh(benchmark::State& state, const Case& c, const std::string& path, bool obj) {
  const gr::TriMesh* mesh = gr::bench::cachedMesh<gr::TriMesh>(state, c.name, c.file, c.subdivisions);
  if (!mesh) return false;
  std::ofstream out(path);
  out.precision(17);
  if (!obj) out << "OFF\n" << mesh->vertexCount() << " " << mesh->faceCount() << " 0\n";
  for (const gr::Vec3& p : mesh->positions) out << (obj ? "v " : "") << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const gr::Tri& t : mesh->triangles)
    if (obj)
      out << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
    else
      out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  return static_cast<bool>(out);
}

/// UV charts of a per-corner map: faces joined across each edge whose two ends have the same UVs
/// on both sides (union-find).
int uvCharts(const gr::TriMesh& mesh, const std::vector<gr::Vec2>& cornerUv) {
  std::vector<int> parent(mesh.faceCount());
  for (int f = 0; f < mesh.faceCount(); ++f) parent[f] = f;
  const auto root = [&](int f) {
    while (parent[f] != f) f = parent[f] = parent[parent[f]];
    return f;
  };
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) {
    const int o = mesh.oppositeCorner[c];
    if (o < 0) continue;
    // Edge (next(c), prev(c)) is (prev(o), next(o)) in the other face.
    if (cornerUv[gr::TriMesh::next(c)] == cornerUv[gr::TriMesh::prev(o)] &&
        cornerUv[gr::TriMesh::prev(c)] == cornerUv[gr::TriMesh::next(o)])
      parent[root(c / 3)] = root(o / 3);
  }
  int charts = 0;
  for (int f = 0; f < mesh.faceCount(); ++f) charts += root(f) == f;
  return charts;
}

void BM_BlenderSmartUv(benchmark::State& state, const Case& c) {
  if (std::system("command -v blender > /dev/null 2>&1") != 0) return state.SkipWithError("blender not installed");
  char dirTemplate[] = "/tmp/bench_atlas_XXXXXX";
  if (!mkdtemp(dirTemplate)) return state.SkipWithError("mkdtemp failed");
  const std::string dir = dirTemplate, input = dir + "/in.obj", out = dir + "/out.obj", log = dir + "/log.txt";
  if (!writeCaseMesh(state, c, input, true)) return;
  const std::string command = "blender -b --python '" + std::string(GR_BENCH_DIR) + "/blender_smart_uv.py' -- '" +
                              input + "' '" + out + "' > '" + log + "' 2>&1";
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = std::system(command.c_str());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (rc != 0) return state.SkipWithError(("blender failed, see " + log).c_str());
  }
  std::ifstream logIn(log);
  for (std::string word; logIn >> word;)
    if (word == "SMART_UV_SECONDS") logIn >> state.counters["operator_s"];
  gr::TriMesh mesh;
  std::vector<gr::Vec2> cornerUv;
  if (!readObj(out, mesh, cornerUv)) return state.SkipWithError(("cannot read " + out).c_str());
  setUvCounters(state, mesh, cornerUv, uvCharts(mesh, cornerUv));
}

void BM_MeshLabVoronoiAtlas(benchmark::State& state, const Case& c) {
  char dirTemplate[] = "/tmp/bench_atlas_XXXXXX";
  if (!mkdtemp(dirTemplate)) return state.SkipWithError("mkdtemp failed");
  const std::string dir = dirTemplate, script = dir + "/va.mlx", out = dir + "/out.obj", log = dir + "/log.txt";
  std::string input = gr::bench::benchMeshPath(c.file);
  if (c.subdivisions > 0) {  // the same subdivided mesh as ours, written once
    input = dir + "/in.off";
    if (!writeCaseMesh(state, c, input, false)) return;
  }
  std::ofstream(script) << "<!DOCTYPE FilterScript>\n<FilterScript>\n"
                           " <filter name=\"Parametrization: Voronoi Atlas\">\n"
                           "  <Param type=\"RichInt\" name=\"regionNum\" value=\""
                        << lastCharts(c.name)
                        << "\"/>\n"
                           "  <Param type=\"RichBool\" name=\"overlapFlag\" value=\"false\"/>\n"
                           " </filter>\n"
                           // The atlas is a new layer: the input deleted, it becomes the one saved.
                           " <filter name=\"Delete Current Mesh\"/>\n"
                           "</FilterScript>\n";
  const std::string command =
      "xvfb-run -a meshlabserver -i '" + input + "' -o '" + out + "' -m wt -s '" + script + "' > '" + log + "' 2>&1";
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    const int rc = std::system(command.c_str());
    state.SetIterationTime(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    if (rc != 0) return state.SkipWithError(("meshlabserver failed, see " + log).c_str());
  }
  gr::TriMesh mesh;
  std::vector<gr::Vec2> cornerUv;
  if (!readObj(out, mesh, cornerUv)) return state.SkipWithError(("cannot read " + out).c_str());
  setUvCounters(state, mesh, cornerUv, lastCharts(c.name));
}

void registerAll() {
  for (const Case& c : kCases) {
    auto* b = benchmark::RegisterBenchmark((std::string("Atlas/") + c.name).c_str(), BM_Atlas, c)
                  ->Unit(benchmark::kMillisecond)
                  ->MeasureProcessCPUTime();
    if (c.subdivisions > 0) b->Iterations(1);
  }
  for (const Case& c : kCases)
    benchmark::RegisterBenchmark((std::string("MeshLabVoronoiAtlas/") + c.name).c_str(), BM_MeshLabVoronoiAtlas, c)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(1);
  for (const Case& c : kCases)
    benchmark::RegisterBenchmark((std::string("BlenderSmartUv/") + c.name).c_str(), BM_BlenderSmartUv, c)
        ->Unit(benchmark::kMillisecond)
        ->UseManualTime()
        ->Iterations(1);
}

}  // namespace

int main(int argc, char** argv) { return gr::bench::runBenchmarks(argc, argv, registerAll); }
