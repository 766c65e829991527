#include "filter_geodesic_remesh/remesh_layer.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/format.h"
#include "filter_geodesic_remesh/parameter_names.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {
namespace {

std::string count(int n) { return std::to_string(n); }
/// "1 round", "n rounds".
/// A share as a percentage ("2%").
std::string percent(double share) { return formatNumber(100 * share, "%.2g") + "%"; }

std::string rounds(int n) { return count(n) + (n == 1 ? " round" : " rounds"); }

/// What the edge collapses were for: the count asked for, the worst faces last, or both.
std::string collapses(const SurfaceRemeshResult& r) {
  const int toCount = r.collapsedVertices - r.worstFaceCollapses;
  const std::string worst =
      " last, at the triangle with the smallest angle, where that raised it and the distance to "
      "the input did not grow";
  if (r.worstFaceCollapses == 0) return " to reach the count asked for";
  if (toCount == 0) return worst;
  return " to reach the count asked for (" + count(r.worstFaceCollapses) + " of them" + worst + ")";
}

/// Faces that ran against their neighbours: the work used an oriented copy.
void logOrientation(const TriMesh& input, const SurfaceRemeshResult& r, FilterContext& ctx) {
  if (r.reorientedFaces == 0) return;
  ctx.log(count(r.reorientedFaces) + " of the " + count(input.faceCount()) +
          " faces run against their neighbours' orientation (" + count(input.topology.inconsistentEdges) +
          " edges): the remeshing uses a coherently oriented copy; the input layer is not changed");
}

/// The first two lines: what was remeshed into what, and how the samples came about.
void logCounts(const TriMesh& input, const SurfaceRemeshResult& r, const RemeshCommit& commit, const QString& label,
               FilterContext& ctx) {
  ctx.log(commit.title + " of " + count(input.vertexCount()) + " vertices, " + count(input.faceCount()) + " faces" +
          (commit.refinement > 0 && !r.refinedSurface && r.frontVertices > input.vertexCount()
               ? " (fronts on " + count(r.frontVertices) + " vertices, " + count(commit.refinement) + " subdivisions)"
               : std::string()) +
          ": " + count(r.mesh.vertexCount()) + " vertices, " + count(r.mesh.faceCount()) + " faces on the new layer '" +
          label.toStdString() + "'");
  ctx.log("Samples: " + count(r.sampledCount) + " by farthest-point sampling" +
          (r.lloydIterations > 0
               ? " moved by " + count(r.lloydIterations) + " geodesic Lloyd iterations (their energy " +
                     formatNumber(100 * (r.lloydEnergyRatio - 1.0), "%+.1f") + "%)"
               : std::string()) +
          ", " + count(r.addedSamples) + " added to make the triangulation valid (" + rounds(r.repairRounds) +
          (r.crossingRounds > 0 ? ", " + count(r.crossingRounds) + " of them where output triangles crossed"
                                : std::string()) +
          ")" +
          (r.droppedSamples > 0 ? ", " + count(r.droppedSamples) + " left out (nearest to no vertex)" : std::string()) +
          (r.collapsedVertices > 0 ? ", " + count(r.collapsedVertices) + " removed by edge collapses" + collapses(r)
                                   : std::string()) +
          (r.removedEars > r.thinEars
               ? ", " + count(r.removedEars - r.thinEars) +
                     " removed with flat ears off the boundary (a triangle with two boundary edges and an "
                     "angle under 30 deg, its tip near its base, which the boundary then follows)"
               : std::string()) +
          (r.thinEars > 0 ? ", " + count(r.thinEars) +
                                " removed with thin ears off the boundary (a triangle with two boundary edges and an "
                                "angle under 30 deg; cut where the distance to the input grows by at most " +
                                percent(SurfaceRemeshParams{}.earSlack) + ", all cuts together)"
                          : std::string()) +
          (r.splitVertices > 0 ? ", " + count(r.splitVertices) +
                                     " added by splitting the edge facing a wide angle of triangles under 30 deg (" +
                                     rounds(r.splitRounds) + ")"
                               : std::string()) +
          "; covering radius " + formatNumber(r.coveringRadius, "%.4g") +
          (commit.weighted ? " (a travel time: distance over speed)" : std::string()) +
          (r.flippedEdges > 0 ? "; " + count(r.flippedEdges) + " edges flipped to Delaunay" : std::string()));
}

/// When the repair added samples and the sampling was redone to land at the count asked for
/// (issue 20): how many samplings, and the fewest vertices reached when the count was not.
void logCountSearch(const SurfaceRemeshResult& r, FilterContext& ctx) {
  if (r.samplingRounds <= 1) return;
  const int got = r.mesh.vertexCount();
  std::string line =
      r.centroidalRescue
          ? "The first sampling's repair added more than " +
                formatNumber(100 * SurfaceRemeshParams::kRescueShare, "%g") +
                "% of the count (or, on a refined surface, its output crossed itself), so the sampling was redone "
                "with the samples moved by " +
                std::to_string(SurfaceRemeshParams::kRescueCentroidalIterations) +
                " geodesic Lloyd iterations, then with fewer if needed: "
          : std::string("The repair added samples, so the sampling was redone with fewer: ");
  line += count(r.samplingRounds) + " samplings, the output closest to the " + count(r.countAsked) +
          " vertices asked for kept (" + count(r.sampledAsked) + " samples asked of the sampling)";
  if (got > r.countAsked && r.fewestCount > 0)
    line += "; the fewest vertices of an output without crossing faces at these settings: " + count(r.fewestCount) +
            " (" + count(r.countAsked) + " asked)";
  ctx.log(line);
}

/// The remesh had more vertices than the input: the input's triangles were kept.
void logInputKept(const TriMesh& input, const SurfaceRemeshResult& r, FilterContext& ctx) {
  if (!r.inputKept) return;
  ctx.warn("The remesh needed " + count(r.remeshedCount) + " vertices to keep this surface's topology (" +
           count(input.topology.components) + " components, " + count(input.topology.boundaryLoops) +
           " boundary loops), more than the input's " + count(input.vertexCount()) +
           ": the new layer is the input's own triangles.");
}

/// The fronts ran on the intrinsic Delaunay refinement of the input (its triangles were poor).
void logRefinedSurface(const SurfaceRemeshResult& r, FilterContext& ctx) {
  if (!r.refinedSurface) return;
  ctx.log(
      "The input's triangles are poor (slivers or caps, as CAD exports have): the fronts ran on its intrinsic "
      "Delaunay refinement, " +
      count(r.refinedPoints) + " points inserted (" + count(r.frontVertices) +
      " vertices); every output vertex lies on the input");
}

/// A triangle soup comes back as it was: say why, and what helps.
void warnIfSoup(const TriMesh& input, const SurfaceRemeshResult& r, int refinement, FilterContext& ctx) {
  if (!r.looksLikeTriangleSoup) return;
  ctx.warn(count(r.looseFaces) + " of the " + count(input.faceCount()) +
           " faces share no edge with another face (separate triangles, as an STL file read without merging "
           "its vertices gives): each is a component of its own and keeps its three vertices" +
           (refinement > 0 ? std::string(" (Refinement is not applied to a soup)") : std::string()) +
           ". Run 'Cleaning and Repairing > Merge Close Vertices' first to remesh the surface they form.");
}

/// Relaxation, topology, angles and the distance to the input.
void logQuality(const SurfaceRemeshResult& r, FilterContext& ctx) {
  const RelaxationResult& relaxed = r.relaxation;
  if (relaxed.iterations > 0)
    ctx.log(
        "Relaxation on the input surface: " + rounds(relaxed.iterations) + ", " + count(relaxed.moves) +
        " vertex moves, " + count(relaxed.flips) + " flips" +
        (relaxed.polishMoves > 0
             ? "; then " + count(relaxed.polishMoves) + " moves of the polish, raising the smallest angles"
             : std::string()) +
        (r.lastPolishes > 0 ? "; polished again from where it stood, kept " +
                                  (r.lastPolishes == 1 ? std::string("once") : count(r.lastPolishes) + " times") +
                                  " (better angles, no farther from the input)"
                            : std::string()) +
        (r.floorPolishes > 0
             ? "; then polished " + (r.floorPolishes == 1 ? std::string("once") : count(r.floorPolishes) + " times") +
                   " more from where it stood, the input's boundaries and creases held (better "
                   "angles, no farther from the input)"
             : std::string()) +
        (r.jointMoves > 0
             ? "; " + count(r.jointMoves) + " joint moves of the worst faces' vertices (no farther from the input)"
             : std::string()) +
        (r.shakesKept > 0 ? "; " + count(r.shakesKept) + " of " + count(r.shakesRun) +
                                " shakes kept (its inner vertices moved at random, then polished: better angles, no "
                                "farther from the input)"
                          : std::string()) +
        (relaxed.slidingVertices > 0
             ? "; " + count(relaxed.slidingVertices) + " vertices moved only along the input's boundaries and creases"
             : std::string()) +
        (relaxed.fixedVertices > 0
             ? "; " + count(relaxed.fixedVertices) + " kept in place (corners of boundaries and creases)"
             : std::string()) +
        (relaxed.pinnedVertices > 0 ? " and " + count(relaxed.pinnedVertices) + " where moving them made faces cross"
                                    : std::string()) +
        (relaxed.refusedCrossing > 0
             ? "; " + count(relaxed.refusedCrossing) + " moves refused where faces would have crossed"
             : std::string()));
  if (r.angleRescueTried)
    ctx.log("The smallest angle was " + formatNumber(r.firstSmallestAngle, "%.1f") + " deg (under " +
            formatNumber(SurfaceRemeshParams::kRescueAngleDegrees, "%g") + "), so the remeshing was redone with " +
            std::to_string(SurfaceRemeshParams::kRescueCentroidalIterations) + " geodesic Lloyd iterations: " +
            (r.angleRescued ? std::string("that output, better, kept") : std::string("not better, the first kept")));
  if (r.starts > 1)
    ctx.log("A small output (at most " + std::to_string(SurfaceRemeshParams::kRestartVertices) +
            " vertices): remeshed " + count(r.starts) + " times (other seeds of the sampling" +
            (r.cornerStarts > 0 ? std::string(", from the corners of the input's boundaries and creases") : "") +
            (r.boundaryStarts > 0 ? std::string(", with the boundaries sampled less densely") : "") +
            ", each also relaxed with moves further off the surface); " +
            (r.keptStart > 0 ? "kept: " +
                                   (r.keptCorners > 0 ? "sampled from the " + count(r.keptCorners) + " corners"
                                                      : "seed " + std::to_string(r.keptSeed)) +
                                   (r.keptBoundaryPriority != FpsParams{}.boundaryPriority
                                        ? ", the boundaries sampled 1/" + formatNumber(r.keptBoundaryPriority, "%g") +
                                              " of the inner spacing apart"
                                        : std::string()) +
                                   ", moves up to " + formatNumber(r.keptDeviation, "%g") +
                                   " of the ring (fewer triangles under 30 deg or a larger smallest angle, no "
                                   "farther from the input)"
                             : std::string("the first kept (no other better)")));
  const Topology& topology = r.mesh.topology;
  ctx.log("Topology kept: " + count(topology.components) + " components, genus " + count(topology.genus) + ", " +
          count(topology.boundaryLoops) + " boundary loops; " +
          (r.crossingPairs == 0 ? std::string("no faces cross each other")
                                : count(r.crossingPairs) + " pairs of faces cross each other"));
  if (r.crossingPairs > 0)
    ctx.warn(count(r.crossingPairs) +
             " pairs of output faces cross each other: where the input crosses itself, or where the "
             "triangulation could not be refined further. 'Select Self Intersecting Faces' shows them.");
  const RemeshMeasures& m = r.measures;
  ctx.log("Angles: standard deviation " + formatNumber(m.angles.stdDegrees, "%.1f") + " deg, smallest " +
          formatNumber(m.angles.minDegrees, "%.1f") + " deg, " + formatNumber(100 * m.angles.shareMinBelow30, "%.2f") +
          " % of triangles with an angle under 30 deg");
  if (!m.distances) return;  // ReportError off
  const double rms = std::sqrt(0.5 * (m.toInput.rms * m.toInput.rms + m.fromInput.rms * m.fromInput.rms));
  const double diag = m.inputDiagonal;
  ctx.log("Hausdorff distance to the input (one-sided): " + formatNumber(100 * m.toInput.max / diag, "%.3f") +
          " % of the bounding-box diagonal; two-sided " +
          formatNumber(100 * std::max(m.toInput.max, m.fromInput.max) / diag, "%.3f") + " %, RMS " +
          formatNumber(100 * rms / diag, "%.3f") + " %");
}

}  // namespace

