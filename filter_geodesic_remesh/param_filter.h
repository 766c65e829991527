// Filters "Remeshing: Geodesic Semi-Regular" and "Parametrization: Geodesic Barycentric" (paper
// §4.1): core/param/semi_regular.h and core/param/geodesic_parameterization.h.
#pragma once

#include "filter_geodesic_remesh/filter_spec.h"

namespace gr::filters {

void declareSemiRegular(const MeshModel& mesh, RichParameterList& params);
Status applySemiRegular(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

void declareGeodesicBarycentric(const MeshModel& mesh, RichParameterList& params);
Status applyGeodesicBarycentric(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

}  // namespace gr::filters
