// The remeshing pipeline both remeshing filters share (paper §3.1-3.4): farthest-point samples
// under a metric, their geodesic Delaunay triangulation, its relaxation (core/remesh/remesh.h), a new
// layer, and the log.
#pragma once

#include <chrono>
#include <string>

#include "core/geodesic/farthest_point_sampling.h"
#include "core/geodesic/metric.h"
#include "filter_geodesic_remesh/filter_spec.h"
#include "filter_geodesic_remesh/filter_support.h"

namespace gr::filters {

struct RemeshRequest {
  FpsParams sampling;
  Metric metric;            ///< on the input's core mesh (uniform for the uniform filter)
  int refinement = 0;       ///< midpoint subdivisions the fronts run on (0-3)
  int relaxation = 0;       ///< rounds of tangential relaxation after the triangulation (0-100)
  bool labelInput = false;  ///< also write each input vertex's cell into its quality and colour
  std::string title;        ///< first words of the log ("Geodesic uniform remeshing")
  std::string layerSuffix;  ///< appended to the input layer's name for the new layer
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();  ///< for the logged time
};

/// Reads the sampling parameters every remeshing filter has (TargetVertices, Spacing, Seed,
/// SubVertexPlacement) and checks them; declareSampling adds them to a parameter list.
void declareSampling(const MeshModel& mesh, RichParameterList& params);
Expected<FpsParams> readSampling(const RichParameterList& params);

/// Checks the mesh, remeshes it, then (only on success) adds the new layer, writes the labels if
/// asked, and logs counts, added samples, topology, angles, Hausdorff distances and time.
Status remeshToNewLayer(MeshDocument& doc, const CurrentMesh& current, const RemeshRequest& request,
                        FilterContext& ctx);

}  // namespace gr::filters