void declareSampling(const MeshModel& mesh, RichParameterList& params, const SurfaceRemeshParams& defaults) {
  const float diag = mesh.cm.bbox.IsNull() ? 1.0f : mesh.cm.bbox.Diag();
  const double spacing = SurfaceRemeshParams::kDefaultSpacingFraction;
  params.addParam(RichInt(param::kTargetVertices, SurfaceRemeshParams::defaultTargetCount(mesh.cm.vn),
                          "Target vertices",
                          "Number of vertices of the new mesh (default: " +
                              QString::number(100 * SurfaceRemeshParams::kDefaultTargetFraction) +
                              "% of the input). The repair of the geodesic Delaunay triangulation may add a few; the "
                              "log says how many. 0 = use Spacing."));
  params.addParam(RichAbsPerc(param::kSpacing, float(spacing * diag), 0.0f, diag, "Spacing",
                              "Used when Target vertices is 0: sample until every point of the surface is closer "
                              "than this geodesic distance to a sample (mesh units or % of the bounding-box "
                              "diagonal; default " +
                                  QString::number(100 * spacing) + "%)."));
  params.addParam(RichInt(param::kSeed, int(defaults.sampling.seed), "Seed",
                          "Picks the start of the farthest-point sampling: the same seed gives the same mesh "
                          "(default " +
                              QString::number(defaults.sampling.seed) + ")."));
  params.addParam(RichBool(param::kSubVertexPlacement, defaults.sampling.subVertexPlacement, "Sub-vertex placement",
                           QString("Place each new sample where the fronts meet, inside a face, rather than at the "
                                   "farthest input vertex (paper 3.1): fewer thin triangles on smooth surfaces, but "
                                   "samples may leave sharp edges (default ") +
                               (defaults.sampling.subVertexPlacement ? "true" : "false") + ")."));
  params.addParam(
      RichInt(param::kCentroidalIterations, defaults.centroidalIterations, "Centroidal iterations",
              "Geodesic Lloyd iterations on the samples before the triangulation (0 to " +
                  QString::number(SurfaceRemeshParams::kMaxCentroidalIterations) +
                  "): each sample moves to the centre of mass of its Voronoi cell in the remeshing's "
                  "metric (paper 4.2), evening out the cells; the relaxation then also flips edges toward "
                  "valence 6 (regular triangles, no new angle under 30 degrees). About 0.06 s per iteration "
                  "at 3,800 samples on a 38k-vertex mesh (default " +
                  QString::number(defaults.centroidalIterations) + ")."));
}

