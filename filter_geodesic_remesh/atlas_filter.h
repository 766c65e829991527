// Filters "Parametrization: Geodesic Texture Atlas" and "Parametrization: Geodesic LLE Flattening"
// (paper §4.3 and §5).
#pragma once

#include "filter_geodesic_remesh/filter_spec.h"

namespace gr::filters {

void declareTextureAtlas(const MeshModel& mesh, RichParameterList& params);
Status applyTextureAtlas(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

void declareLleFlattening(const MeshModel& mesh, RichParameterList& params);
Status applyLleFlattening(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

}  // namespace gr::filters
