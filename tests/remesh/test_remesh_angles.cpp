// Triangle quality of the uniform remeshing at its defaults against CGAL's isotropic remeshing
// (issue 20, point 3), over the data set at 5%, 10% and 30%:
// - on every mesh of the population listed below, the smallest angle and the share of triangles
//   with an angle under 30 degrees at least as good as CGAL's with 10 iterations at the same count
//   (CGAL runs here, on the same mesh). At 10% the relaxation that raises the smallest angle, the
//   vertices sliding along boundaries and creases, the angle rescue (remesh_surface.h) and the
//   polish of the final output (polishOnSurface: homer, oblong, retinal, sphere966, blobby_3cc,
//   femur; pig by its flips with climbs of the faces under 30 degrees) and the other starts of a
//   small output (SurfaceRemeshParams::restarts: patch-20; more of them for the smallest,
//   restartsFor: blob, patch-13) brought ours from worse to as good; the other stages and counts
//   are named with the list.
// - no angle under 20 degrees on every closed mesh of the data set whose input has no angle
//   under 1 degree.
// - each stage's own effect, with it and without.
// Angles are recounted here from the positions (test::recountAngles), not taken from the result.
#include <gtest/gtest.h>

#include <cstdio>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/mesh/vcg_mesh.h"
#include "core/remesh/edge_collapse.h"
#include "core/remesh/remesh_surface.h"
#include "core/remesh/surface_relaxation.h"
#include "tests/oracles/remesh_oracles.h"
#include "tests/support/test_support.h"

