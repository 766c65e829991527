// In-process tests of the filters: the plugin class on a real MeshDocument (MeshLab's
// libmeshlab-common), without meshlabserver. These see what a script run cannot: after a failed
// filter, the user's mesh (positions, quality, colour, flags, data mask) is exactly as before.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <optional>
#include <regex>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <common/GLLogStream.h>
#include <common/meshmodel.h>

#include "core/atlas/texture_atlas.h"
#include "core/base/math.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/geodesic_surface.h"
#include "core/measure/evaluation.h"
#include "core/mesh/vcg_mesh.h"
#include "core/param/semi_regular.h"
#include "core/remesh/remesh_surface.h"
#include "core/segment/geodesic_segmentation.h"
#include "filter_geodesic_remesh/fast_marching_filter.h"
#include "filter_geodesic_remesh/filter_geodesic_remesh.h"
#include "filter_geodesic_remesh/filter_support.h"
#include "filter_geodesic_remesh/parameter_names.h"
#include "tests/oracles/geodesic_oracles.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/oracles/uv_oracles.h"
#include "tests/support/cad_meshes.h"
#include "tests/support/test_support.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr {
namespace {

/// Copies a core mesh into a new layer of `doc`.
MeshModel* addMesh(MeshDocument& doc, const std::vector<Vec3>& positions, const std::vector<Tri>& triangles) {
  MeshModel* mm = doc.addNewMesh("", "input", true);
  CMeshO& m = mm->cm;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, positions.size());
  for (const Vec3& p : positions) (vi++)->P() = CMeshO::CoordType(float(p.x()), float(p.y()), float(p.z()));
  if (!triangles.empty()) {
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, triangles.size());
    for (const Tri& t : triangles) {
      for (int k = 0; k < 3; ++k) fi->V(k) = &m.vert[t[k]];
      ++fi;
    }
  }
  vcg::tri::UpdateBounding<CMeshO>::Box(m);
  return mm;
}

/// The faces of a layer (with no deleted elements, as the filters leave them) as vertex indices.
std::vector<Tri> faceIndices(const MeshModel& mm) {
  std::vector<Tri> tris;
  if (mm.cm.vert.empty()) return tris;
  tris.reserve(mm.cm.face.size());
  const CVertexO* const first = &mm.cm.vert[0];
  for (const auto& f : mm.cm.face) tris.push_back({int(f.cV(0) - first), int(f.cV(1) - first), int(f.cV(2) - first)});
  return tris;
}

/// The core's uniform remesh (the function the filter calls) of a layer as the filter reads it:
/// MeshLab holds coordinates as float, so the core must see the same.
Expected<SurfaceRemeshResult> remeshAsTheFilterReads(const MeshModel& mm, const SurfaceRemeshParams& params) {
  const Expected<adapters::CoreView> asRead = adapters::toCore(mm.cm);
  if (!asRead) return asRead.status();
  return remeshSurface(asRead->mesh, params);
}

/// Everything a filter could change in a mesh.
struct Snapshot {
  std::vector<float> values;
  std::vector<unsigned> colorsAndFlags;
  int mask = 0, vn = 0, fn = 0;
  explicit Snapshot(const MeshModel& mm) : mask(mm.dataMask()), vn(mm.cm.vn), fn(mm.cm.fn) {
    for (const auto& v : mm.cm.vert) {
      for (int k = 0; k < 3; ++k) values.push_back(v.cP()[k]);
      values.push_back(v.cQ());
      colorsAndFlags.push_back(*reinterpret_cast<const unsigned*>(&v.cC()[0]));
      colorsAndFlags.push_back(unsigned(v.Flags()));
    }
    for (const auto& f : mm.cm.face) colorsAndFlags.push_back(unsigned(f.cFlags()));
  }
  bool operator==(const Snapshot& o) const {
    // Compare bit patterns so NaN coordinates compare equal to themselves.
    return mask == o.mask && vn == o.vn && fn == o.fn && colorsAndFlags == o.colorsAndFlags &&
           values.size() == o.values.size() &&
           std::equal(values.begin(), values.end(), o.values.begin(),
                      [](float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; });
  }
};

class FilterInProcess : public ::testing::Test {
 protected:
  FilterGeodesicRemeshPlugin plugin;
  GLLogStream log;
  MeshDocument doc;
  QAction* action = nullptr;
  RichParameterList params;

  void SetUp() override {
    plugin.setLog(&log);
    use("Geodesic Distance: Fast Marching from Selected Vertices");
  }
  void use(const char* filterName) {
    action = nullptr;
    for (QAction* a : plugin.actions())
      if (a->text() == filterName) action = a;
    ASSERT_NE(action, nullptr) << filterName;
  }
  void declare(MeshModel& mm) {
    params = RichParameterList();
    plugin.initParameterSet(action, mm, params);
  }
  bool apply() { return plugin.applyFilter(action, doc, params, nullptr); }
  /// The uniform filter with its defaults on the data-set mesh `name` at `percent` of its
  /// vertices, applied (its output the current layer); returns the core's remesh of the input
  /// layer as the filter read it, to compare the log with. Empty if the filter failed.
  std::optional<SurfaceRemeshResult> uniformAndItsCore(const std::string& name, int percent) {
    use("Remeshing: Geodesic Uniform");
    const TriMesh input = test::loadRealMesh(name);
    MeshModel* mm = addMesh(doc, input.positions, input.triangles);
    declare(*mm);
    const int target = input.vertexCount() * percent / 100;
    params.setValue(filters::param::kTargetVertices, IntValue(target));
    if (!apply()) return std::nullopt;
    SurfaceRemeshParams core;
    core.sampling.targetCount = target;
    core.measure = false;
    Expected<SurfaceRemeshResult> r = remeshAsTheFilterReads(*mm, core);
    if (!r) return std::nullopt;
    return std::move(r).value();
  }
  std::string logText() const {
    std::string all;
    for (const auto& entry : log.logStringList()) all += entry.second.toStdString() + "\n";
    return all;
  }
  /// Applies the filter to a bad mesh and checks: false, the status code in the log ("<filter>
  /// failed (<code>): <message>"), an error message that names the culprit (`names`), the mesh
  /// untouched.
  void expectCleanFailure(MeshModel& mm, StatusCode code, const std::string& names) {
    const Snapshot before(mm);
    EXPECT_FALSE(apply());
    const std::string failed = std::string("failed (") + toString(code) + "): ";
    const std::string error = plugin.errorMsg().toStdString();
    EXPECT_NE(error.find(names), std::string::npos) << "errorMessage: " << error;
    EXPECT_NE(logText().find(failed), std::string::npos) << "log:\n" << logText();
    EXPECT_TRUE(Snapshot(mm) == before) << "a failed filter changed the mesh";
  }
};

// An exception escaping a filter becomes a status (applyFilter runs every filter through
// runCatchingExceptions): std::bad_alloc is OutOfMemory, anything else Internal (a bug).
TEST(FilterExceptions, BecomeOutOfMemoryOrInternal) {
  const Status oom = filters::runCatchingExceptions([]() -> Status { throw std::bad_alloc(); });
  EXPECT_EQ(oom.code, StatusCode::OutOfMemory);
  EXPECT_EQ(oom.message, "out of memory");
  const Status bug = filters::runCatchingExceptions([]() -> Status { throw std::logic_error("index 7 out of range"); });
  EXPECT_EQ(bug.code, StatusCode::Internal);
  EXPECT_EQ(bug.message, "internal error: index 7 out of range") << "the message keeps what() for the bug report";
  EXPECT_EQ(filters::runCatchingExceptions([]() -> Status { throw 42; }).code, StatusCode::Internal);
  // Without an exception the filter's own status passes through.
  EXPECT_TRUE(filters::runCatchingExceptions([] { return Status::ok(); }));
  EXPECT_EQ(filters::runCatchingExceptions([] { return nonManifold("edge 1-2"); }).code, StatusCode::NonManifold);
}

TEST_F(FilterInProcess, FandiskMatchesCoreAndMarksQualityAndColor) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  mm->cm.vert[0].SetS();
  mm->cm.vert[3000].SetS();
  declare(*mm);
  ASSERT_TRUE(apply()) << logText();
  EXPECT_TRUE(mm->hasDataMask(MeshModel::MM_VERTQUALITY));
  EXPECT_TRUE(mm->hasDataMask(MeshModel::MM_VERTCOLOR));
  // The filter converts coordinates to float and back; compare with the core on those.
  std::vector<Vec3> asFloat;
  for (const auto& v : mm->cm.vert) asFloat.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
  const TriMesh same = std::move(buildTriMesh(asFloat, fandisk.triangles)).value();
  // The core function the filter calls: geodesicDistance (here on the mesh as it is: fandisk's
  // triangles are well shaped, the log says so).
  const auto core = geodesicDistance(same, {}, {0, 3000});
  ASSERT_TRUE(core);
  ASSERT_FALSE(core->refined);
  for (int v = 0; v < same.vertexCount(); ++v)
    ASSERT_NEAR(mm->cm.vert[v].Q(), core->field.distance[v], 1e-6 * (1 + core->field.distance[v])) << v;
  EXPECT_NE(logText().find("Reached 6475 of 6475 vertices"), std::string::npos) << logText();
  EXPECT_NE(logText().find("Triangulation fine as it is ("), std::string::npos) << logText();
  // Against CGAL's exact geodesics: at least as close as the plain engine (fastMarching, what the
  // filter ran before geodesicDistance), and within 1% on average.
  const std::vector<double> exact0 = oracle::exactGeodesic(same, 0), exact1 = oracle::exactGeodesic(same, 3000);
  std::vector<double> exact(same.vertexCount()), written(same.vertexCount());
  for (int v = 0; v < same.vertexCount(); ++v) {
    exact[v] = std::min(exact0[v], exact1[v]);
    written[v] = mm->cm.vert[v].Q();
  }
  const auto plain = fastMarching(same, Metric::uniform(), {0, 3000});
  ASSERT_TRUE(plain);
  const DistanceError ours = distanceError(written, exact), before = distanceError(plain->distance, exact);
  std::printf("fandisk, 2 sources: filter mean %.4f %% max %.4f %% | fastMarching mean %.4f %% max %.4f %%\n",
              100 * ours.meanRelative, 100 * ours.maxRelativeToMax, 100 * before.meanRelative,
              100 * before.maxRelativeToMax);
  EXPECT_LE(ours.meanRelative, 0.01);
  EXPECT_LE(ours.meanRelative, before.meanRelative);
}

TEST_F(FilterInProcess, QualityAsSpeedHalvesDistancesForSpeedTwo) {
  const TriMesh grid = test::planeGrid(10);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  for (auto& v : mm->cm.vert) v.Q() = 2.0f;
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  mm->cm.vert[0].SetS();
  declare(*mm);
  params.setValue(filters::param::kUseQualityAsSpeed, BoolValue(true));
  ASSERT_TRUE(apply()) << logText();
  const auto unit = fastMarching(grid, Metric::uniform(), {0});
  for (int v = 0; v < grid.vertexCount(); ++v) EXPECT_NEAR(mm->cm.vert[v].Q(), 0.5 * unit->distance[v], 1e-5) << v;
}

TEST_F(FilterInProcess, MaxDistanceLeavesFarVerticesAtMinusOne) {
  const TriMesh grid = test::planeGrid(10);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  mm->cm.vert[0].SetS();
  declare(*mm);
  params.setValue(filters::param::kMaxDistance, AbsPercValue(0.5f));
  ASSERT_TRUE(apply()) << logText();
  int reached = 0;
  for (const auto& v : mm->cm.vert) {
    EXPECT_TRUE(v.cQ() == -1.0f || (v.cQ() >= 0.0f && v.cQ() <= 0.5f)) << v.cQ();
    reached += v.cQ() >= 0.0f;
  }
  EXPECT_GT(reached, 0);
  EXPECT_LT(reached, mm->cm.vn);
  EXPECT_NE(logText().find("were not reached"), std::string::npos) << logText();
}

TEST_F(FilterInProcess, NoSelection) {
  const TriMesh grid = test::planeGrid(4);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  declare(*mm);
  expectCleanFailure(*mm, StatusCode::InvalidInput, "no vertex is selected");
}

TEST_F(FilterInProcess, PointCloud) {
  MeshModel* mm = addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {});
  mm->cm.vert[0].SetS();
  declare(*mm);
  expectCleanFailure(*mm, StatusCode::InvalidInput, "the mesh has no faces");
}

TEST_F(FilterInProcess, EmptyMesh) {
  MeshModel* mm = addMesh(doc, {}, {});
  declare(*mm);
  expectCleanFailure(*mm, StatusCode::InvalidInput, "the mesh has no vertices");
}

TEST_F(FilterInProcess, NanCoordinate) {
  const TriMesh grid = test::planeGrid(4);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  mm->cm.vert[7].P()[1] = std::numeric_limits<float>::quiet_NaN();
  mm->cm.vert[0].SetS();
  declare(*mm);
  expectCleanFailure(*mm, StatusCode::InvalidInput, "vertex 7 has a non-finite coordinate");
}

