#include "filter_geodesic_remesh/uniform_remesh_filter.h"

#include "filter_geodesic_remesh/parameter_names.h"
#include "filter_geodesic_remesh/remesh_pipeline.h"

namespace gr::filters {

void declareUniformRemesh(const MeshModel& mesh, RichParameterList& params) {
  declareSampling(mesh, params);
  params.addParam(RichInt(param::kRefinement, 0, "Refinement",
                          "Compute the sampling and the Voronoi cells on the input subdivided this many times "
                          "(0 to 3; each level: 4x the vertices and about 4x the time). Finer cells give better "
                          "shaped triangles when the target is a large share of the input's vertices; samples "
                          "then also lie between input vertices (default 0)."));
  params.addParam(RichInt(param::kRelaxation, 3, "Relaxation",
                          "Rounds of tangential relaxation after the triangulation: each vertex moves toward the "
                          "mean of its neighbours on the input surface (never across a crease, never smoothing "
                          "away a tip), then edges are flipped back to Delaunay. Raises the smallest angles; "
                          "0 keeps the paper's triangulation as it is (default 3)."));
  params.addParam(RichBool(param::kLabelInput, false, "Label input",
                           "Also write into the input mesh each vertex's Voronoi cell (the output vertex it belongs "
                           "to) as vertex quality, and color it by cell (default false: the input is not changed)."));
}

Status applyUniformRemesh(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  RemeshRequest request;
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  Expected<FpsParams> sampling = readSampling(params);
  if (!sampling) return sampling.status();
  request.sampling = *sampling;
  request.metric = Metric::uniform();
  request.refinement = params.getInt(param::kRefinement);
  request.relaxation = params.getInt(param::kRelaxation);
  request.labelInput = params.getBool(param::kLabelInput);
  request.title = "Geodesic uniform remeshing";
  request.layerSuffix = " - geodesic remesh";
  return remeshToNewLayer(doc, *current, request, ctx);
}

}  // namespace gr::filters
