// Names of the filters' parameters, as .mlx scripts spell them (resources/*.mlx use the same).
#pragma once

namespace gr::filters::param {

// Geodesic Distance: Fast Marching from Selected Vertices
constexpr const char* kUseQualityAsSpeed = "UseQualityAsSpeed";
constexpr const char* kMaxDistance = "MaxDistance";
constexpr const char* kColorBy = "ColorBy";

}  // namespace gr::filters::param

namespace gr::filters::param {

// Remeshing: Geodesic Uniform
constexpr const char* kTargetVertices = "TargetVertices";
constexpr const char* kSpacing = "Spacing";
constexpr const char* kSeed = "Seed";
constexpr const char* kLabelInput = "LabelInput";
constexpr const char* kRefinement = "Refinement";
constexpr const char* kRelaxation = "Relaxation";
constexpr const char* kSubVertexPlacement = "SubVertexPlacement";

}  // namespace gr::filters::param

namespace gr::filters::param {

// Remeshing: Geodesic Adaptive (plus TargetVertices, Spacing, Seed, SubVertexPlacement above)
constexpr const char* kField = "Field";
constexpr const char* kMapping = "Mapping";
constexpr const char* kStrength = "Strength";
constexpr const char* kCurvatureRadius = "CurvatureRadius";  // also: Compute Total Curvature

}  // namespace gr::filters::param