namespace gr {
namespace {

Expected<SurfaceRemeshResult> remeshPercent(const TriMesh& input, int percent) {
  SurfaceRemeshParams params;
  params.sampling.targetCount = input.vertexCount() * percent / 100;
  params.measure = false;
  return remeshSurface(input, params);
}

/// CGAL's runs to find the edge length that gives our count: the run that came nearest is
/// compared (CgalCalibration::closestEdgeLength). With 3, and the estimate after the last run
/// taken, CGAL was compared at 10 vertices to our 8 on ellipsoid.off at 5%; its ninth run gives 8.
constexpr int kCgalCalibrationRuns = 10;

/// Remeshes `name` at `percent` and compares with CGAL's isotropic remeshing (10 iterations) at
/// the same count, run here: the input's topology recounted, then the smallest angle and the
/// share of triangles under 30 degrees at least as good.
void expectAtLeastAsGoodAsCgal(const std::string& name, int percent) {
  const TriMesh input = test::loadRealMesh(name);
  const Expected<SurfaceRemeshResult> ours = remeshPercent(input, percent);
  ASSERT_TRUE(ours) << ours.status().message;
  test::expectValidWithTopologyOf(test::recount(ours->mesh.triangles, ours->mesh.vertexCount()),
                                  test::recount(input.triangles, input.vertexCount()));

  Expected<std::unique_ptr<oracle::SurfaceMesh>> cgal = oracle::toSurfaceMesh(input);
  ASSERT_TRUE(cgal);
  const oracle::CgalCalibration calibration =
      oracle::calibrateCgalEdgeLength(**cgal, ours->mesh.vertexCount(), 10, kCgalCalibrationRuns, 0.02);
  oracle::cgalIsotropicRemeshing(**cgal, calibration.closestEdgeLength, 10);
  const Expected<TriMesh> theirs = oracle::toTriMesh(**cgal);
  ASSERT_TRUE(theirs);

  const test::AngleRecount a = test::recountAngles(ours->mesh), c = test::recountAngles(*theirs);
  std::printf("%s at %d%%: ours %d vertices, smallest %.2f deg, %.2f %% under 30 | CGAL %d, %.2f deg, %.2f %%%s\n",
              name.c_str(), percent, ours->mesh.vertexCount(), a.smallestDegrees, 100 * a.shareBelow30,
              theirs->vertexCount(), c.smallestDegrees, 100 * c.shareBelow30,
              ours->angleRescued ? " (angle rescue)" : "");
  EXPECT_GE(a.smallestDegrees, c.smallestDegrees);
  EXPECT_LE(a.shareBelow30, c.shareBelow30);
}

// Among these cases, the stages that brought ours from worse to as good: at 10%, those the file's
// first lines name; at 5% and 30% (and 10% where said), the polish's flips (to fewer faces under 30
// degrees, flipToBetterAngles; the worst face's edges flipped with climbs after, flipAndClimb)
// brought from worse to as good: patch-20, bear_bis, blobby_3cc, ellipe0.003 at 5%;
// elephant-with-holes, double-torus-3-holes, fandisk, knot2 at 30%; and the flips with climbs of
// the faces under 30 degrees (flipAndClimbUnder30): pig at 10%, above; the valence flips with
// climbs (valenceFlipsAndClimbs): blobby_3cc at 30%; and the other starts of a small output
// (SurfaceRemeshParams::restarts): patch-30 at 5%, blob-closed and corner_tris_with_hole at 30%; and their looser relaxation (restartDeviation): sphere.off,
// sphere.ply, itemb and ALSTOM_TEST4 at 5%; and the polish's measured valence batches
// (SurfaceRemeshParams::measuredPolishVertices): knot1 and larger_sphere at 30%; and more starts
// for the smallest outputs (SurfaceRemeshParams::restartsFor): corner_with_hole at 30%; and the
// short creases free (RelaxationParams::minCreaseLength): femur at 5% and 30%, knot2 at 5%,
// b9_mesh at 10% and 30%; and CGAL compared at our count (kCgalCalibrationRuns): ellipsoid and
// pig at 5%, where 3 runs left CGAL at 10 and 26 vertices for our 8 and 24; and the splits of
// boundary edges facing wide angles (SplitEdges::Boundary): cylinder_locally_refined at 30% (as
// good by flipAndClimbUnder30 against CGAL at 2,430 vertices for our 2,485, worse against CGAL at
// our count until these splits); and the last polishes (SurfaceRemeshParams::lastPolishVertices):
// mannequin-devil at 5%, anchor_dense at 30%; and the thin ears cut (SurfaceRemeshParams::cutThinEars):
// lion at 10%; and the tiny holes' rings left where they are (the relaxation's tiny loops,
// surface_relaxation.h): ChineseDragon-10kv at 5% and 30% (and at 10%, above); and the joint
// climbs (SurfaceRemeshParams::jointClimbVertices): patch-13 at 5%; and the starts from the
// corners (SurfaceRemeshParams::cornerStarts): patch-23 at 5% and 10%; and the splits from the
// output with its thin ears cut too (SurfaceRemeshParams::earsBeforeSplits): mech-holes-shark at
// 10%; and the collapses at the worst face (SurfaceRemeshParams::worstFaceCollapses): b9_mesh at
// 5%; and the floor polishes (SurfaceRemeshParams::floorVertices): fandisk_large at 30%; and the
// thin ears' slack (SurfaceRemeshParams::earSlack): lion at 30%; and the shakes of small outputs
// (SurfaceRemeshParams::shakes): dragknob at 5%; and the starts with the boundaries sampled less
// densely (SurfaceRemeshParams::boundaryStartPriority): patch-23 at 30%.
//
// The whole of issue 20's population at 5%, 10% and 30% (every case listed): the data set's meshes
// (scripts/setup.sh) of up to 20,000 vertices whose input is manifold and oriented, boeing.off left
// out (its remesh would need more vertices than it has, so its own triangles, which cross, are
// kept: RemeshCrossing.NoMoreCrossingsThanAnInputThatCrossesItself), at the counts where at
// least 4 vertices are asked for (the others have fewer at 5% or 10%). The four larger meshes
// (armadillo, bunny00, diplodocus, refined_elephant) are left to bench_remesh, for the suite's
// time. docs/BENCHMARKS.md ("Angles over the data set") says which stage brought which output
// from worse to as good.
const char* const kAtEveryCount[] = {
    "ALSTOM_TEST4.off",
    "anchor.off",
    "anchor_dense.off",
    "b9_mesh.off",
    "bear.off",
    "bear_bis.off",
    "blade.off",
    "blob-closed.off",
    "blob.off",
    "blobby.off",
    "blobby_3cc.off",
    "bones.off",
    "bull.off",
    "cactus.off",
    "camel.off",
    "cheese.off",
    "ChineseDragon-10kv.off",
    "couplingdown.off",
    "cow.off",
    "cube-meshed.off",
    "cylinder.off",
    "cylinder_locally_refined.off",
    "dino.off",
    "double-torus-3-holes.off",
    "double-torus-example.off",
    "dragknob.off",
    "eight.off",
    "elephant-with-holes.off",
    "elephant.off",
    "elk.off",
    "ellipe0.003.off",
    "ellipsoid.off",
    "fandisk.off",
    "fandisk_large.off",
    "femur.off",
    "geosphere.off",
    "hand.off",
    "handle.off",
    "head.off",
    "helmet.off",
    "holes.off",
    "homer.off",
    "horizons.off",
    "itemb.off",
    "joint.off",
    "knot.off",
    "knot1.off",
    "knot2.off",
    "larger_sphere.off",
    "lion-head.off",
    "lion.off",
    "man.off",
    "mannequin-devil.off",
    "mask_cone.off",
    "mech-holes-shark.off",
    "mesh_with_border.off",
    "mpi.off",
    "mpi_triang.off",
    "mushroom.off",
    "nefertiti.off",
    "oblong.off",
    "part.off",
    "patch-01.off",
    "patch-13.off",
    "patch-20.off",
    "patch-21.off",
    "patch-23.off",
    "patch-30.off",
    "pig.off",
    "pinion.off",
    "pinion_small.off",
    "pipe.off",
    "plane.off",
    "poly2x^2+y^2-0.062500.off",
    "retinal.off",
    "rotor.off",
    "rotor_small.off",
    "sphere.off",
    "sphere.ply",
    "sphere.stl",
    "sphere966.off",
    "spool.off",
    "three_peaks.off",
    "triceratops.off",
    "turbine.off",
    "u.off",
};
const char* const kFrom10Percent[] = {
    "cross.off",
    "cross_quad.off",
};
const char* const kAt30PercentOnly[] = {
    "3torus.off",
    "corner.off",
    "corner_tris_with_hole.off",
    "corner_with_hole.off",
    "corner_with_sharp_edge.off",
    "hole.off",
    "P.off",
    "quads_to_stitch.off",
    "star.off",
    "torus_quad.off",
    "tripod.off",
};

std::vector<std::pair<std::string, int>> populationCases() {
  std::vector<std::pair<std::string, int>> cases;
  for (const int percent : {5, 10, 30}) {
    for (const char* name : kAtEveryCount) cases.emplace_back(name, percent);
    if (percent >= 10)
      for (const char* name : kFrom10Percent) cases.emplace_back(name, percent);
    if (percent == 30)
      for (const char* name : kAt30PercentOnly) cases.emplace_back(name, percent);
  }
  return cases;
}

class RemeshAnglesAgainstCgalOverTheDataSet : public ::testing::TestWithParam<std::pair<std::string, int>> {};

TEST_P(RemeshAnglesAgainstCgalOverTheDataSet, SmallestAngleAndShareUnder30AtLeastAsGood) {
  expectAtLeastAsGoodAsCgal(GetParam().first, GetParam().second);
}

INSTANTIATE_TEST_SUITE_P(Meshes, RemeshAnglesAgainstCgalOverTheDataSet, ::testing::ValuesIn(populationCases()),
                         [](const ::testing::TestParamInfo<std::pair<std::string, int>>& p) {
                           return test::testNameOfFile(p.param.first) + "_" + std::to_string(p.param.second);
                         });

/// `before` and `after`, remeshes of `input` at the same target without and with more starts:
/// the same count, the input's topology (recounted), no crossing faces (CGAL's test), both angle
/// figures no worse and one better, a two-sided distance to the input (the oracle's) no larger.
void expectBetterStartKept(const std::string& name, const TriMesh& input, const SurfaceRemeshResult& before,
                           const SurfaceRemeshResult& after) {
  const test::AngleRecount a = test::recountAngles(before.mesh), b = test::recountAngles(after.mesh);
  const double diagonal = input.boundingBoxDiagonal();
  const double d0 = oracle::twoSidedDistance(before.mesh, input).max / diagonal;
  const double d1 = oracle::twoSidedDistance(after.mesh, input).max / diagonal;
  std::printf(
      "%s: %d starts %.2f deg, %.2f %% under 30, Hausdorff %.3f %% | start %d of %d (seed %u, moves up to %g): %.2f "
      "deg, %.2f %%, %.3f %%\n",
      name.c_str(), before.starts, a.smallestDegrees, 100 * a.shareBelow30, 100 * d0, after.keptStart + 1, after.starts,
      after.keptSeed, after.keptDeviation, b.smallestDegrees, 100 * b.shareBelow30, 100 * d1);
  ASSERT_LE(after.mesh.vertexCount(), SurfaceRemeshParams::kRestartVertices);
  EXPECT_EQ(after.mesh.vertexCount(), before.mesh.vertexCount());
  EXPECT_GE(b.smallestDegrees, a.smallestDegrees);
  EXPECT_LE(b.shareBelow30, a.shareBelow30);
  EXPECT_TRUE(b.smallestDegrees > a.smallestDegrees || b.shareBelow30 < a.shareBelow30);
  EXPECT_LE(d1, d0);
  test::expectValidWithTopologyOf(test::recount(after.mesh.triangles, after.mesh.vertexCount()),
                                  test::recount(input.triangles, input.vertexCount()));
  EXPECT_TRUE(oracle::selfIntersections(after.mesh).value().empty());
  EXPECT_GT(after.times.restarts, 0.0);
}

/// `name` remeshed at `percent` twice: `before` with `lessen` applied to the defaults, `after`
/// with the defaults (`both`, if given, applied to the two first).
struct BeforeAndAfter {
  TriMesh input;
  Expected<SurfaceRemeshResult> before, after;
};
BeforeAndAfter remeshBeforeAndAfter(const std::string& name, int percent,
                                    const std::function<void(SurfaceRemeshParams&)>& lessen,
                                    const std::function<void(SurfaceRemeshParams&)>& both = {}) {
  const TriMesh input = test::loadRealMesh(name);
  SurfaceRemeshParams params;
  params.sampling.targetCount = input.vertexCount() * percent / 100;
  params.measure = false;
  if (both) both(params);
  SurfaceRemeshParams lessened = params;
  lessen(lessened);
  return {input, remeshSurface(input, lessened), remeshSurface(input, params)};
}

/// The angles of b's outputs (recounted) and their two-sided distances to the input (the oracle's,
/// shares of the input's bounding-box diagonal).
struct Figures {
  test::AngleRecount before, after;
  double distanceBefore = 0.0, distanceAfter = 0.0;
};
Figures figuresOf(const BeforeAndAfter& b) {
  const double diagonal = b.input.boundingBoxDiagonal();
  return {test::recountAngles(b.before->mesh), test::recountAngles(b.after->mesh),
          oracle::twoSidedDistance(b.before->mesh, b.input).max / diagonal,
          oracle::twoSidedDistance(b.after->mesh, b.input).max / diagonal};
}

/// Prints f under `what` (the mesh, the count, what was kept).
void printFigures(const std::string& what, const Figures& f) {
  std::printf("%s: smallest %.2f -> %.2f deg, %.3f -> %.3f %% under 30, Hausdorff %.6f -> %.6f %%\n", what.c_str(),
              f.before.smallestDegrees, f.after.smallestDegrees, 100 * f.before.shareBelow30,
              100 * f.after.shareBelow30, 100 * f.distanceBefore, 100 * f.distanceAfter);
}

/// b's second output has the input's topology (recounted) and no more pairs of crossing faces
/// (CGAL) than the input or the first output: none where the input has none.
void expectValidWithoutNewCrossings(const BeforeAndAfter& b) {
  test::expectValidWithTopologyOf(test::recount(b.after->mesh.triangles, b.after->mesh.vertexCount()),
                                  test::recount(b.input.triangles, b.input.vertexCount()));
  const size_t input = oracle::selfIntersections(b.input).value().size();
  const size_t before = oracle::selfIntersections(b.before->mesh).value().size();
  const size_t after = oracle::selfIntersections(b.after->mesh).value().size();
  std::printf("crossing pairs: input %zu, outputs %zu -> %zu\n", input, before, after);
  EXPECT_LE(after, input);
  EXPECT_LE(after, before);
}

/// b's second output (its figures f) against the first: the same count, the smallest angle up by
/// more than `gain` degrees, no larger share under 30, the oracle's distance to the input no
/// larger, valid without new crossings (expectValidWithoutNewCrossings).
void expectSameCountBetterNoFarther(const BeforeAndAfter& b, const Figures& f, double gain) {
  EXPECT_EQ(b.after->mesh.vertexCount(), b.before->mesh.vertexCount());
  EXPECT_GT(f.after.smallestDegrees, f.before.smallestDegrees + gain);
  EXPECT_LE(f.after.shareBelow30, f.before.shareBelow30);
  EXPECT_LE(f.distanceAfter, f.distanceBefore);
  expectValidWithoutNewCrossings(b);
}

/// The first start of a small output alone: no other starts, every crease held
/// (RelaxationParams::minCreaseLength 0, as the starts hold them).
void onlyTheFirstStart(SurfaceRemeshParams& p) {
  p.restarts = 0;
  p.relaxation.minCreaseLength = 0;
}

/// The seeds' starts alone (SurfaceRemeshParams::cornerStarts off): the figures of the tests that
/// measure them (patch-20 and blob at 10% keep a start from their corners, better still, with them).
void withoutCornerStarts(SurfaceRemeshParams& p) { p.cornerStarts = false; }
/// The seeds' starts alone, neither from the corners nor with the boundaries sampled less densely
/// (SurfaceRemeshParams::boundaryStartPriority 0): for the tests that count them.
void onlyTheSeedsStarts(SurfaceRemeshParams& p) {
  p.cornerStarts = false;
  p.boundaryStartPriority = 0;
}

// The starts are judged by their distance to the input at its faces' centroids and side midpoints
// too (outputDistance). spool at 10% (64 vertices): judged at the input's vertices alone, a start
// with a larger smallest angle (39.4 against 36.8 degrees) was kept though the oracle finds it
// farther than the first (6.90 against 6.78% of the diagonal); now the output is no farther than
// the first start's. dragknob at 30% (48 vertices): another start, better (49.8 degrees) and
// nearer, is kept.
TEST(RemeshAngles, OtherStartsAreJudgedAtTheInputsFacesToo) {
  const BeforeAndAfter spool = remeshBeforeAndAfter("spool.off", 10, onlyTheFirstStart);
  ASSERT_TRUE(spool.before) << spool.before.status().message;
  ASSERT_TRUE(spool.after) << spool.after.status().message;
  ASSERT_LE(spool.after->mesh.vertexCount(), SurfaceRemeshParams::kRestartVertices);
  const Figures f = figuresOf(spool);
  printFigures("spool at 10% (start " + std::to_string(spool.after->keptStart) + " kept)", f);
  EXPECT_GT(spool.after->starts, 1);
  EXPECT_LE(f.distanceAfter, f.distanceBefore);
  EXPECT_GE(f.after.smallestDegrees, f.before.smallestDegrees);
  EXPECT_LE(f.after.shareBelow30, f.before.shareBelow30);

  // Without the shakes on both sides (they come after the starts): from the first start alone they
  // reach 48.2 degrees at 7.07% of the diagonal, nearer than the start the others keep (49.8 at
  // 7.16%), which no shake improves.
  const BeforeAndAfter dragknob =
      remeshBeforeAndAfter("dragknob.off", 30, onlyTheFirstStart, [](SurfaceRemeshParams& p) { p.shakes = 0; });
  ASSERT_TRUE(dragknob.before) << dragknob.before.status().message;
  ASSERT_TRUE(dragknob.after) << dragknob.after.status().message;
  EXPECT_GT(dragknob.after->keptStart, 0) << "on this mesh another start is better";
  expectBetterStartKept("dragknob at 30%", dragknob.input, *dragknob.before, *dragknob.after);
}

// The other starts of a small output (SurfaceRemeshParams::restarts): patch-20 at 10% (35
// vertices) remeshed with them and without; another start is kept, better (33.9 -> 41.4 degrees).
TEST(RemeshAngles, OtherStartsOfASmallOutputKeepOnlyABetterOne) {
  const BeforeAndAfter b = remeshBeforeAndAfter("patch-20.off", 10, onlyTheFirstStart, onlyTheSeedsStarts);
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  EXPECT_EQ(b.before->starts, 1);
  const int n = b.before->mesh.vertexCount();
  const SurfaceRemeshParams defaults;
  EXPECT_EQ(b.after->starts, 2 + defaults.restarts + 1 + defaults.restartsFor(n))
      << "the first seed also with short creases free, the first seeds with both relaxations, the rest with the "
         "looser";
  EXPECT_GT(b.after->keptStart, 0) << "on this mesh another start is better";
  expectBetterStartKept("patch-20 at 10%", b.input, *b.before, *b.after);
}

// The starts from the corners of the input's feature curves (SurfaceRemeshParams::cornerStarts):
// patch-23, a 100 x 33 rectangle of 109 vertices, at 5% and 10% (5 and 10 vertices), and patch-13 at
// 10%, remeshed with them and without. Without, the seeds' samplings leave corners out and the
// output's boundary cuts them (patch-23 at 5%: 26.0 degrees, 66.7% under 30, two-sided Hausdorff
// 17.5% of the diagonal); with them, the start from the corners is kept, better and nearer, and
// has an output vertex at each of the rectangle's four corners (found here from the coordinates).
TEST(RemeshAngles, StartsFromTheCornersKeepThem) {
  for (const auto& [name, percent] :
       {std::pair<const char*, int>{"patch-23.off", 5}, {"patch-23.off", 10}, {"patch-13.off", 10}}) {
    const std::string what = std::string(name) + " at " + std::to_string(percent) + "%";
    SCOPED_TRACE(what);
    const BeforeAndAfter b = remeshBeforeAndAfter(name, percent, withoutCornerStarts);
    ASSERT_TRUE(b.before) << b.before.status().message;
    ASSERT_TRUE(b.after) << b.after.status().message;
    const bool looser = b.after->keptDeviation > SurfaceRemeshParams{}.relaxation.maxDeviation;
    EXPECT_EQ(b.after->starts, b.before->starts + (looser ? 2 : 1))
        << "from the corners, the looser relaxation's passed over once the other's has them all";
    EXPECT_EQ(b.after->cornerStarts, looser ? 2 : 1);
    EXPECT_EQ(b.before->cornerStarts, 0);
    EXPECT_EQ(b.before->keptCorners, 0);
    EXPECT_GT(b.after->keptCorners, 0) << "the start from the corners is better here";
    expectBetterStartKept(what, b.input, *b.before, *b.after);
    if (std::string(name) != "patch-23.off") continue;
    EXPECT_EQ(b.after->keptCorners, 4);
    Vec3 lo = b.input.positions[0], hi = lo;
    for (const Vec3& p : b.input.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    int corners = 0;  // the rectangle spans x and z; y is its plane (within 0.15 of a 100-long side)
    for (const Vec3& p : b.after->mesh.positions)
      corners += (p.x() == lo.x() || p.x() == hi.x()) && (p.z() == lo.z() || p.z() == hi.z());
    EXPECT_EQ(corners, 4);
  }
}

// More starts for the smallest outputs (SurfaceRemeshParams::restartsFor): the rule, then blob at
// 10% (13 vertices: 14 other seeds instead of 3) remeshed with the starts and without; the start
// kept has a seed only the scaled starts try, and is better (39.0 -> 43.6 degrees) and no farther.
TEST(RemeshAngles, SmallestOutputsGetMoreStarts) {
  const SurfaceRemeshParams defaults;
  EXPECT_EQ(defaults.restartsFor(SurfaceRemeshParams::kRestartVertices), defaults.restarts);
  EXPECT_EQ(defaults.restartsFor(1000), defaults.restarts);
  EXPECT_EQ(defaults.restartsFor(13), 3 * 64 / 13);
  EXPECT_EQ(defaults.restartsFor(4), SurfaceRemeshParams::kMaxRestarts);
  SurfaceRemeshParams none;
  none.restarts = 0;
  EXPECT_EQ(none.restartsFor(4), 0);

  const BeforeAndAfter b = remeshBeforeAndAfter("blob.off", 10, onlyTheFirstStart, onlyTheSeedsStarts);
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const int n = b.before->mesh.vertexCount();
  EXPECT_EQ(b.after->starts, 2 + defaults.restarts + 1 + defaults.restartsFor(n))
      << "the first seed also with short creases free, the first 3 seeds also with the tight relaxation, every "
         "seed with the looser";
  EXPECT_GT(b.after->keptSeed, defaults.sampling.seed + static_cast<unsigned>(defaults.restarts))
      << "on this mesh a seed beyond the first 3 others is better";
  expectBetterStartKept("blob at 10%", b.input, *b.before, *b.after);
}

// The looser relaxation of a small output's starts (SurfaceRemeshParams::restartDeviation):
// sphere.off at 5% (8 vertices) with it and without; one relaxed with moves up to
// restartDeviation of the ring is kept, better (42.5 -> 51.5 degrees).
TEST(RemeshAngles, LooserStartsOfASmallOutputKeepOnlyABetterOne) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter("sphere.off", 5, [](SurfaceRemeshParams& p) { p.restartDeviation = 0.0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const SurfaceRemeshParams defaults;
  const int n = b.after->mesh.vertexCount();
  EXPECT_EQ(b.before->starts, 2 + defaults.restartsFor(n))
      << "without the looser relaxation, every seed tight, and the first with short creases free";
  EXPECT_EQ(b.after->starts, 2 + defaults.restarts + 1 + defaults.restartsFor(n));
  EXPECT_EQ(b.before->keptDeviation, defaults.relaxation.maxDeviation);
  EXPECT_EQ(b.after->keptDeviation, defaults.restartDeviation) << "on this mesh a looser start is better";
  expectBetterStartKept("sphere.off at 5%", b.input, *b.before, *b.after);
}

// Short creases free (RelaxationParams::minCreaseLength): femur.off is a scan whose edges are
// over 60 degrees on 14% of them, in 1,095 chains of one or two edges; held as creases they kept
// the vertices on them in place. At 10%, with every crease held and with the short ones free
// (the defaults; no other starts at this size): the smallest angle rises (15.1 -> 27.7 degrees),
// fewer triangles under 30 degrees, the two-sided distance to the input by the oracle no larger
// (3.04 -> 2.18% of the diagonal), the count asked for, the input's topology recounted, and no
// crossing faces (CGAL) where the input has none.
TEST(RemeshAngles, ShortCreasesOfAScanDoNotHoldVertices) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter("femur.off", 10, [](SurfaceRemeshParams& p) { p.relaxation.minCreaseLength = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  ASSERT_GT(b.after->mesh.vertexCount(), SurfaceRemeshParams::kRestartVertices);
  const auto [a, c, d0, d1] = figuresOf(b);
  std::printf(
      "femur at 10%%: every crease held %d vertices, %.2f deg, %.2f %% under 30, Hausdorff %.3f %% | short "
      "ones free %d, %.2f deg, %.2f %%, %.3f %%\n",
      b.before->mesh.vertexCount(), a.smallestDegrees, 100 * a.shareBelow30, 100 * d0, b.after->mesh.vertexCount(),
      c.smallestDegrees, 100 * c.shareBelow30, 100 * d1);
  EXPECT_GT(c.smallestDegrees, a.smallestDegrees + 5.0);
  EXPECT_LT(c.shareBelow30, a.shareBelow30);
  EXPECT_LE(d1, d0);
  const int asked = b.input.vertexCount() / 10;
  EXPECT_LE(b.after->mesh.vertexCount(), 1.1 * asked);
  expectValidWithoutNewCrossings(b);
}

/// `name` at `percent` remeshed without splits (splitRounds 0) and with them: vertices split in
/// (at most kSplitShare of the count asked) and no more (the thin ears cut after the splits
/// counted apart: they may go with the splits), the smallest angle more than `gain`
/// degrees higher, fewer faces under 30, the two-sided distance to the input (the oracle's) no
/// larger, the input's topology kept (recounted), no faces crossing (CGAL).
void expectSplitsMendTheAngles(const std::string& name, int percent, double gain) {
  const BeforeAndAfter b = remeshBeforeAndAfter(name, percent, [](SurfaceRemeshParams& p) { p.splitRounds = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const auto [a, c, d0, d1] = figuresOf(b);
  std::printf(
      "%s at %d%%: no splits %d vertices, %.2f deg, %.2f %% under 30, Hausdorff %.4f %% | %d split in %d "
      "round(s): %d, %.2f deg, %.2f %%, %.4f %%\n",
      name.c_str(), percent, b.before->mesh.vertexCount(), a.smallestDegrees, 100 * a.shareBelow30, 100 * d0,
      b.after->splitVertices, b.after->splitRounds, b.after->mesh.vertexCount(), c.smallestDegrees,
      100 * c.shareBelow30, 100 * d1);
  EXPECT_EQ(b.before->splitVertices, 0);
  EXPECT_GT(b.after->splitVertices, 0);
  EXPECT_EQ(b.after->mesh.vertexCount() + b.after->thinEars,
            b.before->mesh.vertexCount() + b.before->thinEars + b.after->splitVertices);
  const int asked = b.input.vertexCount() * percent / 100;
  EXPECT_LE(b.after->splitVertices, static_cast<int>(SurfaceRemeshParams::kSplitShare * asked));
  EXPECT_GT(c.smallestDegrees, a.smallestDegrees + gain);
  EXPECT_LT(c.shareBelow30, a.shareBelow30);
  EXPECT_LE(d1, d0);
  expectValidWithoutNewCrossings(b);
  // The result's own topology, which the filter logs, is the one recounted from its faces.
  const test::Recount recounted = test::recount(b.after->mesh.triangles, b.after->mesh.vertexCount());
  EXPECT_EQ(b.after->mesh.topology.components, recounted.components);
  EXPECT_EQ(b.after->mesh.topology.genus, recounted.genusSum);
  EXPECT_EQ(b.after->mesh.topology.boundaryLoops, recounted.boundaryLoops);
}

// The splits of faces under 30 degrees held by a wide angle (SurfaceRemeshParams::splitRounds) on
// mech-holes-shark at 5%: vertices on the rims of its holes hold wide angles the polish cannot
// mend (5.2 degrees); with the splits the smallest angle is more than 15 degrees higher.
TEST(RemeshAngles, WideAnglesHeldOnHoleRimsAreSplit) { expectSplitsMendTheAngles("mech-holes-shark.off", 5, 15.0); }

// The splits of boundary edges (SplitEdges::Boundary, after the inner edges') on
// cylinder_locally_refined at 30%: faces of 24-29 degrees lie on the input's rim, their wide
// angles (114-128 degrees) facing rim edges that are input edges (consecutive input vertices),
// which the polish left so; with the splits the smallest angle is more than 5 degrees higher.
TEST(RemeshAngles, WideAnglesFacingTheBoundaryAreSplit) {
  expectSplitsMendTheAngles("cylinder_locally_refined.off", 30, 5.0);
}

// The polish's measured valence batches (SurfaceRemeshParams::measuredPolishVertices, the
// remesh's cells given to polishOnSurface): larger_sphere at 30% (243 vertices) remeshed with them
// and without. With them the smallest angle is higher (40.6 -> 43.0 degrees) and the two-sided
// distance to the input, measured by the oracle, no larger (they are kept only where
// remeshDistances' does not grow); the same count, the input's topology recounted, no crossing
// faces (CGAL). Cells of the wrong size, or naming no output vertex, are refused by the polish,
// the mesh unchanged.
TEST(RemeshAngles, MeasuredValenceBatchesRaiseTheSmallestAngleNotTheDistance) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter("larger_sphere.off", 30, [](SurfaceRemeshParams& p) { p.measuredPolishVertices = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  ASSERT_LE(b.after->mesh.vertexCount(), SurfaceRemeshParams{}.measuredPolishVertices);
  const double before = test::recountAngles(b.before->mesh).smallestDegrees;
  const double after = test::recountAngles(b.after->mesh).smallestDegrees;
  const double diagonal = b.input.boundingBoxDiagonal();
  const double d0 = oracle::twoSidedDistance(b.before->mesh, b.input).max / diagonal;
  const double d1 = oracle::twoSidedDistance(b.after->mesh, b.input).max / diagonal;
  std::printf("larger_sphere at 30%%: smallest %.2f -> %.2f deg, two-sided Hausdorff %.4f -> %.4f %%\n", before, after,
              100 * d0, 100 * d1);
  EXPECT_EQ(b.after->mesh.vertexCount(), b.before->mesh.vertexCount());
  EXPECT_GT(after, before + 1.0);
  EXPECT_LE(d1, d0);
  test::expectValidWithTopologyOf(test::recount(b.after->mesh.triangles, b.after->mesh.vertexCount()),
                                  test::recount(b.input.triangles, b.input.vertexCount()));
  EXPECT_TRUE(oracle::selfIntersections(b.after->mesh).value().empty());

  TriMesh refused = b.before->mesh;
  std::vector<SurfacePoint> points = b.before->origin;
  const std::vector<int> tooShort(b.before->cell.begin(), b.before->cell.end() - 1);
  PolishGuard guard;
  guard.cell = &tooShort;
  const Expected<RelaxationResult> wrong = polishOnSurface(refused, points, b.input, RelaxationParams{}, guard);
  ASSERT_FALSE(wrong);
  EXPECT_EQ(wrong.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(refused.positions, b.before->mesh.positions);
  EXPECT_EQ(refused.triangles, b.before->mesh.triangles);
  std::vector<int> outOfRange = b.before->cell;
  outOfRange.back() = b.before->mesh.vertexCount();  // no such output vertex
  guard.cell = &outOfRange;
  const Expected<RelaxationResult> beyond = polishOnSurface(refused, points, b.input, RelaxationParams{}, guard);
  ASSERT_FALSE(beyond);
  EXPECT_EQ(beyond.status().code, StatusCode::InvalidInput);
  EXPECT_EQ(refused.positions, b.before->mesh.positions);
}

// The last polishes (SurfaceRemeshParams::lastPolishVertices): anchor_dense at 30% (1,141
// vertices, a CAD part) remeshed with them and without. One polish stops at its aim (34.1
// degrees, CGAL's isotropic remeshing 36.6 at our count); polished again from there, the smallest
// angle is more than 2 degrees higher (37.9), no more faces under 30 degrees, the two-sided
// distance to the input by the oracle no larger (1.63 -> 1.60% of the diagonal); the same count,
// the input's topology recounted, no crossing faces (CGAL). The joint climbs and the floor
// polishes after them are off in both, so that the figures are the last polishes' alone (without
// the last polishes, the floor polishes take this output to 38.0 degrees, 1.606% of the diagonal).
TEST(RemeshAngles, LastPolishesRaiseTheSmallestAngleNotTheDistance) {
  const BeforeAndAfter b = remeshBeforeAndAfter(
      "anchor_dense.off", 30, [](SurfaceRemeshParams& p) { p.lastPolishVertices = 0; },
      [](SurfaceRemeshParams& p) {
        p.jointClimbVertices = 0;
        p.floorVertices = 0;
      });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  ASSERT_LE(b.after->mesh.vertexCount(), SurfaceRemeshParams{}.lastPolishVertices);
  const Figures f = figuresOf(b);
  printFigures("anchor_dense at 30% (" + std::to_string(b.after->lastPolishes) + " last polishes kept)", f);
  EXPECT_EQ(b.before->lastPolishes, 0);
  EXPECT_GE(b.after->lastPolishes, 1);
  expectSameCountBetterNoFarther(b, f, 2.0);
}

// The last polishes are refused where they take the output farther from the input: dino at 10%
// (33.5 degrees when they run, 35.8 after the joint climbs that follow them: under
// kLastPolishBelowDegrees). Its output polished again directly (polishOnSurface, with the
// relaxation's deviation limit and with restartDeviation's) has a larger smallest angle (37.3,
// 38.1 degrees) but is farther from the input by the oracle (two-sided Hausdorff 2.13 -> 2.26,
// 2.35% of the diagonal); the remesh keeps neither: its output is the one without them, vertex
// for vertex.
TEST(RemeshAngles, LastPolishesFartherFromTheInputAreRefused) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter("dino.off", 10, [](SurfaceRemeshParams& p) { p.lastPolishVertices = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  ASSERT_LE(b.after->mesh.vertexCount(), SurfaceRemeshParams{}.lastPolishVertices);
  ASSERT_TRUE(test::recount(b.input.triangles, b.input.vertexCount()).oriented)
      << "the input is the surface polished on";
  const double diagonal = b.input.boundingBoxDiagonal();
  const double smallest = test::recountAngles(b.before->mesh).smallestDegrees;
  ASSERT_LT(smallest, SurfaceRemeshParams::kLastPolishBelowDegrees) << "the last polishes are tried";
  const double distance = oracle::twoSidedDistance(b.before->mesh, b.input).max / diagonal;
  const SurfaceRemeshParams defaults;
  for (const double deviation : {defaults.relaxation.maxDeviation, defaults.restartDeviation}) {
    TriMesh polished = b.before->mesh;
    std::vector<SurfacePoint> points = b.before->origin;
    RelaxationParams relaxation = defaults.relaxation;
    relaxation.maxDeviation = deviation;
    ASSERT_TRUE(polishOnSurface(polished, points, b.input, relaxation));
    const double higher = test::recountAngles(polished).smallestDegrees;
    const double farther = oracle::twoSidedDistance(polished, b.input).max / diagonal;
    std::printf(
        "dino at 10%%, polished again with deviation %g: smallest %.2f -> %.2f deg, Hausdorff %.4f -> %.4f %%\n",
        deviation, smallest, higher, 100 * distance, 100 * farther);
    EXPECT_GT(higher, smallest + 1.0);
    EXPECT_GT(farther, distance);
  }

  EXPECT_EQ(b.after->lastPolishes, 0);
  EXPECT_EQ(b.after->mesh.positions, b.before->mesh.positions);
  EXPECT_EQ(b.after->mesh.triangles, b.before->mesh.triangles);
}

// The joint climbs (SurfaceRemeshParams::jointClimbVertices): lion at 10% remeshed without them and
// with them, the splits from the starts' output alone on both sides (earsBeforeSplits off: with
// it, an ear cut before the splits leaves 32.2 degrees for the climbs). Without, the polish's
// one-vertex climbs leave 20.2 degrees; with them the smallest
// angle is more than 5 degrees higher, no more faces under 30, the oracle's two-sided Hausdorff
// distance no larger (they are kept only where the remesh's own distance does not grow), the same
// triangles (they move vertices only), the topology recounted, no new crossing faces (CGAL).
TEST(RemeshAngles, JointClimbsRaiseTheSmallestAngleNotTheDistance) {
  const BeforeAndAfter b = remeshBeforeAndAfter(
      "lion.off", 10, [](SurfaceRemeshParams& p) { p.jointClimbVertices = 0; },
      [](SurfaceRemeshParams& p) { p.earsBeforeSplits = false; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const Figures f = figuresOf(b);
  printFigures("lion at 10% (" + std::to_string(b.after->jointMoves) + " joint moves)", f);
  EXPECT_EQ(b.before->jointMoves, 0);
  EXPECT_GT(b.after->jointMoves, 0);
  EXPECT_EQ(b.after->mesh.triangles, b.before->mesh.triangles);
  EXPECT_NE(b.after->mesh.positions, b.before->mesh.positions);
  EXPECT_GT(f.after.smallestDegrees, f.before.smallestDegrees + 5.0);
  EXPECT_LE(f.after.shareBelow30, f.before.shareBelow30);
  EXPECT_LE(f.distanceAfter, f.distanceBefore);
  expectValidWithoutNewCrossings(b);
}

/// The smallest angle (degrees) of the faces of `mesh` and how many are under 30 degrees,
/// recounted face by face.
std::pair<double, int> smallestAndUnder30(const TriMesh& mesh) {
  double smallest = 180;
  int under = 0;
  for (const Tri& t : mesh.triangles) {
    const double face = test::recountAngles(buildTriMesh(mesh.positions, {t}).value()).smallestDegrees;
    smallest = std::min(smallest, face);
    under += face < 30;
  }
  return {smallest, under};
}

// climbJointly on its own, on lion's output at 10% without joint climbs (and without the ears cut
// before the splits, as above): the smallest angle rises,
// no face is added under 30 degrees, the triangles stay, every vertex stays at its point of the
// input, and only the worst faces' vertices move (none farther than a mean edge). With the worst
// face's vertices pinned it moves nothing; pins of the wrong size are refused, the mesh
// unchanged.
TEST(RemeshAngles, ClimbJointlyMovesTheWorstFacesVerticesTogether) {
  const TriMesh input = test::loadRealMesh("lion.off");
  SurfaceRemeshParams params;
  params.sampling.targetCount = input.vertexCount() / 10;
  params.measure = false;
  params.jointClimbVertices = 0;
  params.earsBeforeSplits = false;
  const Expected<SurfaceRemeshResult> r = remeshSurface(input, params);
  ASSERT_TRUE(r) << r.status().message;
  ASSERT_TRUE(test::recount(input.triangles, input.vertexCount()).oriented) << "the input is the surface climbed on";
  const auto [smallest, under] = smallestAndUnder30(r->mesh);

  TriMesh climbed = r->mesh;
  std::vector<SurfacePoint> points = r->origin;
  const Expected<int> moves = climbJointly(climbed, points, input, params.relaxation);
  ASSERT_TRUE(moves) << moves.status().message;
  const auto [higher, fewer] = smallestAndUnder30(climbed);
  std::printf("lion at 10%%: smallest %.2f -> %.2f deg, %d -> %d faces under 30, %d joint moves\n", smallest, higher,
              under, fewer, *moves);
  EXPECT_GT(*moves, 0);
  EXPECT_GT(higher, smallest + 1.0);
  EXPECT_LE(fewer, under);
  EXPECT_EQ(climbed.triangles, r->mesh.triangles);
  int moved = 0;
  for (int v = 0; v < climbed.vertexCount(); ++v) {
    EXPECT_LT((points[v].position(input) - climbed.positions[v]).norm(), 1e-9 * input.boundingBoxDiagonal());
    const double away = (climbed.positions[v] - r->mesh.positions[v]).norm();
    moved += away > 0;
    EXPECT_LE(away, r->mesh.meanEdgeLength()) << "vertex " << v;
  }
  EXPECT_GE(moved, 2);
  EXPECT_LE(moved, 3 * *moves);

  std::vector<char> pinned(r->mesh.vertexCount(), 0);  // the vertices of the worst face (or faces)
  for (const Tri& t : r->mesh.triangles)
    if (test::recountAngles(buildTriMesh(r->mesh.positions, {t}).value()).smallestDegrees <= smallest)
      for (const int v : t) pinned[v] = 1;
  TriMesh held = r->mesh;
  std::vector<SurfacePoint> heldPoints = r->origin;
  const Expected<int> none = climbJointly(held, heldPoints, input, params.relaxation, pinned);
  ASSERT_TRUE(none) << none.status().message;
  EXPECT_EQ(*none, 0);
  EXPECT_EQ(held.positions, r->mesh.positions);

  pinned.pop_back();
  const Expected<int> refused = climbJointly(held, heldPoints, input, params.relaxation, pinned);
  EXPECT_FALSE(refused);
  EXPECT_EQ(held.positions, r->mesh.positions);
}

/// `name` at `percent` without and with the thin ears cut (SurfaceRemeshParams::cutThinEars, or
/// what `lessen` takes away; last only, without earsBeforeSplits on both sides): at least one cut,
/// the smallest angle up by more than `gain` degrees, fewer faces under 30, the oracle's two-sided
/// Hausdorff no larger (with `slack` > 0: larger, by at most that share), the topology recounted,
/// no crossing faces by CGAL.
void expectThinEarsCut(
    const std::string& name, int percent, double gain,
    const std::function<void(SurfaceRemeshParams&)>& lessen = [](SurfaceRemeshParams& p) { p.cutThinEars = false; },
    double slack = 0.0) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter(name, percent, lessen, [](SurfaceRemeshParams& p) { p.earsBeforeSplits = false; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const Figures f = figuresOf(b);
  printFigures(name + " at " + std::to_string(percent) + "% (" + std::to_string(b.after->thinEars) + " thin ears cut)",
               f);
  EXPECT_EQ(b.before->thinEars, 0);
  EXPECT_GE(b.after->thinEars, 1);
  EXPECT_EQ(b.after->mesh.vertexCount(), b.before->mesh.vertexCount() - b.after->thinEars);
  EXPECT_EQ(b.after->removedEars, b.before->removedEars + b.after->thinEars);
  EXPECT_GT(f.after.smallestDegrees, f.before.smallestDegrees + gain);
  EXPECT_LT(f.after.shareBelow30, f.before.shareBelow30);
  if (slack > 0) {
    EXPECT_GT(f.distanceAfter, f.distanceBefore);  // the slack is what lets it be cut
  }
  EXPECT_LE(f.distanceAfter, (1.0 + slack) * f.distanceBefore);
  expectValidWithoutNewCrossings(b);
}

// Thin ears cut last (SurfaceRemeshParams::cutThinEars): lion at 10% kept its input's own ear
// (a triangle of 8 degrees at a corner of its boundary) as an output ear of 10.5 degrees, the
// output's smallest angle. Cut, the smallest angle is the next one's (20.2; CGAL at our count
// 17.8), one face fewer under 30 degrees, one vertex fewer, the two-sided distance to the input
// by the oracle no larger (its largest is elsewhere); the input's topology recounted, no
// crossing faces (CGAL).
TEST(RemeshAngles, ThinEarsAreCutWhereTheDistanceDoesNotGrow) { expectThinEarsCut("lion.off", 10, 5.0); }

// ALSTOM_TEST4 at 10%: its smallest angle, 6.9 degrees, was an ear 2.15 mean output edges deep,
// which a bound of one mean edge on the ears' depth held; the distance, which bounds it now, does
// not grow when it is cut (18.6 degrees; CGAL at our count 11.9).
TEST(RemeshAngles, DeepThinEarsAreCutWhereTheDistanceDoesNotGrow) { expectThinEarsCut("ALSTOM_TEST4.off", 10, 10.0); }

// With no slack for the cuts (SurfaceRemeshParams::earSlack 0), a thin ear is kept where its cut
// takes the output farther from the input: lion at 30% (the same ear of the input, 12.0 degrees
// in the output). Cut directly (removeEar), the smallest angle rises (22.7) but the oracle's
// two-sided distance grows (1.2373 -> 1.2388% of the diagonal: the input's spike is now the
// farthest point); the remesh keeps the output without the cut.
TEST(RemeshAngles, ThinEarsFartherFromTheInputAreKept) {
  const BeforeAndAfter b = remeshBeforeAndAfter(
      "lion.off", 30, [](SurfaceRemeshParams& p) { p.cutThinEars = false; },
      [](SurfaceRemeshParams& p) { p.earSlack = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const std::vector<int> ears = thinEars(b.before->mesh, b.before->mesh.meanEdgeLength());
  ASSERT_FALSE(ears.empty());
  TriMesh cut = b.before->mesh;
  std::vector<SurfacePoint> origin = b.before->origin;
  std::vector<int> cell = b.before->cell;
  ASSERT_TRUE(removeEar(cut, origin, cell, ears.front()));
  const double diagonal = b.input.boundingBoxDiagonal();
  const double smallest = test::recountAngles(b.before->mesh).smallestDegrees;
  const double higher = test::recountAngles(cut).smallestDegrees;
  const double distance = oracle::twoSidedDistance(b.before->mesh, b.input).max / diagonal;
  const double farther = oracle::twoSidedDistance(cut, b.input).max / diagonal;
  std::printf("lion at 30%%, its thinnest ear cut: smallest %.2f -> %.2f deg, Hausdorff %.4f -> %.4f %%\n", smallest,
              higher, 100 * distance, 100 * farther);
  EXPECT_GT(higher, smallest + 5.0);
  EXPECT_GT(farther, distance);
  EXPECT_EQ(b.after->thinEars, 0);
  EXPECT_EQ(b.after->mesh.positions, b.before->mesh.positions);
  EXPECT_EQ(b.after->mesh.triangles, b.before->mesh.triangles);
}

// The starts with the boundaries sampled less densely (SurfaceRemeshParams::boundaryStartPriority):
// patch-23 (a 100 x 33 rectangle) at 30% without and with them. Without, 24 of its 32 vertices lie
// on the outline and the faces between it and the one row inside are tall: 40.7 degrees (CGAL's
// isotropic remeshing at our count: 41.7). With them, the start sampled with a boundary priority
// of 1.2 is kept: 44.8 degrees, fewer vertices on the outline (counted here from the faces: F = 2V
// - B - 2 on a disk), the same count. It is judged as the seeds' starts, no farther than the first
// start by the remesh's own distance (at the input's vertices, centroids and midpoints); by the
// oracle 3.7449 -> 3.7469% of the diagonal, within the 1% the sampled judge and the oracle differ
// by here (the first start alone: 3.6997% by the oracle, kept seeds judged no farther at 3.7449%).
TEST(RemeshAngles, BoundaryStartsOfASmallOutput) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter("patch-23.off", 30, [](SurfaceRemeshParams& p) { p.boundaryStartPriority = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  EXPECT_EQ(b.before->boundaryStarts, 0);
  EXPECT_GE(b.after->boundaryStarts, 1);
  EXPECT_EQ(b.after->keptBoundaryPriority, SurfaceRemeshParams{}.boundaryStartPriority);
  EXPECT_EQ(b.after->mesh.vertexCount(), b.before->mesh.vertexCount());
  const auto outline = [](const TriMesh& m) { return 2 * m.vertexCount() - 2 - m.faceCount(); };
  std::printf("patch-23 at 30%%: %d -> %d vertices on the outline\n", outline(b.before->mesh), outline(b.after->mesh));
  EXPECT_LT(outline(b.after->mesh), outline(b.before->mesh));
  const Figures f = figuresOf(b);
  printFigures("patch-23 at 30% (boundary priority 1.2 kept)", f);
  EXPECT_GT(f.after.smallestDegrees, f.before.smallestDegrees + 3.0);
  EXPECT_LE(f.after.shareBelow30, f.before.shareBelow30);
  EXPECT_LE(f.distanceAfter, 1.01 * f.distanceBefore);
  expectValidWithoutNewCrossings(b);
}

// The shakes of a small output (SurfaceRemeshParams::shakes): dragknob at 5% (8 vertices) without
// and with them. Without, the starts and the polishes leave 41.12 degrees (CGAL's isotropic
// remeshing at our count: 43.04); the shakes kept take it above 45, the oracle's two-sided
// distance no larger (15.705 -> 15.630% of the diagonal), the same count, the input's topology
// recounted, no crossing faces (CGAL). The shakes' draws are seeded: a second run gives the same
// output.
TEST(RemeshAngles, ShakesRaiseTheSmallestAngleOfASmallOutput) {
  const BeforeAndAfter b = remeshBeforeAndAfter("dragknob.off", 5, [](SurfaceRemeshParams& p) { p.shakes = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const Figures f = figuresOf(b);
  printFigures("dragknob at 5% (" + std::to_string(b.after->shakesKept) + " of " + std::to_string(b.after->shakesRun) +
                   " shakes kept)",
               f);
  EXPECT_EQ(b.before->shakesKept, 0);
  EXPECT_GE(b.after->shakesKept, 1);
  expectSameCountBetterNoFarther(b, f, 2.0);

  SurfaceRemeshParams params;
  params.sampling.targetCount = b.input.vertexCount() * 5 / 100;
  params.measure = false;
  const Expected<SurfaceRemeshResult> again = remeshSurface(b.input, params);
  ASSERT_TRUE(again) << again.status().message;
  EXPECT_EQ(again->mesh.positions, b.after->mesh.positions);
  EXPECT_EQ(again->mesh.triangles, b.after->mesh.triangles);
}

// The thin ears' slack (SurfaceRemeshParams::earSlack): lion at 30% without it and with it (the
// defaults; both cut last only). With it, its boundary's spike is cut: the smallest angle 12.0 ->
// 22.7 degrees, one face fewer under 30, the oracle's two-sided distance 1.2373 -> 1.2388% of the
// diagonal, farther but within the slack. (With the ears cut before the splits too, as the
// defaults do, the output reaches 30.0 degrees and no face under 30: RemeshAnglesAgainstCgalOver-
// TheDataSet, lion at 30%, against CGAL's 16.7 degrees and 0.16%.)
TEST(RemeshAngles, ThinEarsAreCutWithinTheSlack) {
  expectThinEarsCut(
      "lion.off", 30, 10.0, [](SurfaceRemeshParams& p) { p.earSlack = 0; }, SurfaceRemeshParams{}.earSlack);
}

// The splits also from the output with its thin ears cut (SurfaceRemeshParams::earsBeforeSplits):
// mech-holes-shark at 10% left its starts with an ear of 17.4 degrees, its smallest angle; the
// splits turned it into two faces no cut takes (17.5 degrees at last). With the ears cut before
// the splits too, that output's angles are the better and are kept: the smallest angle above 30
// degrees, no face under 30, the input's topology recounted, no crossing faces (CGAL). At 5% the
// ears cut first would not raise the smallest angle (a face that is no ear holds it): the splits
// from the starts' output alone, the same output with and without.
TEST(RemeshAngles, SplitsAlsoFromTheOutputWithItsThinEarsCut) {
  const auto splitsFirst = [](SurfaceRemeshParams& p) { p.earsBeforeSplits = false; };
  const BeforeAndAfter b = remeshBeforeAndAfter("mech-holes-shark.off", 10, splitsFirst);
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const Figures f = figuresOf(b);
  printFigures("mech-holes-shark at 10% (" + std::to_string(b.after->thinEars) + " thin ears cut)", f);
  EXPECT_GT(f.after.smallestDegrees, f.before.smallestDegrees + 10.0);
  EXPECT_GE(f.after.smallestDegrees, 30.0);
  EXPECT_EQ(f.after.shareBelow30, 0.0);
  EXPECT_GT(f.before.shareBelow30, 0.0);
  EXPECT_GE(b.after->thinEars, 1);
  expectValidWithoutNewCrossings(b);

  const BeforeAndAfter same = remeshBeforeAndAfter("mech-holes-shark.off", 5, splitsFirst);
  ASSERT_TRUE(same.before) << same.before.status().message;
  ASSERT_TRUE(same.after) << same.after.status().message;
  EXPECT_EQ(same.after->mesh.positions, same.before->mesh.positions);
  EXPECT_EQ(same.after->mesh.triangles, same.before->mesh.triangles);
  EXPECT_GT(same.after->splitRounds, 0) << "the splits kept from the starts' output";
}

/// `name` at `percent` without and with the collapses at the worst face
/// (SurfaceRemeshParams::worstFaceCollapses): at least one, each a vertex fewer (counted in
/// collapsedVertices too), still at least the count asked for; the smallest angle higher and no
/// more faces under 30 (recounted), the oracle's two-sided Hausdorff no larger, the topology
/// recounted, no new crossing faces (CGAL).
void expectWorstFaceCollapses(const std::string& name, int percent) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter(name, percent, [](SurfaceRemeshParams& p) { p.worstFaceCollapses = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const Figures f = figuresOf(b);
  printFigures(name + " at " + std::to_string(percent) + "% (" + std::to_string(b.after->worstFaceCollapses) +
                   " collapses at the worst face, " + std::to_string(b.before->mesh.vertexCount()) + " -> " +
                   std::to_string(b.after->mesh.vertexCount()) + " vertices for " +
                   std::to_string(b.after->countAsked) + ")",
               f);
  EXPECT_EQ(b.before->worstFaceCollapses, 0);
  EXPECT_GE(b.after->worstFaceCollapses, 1);
  EXPECT_EQ(b.after->mesh.vertexCount(), b.before->mesh.vertexCount() - b.after->worstFaceCollapses);
  EXPECT_EQ(b.after->collapsedVertices, b.before->collapsedVertices + b.after->worstFaceCollapses);
  EXPECT_GE(b.after->mesh.vertexCount(), b.after->countAsked);
  EXPECT_GT(f.after.smallestDegrees, f.before.smallestDegrees);
  EXPECT_LE(f.after.shareBelow30, f.before.shareBelow30);
  EXPECT_LE(f.distanceAfter, f.distanceBefore);
  expectValidWithoutNewCrossings(b);
}

// The collapses at the worst face, last (SurfaceRemeshParams::worstFaceCollapses): b9_mesh at 5%
// (47 components, 14 of them single triangles) ends at 305 vertices for 297 asked, its smallest
// angle 0.961 degrees in a face 70 units long across a thin part, its shortest side 2; an edge of
// that face collapsed, 1.17 degrees (CGAL's isotropic remeshing at our count: 0.978). pig at 30%
// (142 vertices for 140, the splits' vertex above the count): 30.73 -> 30.82 degrees.
TEST(RemeshAngles, CollapsesAtTheWorstFaceOfAnOutputAboveTheCount) {
  expectWorstFaceCollapses("b9_mesh.off", 5);
  expectWorstFaceCollapses("pig.off", 30);
}

// An output at the count asked for (within countTolerance) is left as it is, its smallest angle
// under 36 degrees though: fandisk at 30% (1,944 vertices for 1,942, 33.6 degrees). So is one
// above it whose collapses at the worst face would not raise that angle: mech-holes-shark at 5%
// (268 for 262, 30.1 degrees at a face of a hole's rim).
TEST(RemeshAngles, NoCollapsesAtTheWorstFaceWhereTheyWouldNotHelp) {
  for (const auto& [name, percent, atCount] :
       {std::tuple<const char*, int, bool>{"fandisk.off", 30, true}, {"mech-holes-shark.off", 5, false}}) {
    SCOPED_TRACE(name);
    const BeforeAndAfter b =
        remeshBeforeAndAfter(name, percent, [](SurfaceRemeshParams& p) { p.worstFaceCollapses = 0; });
    ASSERT_TRUE(b.before) << b.before.status().message;
    ASSERT_TRUE(b.after) << b.after.status().message;
    const double bound = (1.0 + SurfaceRemeshParams{}.countTolerance) * b.after->countAsked;
    ASSERT_EQ(b.after->mesh.vertexCount() <= bound, atCount);
    ASSERT_LT(test::recountAngles(b.after->mesh).smallestDegrees, SurfaceRemeshParams::kLastPolishBelowDegrees);
    EXPECT_EQ(b.after->worstFaceCollapses, 0);
    EXPECT_EQ(b.after->mesh.positions, b.before->mesh.positions);
    EXPECT_EQ(b.after->mesh.triangles, b.before->mesh.triangles);
  }
}

/// Whether the face of `mesh` with the smallest angle (recounted, test::recountAngles' atan2) has
/// a vertex in exactly three faces, each of whose edges two faces share: counted here from the
/// triangles.
bool worstFaceHasAnInnerVertexOfThreeFaces(const TriMesh& mesh) {
  int worst = 0;
  double smallest = 1e9;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    TriMesh one;
    const Tri& t = mesh.triangles[f];
    one.positions = {mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]};
    one.triangles = {Tri{0, 1, 2}};
    const double a = test::recountAngles(one).smallestDegrees;
    if (a < smallest) smallest = a, worst = f;
  }
  std::map<std::pair<int, int>, int> edges;
  std::vector<int> faces(mesh.vertexCount(), 0);
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      ++faces[t[k]];
      ++edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
    }
  for (const int v : mesh.triangles[worst]) {
    if (faces[v] != 3) continue;
    bool inner = true;
    for (const Tri& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        const int a = t[k], b = t[(k + 1) % 3];
        if (a == v || b == v) inner &= edges[{std::min(a, b), std::max(a, b)}] == 2;
      }
    if (inner) return true;
  }
  return false;
}

// The floor polishes, last (SurfaceRemeshParams::floorVertices): fandisk_large at 30% (4,752
// vertices for 4,752 asked) had one face of 22.9 degrees at a vertex inside the surface with three
// faces, the next at 30.3, and CGAL's isotropic remeshing at our count reaches 36.7. The vertex
// is collapsed (one vertex under the count asked, within its tolerance), and the polishes from
// where the output stands, the creases held, raise the whole floor: 38.8 degrees, no farther from
// the input by the oracle.
TEST(RemeshAngles, FloorPolishesAfterTheCollapseOfAVertexOfThreeFaces) {
  const BeforeAndAfter b =
      remeshBeforeAndAfter("fandisk_large.off", 30, [](SurfaceRemeshParams& p) { p.floorVertices = 0; });
  ASSERT_TRUE(b.before) << b.before.status().message;
  ASSERT_TRUE(b.after) << b.after.status().message;
  const Figures f = figuresOf(b);
  printFigures("fandisk_large at 30% (" + std::to_string(b.after->worstFaceCollapses) + " collapse, " +
                   std::to_string(b.after->floorPolishes) + " floor polishes, " +
                   std::to_string(b.before->mesh.vertexCount()) + " -> " + std::to_string(b.after->mesh.vertexCount()) +
                   " vertices for " + std::to_string(b.after->countAsked) + ")",
               f);
  EXPECT_TRUE(worstFaceHasAnInnerVertexOfThreeFaces(b.before->mesh));
  EXPECT_LE(f.before.smallestDegrees, 30.0);
  EXPECT_EQ(b.before->worstFaceCollapses, 0);
  EXPECT_EQ(b.before->floorPolishes, 0);
  EXPECT_EQ(b.after->worstFaceCollapses, 1);
  EXPECT_GE(b.after->floorPolishes, 1);
  EXPECT_EQ(b.after->mesh.vertexCount(), b.before->mesh.vertexCount() - 1);
  EXPECT_GE(b.after->mesh.vertexCount(), (1.0 - SurfaceRemeshParams{}.countTolerance) * b.after->countAsked);
  EXPECT_GE(f.after.smallestDegrees, SurfaceRemeshParams::kLastPolishBelowDegrees);
  EXPECT_LE(f.after.shareBelow30, f.before.shareBelow30);
  EXPECT_LE(f.distanceAfter, f.distanceBefore);
  expectValidWithoutNewCrossings(b);
}

// Flat ears off the boundary (removeFlatEars): lion-head at 30% had two ears of 5.8 and 6.2
// degrees, their tips at 168 degrees on a straight stretch of its boundary. They go: no angle
// under 20 degrees (5.75 without), the input's topology recounted.
/// The boundary loops of `mesh` (edges in one face, joined end to end), each as its vertices.
std::vector<std::vector<int>> boundaryLoopsOf(const TriMesh& mesh) {
  std::map<std::pair<int, int>, int> edges;  // directed edge -> faces, either way
  for (const Tri& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) ++edges[{std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])}];
  std::map<int, std::vector<int>> around;  // boundary vertex -> its boundary neighbours
  for (const auto& [e, faces] : edges)
    if (faces == 1) around[e.first].push_back(e.second), around[e.second].push_back(e.first);
  std::vector<std::vector<int>> loops;
  std::set<int> seen;
  for (const auto& [v, next] : around) {
    if (seen.count(v)) continue;
    std::vector<int> loop;
    for (int u = v, from = -1; !seen.count(u);) {
      seen.insert(u);
      loop.push_back(u);
      const int to = around[u][0] != from ? around[u][0] : around[u][1];
      from = u;
      u = to;
    }
    loops.push_back(loop);
  }
  return loops;
}

/// The faces of `m` with an angle under 30 degrees (recounted), and of them those on an edge
/// between two vertices of one loop (`loopOf`: per vertex, its loop or -1).
std::pair<int, int> facesUnder30OnLoops(const TriMesh& m, const std::vector<int>& loopOf) {
  int under30 = 0, onLoops = 0;
  for (const Tri& t : m.triangles) {
    if (test::recountAngles(buildTriMesh(m.positions, {t}).value()).smallestDegrees >= 30) continue;
    ++under30;
    bool on = false;
    for (int k = 0; k < 3; ++k) on = on || (loopOf[t[k]] >= 0 && loopOf[t[k]] == loopOf[t[(k + 1) % 3]]);
    onLoops += on;
  }
  return {under30, onLoops};
}

// ChineseDragon-10kv has two holes of about a hundredth of an output edge: at the output's
// resolution two points, whose three edges each have a sliver on them whatever is around. With
// every angle counted, the relaxation and the polish drew the rings in to widen those (8 to 12
// faces under 30 degrees per hole: 1.05 % of the output's faces against CGAL's 0.34 % at 10 %);
// with the tiny loops left out (RelaxationParams::tinyLoopLength), the output's faces under 30
// degrees are the six slivers and no vertex is nearer a hole than half an edge but its own.
// Recounted from the output's triangles.
TEST(RemeshAngles, TinyHolesKeepOnlyTheirSlivers) {
  const TriMesh input = test::loadRealMesh("ChineseDragon-10kv.off");
  ASSERT_EQ(test::recount(input.triangles, input.vertexCount()).boundaryLoops, 2);
  const Expected<SurfaceRemeshResult> r = remeshPercent(input, 10);
  ASSERT_TRUE(r) << r.status().message;
  const TriMesh& m = r->mesh;
  test::expectValidWithTopologyOf(test::recount(m.triangles, m.vertexCount()),
                                  test::recount(input.triangles, input.vertexCount()));
  double meanEdge = 0;
  for (const Tri& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      meanEdge += (m.positions[t[k]] - m.positions[t[(k + 1) % 3]]).norm() / (3.0 * m.faceCount());
  std::vector<int> loopOf(m.vertexCount(), -1);
  const std::vector<std::vector<int>> loops = boundaryLoopsOf(m);
  ASSERT_EQ(loops.size(), 2u);
  for (size_t l = 0; l < loops.size(); ++l) {
    double length = 0;
    for (size_t k = 0; k < loops[l].size(); ++k)
      length += (m.positions[loops[l][k]] - m.positions[loops[l][(k + 1) % loops[l].size()]]).norm();
    std::printf("hole %zu: %zu vertices, %.4f mean edges round\n", l, loops[l].size(), length / meanEdge);
    EXPECT_LT(length, 0.1 * meanEdge);
    for (int v : loops[l]) loopOf[v] = static_cast<int>(l);
    for (int v = 0; v < m.vertexCount(); ++v) {
      if (loopOf[v] != static_cast<int>(l)) {
        EXPECT_GT((m.positions[v] - m.positions[loops[l][0]]).norm(), 0.5 * meanEdge);
      }
    }
  }
  const auto [under30, onHoles] = facesUnder30OnLoops(m, loopOf);
  SurfaceRemeshParams every;
  every.sampling.targetCount = input.vertexCount() / 10;
  every.measure = false;
  every.relaxation.tinyLoopLength = 0;
  const Expected<SurfaceRemeshResult> drawnIn = remeshSurface(input, every);
  ASSERT_TRUE(drawnIn) << drawnIn.status().message;
  const test::AngleRecount a = test::recountAngles(m), b = test::recountAngles(drawnIn->mesh);
  std::printf(
      "%d vertices: %d faces under 30 degrees, %d on the holes' edges (%.2f %%); every angle counted: %d "
      "vertices, %.2f %%\n",
      m.vertexCount(), under30, onHoles, 100 * a.shareBelow30, drawnIn->mesh.vertexCount(), 100 * b.shareBelow30);
  EXPECT_EQ(under30, 6);
  EXPECT_EQ(onHoles, 6);
  EXPECT_GT(b.shareBelow30, 2 * a.shareBelow30);
}

TEST(RemeshAngles, FlatEarsOffTheBoundaryAreRemoved) {
  const Expected<TriMesh> input = loadTriMesh(test::meshPath("lion-head.off"));
  ASSERT_TRUE(input);
  SurfaceRemeshParams params;
  params.sampling.targetCount = input->vertexCount() * 3 / 10;
  params.measure = false;
  const Expected<SurfaceRemeshResult> ours = remeshSurface(*input, params);
  ASSERT_TRUE(ours) << ours.status().message;
  const test::AngleRecount a = test::recountAngles(ours->mesh);
  const test::Recount in = test::recount(input->triangles, input->vertexCount());
  const test::Recount out = test::recount(ours->mesh.triangles, ours->mesh.vertexCount());
  std::printf("lion-head at 30%%: %d ears removed, smallest angle %.2f deg\n", ours->removedEars, a.smallestDegrees);
  EXPECT_GE(ours->removedEars, 1);
  EXPECT_GE(a.smallestDegrees, 20.0);
  EXPECT_EQ(out.components, in.components);
  EXPECT_EQ(out.genusSum, in.genusSum);
  EXPECT_EQ(out.boundaryLoops, in.boundaryLoops);
}

// The polish's flips to fewer faces under 30 degrees (flipToBetterAngles) cross edges of up to
// the input's feature angle: knot2 at 5% is a tube a few vertices round, whose last face under
// 30 degrees (21.7, with the Delaunay flips' 30-degree crease bound) sits on an edge of 53
// degrees. Angles, topology and crossings recounted (CGAL's self-intersection test).
TEST(RemeshAngles, ThinTubeFlipsAcrossItsCoarseEdges) {
  const Expected<TriMesh> input = loadTriMesh(test::meshPath("knot2.off"));
  ASSERT_TRUE(input);
  const Expected<SurfaceRemeshResult> ours = remeshPercent(*input, 5);
  ASSERT_TRUE(ours) << ours.status().message;
  const test::AngleRecount a = test::recountAngles(ours->mesh);
  std::printf("knot2 at 5%%: smallest angle %.2f deg, %.2f %% under 30\n", a.smallestDegrees, 100 * a.shareBelow30);
  EXPECT_GE(a.smallestDegrees, 25.0);
  EXPECT_EQ(a.shareBelow30, 0.0);
  test::expectValidWithTopologyOf(test::recount(ours->mesh.triangles, ours->mesh.vertexCount()),
                                  test::recount(input->triangles, input->vertexCount()));
  const auto crossings = oracle::selfIntersections(ours->mesh);
  ASSERT_TRUE(crossings);
  EXPECT_TRUE(crossings->empty());
}

TEST(RemeshAngles, NoAngleUnder20DegreesOnClosedMeshesWithoutSlivers) {
  int checked = 0;
  for (const std::string& name : test::dataSetMeshFiles()) {
    const Expected<TriMesh> input = loadTriMesh(test::meshPath(name));
    if (!input || input->vertexCount() > 60000 || input->vertexCount() / 10 < 4) continue;
    const test::Recount in = test::recount(input->triangles, input->vertexCount());
    if (!(in.manifoldEdges && in.manifoldVertices && in.oriented) || in.boundaryLoops > 0) continue;
    if (test::recountAngles(*input).smallestDegrees < 1.0) continue;
    SCOPED_TRACE(name);
    const Expected<SurfaceRemeshResult> r = remeshPercent(*input, 10);
    ASSERT_TRUE(r) << r.status().message;
    const double smallest = test::recountAngles(r->mesh).smallestDegrees;
    std::printf("%-26s %6d -> %5d vertices: smallest angle %.1f deg%s\n", name.c_str(), input->vertexCount(),
                r->mesh.vertexCount(), smallest, r->angleRescued ? " (angle rescue)" : "");
    EXPECT_GE(smallest, 20.0);
    ++checked;
  }
  EXPECT_GE(checked, 30);  // the data set has 36 such meshes up to 60,000 vertices
}

}  // namespace
}  // namespace gr
