#include "filter_geodesic_remesh/remesh_pipeline.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "core/measure/evaluation.h"
#include "core/remesh/remesh.h"
#include "core/mesh/subdivide.h"
#include "filter_geodesic_remesh/parameter_names.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {
namespace {

/// The metric at the vertices of a subdivision: P interpolated at each vertex's original point.
Metric metricOnSubdivision(const Metric& metric, const TriMesh& original, const Subdivision& fine) {
  if (metric.isUniform()) return metric;
  Metric m;
  m.P.resize(fine.mesh.vertexCount());
  for (int v = 0; v < fine.mesh.vertexCount(); ++v) {
    const SurfacePoint& o = fine.origin[v];
    if (o.vertex >= 0) {
      m.P[v] = metric.P[o.vertex];
    } else {
      const Tri& t = original.triangles[o.face];
      m.P[v] = o.bary[0] * metric.P[t[0]] + o.bary[1] * metric.P[t[1]] + o.bary[2] * metric.P[t[2]];
    }
  }
  return m;
}

}  // namespace

void declareSampling(const MeshModel& mesh, RichParameterList& params) {
  const float diag = mesh.cm.bbox.IsNull() ? 1.0f : mesh.cm.bbox.Diag();
  const FpsParams defaults;
  params.addParam(RichInt(param::kTargetVertices, std::max(4, mesh.cm.vn / 10), "Target vertices",
                          "Number of vertices of the new mesh (default: 10% of the input). The repair of the "
                          "geodesic Delaunay triangulation may add a few; the log says how many. 0 = use Spacing."));
  params.addParam(RichAbsPerc(param::kSpacing, 0.02f * diag, 0.0f, diag, "Spacing",
                              "Used when Target vertices is 0: sample until every point of the surface is closer "
                              "than this geodesic distance to a sample (mesh units or % of the bounding-box "
                              "diagonal; default 2%)."));
  params.addParam(RichInt(param::kSeed, int(defaults.seed), "Seed",
                          "Picks the start of the farthest-point sampling: the same seed gives the same mesh "
                          "(default 0)."));
  params.addParam(RichBool(param::kSubVertexPlacement, defaults.subVertexPlacement, "Sub-vertex placement",
                           "Place each new sample where the fronts meet, inside a face, rather than at the "
                           "farthest input vertex (paper 3.1): fewer thin triangles on smooth surfaces, but samples "
                           "may leave sharp edges (default false)."));
}

Expected<FpsParams> readSampling(const RichParameterList& params) {
  FpsParams fps;
  fps.targetCount = params.getInt(param::kTargetVertices);
  fps.minSpacing = fps.targetCount > 0 ? 0.0 : params.getAbsPerc(param::kSpacing);
  fps.seed = static_cast<unsigned>(params.getInt(param::kSeed));
  fps.subVertexPlacement = params.getBool(param::kSubVertexPlacement);
  if (fps.targetCount < 0) return invalidInput("TargetVertices must be >= 0, got " + std::to_string(fps.targetCount));
  if (fps.targetCount == 0 && !(fps.minSpacing > 0.0))
    return invalidInput("TargetVertices is 0 and Spacing is not > 0: give one of them");
  return fps;
}

