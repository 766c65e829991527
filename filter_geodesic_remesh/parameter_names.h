// Names of the filters' parameters, as .mlx scripts spell them (resources/*.mlx use the same).
#pragma once

namespace gr::filters::param {

// Geodesic Distance: Fast Marching from Selected Vertices
constexpr const char *kUseQualityAsSpeed = "UseQualityAsSpeed", *kMaxDistance = "MaxDistance", *kColorBy = "ColorBy";
// Its surface refinement (a RichEnum Auto/On/Off); the same name as the uniform filter's RichInt below
constexpr const char* kSurfaceRefinement = "Refinement";

// Both remeshing filters: the sampling
constexpr const char *kTargetVertices = "TargetVertices", *kSpacing = "Spacing", *kSeed = "Seed",
                     *kSubVertexPlacement = "SubVertexPlacement", *kCentroidalIterations = "CentroidalIterations";

// Remeshing: Geodesic Uniform
constexpr const char *kRefinement = "Refinement", *kRelaxation = "Relaxation", *kLabelInput = "LabelInput",
                     *kReportError = "ReportError";

// Remeshing: Geodesic Adaptive; CurvatureRadius also in Compute Total Curvature
constexpr const char *kField = "Field", *kMapping = "Mapping", *kStrength = "Strength",
                     *kCurvatureRadius = "CurvatureRadius", *kGradation = "Gradation";

// Segmentation: Geodesic Centroidal Tessellation (also Seed and UseQualityAsSpeed above)
constexpr const char *kRegions = "Regions", *kIterations = "Iterations", *kFeatureAlignment = "FeatureAlignment",
                     *kSharpEdgeAngle = "SharpEdgeAngle", *kSplitIntoLayers = "SplitIntoLayers";

// Parametrization: Geodesic Texture Atlas (also Regions, Iterations, FeatureAlignment, SharpEdgeAngle,
// Seed) and
// Parametrization: Geodesic LLE Flattening
constexpr const char *kBasePoints = "BasePoints", *kNeighbours = "Neighbours", *kTextureSize = "TextureSize",
                     *kGutter = "Gutter", *kBoundary = "Boundary", *kFlatLayer = "FlatLayer";

// Remeshing: Geodesic Semi-Regular and Parametrization: Geodesic Barycentric (also Seed and
// CentroidalIterations above)
constexpr const char *kBaseVertices = "BaseVertices", *kLevels = "Levels";

}  // namespace gr::filters::param