TEST_F(FilterInProcess, NonManifoldEdge) {
  MeshModel* mm =
      addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  mm->cm.vert[0].SetS();
  declare(*mm);
  expectCleanFailure(*mm, StatusCode::NonManifold, "1 non-manifold edges");
}

TEST_F(FilterInProcess, FaceRepeatingAVertex) {
  MeshModel* mm = addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 1, 1}});
  mm->cm.vert[0].SetS();
  declare(*mm);
  expectCleanFailure(*mm, StatusCode::Degenerate, "face 1 uses vertex 1 twice");
}

TEST_F(FilterInProcess, QualityAsSpeedWithZeroOrNegativeSpeed) {
  for (float bad : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN()}) {
    const TriMesh grid = test::planeGrid(4);
    MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
    for (auto& v : mm->cm.vert) v.Q() = 1.0f;
    mm->cm.vert[5].Q() = bad;
    mm->updateDataMask(MeshModel::MM_VERTQUALITY);
    mm->cm.vert[0].SetS();
    declare(*mm);
    params.setValue(filters::param::kUseQualityAsSpeed, BoolValue(true));
    expectCleanFailure(*mm, StatusCode::InvalidInput, "vertex 5 has");
  }
}

TEST_F(FilterInProcess, QualityAsSpeedWithoutQuality) {
  const TriMesh grid = test::planeGrid(4);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  mm->cm.vert[0].SetS();
  declare(*mm);
  params.setValue(filters::param::kUseQualityAsSpeed, BoolValue(true));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "the mesh has no per-vertex quality");
}

TEST_F(FilterInProcess, ImpossibleParameters) {
  const TriMesh grid = test::planeGrid(4);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  mm->cm.vert[0].SetS();
  declare(*mm);
  params.setValue(filters::param::kMaxDistance, AbsPercValue(-1.0f));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "distance limit must be >= 0");
  declare(*mm);
  params.setValue(filters::param::kColorBy, EnumValue(7));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "ColorBy must be 0");
  declare(*mm);
  params.setValue(filters::param::kSurfaceRefinement, EnumValue(4));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Refinement must be 0 (Auto), 1 (On), 2 (Off) or 3 (Exact), got 4");
  declare(*mm);
  params.setValue(filters::param::kSurfaceRefinement, EnumValue(-1));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Refinement must be 0");
}

// --- Fast marching on poor triangulations (issue 17): the fronts run on the intrinsic Delaunay
// refinement of a CAD sliver mesh, the values are read at the mesh's own vertices ---------------

/// A layer's mesh as the filter sees it (MeshLab's float coordinates).
TriMesh layerMesh(const MeshModel& mm) {
  std::vector<Vec3> positions;
  for (const auto& v : mm.cm.vert) positions.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
  return std::move(buildTriMesh(positions, faceIndices(mm))).value();
}

std::vector<double> vertexQualities(const MeshModel& mm) {
  std::vector<double> q;
  for (const auto& v : mm.cm.vert) q.push_back(v.cQ());
  return q;
}

class FastMarchingRefined : public FilterInProcess {
 protected:
  MeshModel* gear = nullptr;
  TriMesh mesh;               ///< the gear as the filter sees it
  std::vector<double> exact;  ///< CGAL's exact geodesic distance from vertex 0

  void SetUp() override {
    FilterInProcess::SetUp();
    const TriMesh cad = test::cadGear();
    gear = addMesh(doc, cad.positions, cad.triangles);
    mesh = layerMesh(*gear);
    exact = oracle::exactGeodesic(mesh, 0);
  }
  /// Runs the filter from the selected `sources` with the given Refinement entry (0 Auto, 1 On,
  /// 2 Off, 3 Exact); the log of this run.
  std::string run(const std::vector<int>& sources, int refinement) {
    for (auto& v : gear->cm.vert) v.ClearS();
    for (int s : sources) gear->cm.vert[s].SetS();
    declare(*gear);
    params.setValue(filters::param::kSurfaceRefinement, EnumValue(refinement));
    log.Clear();
    EXPECT_TRUE(apply()) << logText();
    return logText();
  }
};

// Auto gives the gear exact distances (window propagation: the log says so, with the windows); On
// refines its slivers (the log says so, with the points inserted), Off does not; On's quality is
// the core's geodesicDistance and within 1% of exact on average, Off's is worse.
TEST_F(FastMarchingRefined, AutoRefinesTheSliverMeshAndIsCloserToExactThanOff) {
  const std::string exactLog = run({0}, int(SurfaceRefinement::Auto));
  EXPECT_NE(exactLog.find("Exact geodesic distances (window propagation, "), std::string::npos) << exactLog;
  EXPECT_GT(test::numberBefore(exactLog, "windows"), 0) << exactLog;
  EXPECT_EQ(exactLog.find("Surface refined"), std::string::npos) << exactLog;
  const DistanceError exactError = distanceError(vertexQualities(*gear), exact);
  EXPECT_LE(exactError.maxRelativeToMax, 1e-6);                                // the quality is a float
  EXPECT_NE(run({0}, 3).find("Exact geodesic distances"), std::string::npos);  // Exact: the same

  const std::string autoLog = run({0}, int(SurfaceRefinement::On));
  const std::vector<double> autoQ = vertexQualities(*gear);
  EXPECT_NE(autoLog.find("Surface refined for the fronts (intrinsic Delaunay, angles >= 25 deg, edges <= 2% of the "
                         "diagonal): "),
            std::string::npos)
      << autoLog;
  EXPECT_GT(test::numberBefore(autoLog, "points inserted"), 0) << autoLog;
  EXPECT_NE(autoLog.find(describe(assessTriangulation(mesh))), std::string::npos) << autoLog;
  EXPECT_LT(autoLog.find("Surface refined"), autoLog.find("Time: ")) << "the Time line is last";
  GeodesicDistanceParams on;
  on.surface.refinement = SurfaceRefinement::On;
  const Expected<GeodesicDistanceResult> core = geodesicDistance(mesh, {}, {0}, on);
  ASSERT_TRUE(core);
  ASSERT_TRUE(core->refined);
  for (int v = 0; v < mesh.vertexCount(); ++v)
    ASSERT_NEAR(autoQ[v], core->field.distance[v], 1e-6 * (1 + core->field.distance[v])) << v;

  const std::string offLog = run({0}, int(SurfaceRefinement::Off));
  const std::vector<double> offQ = vertexQualities(*gear);
  EXPECT_EQ(offLog.find("Surface refined"), std::string::npos) << offLog;
  EXPECT_NE(offLog.find("Refinement Off: the fronts ran on the triangulation as it is (" +
                        describe(assessTriangulation(mesh)) + ")"),
            std::string::npos)
      << offLog;

  const DistanceError autoError = distanceError(autoQ, exact), offError = distanceError(offQ, exact);
  std::printf("cad_gear %d v, %d points inserted: On mean %.3f %% max %.3f %% | Off mean %.3f %% max %.3f %%\n",
              mesh.vertexCount(), core->insertedPoints, 100 * autoError.meanRelative, 100 * autoError.maxRelativeToMax,
              100 * offError.meanRelative, 100 * offError.maxRelativeToMax);
  EXPECT_EQ(autoError.comparedVertices, offError.comparedVertices);
  EXPECT_LE(autoError.meanRelative, 0.01);
  EXPECT_LT(autoError.meanRelative, offError.meanRelative);
  EXPECT_LT(autoError.maxRelativeToMax, offError.maxRelativeToMax);
}

/// The log line of each Refinement entry run on the gear: Auto's exact propagation, On's refinement.
const char* methodLine(int refinement) { return refinement == 0 ? "Exact geodesic distances" : "Surface refined"; }

// MaxDistance with exact propagation (Auto) and on the refined surface (On): unreached vertices
// get -1, reached ones are within the limit.
TEST_F(FastMarchingRefined, MaxDistanceOnTheRefinedSurface) {
  for (int refinement : {0, 1}) {
    SCOPED_TRACE(refinement);
    const double limit = 0.5 * *std::max_element(exact.begin(), exact.end());
    for (auto& v : gear->cm.vert) v.ClearS();
    gear->cm.vert[0].SetS();
    declare(*gear);
    params.setValue(filters::param::kMaxDistance, AbsPercValue(float(limit)));
    params.setValue(filters::param::kSurfaceRefinement, EnumValue(refinement));
    log.Clear();
    ASSERT_TRUE(apply()) << logText();
    EXPECT_NE(logText().find(methodLine(refinement)), std::string::npos) << logText();
    int reached = 0;
    for (int v = 0; v < mesh.vertexCount(); ++v) {
      const float q = gear->cm.vert[v].cQ();
      ASSERT_TRUE(q == -1.0f || (q >= 0.0f && q <= float(limit))) << v << ": " << q;
      reached += q >= 0.0f;
      // Within 1% of the limit, exact geodesics say on which side of it a vertex is.
      if (exact[v] < 0.99 * limit) {
        EXPECT_GE(q, 0.0f) << v;
      } else if (exact[v] > 1.01 * limit) {
        EXPECT_EQ(q, -1.0f) << v;
      }
    }
    EXPECT_GT(reached, 0);
    EXPECT_LT(reached, mesh.vertexCount());
    EXPECT_NE(logText().find("were not reached"), std::string::npos) << logText();
  }
}

// Two sources, ColorBy = Voronoi cell, exact (Auto) and on the refined surface (On): away from
// the bisector, each vertex has its nearest source's colour by the exact distances;
// UseQualityAsSpeed with quality 2 halves the distance.
TEST_F(FastMarchingRefined, VoronoiCellsAndSpeedOnTheRefinedSurface) {
  const int far = static_cast<int>(std::max_element(exact.begin(), exact.end()) - exact.begin());
  const std::vector<double> exactFar = oracle::exactGeodesic(mesh, far);
  for (int refinement : {0, 1}) {
    SCOPED_TRACE(refinement);
    gear->clearDataMask(MeshModel::MM_VERTQUALITY);
    for (auto& v : gear->cm.vert) v.ClearS();
    gear->cm.vert[0].SetS();
    gear->cm.vert[far].SetS();
    declare(*gear);
    params.setValue(filters::param::kColorBy, EnumValue(int(filters::ColorBy::VoronoiCell)));
    params.setValue(filters::param::kSurfaceRefinement, EnumValue(refinement));
    log.Clear();
    ASSERT_TRUE(apply()) << logText();
    EXPECT_NE(logText().find(methodLine(refinement)), std::string::npos) << logText();
    const vcg::Color4b colour0 = gear->cm.vert[0].cC(), colourFar = gear->cm.vert[far].cC();
    ASSERT_NE(colour0, colourFar);
    int compared = 0, wrong = 0;
    for (int v = 0; v < mesh.vertexCount(); ++v) {
      if (std::abs(exact[v] - exactFar[v]) < 0.02 * exact[far]) continue;  // near the bisector
      ++compared;
      wrong += gear->cm.vert[v].cC() != (exact[v] < exactFar[v] ? colour0 : colourFar);
    }
    EXPECT_GT(compared, mesh.vertexCount() / 2);
    EXPECT_EQ(wrong, 0);

    // Speed 2 everywhere: twice the travel time is the distance to the nearest source.
    for (auto& v : gear->cm.vert) v.Q() = 2.0f;
    gear->updateDataMask(MeshModel::MM_VERTQUALITY);
    declare(*gear);
    params.setValue(filters::param::kUseQualityAsSpeed, BoolValue(true));
    params.setValue(filters::param::kSurfaceRefinement, EnumValue(refinement));
    log.Clear();
    ASSERT_TRUE(apply()) << logText();
    EXPECT_NE(logText().find(methodLine(refinement)), std::string::npos) << logText();
    std::vector<double> twice(mesh.vertexCount()), nearest(mesh.vertexCount());
    for (int v = 0; v < mesh.vertexCount(); ++v) {
      ASSERT_GE(gear->cm.vert[v].cQ(), 0.0f) << "vertex " << v << " not reached";
      twice[v] = 2.0 * gear->cm.vert[v].cQ();
      nearest[v] = std::min(exact[v], exactFar[v]);
    }
    const DistanceError e = distanceError(twice, nearest);
    std::printf("cad_gear, speed 2, two sources: twice the time vs exact: mean %.3f %% max %.3f %%\n",
                100 * e.meanRelative, 100 * e.maxRelativeToMax);
    EXPECT_LE(e.meanRelative, 0.01);
    if (refinement == 0) {
      EXPECT_LE(e.maxRelativeToMax, 1e-6);
    }
  }
}

