// Filter "Geodesic Distance: Fast Marching from Selected Vertices" (paper §2.1–2.2).
#pragma once

#include "filter_geodesic_remesh/filter_spec.h"

namespace gr::filters {

/// Values of the ColorBy enum, in the order of the RichEnum.
enum class ColorBy { Distance = 0, VoronoiCell = 1 };

void declareFastMarching(const MeshModel& mesh, RichParameterList& params);
Status applyFastMarching(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx);

}  // namespace gr::filters