void declareReportError(RichParameterList& params) {
  const bool defaultValue = SurfaceRemeshParams{}.measureDistance;
  params.addParam(RichBool(param::kReportError, defaultValue, "Report error",
                           "Also measure the distance between the new mesh and the input both ways and write it to "
                           "the log (Hausdorff and RMS, in % of the bounding-box diagonal): exact at its samples, "
                           "about a tenth more time (bunny00 at 10%: 15 ms of 150). MeshLab's 'Hausdorff Distance' "
                           "filter measures it too (default " +
                               QString(defaultValue ? "true" : "false") + ")."));
}

bool readReportError(const RichParameterList& params) { return params.getBool(param::kReportError); }

FpsParams readSampling(const RichParameterList& params) {
  FpsParams fps;
  fps.targetCount = params.getInt(param::kTargetVertices);
  fps.minSpacing = fps.targetCount > 0 ? 0.0 : params.getAbsPerc(param::kSpacing);
  fps.seed = static_cast<unsigned>(params.getInt(param::kSeed));
  fps.subVertexPlacement = params.getBool(param::kSubVertexPlacement);
  return fps;
}

void commitRemesh(MeshDocument& doc, const CurrentMesh& current, const SurfaceRemeshResult& result,
                  const RemeshCommit& commit, FilterContext& ctx) {
  MeshModel* mm = current.model;
  const adapters::CoreView& view = current.view;
  const bool copyColor = mm->hasDataMask(MeshModel::MM_VERTCOLOR);
  const bool copyQuality = mm->hasDataMask(MeshModel::MM_VERTQUALITY);
  const QString label = mm->label() + QString::fromStdString(commit.layerSuffix);
  MeshModel* out = doc.addNewMesh("", label, true);
  if (copyColor) out->updateDataMask(MeshModel::MM_VERTCOLOR);
  if (copyQuality) out->updateDataMask(MeshModel::MM_VERTQUALITY);
  adapters::writeMesh(result.mesh, out->cm, mm->cm, view, result.origin, copyColor, copyQuality);
  if (commit.labelInput) {
    adapters::writeVertexQuality(mm->cm, view, std::vector<double>(result.cell.begin(), result.cell.end()), -1.0);
    adapters::colorByLabel(mm->cm, view, result.cell, result.mesh.vertexCount());
    mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - commit.start).count();
  logOrientation(view.mesh, result, ctx);
  logCounts(view.mesh, result, commit, label, ctx);
  logCountSearch(result, ctx);
  logInputKept(view.mesh, result, ctx);
  logRefinedSurface(result, ctx);
  warnIfSoup(view.mesh, result, commit.refinement, ctx);
  logQuality(result, ctx);
  const RemeshStageTimes& t = result.times;
  const double stages = 1e3 * (t.remesh() + t.restarts + t.measure);
  ctx.log("Time: " + formatDuration(ms) + " (preparation " + formatDuration(1e3 * t.prepare) + ", engine " +
          formatDuration(1e3 * t.engine) + ", sampling " + formatDuration(1e3 * t.sampling) + ", triangulation " +
          formatDuration(1e3 * t.triangulation) + ", relaxation " + formatDuration(1e3 * t.relaxation) +
          (t.restarts > 0 ? ", the other starts " + formatDuration(1e3 * t.restarts) : std::string()) +
          ", the log's measures " + formatDuration(1e3 * t.measure) +
          ", other (MeshLab's mesh in and out, the speed field) " + formatDuration(std::max(0.0, ms - stages)) + ")");
}

}  // namespace gr::filters