Status remeshToNewLayer(MeshDocument& doc, const CurrentMesh& current, const RemeshRequest& request,
                        FilterContext& ctx) {
  // Compute, with no change to the document...
  MeshModel* mm = current.model;
  CMeshO& m = mm->cm;
  const adapters::CoreView& view = current.view;
  const TriMesh& mesh = view.mesh;
  const Topology& topology = mesh.topology;
  if (!topology.isManifold())
    return nonManifold("the mesh has " + std::to_string(topology.nonManifoldEdges) + " non-manifold edges and " +
                       std::to_string(topology.nonManifoldVertices) +
                       " non-manifold vertices; repair them first (Cleaning and Repairing menu)");
  const int refinement = request.refinement;
  if (refinement < 0 || refinement > 3) return invalidInput("Refinement must be 0 to 3, got " + std::to_string(refinement));
  if (request.relaxation < 0 || request.relaxation > 100)
    return invalidInput("Relaxation must be 0 to 100 rounds, got " + std::to_string(request.relaxation));

  // Faces that run against their neighbours' orientation: the output takes its orientation
  // from the input's faces, so the work is done on a coherently oriented copy (same vertices,
  // same faces, some with corners 1 and 2 swapped); the input layer is not changed.
  std::vector<char> flipped;
  std::optional<TriMesh> orientedCopy;
  if (topology.inconsistentEdges > 0) {
    Expected<TriMesh> oriented = orientCoherently(mesh, &flipped);
    if (!oriented) return oriented.status();
    orientedCopy = std::move(oriented).value();
    ctx.log(std::to_string(std::count(flipped.begin(), flipped.end(), 1)) + " of the " +
            std::to_string(mesh.faceCount()) + " faces run against their neighbours' orientation (" +
            std::to_string(topology.inconsistentEdges) +
            " edges): the remeshing uses a coherently oriented copy; the input layer is not changed");
  }
  const TriMesh& surface = orientedCopy ? *orientedCopy : mesh;
  // The mesh the fronts run on: the input, or its midpoint subdivision (same surface).
  Expected<Subdivision> fine = subdivideMidpoint(surface, refinement);
  if (!fine) return fine.status();
  // One engine for both stages: the triangulation starts from the sampling's Voronoi diagram.
  const Metric metric = metricOnSubdivision(request.metric, surface, *fine);
  FastMarcher marcher(fine->mesh, metric);
  RemeshParams params;
  params.sampling = request.sampling;
  params.relaxation.iterations = request.relaxation;
  Expected<RemeshResult> remeshed = remesh(marcher, params, ctx.progress.sub(0.0, 0.9));
  if (!remeshed) return remeshed.status();
  const FpsResult& samples = remeshed->sampling;
  const DelaunayResult& result = remeshed->mesh;
  const RelaxationResult& relaxed = remeshed->relaxation;
  const AngleStatistics angles = angleStatistics(result.mesh);
  // The distance to the input both ways, for the log: on a large input the longest step after
  // the sampling (on all cores; 15 million samples for 1.66M input vertices).
  const SurfaceDistance there = surfaceDistance(result.mesh, mesh, ctx.progress.sub(0.9, 0.92));
  const SurfaceDistance back = surfaceDistance(mesh, result.mesh, ctx.progress.sub(0.92, 1.0));
  if (!there.complete || !back.complete) return cancelled();
  const double diag = mesh.boundingBoxDiagonal();

  // ...then commit: a new layer, and the input's labels only if asked.
  const bool copyColor = mm->hasDataMask(MeshModel::MM_VERTCOLOR);
  const bool copyQuality = mm->hasDataMask(MeshModel::MM_VERTQUALITY);
  const QString label = mm->label() + QString::fromStdString(request.layerSuffix);
  MeshModel* out = doc.addNewMesh("", label, true);
  if (copyColor) out->updateDataMask(MeshModel::MM_VERTCOLOR);
  if (copyQuality) out->updateDataMask(MeshModel::MM_VERTQUALITY);
  std::vector<SurfacePoint> origin(result.origin.size());
  for (size_t i = 0; i < origin.size(); ++i) {
    origin[i] = fine->originOf(surface, result.origin[i]);
    if (origin[i].face >= 0 && !flipped.empty() && flipped[origin[i].face]) std::swap(origin[i].bary[1], origin[i].bary[2]);
  }
  adapters::writeMesh(result.mesh, out->cm, m, view, origin, copyColor, copyQuality);
  if (request.labelInput) {  // the input's vertices keep their indices in the subdivision
    const std::vector<int> region(result.cell.begin(), result.cell.begin() + mesh.vertexCount());
    adapters::writeVertexQuality(m, view, std::vector<double>(region.begin(), region.end()), -1.0);
    adapters::colorByLabel(m, view, region, result.mesh.vertexCount());
    mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  }

  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - request.start).count();
  ctx.log(request.title + " of " + std::to_string(mesh.vertexCount()) + " vertices, " +
          std::to_string(mesh.faceCount()) + " faces" +
          (refinement > 0 ? " (fronts on " + std::to_string(fine->mesh.vertexCount()) + " vertices, " +
                                std::to_string(refinement) + " subdivisions)"
                          : std::string()) +
          ": " + std::to_string(result.mesh.vertexCount()) + " vertices, " +
          std::to_string(result.mesh.faceCount()) + " faces on the new layer '" + label.toStdString() + "'");
  ctx.log("Samples: " + std::to_string(samples.samples.size()) + " by farthest-point sampling, " +
          std::to_string(result.addedSamples) + " added to make the triangulation valid (" +
          std::to_string(result.repairRounds) + " rounds)" +
          (result.droppedSamples > 0 ? ", " + std::to_string(result.droppedSamples) + " left out (nearest to no vertex)"
                                      : std::string()) +
          "; covering radius " + formatNumber(samples.coveringRadius, "%.4g") +
          (request.metric.isUniform() ? std::string() : " (a travel time: distance over speed)") +
          (result.flippedEdges > 0 ? "; " + std::to_string(result.flippedEdges) + " edges flipped to Delaunay"
                                    : std::string()));
  // A triangle soup (an STL read without merging its vertices) is as many components as faces,
  // each of which keeps its own vertices: the output is then the input. Say why, and what helps.
  int looseFaces = 0;
  for (int f = 0; f < mesh.faceCount(); ++f)
    looseFaces += mesh.oppositeCorner[3 * f] < 0 && mesh.oppositeCorner[3 * f + 1] < 0 && mesh.oppositeCorner[3 * f + 2] < 0;
  if (looseFaces > 0 && 10 * looseFaces >= mesh.faceCount())
    ctx.warn(std::to_string(looseFaces) + " of the " + std::to_string(mesh.faceCount()) +
             " faces share no edge with another face (separate triangles, as an STL file read without merging "
             "its vertices gives): each is a component of its own and keeps its three vertices. Run 'Cleaning "
             "and Repairing > Merge Close Vertices' first to remesh the surface they form.");
  if (relaxed.iterations > 0)
    ctx.log("Relaxation on the input surface: " + std::to_string(relaxed.iterations) + " rounds, " +
            std::to_string(relaxed.moves) + " vertex moves, " + std::to_string(relaxed.flips) + " flips; " +
            std::to_string(relaxed.fixedVertices) + " vertices kept in place (boundary, creases and corners)");
  ctx.log("Topology kept: " + std::to_string(result.mesh.topology.components) + " components, genus " +
          std::to_string(result.mesh.topology.genus) + ", " + std::to_string(result.mesh.topology.boundaryLoops) +
          " boundary loops");
  ctx.log("Angles: standard deviation " + formatNumber(angles.stdDegrees, "%.1f") + " deg, smallest " +
          formatNumber(angles.minDegrees, "%.1f") + " deg, " + formatNumber(100 * angles.shareMinBelow30, "%.2f") +
          " % of triangles with an angle under 30 deg");
  const double rms = std::sqrt(0.5 * (there.rms * there.rms + back.rms * back.rms));
  ctx.log("Hausdorff distance to the input (one-sided): " + formatNumber(100 * there.max / diag, "%.3f") +
          " % of the bounding-box diagonal; two-sided " + formatNumber(100 * std::max(there.max, back.max) / diag, "%.3f") +
          " %, RMS " + formatNumber(100 * rms / diag, "%.3f") + " %");
  ctx.log("Time: " + formatDuration(ms));
  return Status::ok();
}

}  // namespace gr::filters
