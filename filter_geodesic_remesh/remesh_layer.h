// What both remeshing filters share: the sampling parameters, and committing a remesh (the new
// layer, the input's cells if asked, the log). The remeshing itself is core/remesh/remesh_surface.h.
#pragma once

#include <chrono>
#include <string>

#include "core/geodesic/farthest_point_sampling.h"
#include "core/remesh/remesh_surface.h"
#include "filter_geodesic_remesh/filter_spec.h"
#include "filter_geodesic_remesh/filter_support.h"

namespace gr::filters {

/// Adds the sampling parameters every remeshing filter has (TargetVertices, Spacing, Seed,
/// SubVertexPlacement, CentroidalIterations), with the filter's defaults (`defaults`: the core's
/// SurfaceRemeshParams of that filter).
void declareSampling(const MeshModel& mesh, RichParameterList& params, const SurfaceRemeshParams& defaults);
/// Reads them (the core checks them): Spacing is used only when TargetVertices is 0.
FpsParams readSampling(const RichParameterList& params);
/// ReportError, last of both remeshing filters' parameters: the log's distance to the input
/// (SurfaceRemeshParams::measureDistance), off by default.
void declareReportError(RichParameterList& params);
bool readReportError(const RichParameterList& params);

/// How a remesh is committed.
struct RemeshCommit {
  std::string title;        ///< first words of the log ("Geodesic uniform remeshing")
  std::string layerSuffix;  ///< appended to the input layer's name for the new layer
  bool labelInput = false;  ///< also write each input vertex's cell into its quality and colour
  int refinement = 0;       ///< as asked, for the log
  bool weighted = false;    ///< the metric is not uniform (distances are travel times)
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();  ///< for the logged time
};

/// Adds the new layer, writes the cells into the input if asked, and logs counts, added samples,
/// topology, angles, distances and time.
void commitRemesh(MeshDocument& doc, const CurrentMesh& current, const SurfaceRemeshResult& result,
                  const RemeshCommit& commit, FilterContext& ctx);

}  // namespace gr::filters
