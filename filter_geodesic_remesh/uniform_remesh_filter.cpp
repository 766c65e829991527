#include "filter_geodesic_remesh/uniform_remesh_filter.h"

#include <chrono>
#include <cmath>
#include <string>

#include "core/evaluation.h"
#include "core/farthest_point_sampling.h"
#include "core/geodesic_delaunay.h"
#include "core/subdivide.h"
#include "filter_geodesic_remesh/filter_support.h"
#include "filter_geodesic_remesh/parameter_names.h"
#include "vcg_adapters/cmesho_adapter.h"

namespace gr::filters {
void declareUniformRemesh(const MeshModel& mesh, RichParameterList& params) {
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
  params.addParam(RichInt(param::kRefinement, 0, "Refinement",
                          "Compute the sampling and the Voronoi cells on the input subdivided this many times "
                          "(0 to 3; each level: 4x the vertices and about 4x the time). Finer cells give better "
                          "shaped triangles when the target is a large share of the input's vertices; samples "
                          "then also lie between input vertices (default 0)."));
  params.addParam(RichBool(param::kSubVertexPlacement, defaults.subVertexPlacement, "Sub-vertex placement",
                           "Place each new sample where the fronts meet, inside a face, rather than at the "
                           "farthest input vertex (paper 3.1): fewer thin triangles on smooth surfaces, but samples "
                           "may leave sharp edges (default false)."));
  params.addParam(RichBool(param::kLabelInput, false, "Label input",
                           "Also write into the input mesh each vertex's Voronoi cell (the output vertex it belongs "
                           "to) as vertex quality, and color it by cell (default false: the input is not changed)."));
}

Status applyUniformRemesh(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  // Compute, with no change to the document...
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  MeshModel* mm = current->model;
  CMeshO& m = mm->cm;
  const adapters::CoreView& view = current->view;
  const TriMesh& mesh = view.mesh;
  const Topology& topology = mesh.topology;
  if (!topology.isManifold())
    return nonManifold("the mesh has " + std::to_string(topology.nonManifoldEdges) + " non-manifold edges and " +
                       std::to_string(topology.nonManifoldVertices) +
                       " non-manifold vertices; repair them first (Cleaning and Repairing menu)");
  FpsParams fps;
  fps.targetCount = params.getInt(param::kTargetVertices);
  fps.minSpacing = fps.targetCount > 0 ? 0.0 : params.getAbsPerc(param::kSpacing);
  fps.seed = static_cast<unsigned>(params.getInt(param::kSeed));
  fps.subVertexPlacement = params.getBool(param::kSubVertexPlacement);
  if (fps.targetCount < 0) return invalidInput("TargetVertices must be >= 0, got " + std::to_string(fps.targetCount));
  if (fps.targetCount == 0 && !(fps.minSpacing > 0.0))
    return invalidInput("TargetVertices is 0 and Spacing is not > 0: give one of them");
  const bool labelInput = params.getBool(param::kLabelInput);
  const int refinement = params.getInt(param::kRefinement);
  if (refinement < 0 || refinement > 3) return invalidInput("Refinement must be 0 to 3, got " + std::to_string(refinement));

  // The mesh the fronts run on: the input, or its midpoint subdivision (same surface).
  Expected<Subdivision> fine = subdivideMidpoint(mesh, refinement);
  if (!fine) return fine.status();
  // One engine for both stages: the triangulation starts from the sampling's Voronoi diagram.
  const Metric metric = Metric::uniform();
  FastMarcher marcher(fine->mesh, metric);
  Expected<FpsResult> samples = farthestPointSampling(marcher, fps, ctx.progress.sub(0.0, 0.6));
  if (!samples) return samples.status();
  Expected<DelaunayResult> result = geodesicDelaunay(marcher, samples->points, {}, ctx.progress.sub(0.6, 0.9));
  if (!result) return result.status();
  const AngleStatistics angles = angleStatistics(result->mesh);
  const SurfaceDistance hausdorff = surfaceDistance(result->mesh, mesh);
  const double diag = mesh.boundingBoxDiagonal();

  // ...then commit: a new layer, and the input's labels only if asked.
  const bool copyColor = mm->hasDataMask(MeshModel::MM_VERTCOLOR);
  const bool copyQuality = mm->hasDataMask(MeshModel::MM_VERTQUALITY);
  const QString label = mm->label() + " - geodesic remesh";
  MeshModel* out = doc.addNewMesh("", label, true);
  if (copyColor) out->updateDataMask(MeshModel::MM_VERTCOLOR);
  if (copyQuality) out->updateDataMask(MeshModel::MM_VERTQUALITY);
  std::vector<SurfacePoint> origin(result->samplePoint.size());
  for (size_t i = 0; i < origin.size(); ++i) origin[i] = fine->toOriginal(mesh, result->samplePoint[i]);
  adapters::writeMesh(result->mesh, out->cm, m, view, origin, copyColor, copyQuality);
  if (labelInput) {  // the input's vertices keep their indices in the subdivision
    const std::vector<int> region(result->region.begin(), result->region.begin() + mesh.vertexCount());
    adapters::writeVertexQuality(m, view, std::vector<double>(region.begin(), region.end()), -1.0);
    adapters::colorByLabel(m, view, region, result->mesh.vertexCount());
    mm->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR);
  }

  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ctx.log("Geodesic uniform remeshing of " + std::to_string(mesh.vertexCount()) + " vertices, " +
          std::to_string(mesh.faceCount()) + " faces" +
          (refinement > 0 ? " (fronts on " + std::to_string(fine->mesh.vertexCount()) + " vertices, " +
                                std::to_string(refinement) + " subdivisions)"
                          : std::string()) +
          ": " + std::to_string(result->mesh.vertexCount()) + " vertices, " +
          std::to_string(result->mesh.faceCount()) + " faces on the new layer '" + label.toStdString() + "'");
  ctx.log("Samples: " + std::to_string(samples->samples.size()) + " by farthest-point sampling, " +
          std::to_string(result->addedSamples) + " added to make the triangulation valid (" +
          std::to_string(result->repairRounds) + " rounds)" +
          (result->droppedSamples > 0 ? ", " + std::to_string(result->droppedSamples) + " left out (nearest to no vertex)"
                                      : std::string()) +
          "; covering radius " + formatNumber(samples->coveringRadius, "%.4g") +
          (result->flippedEdges > 0 ? "; " + std::to_string(result->flippedEdges) + " edges flipped to Delaunay"
                                    : std::string()));
  ctx.log("Topology kept: " + std::to_string(result->mesh.topology.components) + " components, genus " +
          std::to_string(result->mesh.topology.genus) + ", " + std::to_string(result->mesh.topology.boundaryLoops) +
          " boundary loops");
  ctx.log("Angles: standard deviation " + formatNumber(angles.stdDegrees, "%.1f") + " deg, smallest " +
          formatNumber(angles.minDegrees, "%.1f") + " deg, " + formatNumber(100 * angles.shareMinBelow30, "%.2f") +
          " % of triangles with an angle under 30 deg");
  ctx.log("Hausdorff distance to the input (one-sided): " + formatNumber(100 * hausdorff.max / diag, "%.3f") +
          " % of the bounding-box diagonal, RMS " + formatNumber(100 * hausdorff.rms / diag, "%.3f") + " %");
  ctx.log("Time: " + formatNumber(ms, "%.4g") + " ms");
  return Status::ok();
}

}  // namespace gr::filters
