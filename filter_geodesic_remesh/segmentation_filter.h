// Filter "Segmentation: Geodesic Centroidal Tessellation" (paper §4.2).
#pragma once

#include "filter_geodesic_remesh/filter_spec.h"

namespace gr::filters {

void declareSegmentation(const MeshModel& mesh, RichParameterList& params);
Status applySegmentation(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

}  // namespace gr::filters
