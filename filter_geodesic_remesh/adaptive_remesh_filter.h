// Filters of adaptive remeshing (paper §3.3-3.4): "Remeshing: Geodesic Adaptive" (a per-vertex
// field as the front speed: vertex quality, total curvature or colour gradient) and "Compute
// Total Curvature" (the Cohen-Steiner-Morvan total curvature into vertex quality, to look at it
// or to drive any filter that reads quality).
#pragma once

#include "filter_geodesic_remesh/filter_spec.h"

namespace gr::filters {

void declareAdaptiveRemesh(const MeshModel& mesh, RichParameterList& params);
Status applyAdaptiveRemesh(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

void declareTotalCurvature(const MeshModel& mesh, RichParameterList& params);
Status applyTotalCurvature(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

}  // namespace gr::filters