// A failing case on the refined surface (a zero speed) leaves the gear as it was.
TEST_F(FastMarchingRefined, FailureLeavesTheMeshUnchanged) {
  for (auto& v : gear->cm.vert) v.Q() = 1.0f;
  gear->cm.vert[7].Q() = 0.0f;
  gear->updateDataMask(MeshModel::MM_VERTQUALITY);
  gear->cm.vert[0].SetS();
  declare(*gear);
  params.setValue(filters::param::kUseQualityAsSpeed, BoolValue(true));
  expectCleanFailure(*gear, StatusCode::InvalidInput, "vertex 7 has");
}

// Two grids sharing only their corner vertex 0 (a non-manifold vertex): the intrinsic refinement
// cannot take it. Auto falls back to the mesh as it is (the same values as Off) and says why; On
// fails cleanly.
TEST_F(FilterInProcess, NonManifoldVertexAutoFallsBackOnFails) {
  const TriMesh grid = test::planeGrid(4);
  std::vector<Vec3> positions = grid.positions;
  std::vector<Tri> triangles = grid.triangles;
  const int n = grid.vertexCount();
  for (int v = 1; v < n; ++v) positions.push_back(-grid.positions[v]);  // the mirror image, corner 0 shared
  auto mirrored = [n](int v) { return v == 0 ? 0 : v + n - 1; };
  for (const Tri& t : grid.triangles) triangles.push_back({mirrored(t[0]), mirrored(t[1]), mirrored(t[2])});
  MeshModel* mm = addMesh(doc, positions, triangles);
  ASSERT_EQ(layerMesh(*mm).topology.nonManifoldVertices, 1);
  mm->cm.vert[n - 1].SetS();  // the far corner of the first grid: the front crosses vertex 0
  std::vector<std::vector<double>> fields;
  for (SurfaceRefinement r : {SurfaceRefinement::Auto, SurfaceRefinement::Off}) {
    declare(*mm);
    params.setValue(filters::param::kSurfaceRefinement, EnumValue(int(r)));
    log.Clear();
    ASSERT_TRUE(apply()) << logText();
    if (r == SurfaceRefinement::Off) {
      EXPECT_NE(logText().find("Refinement Off: the fronts ran on the triangulation as it is ("), std::string::npos)
          << logText();
    }
    EXPECT_NE(logText().find("Reached " + std::to_string(mm->cm.vn) + " of"), std::string::npos) << logText();
    const bool skipped = logText().find("could not be refined (intrinsic Delaunay refinement needs a manifold mesh") !=
                         std::string::npos;
    EXPECT_EQ(skipped, r == SurfaceRefinement::Auto) << logText();
    fields.push_back(vertexQualities(*mm));
  }
  EXPECT_EQ(fields[0], fields[1]) << "Auto's fallback is the mesh as it is";
  declare(*mm);
  params.setValue(filters::param::kSurfaceRefinement, EnumValue(int(SurfaceRefinement::On)));
  expectCleanFailure(*mm, StatusCode::NonManifold, "Refinement is On: intrinsic Delaunay refinement needs a manifold");
}

// Every default a filter declares is the default of the core's Params struct it feeds (one
// source of defaults): a filter that hard-codes a value fails here when the core's changes.
TEST_F(FilterInProcess, DeclaredDefaultsAreTheCoreParamsDefaults) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  mm->cm.bbox.SetNull();
  for (const auto& v : mm->cm.vert) mm->cm.bbox.Add(v.cP());
  const float diag = mm->cm.bbox.Diag();
  const SurfaceRemeshParams remesh;
  const AdaptiveRemeshParams adaptive;
  declare(*mm);  // the fast-marching filter (SetUp)
  EXPECT_EQ(params.getEnum(filters::param::kSurfaceRefinement), int(GeodesicSurfaceParams().refinement));
  EXPECT_EQ(params.getEnum(filters::param::kSurfaceRefinement), int(SurfaceRefinement::Auto));
  for (const char* name : {"Remeshing: Geodesic Uniform", "Remeshing: Geodesic Adaptive"}) {
    SCOPED_TRACE(name);
    use(name);
    declare(*mm);
    EXPECT_EQ(params.getInt(filters::param::kTargetVertices), SurfaceRemeshParams::defaultTargetCount(mm->cm.vn));
    EXPECT_EQ(params.getInt(filters::param::kTargetVertices), 647);  // 10% of fandisk's 6,475 vertices
    EXPECT_FLOAT_EQ(params.getAbsPerc(filters::param::kSpacing),
                    float(SurfaceRemeshParams::kDefaultSpacingFraction * diag));
    EXPECT_EQ(params.getInt(filters::param::kSeed), int(remesh.sampling.seed));
    EXPECT_EQ(params.getBool(filters::param::kSubVertexPlacement), remesh.sampling.subVertexPlacement);
    const bool isAdaptive = std::string(name) == "Remeshing: Geodesic Adaptive";
    EXPECT_EQ(params.getInt(filters::param::kCentroidalIterations),
              isAdaptive ? adaptive.remesh.centroidalIterations : remesh.centroidalIterations);
    EXPECT_EQ(params.getBool(filters::param::kReportError),
              isAdaptive ? adaptive.remesh.measureDistance : remesh.measureDistance);
  }
  use("Remeshing: Geodesic Uniform");
  declare(*mm);
  EXPECT_EQ(params.getInt(filters::param::kRefinement), remesh.refinement);
  EXPECT_EQ(params.getInt(filters::param::kRelaxation), remesh.relaxation.iterations);
  use("Remeshing: Geodesic Adaptive");
  declare(*mm);
  EXPECT_EQ(params.getEnum(filters::param::kField), int(adaptive.metric.field));
  EXPECT_EQ(params.getEnum(filters::param::kMapping), int(adaptive.metric.speed.mapping));
  EXPECT_FLOAT_EQ(params.getFloat(filters::param::kStrength), float(adaptive.metric.speed.strength));
  EXPECT_FLOAT_EQ(params.getAbsPerc(filters::param::kCurvatureRadius), float(adaptive.metric.curvature.radius));
  EXPECT_FLOAT_EQ(params.getFloat(filters::param::kGradation), float(adaptive.gradation));
  EXPECT_EQ(params.getInt(filters::param::kRelaxation), adaptive.remesh.relaxation.iterations);
  EXPECT_EQ(adaptive.remesh.relaxation.iterations, 0);  // the adaptive preset's
  EXPECT_EQ(adaptive.remesh.centroidalIterations, AdaptiveRemeshParams::kDefaultCentroidalIterations);
  use("Compute Total Curvature (Normal Cycle) into Vertex Quality");
  declare(*mm);
  EXPECT_FLOAT_EQ(params.getAbsPerc(filters::param::kCurvatureRadius), float(CurvatureParams().radius));
}

TEST_F(FilterInProcess, UniformRemeshMakesANewLayerAndKeepsTheInput) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh knot = test::loadRealMesh("knot2.off");  // two tori
  MeshModel* mm = addMesh(doc, knot.positions, knot.triangles);
  for (auto& v : mm->cm.vert) v.C() = vcg::Color4b(200, 10, 10, 255);
  mm->updateDataMask(MeshModel::MM_VERTCOLOR);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(400));
  const Snapshot before(*mm);
  ASSERT_TRUE(apply()) << logText();
  EXPECT_TRUE(Snapshot(*mm) == before) << "the input layer changed";
  ASSERT_EQ(doc.meshList.size(), 2);
  MeshModel* out = doc.mm();
  ASSERT_NE(out, mm);
  std::vector<Vec3> pos;
  for (const auto& v : out->cm.vert) pos.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
  const std::vector<Tri> tris = faceIndices(*out);
  const auto result = buildTriMesh(pos, tris);
  ASSERT_TRUE(result);
  EXPECT_GE(result->vertexCount(), 400);
  EXPECT_EQ(result->topology.components, 2);
  EXPECT_EQ(result->topology.genus, 2);
  EXPECT_EQ(result->topology.boundaryEdges, 0);
  EXPECT_TRUE(result->topology.isManifold());
  EXPECT_EQ(result->topology.inconsistentEdges, 0);
  // Colours carried from the input vertices.
  EXPECT_TRUE(out->hasDataMask(MeshModel::MM_VERTCOLOR));
  EXPECT_EQ(out->cm.vert[0].C(), vcg::Color4b(200, 10, 10, 255));
  EXPECT_NE(logText().find("added to make the triangulation valid"), std::string::npos) << logText();
  EXPECT_NE(logText().find("Angles: "), std::string::npos) << logText();
  // The distance to the input only when asked for (ReportError), and then the core's figure.
  EXPECT_EQ(logText().find("Hausdorff distance"), std::string::npos) << logText();
  log.Clear();
  doc.setCurrent(mm);
  params.setValue(filters::param::kReportError, BoolValue(true));
  ASSERT_TRUE(apply()) << logText();
  SurfaceRemeshParams core;
  core.sampling.targetCount = 400;
  core.measureDistance = true;
  const Expected<SurfaceRemeshResult> measured = remeshAsTheFilterReads(*mm, core);
  ASSERT_TRUE(measured) << measured.status().message;
  const RemeshMeasures& m = measured->measures;
  char expected[64];
  std::snprintf(expected, sizeof expected, "two-sided %.3f %%",
                100 * std::max(m.toInput.max, m.fromInput.max) / m.inputDiagonal);
  EXPECT_NE(logText().find(expected), std::string::npos) << expected << " in " << logText();
}

// A small output (sphere.off, 8 vertices) is remeshed from other starts (SurfaceRemeshParams::
// restarts, restartDeviation); the log says how many and which was kept, as the core chose, and
// the Time line has their time.
TEST_F(FilterInProcess, UniformRemeshOfASmallOutputLogsItsStarts) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh sphere = test::loadRealMesh("sphere.off");
  MeshModel* mm = addMesh(doc, sphere.positions, sphere.triangles);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(8));
  ASSERT_TRUE(apply()) << logText();
  SurfaceRemeshParams core;
  core.sampling.targetCount = 8;
  core.measure = false;
  const Expected<SurfaceRemeshResult> r = remeshAsTheFilterReads(*mm, core);
  ASSERT_TRUE(r) << r.status().message;
  ASSERT_GT(r->keptStart, 0);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  char kept[96];
  std::snprintf(kept, sizeof kept, "remeshed %d times", r->starts);
  EXPECT_NE(logText().find(kept), std::string::npos) << kept << " in " << logText();
  std::snprintf(kept, sizeof kept, "kept: seed %u, moves up to %g of the ring", r->keptSeed, r->keptDeviation);
  EXPECT_NE(logText().find(kept), std::string::npos) << kept << " in " << logText();
  EXPECT_NE(logText().find("the other starts"), std::string::npos) << logText();
  EXPECT_EQ(r->cornerStarts, 0) << "a sphere has no corners";
  EXPECT_EQ(logText().find("from the corners"), std::string::npos) << logText();
}

// A start from the corners of the input's feature curves (SurfaceRemeshParams::cornerStarts) is
// logged when kept: patch-23 at 10%, a rectangle, keeps its 4 corners (as the core run on the
// filter's input says).
TEST_F(FilterInProcess, UniformRemeshLogsAStartFromTheCorners) {
  const std::optional<SurfaceRemeshResult> r = uniformAndItsCore("patch-23.off", 10);
  ASSERT_TRUE(r) << logText();
  ASSERT_EQ(r->keptCorners, 4);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  char kept[96];
  std::snprintf(kept, sizeof kept, "kept: sampled from the 4 corners, moves up to %g of the ring", r->keptDeviation);
  EXPECT_NE(logText().find(kept), std::string::npos) << kept << " in " << logText();
  EXPECT_NE(logText().find("from the corners of the input's boundaries and creases"), std::string::npos) << logText();
}

// The collapses at the worst face (SurfaceRemeshParams::worstFaceCollapses) are logged among the
// edge collapses: pig at 30%, whose output is above the count by a split's vertex, as the core run
// on the filter's input says.
TEST_F(FilterInProcess, UniformRemeshLogsItsCollapsesAtTheWorstFace) {
  const std::optional<SurfaceRemeshResult> r = uniformAndItsCore("pig.off", 30);
  ASSERT_TRUE(r) << logText();
  ASSERT_GE(r->worstFaceCollapses, 1);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  const std::string last =
      "last, at the triangle with the smallest angle, where that raised it and the distance to "
      "the input did not grow";
  const std::string line =
      std::to_string(r->collapsedVertices) + " removed by edge collapses " +
      (r->collapsedVertices == r->worstFaceCollapses
           ? last
           : "to reach the count asked for (" + std::to_string(r->worstFaceCollapses) + " of them " + last + ")");
  EXPECT_NE(logText().find(line), std::string::npos) << line << " in " << logText();
}

