// Filter "Remeshing: Geodesic Uniform" (paper §3.1-3.2): farthest-point samples and their
// geodesic Delaunay triangulation, on a new layer.
#pragma once

#include "filter_geodesic_remesh/filter_spec.h"

namespace gr::filters {

void declareUniformRemesh(const MeshModel& mesh, RichParameterList& params);
Status applyUniformRemesh(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

}  // namespace gr::filters
