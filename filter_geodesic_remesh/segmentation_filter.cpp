#include "filter_geodesic_remesh/segmentation_filter.h"

#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/append.h>

#include <chrono>
#include <string>
#include <vector>

#include "core/segment/geodesic_segmentation.h"
#include "filter_geodesic_remesh/filter_support.h"
#include "filter_geodesic_remesh/parameter_names.h"

namespace gr::filters {
namespace {

/// Writes the regions into the input: face quality = region, face colour per region, the faces
/// on a region boundary selected.
void writeRegions(MeshModel& mm, const adapters::CoreView& view, const SegmentationResult& r) {
  mm.updateDataMask(MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR);
  CMeshO& m = mm.cm;
  const TriMesh& mesh = view.mesh;
  vcg::tri::UpdateSelection<CMeshO>::FaceClear(m);
  vcg::tri::UpdateSelection<CMeshO>::VertexClear(m);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    CFaceO& face = m.face[view.map.vcgOfCoreFace[f]];
    face.Q() = Scalarm(r.faceRegion[f]);
    face.C() = vcg::Color4b::Scatter(std::max(r.regions, 1), r.faceRegion[f]);
    for (int c = 3 * f; c < 3 * f + 3; ++c) {
      const int o = mesh.oppositeCorner[c];
      if (o >= 0 && r.faceRegion[TriMesh::face(o)] != r.faceRegion[f]) face.SetS();
    }
  }
}

/// One new layer per region (its faces copied from the input), named "<input> - region <i>".
void splitIntoLayers(MeshDocument& doc, MeshModel& mm, const adapters::CoreView& view, const SegmentationResult& r) {
  CMeshO& m = mm.cm;
  std::vector<int> selected;  // the boundary selection, restored afterwards
  for (size_t f = 0; f < m.face.size(); ++f)
    if (!m.face[f].IsD() && m.face[f].IsS()) selected.push_back(static_cast<int>(f));
  const QString base = mm.label();
  for (int region = 0; region < r.regions; ++region) {
    vcg::tri::UpdateSelection<CMeshO>::FaceClear(m);
    vcg::tri::UpdateSelection<CMeshO>::VertexClear(m);
    for (int f = 0; f < view.mesh.faceCount(); ++f)
      if (r.faceRegion[f] == region) m.face[view.map.vcgOfCoreFace[f]].SetS();
    vcg::tri::UpdateSelection<CMeshO>::VertexFromFaceLoose(m);
    MeshModel* layer = doc.addNewMesh(QString(), base + " - region " + QString::number(region), false);
    layer->updateDataMask(MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR);
    vcg::tri::Append<CMeshO, CMeshO>::Mesh(layer->cm, m, true);
    layer->UpdateBoxAndNormals();
  }
  vcg::tri::UpdateSelection<CMeshO>::FaceClear(m);
  vcg::tri::UpdateSelection<CMeshO>::VertexClear(m);
  for (int f : selected) m.face[f].SetS();
}

void logSegmentation(const SegmentationResult& r, const SegmentationParams& p, bool layers, double ms,
                     FilterContext& ctx) {
  ctx.log("Geodesic centroidal tessellation: " + std::to_string(r.regions) + " regions; " +
          std::to_string(r.regionsAsked) + " asked, " + std::to_string(r.regionsAdded) +
          " added to make every region a disk");
  ctx.log("Lloyd: " + std::to_string(r.iterations) + " iterations, energy " + formatNumber(r.energyStart) + " -> " +
          formatNumber(r.energyEnd) + (r.reseeded > 0 ? ", " + std::to_string(r.reseeded) + " seeds re-placed" : ""));
  if (p.featureAlignment > 0.0)
    ctx.log("Speed 1/(1 + " + formatNumber(p.featureAlignment) + " q/s) from the " + toString(p.speedField) +
            (p.speedField == AdaptiveField::TotalCurvature ? " (ball radius " + formatNumber(r.curvatureRadius) + ")"
                                                           : std::string()) +
            ": region boundaries drawn to where it is large");
  else
    ctx.log("FeatureAlignment 0: plain geodesic distance");
  if (r.sharpEdges > 0)
    ctx.log("Fronts stopped at " + std::to_string(r.sharpEdges) + " sharp edges (normals more than " +
            formatNumber(p.sharpEdgeAngle) + " degrees apart): the surface in " + std::to_string(r.surfacePieces) +
            (r.surfacePieces == 1 ? " piece" : " pieces, seeds shared by area"));
  if (r.splitVertices > 0)
    ctx.log(std::to_string(r.splitVertices) +
            " non-manifold vertices (fans of faces meeting at one vertex): the fronts ran with one vertex per fan, "
            "and no region holds two fans of one");
  if (!r.speedFallback.empty()) ctx.warn(r.speedFallback);
  if (r.refined)
    ctx.log("Fronts ran on the intrinsic Delaunay refinement of the input (" + std::to_string(r.insertedPoints) +
            " points inserted): its triangles are poor");
  if (r.snappedFaces > 0)
    ctx.log(std::to_string(r.snappedFaces) +
            " faces moved across region boundaries: boundaries put on the creases beside them and straightened "
            "elsewhere");
  if (r.strayFacesMoved > 0)
    ctx.log(std::to_string(r.strayFacesMoved) +
            " faces given to a neighbouring region so that each region is one piece and no region rings a hole");
  if (r.holesOpened > 0)
    ctx.log(std::to_string(r.holesOpened) +
            " regions cut open around a hole of the mesh (a strip of faces from the hole to a neighbouring region)");
  ctx.log(std::string("Region index in face quality, one colour per region in face colour, faces on region "
                      "boundaries selected") +
          (layers ? "; one layer per region" : ""));
  ctx.log("Time: " + formatDuration(ms));
}

}  // namespace