// The floor polishes (SurfaceRemeshParams::floorVertices) are logged: cylinder_locally_refined at
// 30%, as the core run on the filter's input says. (Through MeshLab's float coordinates the
// outputs differ from the core's on the file's doubles: fandisk_large at 30%, polished so in
// tests/remesh, keeps none here.)
TEST_F(FilterInProcess, UniformRemeshLogsItsFloorPolishes) {
  const std::optional<SurfaceRemeshResult> r = uniformAndItsCore("cylinder_locally_refined.off", 30);
  ASSERT_TRUE(r) << logText();
  ASSERT_GE(r->floorPolishes, 1);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  const std::string times = r->floorPolishes == 1 ? "once" : std::to_string(r->floorPolishes) + " times";
  const std::string line = "then polished " + times +
                           " more from where it stood, the input's boundaries and creases held (better angles, no "
                           "farther from the input)";
  EXPECT_NE(logText().find(line), std::string::npos) << line << " in " << logText();
  // Its output has splits (splitWideFaces builds their adjacency alone): the topology logged is
  // the one recounted from the output's faces (it said 0 components before it was counted).
  const test::Recount recounted = test::recount(r->mesh.triangles, r->mesh.vertexCount());
  const std::string topology = "Topology kept: " + std::to_string(recounted.components) + " components, genus " +
                               std::to_string(recounted.genusSum) + ", " + std::to_string(recounted.boundaryLoops) +
                               " boundary loops";
  ASSERT_GT(r->splitVertices, 0);
  EXPECT_NE(logText().find(topology), std::string::npos) << topology << " in " << logText();
}

// The start with the boundaries sampled less densely (SurfaceRemeshParams::boundaryStartPriority)
// is logged where it is kept: patch-23 at 30%, as the core run on the filter's input says.
TEST_F(FilterInProcess, UniformRemeshLogsItsBoundaryStart) {
  const std::optional<SurfaceRemeshResult> r = uniformAndItsCore("patch-23.off", 30);
  ASSERT_TRUE(r) << logText();
  ASSERT_EQ(r->keptBoundaryPriority, SurfaceRemeshParams{}.boundaryStartPriority);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  EXPECT_NE(logText().find(", with the boundaries sampled less densely,"), std::string::npos) << logText();
  EXPECT_NE(logText().find("the boundaries sampled 1/1.2 of the inner spacing apart"), std::string::npos) << logText();
}

// The shakes of a small output (SurfaceRemeshParams::shakes) are logged: dragknob at 5%, as the
// core run on the filter's input says.
TEST_F(FilterInProcess, UniformRemeshLogsItsShakes) {
  const std::optional<SurfaceRemeshResult> r = uniformAndItsCore("dragknob.off", 5);
  ASSERT_TRUE(r) << logText();
  ASSERT_GE(r->shakesKept, 1);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  const std::string line = std::to_string(r->shakesKept) + " of " + std::to_string(r->shakesRun) +
                           " shakes kept (its inner vertices moved at random, then polished: better angles, no "
                           "farther from the input)";
  EXPECT_NE(logText().find(line), std::string::npos) << line << " in " << logText();
}

// The last polishes (SurfaceRemeshParams::lastPolishVertices) are logged: holes at 5%, whose
// output is polished again once, as the core run on the filter's input says. (Through MeshLab's
// float coordinates the outputs differ from the core's on the file's doubles: mannequin-devil at
// 5% and anchor_dense at 30%, polished again in tests/remesh, keep no last polish here.)
TEST_F(FilterInProcess, UniformRemeshLogsItsLastPolishes) {
  const std::optional<SurfaceRemeshResult> r = uniformAndItsCore("holes.off", 5);
  ASSERT_TRUE(r) << logText();
  ASSERT_EQ(r->lastPolishes, 1);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  EXPECT_NE(logText().find("polished again from where it stood, kept once (better angles, no farther from the input)"),
            std::string::npos)
      << logText();
}

// The thin ears cut last (SurfaceRemeshParams::cutThinEars) are logged, with their slack
// (earSlack): lion at 10%, its input's own spike on the boundary (as the core run on the
// filter's input says).
TEST_F(FilterInProcess, UniformRemeshLogsItsThinEarsCut) {
  const std::optional<SurfaceRemeshResult> r = uniformAndItsCore("lion.off", 10);
  ASSERT_TRUE(r) << logText();
  ASSERT_GE(r->thinEars, 1);
  EXPECT_EQ(doc.mm()->cm.VN(), r->mesh.vertexCount());
  EXPECT_NE(logText().find(std::to_string(r->thinEars) + " removed with thin ears off the boundary (a triangle"),
            std::string::npos)
      << logText();
  EXPECT_NE(logText().find("cut where the distance to the input grows by at most 2%, all cuts together)"),
            std::string::npos)
      << logText();
}

// The log says whether output faces cross (issue 20: the log said "Topology kept" and nothing
// else over a folded face). bunny00 at 30%: the relaxation refuses the moves that would make
// faces cross, says how many, and no pair crosses (CGAL). Next test: two spheres through each
// other, whose output crosses where the input does; a warning says how many pairs and where to look.
TEST_F(FilterInProcess, UniformRemeshTellsWhetherOutputFacesCross) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh bunny = test::loadRealMesh("bunny00.off");
  MeshModel* mm = addMesh(doc, bunny.positions, bunny.triangles);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(11311));  // 30%
  ASSERT_TRUE(apply()) << logText();
  std::vector<Vec3> pos;
  for (const auto& v : doc.mm()->cm.vert) pos.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
  const Expected<std::vector<std::pair<int, int>>> bunnyCrossing =
      oracle::selfIntersections(buildTriMesh(pos, faceIndices(*doc.mm())).value());
  ASSERT_TRUE(bunnyCrossing);
  EXPECT_TRUE(bunnyCrossing->empty());
  EXPECT_NE(logText().find("no faces cross each other"), std::string::npos) << logText();
  EXPECT_NE(logText().find("moves refused where faces would have crossed"), std::string::npos) << logText();
}

TEST_F(FilterInProcess, UniformRemeshWarnsWhereOutputFacesCrossAsTheInputDoes) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh sphere = test::uvSphere(12, 24);
  std::vector<Vec3> p = sphere.positions;
  std::vector<Tri> t = sphere.triangles;
  const int n = static_cast<int>(p.size());
  for (const Vec3& x : sphere.positions) p.push_back(x + Vec3(1.0, 0.1, 0.05));
  for (const Tri& f : sphere.triangles) t.push_back({f[0] + n, f[1] + n, f[2] + n});
  const Expected<std::vector<std::pair<int, int>>> inputCrossing =
      oracle::selfIntersections(buildTriMesh(p, t).value());
  ASSERT_TRUE(inputCrossing);
  ASSERT_FALSE(inputCrossing->empty());
  MeshModel* spheres = addMesh(doc, p, t);
  declare(*spheres);
  ASSERT_TRUE(apply()) << logText();
  EXPECT_NE(logText().find("pairs of output faces cross each other"), std::string::npos) << logText();
  EXPECT_NE(logText().find("Select Self Intersecting Faces"), std::string::npos) << logText();
  EXPECT_EQ(logText().find("no faces cross each other"), std::string::npos) << logText();
}

// With Refinement, samples lie between input vertices: a linear quality field (q = x) must come
// out exact at every output vertex, and the refined run must still keep the topology.
TEST_F(FilterInProcess, UniformRemeshInterpolatesQualityAtRefinedSamples) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  for (auto& v : mm->cm.vert) v.Q() = v.cP()[0];
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(1942));  // 30%
  params.setValue(filters::param::kRefinement, IntValue(1));
  ASSERT_TRUE(apply()) << logText();
  MeshModel* out = doc.mm();
  ASSERT_NE(out, mm);
  int betweenVertices = 0;
  for (const auto& v : out->cm.vert) {
    EXPECT_NEAR(v.cQ(), v.cP()[0], 1e-5) << "quality not interpolated at the sample";
    bool isInputVertex = false;
    for (const auto& w : mm->cm.vert) isInputVertex = isInputVertex || w.cP() == v.cP();
    betweenVertices += !isInputVertex;
  }
  EXPECT_GT(betweenVertices, 0) << "with refinement some samples lie between input vertices";
  EXPECT_NE(logText().find("subdivisions"), std::string::npos) << logText();
  EXPECT_NE(logText().find("Topology kept: 1 components, genus 0, 0 boundary loops"), std::string::npos) << logText();
}

// With SubVertexPlacement, interior samples move inside faces: quality (q = x) is interpolated
// exactly there too, and the topology is kept.
TEST_F(FilterInProcess, UniformRemeshWithSubVertexPlacement) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh bunny = test::loadRealMesh("bunny00.off");
  MeshModel* mm = addMesh(doc, bunny.positions, bunny.triangles);
  for (auto& v : mm->cm.vert) v.Q() = v.cP()[0];
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(3770));  // 10%
  params.setValue(filters::param::kSubVertexPlacement, BoolValue(true));
  ASSERT_TRUE(apply()) << logText();
  MeshModel* out = doc.mm();
  ASSERT_NE(out, mm);
  std::set<std::array<float, 3>> inputPositions;
  for (const auto& w : mm->cm.vert) inputPositions.insert({w.cP()[0], w.cP()[1], w.cP()[2]});
  int betweenVertices = 0;
  for (const auto& v : out->cm.vert) {
    EXPECT_NEAR(v.cQ(), v.cP()[0], 1e-5) << "quality not interpolated at the sample";
    betweenVertices += !inputPositions.count({v.cP()[0], v.cP()[1], v.cP()[2]});
  }
  EXPECT_GT(betweenVertices, out->cm.vn / 2) << "most interior samples should lie inside faces";
  const TriMesh& in = bunny;
  EXPECT_NE(logText().find("Topology kept: " + std::to_string(in.topology.components) + " components, genus " +
                           std::to_string(in.topology.genus) + ", " + std::to_string(in.topology.boundaryLoops) +
                           " boundary loops"),
            std::string::npos)
      << logText();
}

TEST_F(FilterInProcess, UniformRemeshBadInputLeavesTheDocumentAlone) {
  use("Remeshing: Geodesic Uniform");
  MeshModel* nonManifold =
      addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  declare(*nonManifold);
  expectCleanFailure(*nonManifold, StatusCode::NonManifold, "non-manifold edges");
  EXPECT_EQ(doc.meshList.size(), 1) << "a failed filter added a layer";
  const TriMesh grid = test::planeGrid(4);
  MeshModel* cloud = addMesh(doc, grid.positions, {});
  declare(*cloud);
  expectCleanFailure(*cloud, StatusCode::InvalidInput, "the mesh has no faces");
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* f = addMesh(doc, fandisk.positions, fandisk.triangles);
  declare(*f);
  params.setValue(filters::param::kTargetVertices, IntValue(100000));
  expectCleanFailure(*f, StatusCode::InvalidInput, "cannot place 100000 samples");
  declare(*f);
  params.setValue(filters::param::kTargetVertices, IntValue(0));
  params.setValue(filters::param::kSpacing, AbsPercValue(0.0f));
  expectCleanFailure(*f, StatusCode::InvalidInput, "give a target sample count or a spacing");
  declare(*f);
  params.setValue(filters::param::kRefinement, IntValue(7));
  expectCleanFailure(*f, StatusCode::InvalidInput, "Refinement must be 0 to 3");
  declare(*f);
  params.setValue(filters::param::kRelaxation, IntValue(-1));
  expectCleanFailure(*f, StatusCode::InvalidInput, "Relaxation must be 0 to 100 rounds");
  std::vector<Vec3> line = grid.positions;
  for (Vec3& x : line) x = Vec3(x.x(), 0, 0);  // the grid collapsed onto a segment
  MeshModel* flat = addMesh(doc, line, grid.triangles);
  declare(*flat);
  expectCleanFailure(*flat, StatusCode::InvalidInput, "zero area");
  EXPECT_EQ(doc.meshList.size(), 4) << "a failed filter added a layer";
}

// An input whose faces are not oriented coherently (blobby-shuffled.off: 3,069 edges whose two
// faces disagree) is remeshed on an oriented copy: a valid, oriented output, the input layer
// untouched. With Refinement the samples lie inside faces, some of them flipped in the copy: the
// quality q = x interpolated there must still be exact (the barycentric coordinates map back).
TEST_F(FilterInProcess, UniformRemeshOrientsAnIncoherentInput) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh blobby = test::loadRealMesh("blobby-shuffled.off");
  ASSERT_GT(blobby.topology.inconsistentEdges, 0);
  MeshModel* mm = addMesh(doc, blobby.positions, blobby.triangles);
  for (auto& v : mm->cm.vert) v.Q() = v.cP()[0];
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(300));
  params.setValue(filters::param::kRefinement, IntValue(1));
  const Snapshot before(*mm);
  ASSERT_TRUE(apply()) << logText();
  EXPECT_TRUE(Snapshot(*mm) == before) << "the input layer changed";
  MeshModel* out = doc.mm();
  ASSERT_NE(out, mm);
  std::vector<Vec3> pos;
  for (const auto& v : out->cm.vert) pos.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
  const std::vector<Tri> tris = faceIndices(*out);
  const test::Recount r = test::recount(tris, static_cast<int>(pos.size()));
  EXPECT_TRUE(r.closedManifoldEdges && r.oriented && r.manifoldVertices);
  EXPECT_EQ(r.components, 1);
  EXPECT_EQ(r.genusSum, 0);
  int insideFaces = 0;
  for (const auto& v : out->cm.vert) {
    EXPECT_NEAR(v.cQ(), v.cP()[0], 1e-5) << "quality not interpolated at the sample";
    bool isInputVertex = false;
    for (const auto& w : mm->cm.vert) isInputVertex = isInputVertex || w.cP() == v.cP();
    insideFaces += !isInputVertex;
  }
  EXPECT_GT(insideFaces, 0);
  EXPECT_NE(logText().find("faces run against their neighbours' orientation (3069 edges)"), std::string::npos)
      << logText();
}

