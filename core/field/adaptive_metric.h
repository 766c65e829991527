// The metric of adaptive remeshing from a per-vertex field (paper §3.3-3.4): field -> speed -> metric.
//
//   vertex quality (any filter's output) ----------------.
//   total curvature |k1|+|k2| (curvature.h) -------------+--> q --speedFromField--> F --> P = 1/F
//   |grad I| of the colour intensity (color_gradient.h) -'
//
// Cost: O(V) plus the field's own (the curvature: O(V k) for k vertices per ball).
#pragma once

#include <vector>

#include "core/base/progress.h"
#include "core/base/status.h"
#include "core/field/curvature.h"
#include "core/field/speed_field.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Which per-vertex field sets the density.
enum class AdaptiveField {
  VertexQuality,   ///< given values (e.g. MeshLab's vertex quality)
  TotalCurvature,  ///< computed: |k1| + |k2| (paper §3.4)
  ColorGradient,   ///< computed: |grad I| of given intensities (paper §3.3)
};
constexpr int kAdaptiveFieldCount = 3;
/// Name of a field, for logs ("total curvature").
const char* toString(AdaptiveField field);

struct AdaptiveMetricParams {
  AdaptiveField field = AdaptiveField::TotalCurvature;
  SpeedFieldParams speed;     ///< mapping (Attractive), strength (4), scale percentile (95)
  CurvatureParams curvature;  ///< ball radius, for TotalCurvature (0 = the mean edge length)
};

struct AdaptiveMetricResult {
  SpeedFieldResult speed;        ///< the speed, the metric P = 1/F and the field's range and scale
  double curvatureRadius = 0.0;  ///< the ball radius used (TotalCurvature only)
};

/// `values` has one value per vertex: the field itself (VertexQuality) or the intensity whose
/// gradient is the field (ColorGradient); it is not read for TotalCurvature. Fails as the field
/// and speedFromField do: InvalidInput (a field out of range, values of the wrong size or not
/// finite, a negative value with Attractive or Repulsive), NonManifold (TotalCurvature on a
/// non-manifold mesh), Cancelled.
Expected<AdaptiveMetricResult> adaptiveMetric(const TriMesh& mesh, const std::vector<double>& values,
                                              const AdaptiveMetricParams& params = {}, Progress progress = {});

}  // namespace gr