void declareSegmentation(const MeshModel& /*mesh*/, RichParameterList& params) {
  const SegmentationParams d;
  params.addParam(RichInt(param::kRegions, d.regions, "Regions",
                          "Number of regions asked for (seeds of the farthest-point sampling). More are added where "
                          "a region would not be a topological disk (a handle, a ring around a tube, a closed "
                          "component); the log says how many (default " +
                              QString::number(d.regions) + ")."));
  params.addParam(RichInt(param::kIterations, d.lloyd.iterations, "Iterations",
                          "Geodesic Lloyd iterations: each moves every seed to the intrinsic centre of mass of its "
                          "region, giving compact regions of even area; stops early when the energy no longer "
                          "falls (default " +
                              QString::number(d.lloyd.iterations) + ")."));
  params.addParam(RichFloat(param::kFeatureAlignment, float(d.featureAlignment), "Feature alignment",
                            "Strength mu of the edge-attractive speed F = 1/(1 + mu q/s) (paper's F2), q the total "
                            "curvature (or the vertex quality) and s its 95th percentile: fronts slow down where q is "
                            "large, so region boundaries follow curved bands. Dimensionless; 0 = off; large values "
                            "make regions uneven (default " +
                                QString::number(d.featureAlignment) + ")."));
  params.addParam(RichFloat(param::kSharpEdgeAngle, float(d.sharpEdgeAngle), "Sharp edge angle",
                            "Fronts stop at edges whose two faces' normals differ by more than this (degrees): region "
                            "boundaries lie on such edges and no region crosses one. 0 = off (default " +
                                QString::number(d.sharpEdgeAngle) + ")."));
  params.addParam(RichBool(param::kUseQualityAsSpeed, false, "Use quality as speed field",
                           "Use the vertex quality (any filter's output, e.g. a texture intensity) as the field q "
                           "instead of the total curvature (paper Fig. 11)."));
  params.addParam(RichInt(param::kSeed, int(d.seed), "Seed",
                          "Start of the farthest-point sampling: the same seed gives the same regions."));
  params.addParam(RichBool(param::kSplitIntoLayers, false, "Split into layers",
                           "Also put each region on its own new layer (the input keeps all its faces)."));
}

Status applySegmentation(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  MeshModel* mm = current->model;
  SegmentationParams p;
  p.regions = params.getInt(param::kRegions);
  p.lloyd.iterations = params.getInt(param::kIterations);
  p.featureAlignment = params.getFloat(param::kFeatureAlignment);
  p.sharpEdgeAngle = params.getFloat(param::kSharpEdgeAngle);
  p.seed = static_cast<unsigned>(params.getInt(param::kSeed));
  std::vector<double> values;
  if (params.getBool(param::kUseQualityAsSpeed)) {
    if (!mm->hasDataMask(MeshModel::MM_VERTQUALITY))
      return invalidInput(
          "UseQualityAsSpeed is on, but the mesh has no per-vertex quality: compute one first (any filter of the "
          "Quality Measure and Computations menu)");
    p.speedField = AdaptiveField::VertexQuality;
    values = adapters::vertexQuality(mm->cm, current->view);
  }
  Expected<SegmentationResult> r = segmentSurface(current->view.mesh, values, p, ctx.progress);
  if (!r) return r.status();
  // Commit.
  writeRegions(*mm, current->view, *r);
  const bool layers = params.getBool(param::kSplitIntoLayers);
  if (layers) splitIntoLayers(doc, *mm, current->view, *r);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  logSegmentation(*r, p, layers, ms, ctx);
  return Status::ok();
}

}  // namespace gr::filters