TEST_F(FilterInProcess, UniformRemeshOfANonOrientableSurfaceFailsCleanly) {
  use("Remeshing: Geodesic Uniform");
  const TriMesh strip = test::moebiusStrip(40);
  MeshModel* mm = addMesh(doc, strip.positions, strip.triangles);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(20));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "not orientable");
  EXPECT_EQ(doc.meshList.size(), 1) << "a failed filter added a layer";
}

// --- Adaptive remeshing and total curvature ---------------------------------------------------

/// Vertices of `m` that are endpoints of an edge whose dihedral angle exceeds 60 degrees,
/// computed here from face normals (independently of the curvature code).
std::vector<char> onSharpEdges(const TriMesh& m) {
  std::vector<char> sharp(m.vertexCount(), 0);
  const auto normal = [&](int f) {
    const Tri& t = m.triangles[f];
    return Vec3((m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized());
  };
  for (int c = 0; c < 3 * m.faceCount(); ++c) {
    const int o = m.oppositeCorner[c];
    if (o < 0 || normal(TriMesh::face(c)).dot(normal(TriMesh::face(o))) > std::cos(60.0 * kPi / 180.0)) continue;
    sharp[m.vertex(TriMesh::next(c))] = sharp[m.vertex(TriMesh::prev(c))] = 1;
  }
  return sharp;
}

// Attractive total curvature on fandisk: the new layer keeps the topology, and its vertices
// gather on the sharp edges (a larger share of output vertices near them than the uniform run).
TEST_F(FilterInProcess, AdaptiveRemeshGathersVerticesOnSharpEdges) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  const std::vector<char> sharp = onSharpEdges(fandisk);
  const auto shareNearSharp = [&](const MeshModel& out) {
    // An output vertex is "near" when its nearest input vertex is on a sharp edge.
    int near = 0;
    for (const auto& v : out.cm.vert) {
      int best = 0;
      double bestD = 1e300;
      for (int w = 0; w < fandisk.vertexCount(); ++w) {
        const double d = (fandisk.positions[w] - Vec3(v.cP()[0], v.cP()[1], v.cP()[2])).squaredNorm();
        if (d < bestD) bestD = d, best = w;
      }
      near += sharp[best];
    }
    return double(near) / out.cm.vn;
  };
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  use("Remeshing: Geodesic Uniform");
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(647));
  ASSERT_TRUE(apply()) << logText();
  const double uniformShare = shareNearSharp(*doc.mm());
  doc.setCurrentMesh(mm->id());
  use("Remeshing: Geodesic Adaptive");
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(647));
  ASSERT_TRUE(apply()) << logText();
  MeshModel* out = doc.mm();
  ASSERT_NE(out, mm);
  EXPECT_EQ(doc.meshList.size(), 3);
  const double adaptiveShare = shareNearSharp(*out);
  std::printf("share of output vertices on sharp edges: uniform %.3f, adaptive %.3f\n", uniformShare, adaptiveShare);
  EXPECT_GT(adaptiveShare, 1.5 * uniformShare);
  EXPECT_NE(logText().find("Field: total curvature"), std::string::npos) << logText();
  EXPECT_NE(logText().find("mapping Attractive"), std::string::npos) << logText();
  EXPECT_NE(logText().find("Topology kept: 1 components, genus 0, 0 boundary loops"), std::string::npos) << logText();
  const auto tri = adapters::toCore(out->cm);
  ASSERT_TRUE(tri);
  EXPECT_TRUE(tri->mesh.topology.isManifold());
  EXPECT_EQ(tri->mesh.topology.inconsistentEdges, 0);
}

TEST_F(FilterInProcess, AdaptiveRemeshBadFieldsLeaveTheDocumentAlone) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  use("Remeshing: Geodesic Adaptive");
  declare(*mm);
  params.setValue(filters::param::kField, EnumValue(0));  // vertex quality, but the mesh has none
  expectCleanFailure(*mm, StatusCode::InvalidInput, "the mesh has no vertex quality");
  params.setValue(filters::param::kField, EnumValue(2));  // colour gradient, no colour
  expectCleanFailure(*mm, StatusCode::InvalidInput, "the mesh has no vertex colour");
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  for (auto& v : mm->cm.vert) v.Q() = v.cP()[0];  // negative values: not allowed with Attractive
  params.setValue(filters::param::kField, EnumValue(0));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "negative");
  params.setValue(filters::param::kStrength, FloatValue(std::numeric_limits<float>::quiet_NaN()));
  params.setValue(filters::param::kMapping, EnumValue(0));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "strength");
  params.setValue(filters::param::kMapping, EnumValue(7));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Mapping must be 0 to 2");
  params.setValue(filters::param::kMapping, EnumValue(1));
  params.setValue(filters::param::kStrength, FloatValue(4.0f));
  params.setValue(filters::param::kField, EnumValue(1));  // total curvature: valid again
  params.setValue(filters::param::kGradation, FloatValue(-0.5f));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "the gradation must be finite and >= 0");
  params.setValue(filters::param::kGradation, FloatValue(std::numeric_limits<float>::quiet_NaN()));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "the gradation must be finite and >= 0");
  params.setValue(filters::param::kGradation, FloatValue(0.4f));
  params.setValue(filters::param::kRelaxation, IntValue(-1));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Relaxation must be 0 to");
  EXPECT_EQ(doc.meshList.size(), 1) << "a failed filter added a layer";
}

// A non-manifold vertex (two fans of faces meeting at one vertex, common in CAD exports): the
// adaptive filter refuses it with the counts, as the uniform one does (it said "non-manifold
// edges or vertices" without any).
TEST_F(FilterInProcess, AdaptiveRemeshRefusesANonManifoldVertexWithTheCounts) {
  for (const char* filter : {"Remeshing: Geodesic Adaptive", "Remeshing: Geodesic Uniform"}) {
    SCOPED_TRACE(filter);
    use(filter);
    MeshModel* bowtie = addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
    declare(*bowtie);
    expectCleanFailure(*bowtie, StatusCode::NonManifold, "0 non-manifold edges and 1 non-manifold vertices");
  }
}

// The paper's texture-driven example (3.3): a colour edge (white for x < 0, black beyond) on
// fandisk; Attractive on the colour gradient gathers vertices along the edge.
TEST_F(FilterInProcess, AdaptiveRemeshFromColorGradient) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  mm->updateDataMask(MeshModel::MM_VERTCOLOR);
  for (auto& v : mm->cm.vert) v.C() = v.cP()[0] < 0 ? vcg::Color4b::White : vcg::Color4b::Black;
  const double h = fandisk.meanEdgeLength();
  const auto shareNearEdge = [&](const MeshModel& out) {
    int near = 0;
    for (const auto& v : out.cm.vert) near += std::abs(v.cP()[0]) < 2 * h;
    return double(near) / out.cm.vn;
  };
  use("Remeshing: Geodesic Uniform");
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(647));
  ASSERT_TRUE(apply()) << logText();
  const double uniformShare = shareNearEdge(*doc.mm());
  doc.setCurrentMesh(mm->id());
  use("Remeshing: Geodesic Adaptive");
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(647));
  params.setValue(filters::param::kField, EnumValue(2));
  ASSERT_TRUE(apply()) << logText();
  const double adaptiveShare = shareNearEdge(*doc.mm());
  std::printf("share of output vertices within 2 edge lengths of the colour edge: uniform %.3f, adaptive %.3f\n",
              uniformShare, adaptiveShare);
  EXPECT_GT(adaptiveShare, 2.0 * uniformShare);
  EXPECT_NE(logText().find("Field: colour intensity gradient"), std::string::npos) << logText();
}

// A constant quality is not an error: the remeshing falls back to a uniform speed and says so.
TEST_F(FilterInProcess, AdaptiveRemeshOnAConstantFieldFallsBackToUniform) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  for (auto& v : mm->cm.vert) v.Q() = 2.5f;
  use("Remeshing: Geodesic Adaptive");
  declare(*mm);
  params.setValue(filters::param::kField, EnumValue(0));
  params.setValue(filters::param::kTargetVertices, IntValue(300));
  ASSERT_TRUE(apply()) << logText();
  EXPECT_NE(logText().find("the field is constant"), std::string::npos) << logText();
  EXPECT_NE(logText().find("uniform speed"), std::string::npos) << logText();
  EXPECT_EQ(doc.meshList.size(), 2);
  EXPECT_EQ(doc.mm()->cm.vn, 300 + test::numberBefore(logText(), "added to make"));
}

// Any filter's quality drives it: a quality field (here Direct on q = x) is read and logged.
TEST_F(FilterInProcess, AdaptiveRemeshFromVertexQuality) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  for (auto& v : mm->cm.vert) v.Q() = v.cP()[0];
  use("Remeshing: Geodesic Adaptive");
  declare(*mm);
  params.setValue(filters::param::kField, EnumValue(0));
  params.setValue(filters::param::kMapping, EnumValue(0));  // Direct: any sign
  params.setValue(filters::param::kTargetVertices, IntValue(400));
  ASSERT_TRUE(apply()) << logText();
  EXPECT_NE(logText().find("Field: vertex quality"), std::string::npos) << logText();
  EXPECT_NE(logText().find("mapping Direct"), std::string::npos) << logText();
  // Direct, q = x: F grows with x, so the half with the larger x gets fewer vertices.
  float lo = 1e30f, hi = -1e30f;
  for (const auto& v : mm->cm.vert) lo = std::min(lo, v.cP()[0]), hi = std::max(hi, v.cP()[0]);
  int low = 0, high = 0;
  for (const auto& v : doc.mm()->cm.vert) (v.cP()[0] < 0.5f * (lo + hi) ? low : high)++;
  EXPECT_GT(low, high);
}

TEST_F(FilterInProcess, TotalCurvatureBadInputLeavesTheDocumentAlone) {
  use("Compute Total Curvature (Normal Cycle) into Vertex Quality");
  const TriMesh grid = test::planeGrid(4);
  MeshModel* cloud = addMesh(doc, grid.positions, {});
  declare(*cloud);
  expectCleanFailure(*cloud, StatusCode::InvalidInput, "the mesh has no faces");
  MeshModel* nonManifold =
      addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
  declare(*nonManifold);
  expectCleanFailure(*nonManifold, StatusCode::NonManifold, "non-manifold edges");
  MeshModel* nan = addMesh(doc, grid.positions, grid.triangles);
  nan->cm.vert[3].P()[1] = std::numeric_limits<float>::quiet_NaN();
  declare(*nan);
  expectCleanFailure(*nan, StatusCode::InvalidInput, "non-finite coordinate");
  MeshModel* good = addMesh(doc, grid.positions, grid.triangles);
  declare(*good);
  params.setValue(filters::param::kCurvatureRadius, AbsPercValue(-1.0f));
  expectCleanFailure(*good, StatusCode::InvalidInput, "curvature radius");
  EXPECT_EQ(doc.meshList.size(), 4) << "a failed filter added a layer";
}

// Two grids meeting at a corner (a non-manifold vertex): measured, flat everywhere, with the
// split vertex in the log (refused before).
TEST_F(FilterInProcess, TotalCurvatureAcceptsANonManifoldVertex) {
  const TriMesh bowtie = test::gridsMeetingAtACorner(8);
  MeshModel* mm = addMesh(doc, bowtie.positions, bowtie.triangles);
  use("Compute Total Curvature (Normal Cycle) into Vertex Quality");
  declare(*mm);
  ASSERT_TRUE(apply()) << logText();
  for (const auto& v : mm->cm.vert) ASSERT_NEAR(v.cQ(), 0.0f, 1e-5f);
  EXPECT_NE(logText().find("1 non-manifold vertices (fans of faces meeting at one vertex)"), std::string::npos)
      << logText();
}

TEST_F(FilterInProcess, TotalCurvatureOfASphereIsTwoOverR) {
  const double r = 2.5;
  const TriMesh sphere = test::icosphere(5, r);
  MeshModel* mm = addMesh(doc, sphere.positions, sphere.triangles);
  use("Compute Total Curvature (Normal Cycle) into Vertex Quality");
  declare(*mm);
  ASSERT_TRUE(apply()) << logText();
  EXPECT_TRUE(mm->hasDataMask(MeshModel::MM_VERTQUALITY));
  for (const auto& v : mm->cm.vert) ASSERT_NEAR(v.cQ(), 2.0 / r, 0.05 * 2.0 / r);
  EXPECT_NE(logText().find("written to vertex quality"), std::string::npos) << logText();
  EXPECT_EQ(doc.meshList.size(), 1);
}

