#include "filter_geodesic_remesh/atlas_filter.h"

#include <vcg/complex/append.h>

#include <chrono>
#include <string>
#include <vector>

#include "core/atlas/texture_atlas.h"
#include "filter_geodesic_remesh/filter_support.h"
#include "filter_geodesic_remesh/parameter_names.h"

namespace gr::filters {
namespace {

void writeWedgeUv(MeshModel& mm, const adapters::CoreView& view, const std::vector<Vec2>& cornerUv) {
  mm.updateDataMask(MeshModel::MM_WEDGTEXCOORD);
  for (int f = 0; f < view.mesh.faceCount(); ++f) {
    CFaceO& face = mm.cm.face[view.map.vcgOfCoreFace[f]];
    for (int k = 0; k < 3; ++k) {
      face.WT(k).U() = Scalarm(cornerUv[3 * f + k].x());
      face.WT(k).V() = Scalarm(cornerUv[3 * f + k].y());
      face.WT(k).N() = 0;
    }
  }
}

void logAtlas(const AtlasResult& r, const std::string& texture, double ms, FilterContext& ctx) {
  int tutte = 0, apart = 0, cut = 0;
  for (const AtlasChart& c : r.charts) {
    tutte += c.tutte;
    apart += c.facesApart;
    cut += c.splits > 0;
  }
  if (r.segmentation.regionsAsked < r.regionsAsked)
    ctx.log("Regions lowered from " + std::to_string(r.regionsAsked) + " to " +
            std::to_string(r.segmentation.regionsAsked) + ": at most one chart per " +
            std::to_string(AtlasParams::kFacesPerChart) + " faces");
  if (r.segmentation.splitVertices > 0)
    ctx.log(std::to_string(r.segmentation.splitVertices) +
            " non-manifold vertices (fans of faces meeting at one vertex): no chart holds two fans of one");
  ctx.log("Geodesic texture atlas: " + std::to_string(r.charts.size()) + " charts (" +
          std::to_string(r.segmentation.regionsAsked) + " regions asked, " +
          std::to_string(r.segmentation.regionsAdded) + " added so that every chart is a disk)");
  ctx.log(std::to_string(r.repairedCharts) + " charts repaired: " + std::to_string(tutte) +
          " mapped by Tutte's embedding (mean-value weights) where geodesic LLE folded, " + std::to_string(cut) +
          " cut into smaller charts where no map of the whole was fit, " + std::to_string(apart) +
          " laid out face by face (" + std::to_string(r.pieces) +
          " pieces in the texture); no flipped or "
          "overlapping triangle");
  ctx.log("Distortion: L2 stretch " + formatNumber(r.distortion.stretchL2) + ", conformal (sigma1/sigma2) mean " +
          formatNumber(r.distortion.conformalMean) + ", max " + formatNumber(r.distortion.conformalMax) + "; packing " +
          formatNumber(100.0 * r.packing) + "% of the texture");
  if (texture.empty())
    ctx.warn("The checkerboard texture could not be written; the texture coordinates are set");
  else
    ctx.log("Wedge texture coordinates set; checkerboard texture " + texture);
  ctx.log("Time: " + formatDuration(ms));
}

}  // namespace

void declareTextureAtlas(const MeshModel& /*mesh*/, RichParameterList& params) {
  const AtlasParams d;
  params.addParam(RichInt(param::kRegions, d.segmentation.regions, "Regions",
                          "Charts asked for: the regions of the geodesic centroidal tessellation (more are added "
                          "where a region would not be a disk). Fewer charts: fewer seams, more stretch (default " +
                              QString::number(d.segmentation.regions) + ")."));
  params.addParam(RichInt(param::kIterations, d.segmentation.lloyd.iterations, "Iterations",
                          "Geodesic Lloyd iterations of the segmentation (default " +
                              QString::number(d.segmentation.lloyd.iterations) + ")."));
  params.addParam(RichFloat(param::kFeatureAlignment, float(d.segmentation.featureAlignment), "Feature alignment",
                            "Strength of the edge-attractive speed: chart boundaries follow curved bands. 0 = off "
                            "(default " +
                                QString::number(d.segmentation.featureAlignment) + ")."));
  params.addParam(RichFloat(param::kSharpEdgeAngle, float(d.segmentation.sharpEdgeAngle), "Sharp edge angle",
                            "Charts do not cross edges whose faces' normals differ by more than this (degrees): seams "
                            "lie on them. 0 = off (default " +
                                QString::number(d.segmentation.sharpEdgeAngle) + ")."));
  params.addParam(RichInt(param::kBasePoints, d.flattening.basePoints, "Base points",
                          "B: farthest-point base points of each chart's geodesic LLE, at most: a chart of V "
                          "vertices gets at most V/5 and at most max(25, V/50), its ARAP relaxation doing the rest "
                          "(default " +
                              QString::number(d.flattening.basePoints) + ", as the paper)."));
  params.addParam(RichInt(param::kNeighbours, d.flattening.neighbours, "Neighbours",
                          "K: nearest base points of each LLE reconstruction, 3 <= K < B (default " +
                              QString::number(d.flattening.neighbours) + ")."));
  params.addParam(RichInt(param::kTextureSize, d.textureSize, "Texture size",
                          "Texels per side of the square texture the gutter is measured in, and of the checkerboard "
                          "written next to the mesh (default " +
                              QString::number(d.textureSize) + ")."));
  params.addParam(RichInt(param::kGutter, d.gutter, "Gutter",
                          "Empty texels around each chart (default " + QString::number(d.gutter) + ")."));
  params.addParam(
      RichInt(param::kSeed, int(d.segmentation.seed), "Seed", "Start of the segmentation's farthest-point sampling."));
}

Status applyTextureAtlas(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  AtlasParams p;
  p.segmentation.regions = params.getInt(param::kRegions);
  p.segmentation.lloyd.iterations = params.getInt(param::kIterations);
  p.segmentation.featureAlignment = params.getFloat(param::kFeatureAlignment);
  p.segmentation.sharpEdgeAngle = params.getFloat(param::kSharpEdgeAngle);
  p.segmentation.seed = static_cast<unsigned>(params.getInt(param::kSeed));
  p.flattening.basePoints = params.getInt(param::kBasePoints);
  p.flattening.neighbours = params.getInt(param::kNeighbours);
  p.textureSize = params.getInt(param::kTextureSize);
  p.gutter = params.getInt(param::kGutter);
  Expected<AtlasResult> r = buildTextureAtlas(current->view.mesh, p, ctx.progress);
  if (!r) return r.status();
  MeshModel& mm = *current->model;  // commit
  writeWedgeUv(mm, current->view, r->cornerUv);
  const std::string texture = writeCheckerboard(mm, p.textureSize, "_geodesic_atlas.png");
  mm.cm.textures.clear();
  if (!texture.empty()) mm.cm.textures.push_back(texture);
  logAtlas(*r, texture, millisecondsSince(start), ctx);
  return Status::ok();
}

void declareLleFlattening(const MeshModel& /*mesh*/, RichParameterList& params) {
  const LleFlatteningParams d;
  params.addParam(RichInt(param::kBasePoints, d.basePoints, "Base points",
                          "B: farthest-point base points of the geodesic LLE (at most the vertices; default " +
                              QString::number(d.basePoints) + ", as the paper)."));
  params.addParam(RichInt(param::kNeighbours, d.neighbours, "Neighbours",
                          "K: nearest base points of each LLE reconstruction, 3 <= K < B (default " +
                              QString::number(d.neighbours) + ")."));
  params.addParam(RichEnum(param::kBoundary, 0,
                           QStringList() << "Free"
                                         << "Circle",
                           "Boundary",
                           "Free: the LLE map's own boundary (repaired by Tutte's embedding if it folds), then "
                           "relaxed as-rigid-as-possible, kept one-to-one. Circle: the boundary pinned to a circle "
                           "(Tutte's embedding, always one-to-one, not relaxed)."));
  params.addParam(RichBool(param::kFlatLayer, false, "Flat layer",
                           "Also add a layer with the flattened mesh at z = 0, to look at the map."));
}

Status applyLleFlattening(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  LleFlatteningParams p;
  p.basePoints = params.getInt(param::kBasePoints);
  p.neighbours = params.getInt(param::kNeighbours);
  p.boundary = params.getEnum(param::kBoundary) == 1 ? LleBoundary::Circle : LleBoundary::Free;
  const TriMesh& mesh = current->view.mesh;
  Expected<LleFlatteningResult> r = flattenGeodesicLle(mesh, p, ctx.progress);
  if (!r) return r.status();
  MeshModel& mm = *current->model;  // commit
  mm.updateDataMask(MeshModel::MM_VERTTEXCOORD);
  std::vector<Vec2> cornerUv(3 * mesh.faceCount());
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    CVertexO& vertex = mm.cm.vert[current->view.map.vcgOfCoreVertex[v]];
    vertex.T().U() = Scalarm(r->uv[v].x());
    vertex.T().V() = Scalarm(r->uv[v].y());
  }
  for (int c = 0; c < 3 * mesh.faceCount(); ++c) cornerUv[c] = r->uv[mesh.vertex(c)];
  writeWedgeUv(mm, current->view, cornerUv);
  if (params.getBool(param::kFlatLayer)) {
    MeshModel* flat = doc.addNewMesh("", mm.label() + " - flattened", false);
    flat->updateDataMask(MeshModel::MM_VERTTEXCOORD | MeshModel::MM_WEDGTEXCOORD);  // copied with the mesh
    vcg::tri::Append<CMeshO, CMeshO>::MeshCopy(flat->cm, mm.cm);
    for (auto& vertex : flat->cm.vert)
      if (!vertex.IsD()) vertex.P() = Point3m(vertex.T().U(), vertex.T().V(), 0);
    flat->UpdateBoxAndNormals();
  }
  const UvDistortion d = measureUvDistortion(mesh, cornerUv);
  ctx.log("Geodesic LLE flattening: " + std::to_string(r->basePoints.size()) + " base points; " +
          (r->tutte ? std::string("mapped by Tutte's embedding (") +
                          (p.boundary == LleBoundary::Circle ? "Circle boundary asked" : "LLE folded") + ")"
                    : std::to_string(r->foldedBeforeRepair) + " folded triangles untangled") +
          (r->arapRounds > 0 ? "; " + std::to_string(r->arapRounds) + " rounds of ARAP relaxation" : std::string()));
  ctx.log("Distortion: L2 stretch " + formatNumber(d.stretchL2) + ", conformal mean " + formatNumber(d.conformalMean) +
          "; vertex and wedge texture coordinates set" +
          (params.getBool(param::kFlatLayer) ? ", flat layer added" : ""));
  ctx.log("Time: " + formatDuration(millisecondsSince(start)));
  return Status::ok();
}

}  // namespace gr::filters
