#include "filter_geodesic_remesh/uniform_remesh_filter.h"

#include "filter_geodesic_remesh/parameter_names.h"
#include "filter_geodesic_remesh/remesh_layer.h"

namespace gr::filters {

void declareUniformRemesh(const MeshModel& mesh, RichParameterList& params) {
  declareSampling(mesh, params, SurfaceRemeshParams{});
  const SurfaceRemeshParams defaults;
  params.addParam(RichInt(param::kRefinement, defaults.refinement, "Refinement",
                          "Compute the sampling and the Voronoi cells on the input subdivided this many times "
                          "(0 to " +
                              QString::number(SurfaceRemeshParams::kMaxRefinement) +
                              "; each level: 4x the vertices and about 4x the time). Finer cells give better "
                              "shaped triangles when the target is a large share of the input's vertices; samples "
                              "then also lie between input vertices. Not applied where the input's triangles are "
                              "poor (slivers, as CAD exports have): the fronts then run on its intrinsic Delaunay "
                              "refinement (default " +
                              QString::number(defaults.refinement) + ")."));
  params.addParam(RichInt(param::kRelaxation, defaults.relaxation.iterations, "Relaxation",
                          "Rounds of tangential relaxation after the triangulation (0 to " +
                              QString::number(SurfaceRemeshParams::kMaxRelaxationRounds) +
                              "): each vertex moves toward the mean of its neighbours on the input surface, or "
                              "where an angle is small by the step that raises it (never across a crease, never "
                              "smoothing away a tip; vertices on boundaries and creases slide along them), then "
                              "edges are flipped back to Delaunay. Raises the smallest angles; 0 keeps the paper's "
                              "triangulation as it is (default " +
                              QString::number(defaults.relaxation.iterations) + ")."));
  params.addParam(RichBool(param::kLabelInput, false, "Label input",
                           "Also write into the input mesh each vertex's Voronoi cell (the output vertex it belongs "
                           "to) as vertex quality, and color it by cell (default false: the input is not changed)."));
  declareReportError(params);
}

Status applyUniformRemesh(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  RemeshCommit commit;
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  SurfaceRemeshParams remesh;
  remesh.sampling = readSampling(params);
  remesh.centroidalIterations = params.getInt(param::kCentroidalIterations);
  remesh.refinement = params.getInt(param::kRefinement);
  remesh.relaxation.iterations = params.getInt(param::kRelaxation);
  remesh.measureDistance = readReportError(params);
  Expected<SurfaceRemeshResult> result = remeshSurface(current->view.mesh, remesh, ctx.progress);
  if (!result) return result.status();
  commit.title = "Geodesic uniform remeshing";
  commit.layerSuffix = " - geodesic remesh";
  commit.labelInput = params.getBool(param::kLabelInput);
  commit.refinement = remesh.refinement;
  commitRemesh(doc, *current, *result, commit, ctx);
  return Status::ok();
}

}  // namespace gr::filters