/// An icosphere's faces as separate triangles (every face with its own three vertices).
void icosphereSoup(std::vector<Vec3>& positions, std::vector<Tri>& soup) {
  const TriMesh sphere = test::icosphere(2);
  for (const Tri& t : sphere.triangles) {
    const int first = static_cast<int>(positions.size());
    for (int v : t) positions.push_back(sphere.positions[v]);
    soup.push_back({first, first + 1, first + 2});
  }
}

// Issue 20: total curvature on a triangle soup is 0 at every vertex (no face has a neighbour to
// bend against), and the log says why and what to do instead of writing zeros silently.
TEST_F(FilterInProcess, TotalCurvatureOfATriangleSoupWarnsToMergeVertices) {
  std::vector<Vec3> positions;
  std::vector<Tri> soup;
  icosphereSoup(positions, soup);
  MeshModel* mm = addMesh(doc, positions, soup);
  use("Compute Total Curvature (Normal Cycle) into Vertex Quality");
  declare(*mm);
  ASSERT_TRUE(apply()) << logText();
  for (const auto& v : mm->cm.vert) ASSERT_EQ(v.cQ(), 0.0f);
  EXPECT_NE(logText().find("320 of the 320 faces share no edge"), std::string::npos) << logText();
  EXPECT_NE(logText().find("Merge Close Vertices"), std::string::npos) << logText();
}

// A triangle soup (every face with its own three vertices, as an STL read without merging):
// valid output with the input's topology (each face a component: the output is the input), and
// a warning that says what to do.
TEST_F(FilterInProcess, UniformRemeshOfATriangleSoupWarnsToMergeVertices) {
  std::vector<Vec3> positions;
  std::vector<Tri> soup;
  icosphereSoup(positions, soup);
  use("Remeshing: Geodesic Uniform");
  MeshModel* mm = addMesh(doc, positions, soup);
  declare(*mm);
  params.setValue(filters::param::kTargetVertices, IntValue(100));
  ASSERT_TRUE(apply()) << logText();
  MeshModel* out = doc.mm();
  ASSERT_NE(out, mm);
  test::expectValidWithTopologyOf(test::recount(faceIndices(*out), out->cm.vn),
                                  test::recount(soup, static_cast<int>(positions.size())));
  EXPECT_NE(logText().find("320 of the 320 faces share no edge"), std::string::npos) << logText();
  EXPECT_NE(logText().find("Merge Close Vertices"), std::string::npos) << logText();
}

// The soup with Refinement 0, 1 and 2 (issue 20: 2,365 of 2,444 facets came back split into 2-4
// triangles while the log said each keeps its three vertices; at 0 too, the coarse soup being
// refined for the fronts): the output's facets are the input's, compared as sets of corner
// positions.
TEST_F(FilterInProcess, UniformRemeshOfATriangleSoupWithRefinementGivesItsFacetsBack) {
  std::vector<Vec3> positions;
  std::vector<Tri> soup;
  icosphereSoup(positions, soup);
  using Facet = std::array<std::array<float, 3>, 3>;
  const auto facets = [](const std::vector<Vec3>& p, const std::vector<Tri>& tris) {
    std::vector<Facet> out;
    for (const Tri& t : tris) {
      Facet f;
      for (int k = 0; k < 3; ++k) f[k] = {float(p[t[k]].x()), float(p[t[k]].y()), float(p[t[k]].z())};
      std::sort(f.begin(), f.end());
      out.push_back(f);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  for (int refinement : {0, 1, 2}) {
    SCOPED_TRACE(refinement);
    use("Remeshing: Geodesic Uniform");
    MeshModel* mm = addMesh(doc, positions, soup);
    declare(*mm);
    params.setValue(filters::param::kTargetVertices, IntValue(100));
    params.setValue(filters::param::kRefinement, IntValue(refinement));
    ASSERT_TRUE(apply()) << logText();
    MeshModel* out = doc.mm();
    ASSERT_NE(out, mm);
    std::vector<Vec3> outPositions;
    for (const auto& v : out->cm.vert) outPositions.emplace_back(v.cP()[0], v.cP()[1], v.cP()[2]);
    const std::vector<Facet> got = facets(outPositions, faceIndices(*out)), want = facets(positions, soup);
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) ASSERT_EQ(got[i], want[i]) << "facet " << i;
    if (refinement > 0) {
      EXPECT_NE(logText().find("Refinement is not applied to a soup"), std::string::npos) << logText();
    }
  }
}

// A layer with deleted elements, as MeshLab leaves one after "Delete Selected Faces" and
// "Delete Selected Vertices" (nothing compacted): each filter must give on its live part exactly
// what it gives on the same mesh stored compactly, whatever the deleted slots hold (a NaN here).
TEST_F(FilterInProcess, EveryFilterIgnoresDeletedElements) {
  const TriMesh sphere = test::icosphere(4);
  MeshModel* holed = addMesh(doc, sphere.positions, sphere.triangles);
  // Delete the cap z > 0.6 (faces, then the vertices left without a face): a disk remains.
  CMeshO& h = holed->cm;
  std::vector<char> used(h.vert.size(), 0);
  for (auto& f : h.face) {
    if (f.cV(0)->cP()[2] > 0.6f && f.cV(1)->cP()[2] > 0.6f && f.cV(2)->cP()[2] > 0.6f) {
      vcg::tri::Allocator<CMeshO>::DeleteFace(h, f);
      continue;
    }
    for (int k = 0; k < 3; ++k) used[f.cV(k) - &h.vert[0]] = 1;
  }
  std::vector<int> compactIndex(h.vert.size(), -1);
  std::vector<Vec3> livePositions;
  for (size_t i = 0; i < h.vert.size(); ++i) {
    if (!used[i]) {
      vcg::tri::Allocator<CMeshO>::DeleteVertex(h, h.vert[i]);
      continue;
    }
    compactIndex[i] = static_cast<int>(livePositions.size());
    livePositions.push_back(sphere.positions[i]);
  }
  ASSERT_GT(h.vert.size() - h.vn, 10u);
  for (auto& v : h.vert)
    if (v.IsD()) v.P()[0] = std::numeric_limits<float>::quiet_NaN();  // never to be read
  std::vector<Tri> liveTriangles;
  for (const auto& f : h.face)
    if (!f.IsD())
      liveTriangles.push_back(
          {compactIndex[f.cV(0) - &h.vert[0]], compactIndex[f.cV(1) - &h.vert[0]], compactIndex[f.cV(2) - &h.vert[0]]});
  MeshModel* compact = addMesh(doc, livePositions, liveTriangles);
  const std::vector<int> liveSlots = [&] {
    std::vector<int> live;  // (not "slots": a Qt macro)
    for (size_t i = 0; i < h.vert.size(); ++i)
      if (!h.vert[i].IsD()) live.push_back(static_cast<int>(i));
    return live;
  }();
  h.vert[liveSlots[0]].SetS();
  compact->cm.vert[0].SetS();

  for (const char* filter :
       {"Geodesic Distance: Fast Marching from Selected Vertices", "Remeshing: Geodesic Uniform",
        "Remeshing: Geodesic Adaptive", "Compute Total Curvature (Normal Cycle) into Vertex Quality",
        "Remeshing: Geodesic Semi-Regular", "Parametrization: Geodesic Barycentric"}) {
    SCOPED_TRACE(filter);
    use(filter);
    const bool overBase = std::string(filter) == "Remeshing: Geodesic Semi-Regular" ||
                          std::string(filter) == "Parametrization: Geodesic Barycentric";
    MeshModel* out[2] = {nullptr, nullptr};
    MeshModel* in[2] = {holed, compact};
    for (int i = 0; i < 2; ++i) {
      doc.setCurrent(in[i]);
      declare(*in[i]);
      if (std::string(filter) == "Remeshing: Geodesic Uniform")
        params.setValue(filters::param::kTargetVertices, IntValue(300));
      if (overBase) params.setValue(filters::param::kBaseVertices, IntValue(60));
      if (std::string(filter) == "Remeshing: Geodesic Semi-Regular")
        params.setValue(filters::param::kLevels, IntValue(1));
      ASSERT_TRUE(apply()) << logText();
      out[i] = doc.mm();
    }
    if (out[0] == holed) {  // a field written into the input: compare it per live vertex
      for (size_t k = 0; k < liveSlots.size(); ++k)
        ASSERT_EQ(h.vert[liveSlots[k]].cQ(), compact->cm.vert[k].cQ()) << "live vertex " << k;
      continue;
    }
    ASSERT_NE(out[0], holed);
    ASSERT_NE(out[1], compact);
    ASSERT_EQ(out[0]->cm.vn, out[1]->cm.vn);
    ASSERT_EQ(out[0]->cm.fn, out[1]->cm.fn);
    for (int k = 0; k < out[0]->cm.vn; ++k) {
      ASSERT_EQ(out[0]->cm.vert[k].cP(), out[1]->cm.vert[k].cP()) << k;
      ASSERT_EQ(out[0]->cm.vert[k].cQ(), out[1]->cm.vert[k].cQ()) << k;
    }
    EXPECT_EQ(faceIndices(*out[0]), faceIndices(*out[1]));
    const test::Recount r = test::recount(faceIndices(*out[0]), out[0]->cm.vn);
    test::expectValidWithTopologyOf(r, test::recount(liveTriangles, static_cast<int>(livePositions.size())));
    EXPECT_EQ(r.boundaryLoops, 1);
  }
}

// Every script of resources/ lists exactly the parameters its filter declares: MeshLab 2020.09's
// meshlabserver aborts (an assertion) on a script with a parameter missing, so a parameter added to
// a filter must be added to every script that runs it.
TEST_F(FilterInProcess, EveryScriptListsExactlyTheDeclaredParameters) {
  const TriMesh grid = test::planeGrid(8);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  int scripts = 0;
  for (const char* dir : {"/resources", "/resources/acceptance"})
    for (const auto& entry : std::filesystem::directory_iterator(std::string(GR_SOURCE_DIR) + dir)) {
      if (entry.path().extension() != ".mlx") continue;
      std::ifstream in(entry.path());
      const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
      const std::regex filterBlock("<filter name=\"([^\"]+)\">([\\s\\S]*?)</filter>");
      const std::regex paramName("<Param [^>]*name=\"([^\"]+)\"");
      for (std::sregex_iterator f(text.begin(), text.end(), filterBlock), end; f != end; ++f) {
        SCOPED_TRACE(entry.path().filename().string() + ": " + (*f)[1].str());
        const QList<QAction*> ours = plugin.actions();
        if (std::none_of(ours.begin(), ours.end(),
                         [&](QAction* a) { return a->text().toStdString() == (*f)[1].str(); }))
          continue;  // one of MeshLab's own filters (e.g. Conditional Vertex Selection)
        use((*f)[1].str().c_str());
        declare(*mm);
        const std::string body = (*f)[2].str();
        std::set<std::string> listed;
        for (std::sregex_iterator q(body.begin(), body.end(), paramName); q != end; ++q) {
          listed.insert((*q)[1].str());
          EXPECT_TRUE(params.hasParameter(QString::fromStdString((*q)[1].str())))
              << (*q)[1].str() << " is not declared";
        }
        EXPECT_EQ(listed.size(), static_cast<size_t>(params.size()))
            << "a declared parameter is missing from the script";
        ++scripts;
      }
    }
  EXPECT_GE(scripts, 20);
}

// --- Texture atlas and LLE flattening -------------------------------------------------------------

/// The wedge texture coordinates of a layer judged by the atlas oracle: no flip, no zero area, no
/// overlap, all in the unit square.
void expectValidAtlas(const MeshModel& mm) {
  ASSERT_TRUE(mm.hasDataMask(MeshModel::MM_WEDGTEXCOORD));
  std::vector<std::array<Eigen::Vector2d, 3>> triangles;
  Eigen::Vector2d lo(INFINITY, INFINITY), hi(-INFINITY, -INFINITY);
  for (const auto& f : mm.cm.face) {
    std::array<Eigen::Vector2d, 3> t;
    for (int k = 0; k < 3; ++k) {
      t[k] = Eigen::Vector2d(f.cWT(k).U(), f.cWT(k).V());
      lo = lo.cwiseMin(t[k]);
      hi = hi.cwiseMax(t[k]);
    }
    triangles.push_back(t);
  }
  // The LLE flattening is not packed: bring it into the unit square first (a similarity).
  const double size = std::max((hi - lo).maxCoeff(), 1e-300);
  for (auto& t : triangles)
    for (auto& q : t) q = hi.maxCoeff() <= 1.0 && lo.minCoeff() >= 0.0 ? q : Eigen::Vector2d((q - lo) / size);
  const oracle::UvAtlasCheck c = oracle::checkUvAtlas(triangles);
  EXPECT_EQ(c.flipped, 0);
  EXPECT_EQ(c.zeroArea, 0);
  EXPECT_EQ(c.overlaps, 0);
  EXPECT_EQ(c.outsideUnitSquare, 0);
}

/// The layer of "Parametrization: Geodesic Barycentric" with `triangles` base triangles: its
/// wedge texture coordinates (floats, as MeshLab holds them) give every face a positive area, and
/// the faces whose centroid lies in tile (i, j) of the ceil(sqrt(triangles)) grid add up to the
/// area of the tile's triangle (corners at the tile's margin 0.05, a right triangle): with
/// positive faces whose images end on the triangle's sides, area adding up means they tile it,
/// no gap and no overlap (the degree of the map is 1). Cheaper than the atlas oracle's
/// pairwise test on layers of 100k faces.
void expectTiles(const MeshModel& mm, int triangles) {
  ASSERT_TRUE(mm.hasDataMask(MeshModel::MM_WEDGTEXCOORD));
  const int g = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(triangles))));
  const double side = (1.0 - 2.0 * 0.05) / g;
  std::vector<double> area(static_cast<size_t>(g) * g, 0.0);
  int flipped = 0, outside = 0;
  for (const auto& f : mm.cm.face) {
    if (f.IsD()) continue;
    Eigen::Vector2d q[3];
    for (int k = 0; k < 3; ++k) q[k] = Eigen::Vector2d(f.cWT(k).U(), f.cWT(k).V());
    const double a = 0.5 * ((q[1] - q[0]).x() * (q[2] - q[0]).y() - (q[1] - q[0]).y() * (q[2] - q[0]).x());
    flipped += !(a > 0.0);
    const Eigen::Vector2d c = (q[0] + q[1] + q[2]) / 3.0;
    const int i = static_cast<int>(c.x() * g), j = static_cast<int>(c.y() * g);
    if (i < 0 || j < 0 || i >= g || j >= g) {
      ++outside;
      continue;
    }
    area[static_cast<size_t>(j) * g + i] += a;
  }
  EXPECT_EQ(flipped, 0);
  EXPECT_EQ(outside, 0);
  int wrong = 0;
  for (int t = 0; t < triangles; ++t) wrong += std::abs(area[t] - 0.5 * side * side) > 1e-4 * side * side;
  for (size_t t = triangles; t < area.size(); ++t) wrong += area[t] != 0.0;
  EXPECT_EQ(wrong, 0) << "tiles whose faces do not add up to their triangle";
}

TEST_F(FilterInProcess, TextureAtlasWritesTheCoresWedgeUvsAndATexture) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  use("Parametrization: Geodesic Texture Atlas");
  declare(*mm);
  const AtlasParams d;
  EXPECT_EQ(params.getInt(filters::param::kRegions), d.segmentation.regions);
  EXPECT_EQ(params.getInt(filters::param::kIterations), d.segmentation.lloyd.iterations);
  EXPECT_FLOAT_EQ(params.getFloat(filters::param::kFeatureAlignment), float(d.segmentation.featureAlignment));
  EXPECT_FLOAT_EQ(params.getFloat(filters::param::kSharpEdgeAngle), float(d.segmentation.sharpEdgeAngle));
  EXPECT_EQ(params.getInt(filters::param::kBasePoints), d.flattening.basePoints);
  EXPECT_EQ(params.getInt(filters::param::kNeighbours), d.flattening.neighbours);
  EXPECT_EQ(params.getInt(filters::param::kTextureSize), d.textureSize);
  EXPECT_EQ(params.getInt(filters::param::kGutter), d.gutter);
  ASSERT_TRUE(apply()) << plugin.errorMsg().toStdString();
  const Expected<adapters::CoreView> seen = adapters::toCore(mm->cm);  // as the filter sees it (float)
  ASSERT_TRUE(seen);
  const Expected<AtlasResult> core = buildTextureAtlas(seen->mesh, d);
  ASSERT_TRUE(core);
  double worst = 0.0;
  for (int f = 0; f < fandisk.faceCount(); ++f)
    for (int k = 0; k < 3; ++k)
      worst = std::max({worst, std::abs(mm->cm.face[f].WT(k).U() - core->cornerUv[3 * f + k].x()),
                        std::abs(mm->cm.face[f].WT(k).V() - core->cornerUv[3 * f + k].y())});
  EXPECT_LT(worst, 1e-6) << "the filter's UVs are not the core's";
  expectValidAtlas(*mm);
  ASSERT_EQ(mm->cm.textures.size(), 1u);
  EXPECT_TRUE(std::filesystem::exists(mm->cm.textures[0])) << mm->cm.textures[0];
  const std::string text = logText();
  EXPECT_NE(text.find("charts"), std::string::npos) << text;
  EXPECT_NE(text.find("stretch"), std::string::npos) << text;
  EXPECT_NE(text.find("Time:"), std::string::npos) << text;
}

TEST_F(FilterInProcess, TextureAtlasBadInputLeavesTheDocumentAlone) {
  const TriMesh grid = test::planeGrid(10);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  use("Parametrization: Geodesic Texture Atlas");
  declare(*mm);
  params.setValue(filters::param::kTextureSize, IntValue(8));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "TextureSize");
  declare(*mm);
  params.setValue(filters::param::kNeighbours, IntValue(2));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Neighbours");
  declare(*mm);
  params.setValue(filters::param::kRegions, IntValue(0));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Regions");
}

// A cube of 12 faces at the filter's defaults (30 regions): an atlas of at most 12 / 4 charts, with
// the lowered count in the log (refused before: regions without faces).
TEST_F(FilterInProcess, TextureAtlasOfACubeAtTheDefaults) {
  const TriMesh cube = test::unitCube();
  MeshModel* mm = addMesh(doc, cube.positions, cube.triangles);
  use("Parametrization: Geodesic Texture Atlas");
  declare(*mm);
  ASSERT_EQ(params.getInt(filters::param::kRegions), 30);
  ASSERT_TRUE(apply()) << logText();
  expectValidAtlas(*mm);
  EXPECT_NE(logText().find("Regions lowered from 30 to 3: at most one chart per 4 faces"), std::string::npos)
      << logText();
}

// Two grids meeting at a corner (one non-manifold vertex): segmented and given an atlas, with the
// split vertex in the log (both filters refused it before).
TEST_F(FilterInProcess, SegmentationAndAtlasAcceptANonManifoldVertex) {
  const TriMesh bowtie = test::gridsMeetingAtACorner(10);
  for (const char* filter :
       {"Segmentation: Geodesic Centroidal Tessellation", "Parametrization: Geodesic Texture Atlas"}) {
    SCOPED_TRACE(filter);
    MeshModel* mm = addMesh(doc, bowtie.positions, bowtie.triangles);
    use(filter);
    declare(*mm);
    ASSERT_TRUE(apply()) << logText();
    EXPECT_NE(logText().find("1 non-manifold vertices (fans of faces meeting at one vertex)"), std::string::npos)
        << logText();
  }
}

TEST_F(FilterInProcess, LleFlatteningOfADiskWithAFlatLayer) {
  const TriMesh grid = test::planeGrid(30, 1.0, 0.2);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  use("Parametrization: Geodesic LLE Flattening");
  declare(*mm);
  EXPECT_EQ(params.getInt(filters::param::kBasePoints), LleFlatteningParams().basePoints);
  EXPECT_EQ(params.getInt(filters::param::kNeighbours), LleFlatteningParams().neighbours);
  params.setValue(filters::param::kFlatLayer, BoolValue(true));
  const size_t layers = doc.meshList.size();
  ASSERT_TRUE(apply()) << plugin.errorMsg().toStdString();
  ASSERT_TRUE(mm->hasDataMask(MeshModel::MM_VERTTEXCOORD));
  expectValidAtlas(*mm);
  ASSERT_EQ(doc.meshList.size(), layers + 1);
  const MeshModel* flat = doc.meshList.back();
  ASSERT_EQ(flat->cm.vn, mm->cm.vn);
  for (int v = 0; v < flat->cm.vn; ++v) {
    EXPECT_EQ(flat->cm.vert[v].cP()[2], 0.0f);
    EXPECT_EQ(flat->cm.vert[v].cP()[0], mm->cm.vert[v].cT().U());
  }
  // A plane flattens to itself: UV distances are the 3D ones up to one scale.
  const auto uvDistance = [&](int a, int b) {
    return std::hypot(mm->cm.vert[a].cT().U() - mm->cm.vert[b].cT().U(),
                      mm->cm.vert[a].cT().V() - mm->cm.vert[b].cT().V());
  };
  const double scale = uvDistance(0, 30) / (grid.positions[30] - grid.positions[0]).norm();
  EXPECT_NEAR(uvDistance(0, 960) / (grid.positions[960] - grid.positions[0]).norm(), scale, 0.02 * scale);
}

TEST_F(FilterInProcess, AtlasAndFlatteningRefuseBadMeshesCleanly) {
  for (const char* filter : {"Parametrization: Geodesic Texture Atlas", "Parametrization: Geodesic LLE Flattening"}) {
    SCOPED_TRACE(filter);
    use(filter);
    MeshModel* cloud = addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {});
    declare(*cloud);
    expectCleanFailure(*cloud, StatusCode::InvalidInput, "the mesh has no faces");
    TriMesh grid = test::planeGrid(10);
    grid.positions[7].y() = NAN;
    MeshModel* nan = addMesh(doc, grid.positions, grid.triangles);
    declare(*nan);
    expectCleanFailure(*nan, StatusCode::InvalidInput, "non-finite");
    // Three triangles on one edge.
    MeshModel* nm =
        addMesh(doc, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    declare(*nm);
    expectCleanFailure(*nm, StatusCode::NonManifold, "non-manifold");
  }
}

TEST_F(FilterInProcess, LleFlatteningRefusesWhatIsNotADisk) {
  const TriMesh sphere = test::icosphere(3);
  MeshModel* mm = addMesh(doc, sphere.positions, sphere.triangles);
  use("Parametrization: Geodesic LLE Flattening");
  declare(*mm);
  expectCleanFailure(*mm, StatusCode::InvalidInput, "topological disk");
  const TriMesh grid = test::planeGrid(10);
  MeshModel* g = addMesh(doc, grid.positions, grid.triangles);
  declare(*g);
  params.setValue(filters::param::kNeighbours, IntValue(100));
  expectCleanFailure(*g, StatusCode::InvalidInput, "neighbours");
}

// --- Segmentation ------------------------------------------------------------------------------

/// The regions in the face quality: every one an edge-connected topological disk (recounted), as
/// many as the log's "N regions; A asked, B added" says, and A + B = N.
void expectDiskRegions(const MeshModel& mm, const std::string& log) {
  const int regions = test::numberBefore(log, "regions;");
  const int asked = test::numberBefore(log, "asked,");
  const int added = test::numberBefore(log, "added to make every region a disk");
  ASSERT_GT(regions, 0) << log;
  EXPECT_EQ(regions, asked + added);
  std::vector<std::vector<Tri>> faces(regions);
  const CVertexO* const first = &mm.cm.vert[0];
  std::vector<int> compact(mm.cm.vert.size(), -1);
  int n = 0;
  for (size_t i = 0; i < mm.cm.vert.size(); ++i)
    if (!mm.cm.vert[i].IsD()) compact[i] = n++;
  for (const auto& f : mm.cm.face) {
    if (f.IsD()) continue;
    const int r = static_cast<int>(f.cQ());
    ASSERT_GE(r, 0);
    ASSERT_LT(r, regions);
    faces[r].push_back({compact[f.cV(0) - first], compact[f.cV(1) - first], compact[f.cV(2) - first]});
  }
  for (int r = 0; r < regions; ++r) {
    ASSERT_FALSE(faces[r].empty()) << "region " << r << " has no face";
    const test::Recount rc = test::recount(faces[r], n);
    EXPECT_TRUE(rc.components == 1 && rc.eulerCharacteristic == 1 && rc.boundaryLoops == 1 && rc.manifoldVertices)
        << "region " << r << ": components " << rc.components << ", chi " << rc.eulerCharacteristic << ", loops "
        << rc.boundaryLoops;
  }
}

TEST_F(FilterInProcess, SegmentationWritesDiskRegionsAsTheCoreDoes) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  use("Segmentation: Geodesic Centroidal Tessellation");
  declare(*mm);
  const SegmentationParams defaults;
  EXPECT_EQ(params.getInt(filters::param::kRegions), defaults.regions);
  EXPECT_EQ(params.getInt(filters::param::kIterations), defaults.lloyd.iterations);
  EXPECT_FLOAT_EQ(params.getFloat(filters::param::kFeatureAlignment), float(defaults.featureAlignment));
  EXPECT_FLOAT_EQ(params.getFloat(filters::param::kSharpEdgeAngle), float(defaults.sharpEdgeAngle));
  EXPECT_EQ(params.getInt(filters::param::kSeed), int(defaults.seed));
  params.setValue(filters::param::kRegions, IntValue(20));
  params.setValue(filters::param::kSplitIntoLayers, BoolValue(true));
  const size_t layers = doc.meshList.size();
  ASSERT_TRUE(apply()) << logText();
  EXPECT_TRUE(mm->hasDataMask(MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR));
  expectDiskRegions(*mm, logText());
  // The same regions as the core's, with the same parameters.
  SegmentationParams p;
  p.regions = 20;
  // The core on the mesh as the filter sees it (MeshLab holds coordinates as float).
  const Expected<adapters::CoreView> seen = adapters::toCore(mm->cm);
  ASSERT_TRUE(seen);
  const Expected<SegmentationResult> core = segmentSurface(seen->mesh, {}, p);
  ASSERT_TRUE(core);
  ASSERT_EQ(static_cast<int>(mm->cm.face.size()), fandisk.faceCount());
  int selected = 0, cut = 0;
  for (int f = 0; f < fandisk.faceCount(); ++f) {
    EXPECT_EQ(static_cast<int>(mm->cm.face[f].cQ()), core->faceRegion[f]) << "face " << f;
    bool onBoundary = false;
    for (int c = 3 * f; c < 3 * f + 3; ++c) {
      const int o = fandisk.oppositeCorner[c];
      onBoundary = onBoundary || (o >= 0 && core->faceRegion[TriMesh::face(o)] != core->faceRegion[f]);
    }
    cut += onBoundary;
    selected += mm->cm.face[f].IsS();
    EXPECT_EQ(mm->cm.face[f].IsS(), onBoundary) << "face " << f;
  }
  EXPECT_GT(selected, 0);
  EXPECT_EQ(selected, cut);
  // One layer per region, holding that region's faces.
  ASSERT_EQ(doc.meshList.size(), layers + static_cast<size_t>(core->regions));
  int layerFaces = 0;
  for (const MeshModel* layer : doc.meshList)
    if (layer != mm) layerFaces += layer->cm.fn;
  EXPECT_EQ(layerFaces, fandisk.faceCount());
  EXPECT_NE(logText().find("Time:"), std::string::npos);
  EXPECT_NE(logText().find("Fronts stopped at " + std::to_string(core->sharpEdges) + " sharp edges"), std::string::npos)
      << logText();
}

// CentroidalIterations on both remeshing filters: a valid remesh of the input's topology at the
// count asked for, the core's own; out of range, a clean failure.
TEST_F(FilterInProcess, RemeshWithCentroidalIterations) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  const test::Recount in = test::recount(fandisk.triangles, fandisk.vertexCount());
  for (const char* name : {"Remeshing: Geodesic Uniform", "Remeshing: Geodesic Adaptive"}) {
    SCOPED_TRACE(name);
    use(name);
    doc.setCurrent(mm);
    declare(*mm);
    params.setValue(filters::param::kCentroidalIterations, IntValue(-1));
    expectCleanFailure(*mm, StatusCode::InvalidInput, "CentroidalIterations");
    params.setValue(filters::param::kCentroidalIterations, IntValue(3));
    ASSERT_TRUE(apply()) << logText();
    const MeshModel* out = doc.mm();
    ASSERT_NE(out, mm);
    test::expectValidWithTopologyOf(test::recount(faceIndices(*out), out->cm.vn), in);
  }
}

TEST_F(FilterInProcess, SegmentationBadInputLeavesTheDocumentAlone) {
  const TriMesh grid = test::planeGrid(6);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  use("Segmentation: Geodesic Centroidal Tessellation");
  declare(*mm);
  params.setValue(filters::param::kRegions, IntValue(0));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Regions");
  params.setValue(filters::param::kRegions, IntValue(100000));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Regions");
  params.setValue(filters::param::kRegions, IntValue(4));
  params.setValue(filters::param::kIterations, IntValue(-1));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Iterations");
  params.setValue(filters::param::kIterations, IntValue(2));
  params.setValue(filters::param::kFeatureAlignment, FloatValue(-1.0f));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "feature alignment");
  params.setValue(filters::param::kFeatureAlignment, FloatValue(1.0f));
  params.setValue(filters::param::kSharpEdgeAngle, FloatValue(200.0f));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "sharp edge angle");
  params.setValue(filters::param::kSharpEdgeAngle, FloatValue(60.0f));
  params.setValue(filters::param::kUseQualityAsSpeed, BoolValue(true));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "quality");
  // Zero speed from the quality: the quality is the field of an Attractive speed, so a negative
  // value is refused, naming the vertex.
  mm->updateDataMask(MeshModel::MM_VERTQUALITY);
  for (auto& v : mm->cm.vert) v.Q() = -1.0f;
  expectCleanFailure(*mm, StatusCode::InvalidInput, "vertex");
}

// --- Semi-regular remeshing and geodesic barycentric parameterisation (issue 21) ----------------

TEST_F(FilterInProcess, SemiRegularMakesANewLayerAsTheCoreDoes) {
  const TriMesh fandisk = test::loadRealMesh("fandisk.off");
  MeshModel* mm = addMesh(doc, fandisk.positions, fandisk.triangles);
  use("Remeshing: Geodesic Semi-Regular");
  declare(*mm);
  const SemiRegularParams d;
  EXPECT_EQ(params.getInt(filters::param::kBaseVertices), d.base.baseVertices);
  EXPECT_EQ(params.getInt(filters::param::kCentroidalIterations), d.base.centroidalIterations);
  EXPECT_EQ(params.getInt(filters::param::kSeed), int(d.base.seed));
  EXPECT_EQ(params.getInt(filters::param::kLevels), d.levels);
  params.setValue(filters::param::kBaseVertices, IntValue(80));
  params.setValue(filters::param::kLevels, IntValue(2));
  const Snapshot before(*mm);
  ASSERT_TRUE(apply()) << logText();
  EXPECT_TRUE(Snapshot(*mm) == before) << "the input layer changed";
  ASSERT_EQ(doc.meshList.size(), 2);
  const MeshModel* out = doc.mm();
  SemiRegularParams p;
  p.base.baseVertices = 80;
  p.levels = 2;
  const Expected<SemiRegularResult> core = semiRegularRemesh(fandisk, p);
  ASSERT_TRUE(core);
  EXPECT_EQ(out->cm.vn, core->mesh.vertexCount());
  EXPECT_EQ(faceIndices(*out), core->mesh.triangles);
  test::expectValidWithTopologyOf(test::recount(faceIndices(*out), out->cm.vn),
                                  test::recount(fandisk.triangles, fandisk.vertexCount()));
  EXPECT_EQ(test::numberBefore(logText(), "base vertices ("), core->baseVertices) << logText();
  EXPECT_NE(logText().find("Hausdorff distance"), std::string::npos) << logText();
}

TEST_F(FilterInProcess, GeodesicBarycentricWritesTiledUvsOnANewLayer) {
  const TriMesh bunny = test::loadRealMesh("bunny00.off");
  MeshModel* mm = addMesh(doc, bunny.positions, bunny.triangles);
  use("Parametrization: Geodesic Barycentric");
  declare(*mm);
  params.setValue(filters::param::kBaseVertices, IntValue(100));
  const Snapshot before(*mm);
  ASSERT_TRUE(apply()) << logText();
  EXPECT_TRUE(Snapshot(*mm) == before) << "the input layer changed";
  ASSERT_EQ(doc.meshList.size(), 2);
  const MeshModel* out = doc.mm();
  expectValidAtlas(*out);
  expectTiles(*out, test::numberBefore(logText(), "base triangles"));
  EXPECT_EQ(out->cm.textures.size(), 1u);
  // The new layer is the input surface, its first vertices the input's; the quality is a base triangle.
  for (int v = 0; v < mm->cm.vn; v += 97) EXPECT_EQ(out->cm.vert[v].cP(), mm->cm.vert[v].cP());
  const int triangles = test::numberBefore(logText(), "base triangles");
  ASSERT_GT(triangles, 100);
  int outOfRange = 0;
  for (const auto& v : out->cm.vert) outOfRange += v.cQ() < 0 || v.cQ() >= triangles;
  EXPECT_EQ(outOfRange, 0);
  test::expectValidWithTopologyOf(test::recount(faceIndices(*out), out->cm.vn),
                                  test::recount(bunny.triangles, bunny.vertexCount()));
}

TEST_F(FilterInProcess, SemiRegularAndBarycentricBadInputLeavesTheDocumentAlone) {
  const TriMesh grid = test::planeGrid(10);
  MeshModel* mm = addMesh(doc, grid.positions, grid.triangles);
  use("Remeshing: Geodesic Semi-Regular");
  declare(*mm);
  params.setValue(filters::param::kLevels, IntValue(7));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "Levels");
  declare(*mm);
  params.setValue(filters::param::kBaseVertices, IntValue(3));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "BaseVertices");
  use("Parametrization: Geodesic Barycentric");
  declare(*mm);
  params.setValue(filters::param::kCentroidalIterations, IntValue(-1));
  expectCleanFailure(*mm, StatusCode::InvalidInput, "CentroidalIterations");
  EXPECT_EQ(doc.meshList.size(), 1u);
}

// --- Every filter over every mesh of the data set ----------------------------------------------

/// The data set's mesh files that loadTriMesh reads as triangle meshes (point clouds left out).
std::vector<std::string> dataSetTriangleMeshes() {
  std::vector<std::string> names;
  for (const std::string& name : test::dataSetMeshFiles())
    if (loadTriMesh(test::meshPath(name))) names.push_back(name);
  if (names.empty()) names.push_back("(no triangle mesh found in " + std::string(GR_MESH_DIR) + ")");
  return names;
}

class FilterDataSetSweep : public FilterInProcess, public ::testing::WithParamInterface<std::string> {};

// Each filter with its defaults on the mesh (vertex 0 selected for the fast marching): it succeeds
// (a remeshing then leaves a manifold, oriented mesh with the input's components, genus and
// boundary loops, recounted here, on a new layer), or it fails with a message in the log and the
// input exactly as it was.
TEST_P(FilterDataSetSweep, EveryFilterSucceedsOrFailsCleanly) {
  const Expected<TriMesh> input = loadTriMesh(test::meshPath(GetParam()));
  ASSERT_TRUE(input) << input.status().message;
  const test::Recount in = test::recount(input->triangles, input->vertexCount());
  MeshModel* mm = addMesh(doc, input->positions, input->triangles);
  mm->cm.vert[0].SetS();
  for (const char* filter :
       {"Geodesic Distance: Fast Marching from Selected Vertices", "Remeshing: Geodesic Uniform",
        "Remeshing: Geodesic Adaptive", "Compute Total Curvature (Normal Cycle) into Vertex Quality",
        "Segmentation: Geodesic Centroidal Tessellation", "Parametrization: Geodesic Texture Atlas",
        "Parametrization: Geodesic LLE Flattening", "Remeshing: Geodesic Semi-Regular",
        "Parametrization: Geodesic Barycentric"}) {
    SCOPED_TRACE(filter);
    use(filter);
    doc.setCurrent(mm);
    declare(*mm);
    const size_t layers = doc.meshList.size();
    const Snapshot before(*mm);
    if (!apply()) {
      const std::string message = plugin.errorMsg().toStdString();
      EXPECT_FALSE(message.empty());
      EXPECT_NE(logText().find(message), std::string::npos) << "log:\n" << logText();
      EXPECT_TRUE(Snapshot(*mm) == before) << "a failed filter changed the mesh: " << message;
      EXPECT_EQ(doc.meshList.size(), layers) << "a failed filter added a layer";
      continue;
    }
    if (std::string(filter).rfind("Segmentation", 0) == 0) {
      expectDiskRegions(*mm, logText());
      continue;
    }
    if (std::string(filter) == "Parametrization: Geodesic Barycentric") {  // on a new layer
      EXPECT_TRUE(Snapshot(*mm) == before) << "the input layer changed";
      ASSERT_EQ(doc.meshList.size(), layers + 1);
      const std::string text = logText();  // the whole run's log: this filter's line is the last
      expectTiles(*doc.mm(), test::numberBefore(text.substr(text.rfind("Geodesic barycentric")), "base triangles"));
      continue;
    }
    if (std::string(filter).rfind("Parametrization", 0) == 0) {
      expectValidAtlas(*mm);
      continue;
    }
    if (std::string(filter).rfind("Remeshing", 0) != 0) continue;
    EXPECT_TRUE(Snapshot(*mm) == before) << "the input layer changed";
    ASSERT_EQ(doc.meshList.size(), layers + 1);
    const MeshModel* out = doc.mm();
    test::expectValidWithTopologyOf(test::recount(faceIndices(*out), out->cm.vn), in);
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, FilterDataSetSweep, ::testing::ValuesIn(dataSetTriangleMeshes()),
                         [](const auto& mesh) { return test::testNameOfFile(mesh.param); });

}  // namespace
}  // namespace gr
