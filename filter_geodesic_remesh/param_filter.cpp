#include "filter_geodesic_remesh/param_filter.h"

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "core/param/geodesic_parameterization.h"
#include "core/param/semi_regular.h"
#include "filter_geodesic_remesh/filter_support.h"
#include "filter_geodesic_remesh/parameter_names.h"

namespace gr::filters {
namespace {

void declareBase(RichParameterList& params, const BaseDomainParams& d, const QString& what) {
  params.addParam(RichInt(param::kBaseVertices, d.baseVertices, "Base vertices",
                          "Farthest-point samples of the base domain (its geodesic Delaunay triangulation " + what +
                              "); more may be added where the triangulation needs them (default " +
                              QString::number(d.baseVertices) + ")."));
  params.addParam(RichInt(param::kCentroidalIterations, d.centroidalIterations, "Centroidal iterations",
                          "Geodesic Lloyd iterations on the base vertices before their triangulation: evener base "
                          "triangles (default " +
                              QString::number(d.centroidalIterations) + ")."));
  params.addParam(RichInt(param::kSeed, int(d.seed), "Seed", "Start of the farthest-point sampling."));
}

BaseDomainParams readBase(const RichParameterList& params) {
  BaseDomainParams p;
  p.baseVertices = params.getInt(param::kBaseVertices);
  p.centroidalIterations = params.getInt(param::kCentroidalIterations);
  p.seed = static_cast<unsigned>(params.getInt(param::kSeed));
  return p;
}

std::string baseLine(int asked, int got, int added, int triangles) {
  return std::to_string(got) + " base vertices (" + std::to_string(asked) + " asked, " + std::to_string(added) +
         " added by the triangulation's repair), " + std::to_string(triangles) + " base triangles";
}

/// How the pieces were mapped, for the log.
std::string pieceLine(int heron, int smoothed, int repaired) {
  return std::to_string(heron) + " mapped by geodesic barycentric (Heron) coordinates, " + std::to_string(smoothed) +
         " by those with a band around their folds by mean value coordinates, " + std::to_string(repaired) +
         " by mean value coordinates alone";
}

}  // namespace

void declareSemiRegular(const MeshModel& /*mesh*/, RichParameterList& params) {
  const SemiRegularParams d;
  declareBase(params, d.base, "is the coarsest level");
  params.addParam(RichInt(param::kLevels, d.levels, "Levels",
                          "1-to-4 subdivisions of each base triangle, 0 to " +
                              QString::number(SemiRegularParams::kMaxLevels) +
                              ": about 2 x BaseVertices x 4^Levels "
                              "faces (default " +
                              QString::number(d.levels) + ")."));
}

Status applySemiRegular(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  SemiRegularParams p;
  p.base = readBase(params);
  p.levels = params.getInt(param::kLevels);
  Expected<SemiRegularResult> r = semiRegularRemesh(current->view.mesh, p, ctx.progress);
  if (!r) return r.status();
  MeshModel& mm = *current->model;  // commit
  const bool copyColor = mm.hasDataMask(MeshModel::MM_VERTCOLOR);
  const bool copyQuality = mm.hasDataMask(MeshModel::MM_VERTQUALITY);
  const QString label = mm.label() + " - semi-regular L" + QString::number(p.levels);
  MeshModel* out = doc.addNewMesh("", label, true);
  if (copyColor) out->updateDataMask(MeshModel::MM_VERTCOLOR);
  if (copyQuality) out->updateDataMask(MeshModel::MM_VERTQUALITY);
  adapters::writeMesh(r->mesh, out->cm, mm.cm, current->view, r->origin, copyColor, copyQuality);
  const double diagonal = current->view.mesh.boundingBoxDiagonal();
  ctx.log("Geodesic semi-regular remeshing: " +
          baseLine(p.base.baseVertices, r->baseVertices, r->addedBaseVertices, r->baseTriangles) + ", " +
          std::to_string(p.levels) + " levels -> " + std::to_string(r->mesh.vertexCount()) + " vertices, " +
          std::to_string(r->mesh.faceCount()) + " faces on layer \"" + label.toStdString() + "\"");
  ctx.log("Parameterisation, pieces: " + pieceLine(r->heronPieces, r->smoothedPieces, r->repairedPieces) + "; " +
          std::to_string(r->splitEdges) + " input edges split by the cut");
  if (r->reorientedFaces > 0)
    ctx.log(std::to_string(r->reorientedFaces) + " input faces reoriented to agree with their neighbours");
  ctx.log("Hausdorff distance to the input (both ways): " + formatNumber(r->hausdorff) + " (" +
          formatNumber(100.0 * r->hausdorff / diagonal) + "% of the bounding box diagonal); " +
          std::to_string(r->relaxationMoves) + " relaxation moves");
  ctx.log("Time: " + formatDuration(millisecondsSince(start)));
  return Status::ok();
}

void declareGeodesicBarycentric(const MeshModel& /*mesh*/, RichParameterList& params) {
  const ParameterizationParams d;
  declareBase(params, d.base, "is the parameter domain, one texture tile per base triangle");
}

Status applyGeodesicBarycentric(MeshDocument& doc, const RichParameterList& params, FilterContext& ctx) {
  const auto start = std::chrono::steady_clock::now();
  Expected<CurrentMesh> current = currentMesh(doc);
  if (!current) return current.status();
  ParameterizationParams p;
  p.base = readBase(params);
  Expected<Parameterization> r = parameterizeOverBase(current->view.mesh, p, ctx.progress);
  if (!r) return r.status();
  const std::vector<Vec2> uv = tiledUv(*r);
  const TriMesh& cut = r->pieces.mesh;
  MeshModel& mm = *current->model;  // commit
  const QString label = mm.label() + " - geodesic barycentric";
  MeshModel* out = doc.addNewMesh("", label, true);
  out->updateDataMask(MeshModel::MM_VERTQUALITY | MeshModel::MM_VERTCOLOR | MeshModel::MM_WEDGTEXCOORD);
  adapters::writeMesh(cut, out->cm, mm.cm, current->view, cutVertexOrigins(*r), false, false);
  const std::vector<int> triangleOfVertex = baseTriangleOfVertex(*r);
  adapters::CoreView outView;
  for (int v = 0; v < cut.vertexCount(); ++v) outView.map.vcgOfCoreVertex.push_back(v);
  adapters::writeVertexQuality(out->cm, outView, std::vector<double>(triangleOfVertex.begin(), triangleOfVertex.end()),
                               -1.0);
  const int triangles = static_cast<int>(r->base.triangles.size());
  adapters::colorByLabel(out->cm, outView, triangleOfVertex, triangles);
  for (int f = 0; f < cut.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      out->cm.face[f].WT(k).U() = Scalarm(uv[3 * f + k].x());
      out->cm.face[f].WT(k).V() = Scalarm(uv[3 * f + k].y());
      out->cm.face[f].WT(k).N() = 0;
    }
  const int tiles = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(triangles))));
  const std::string texture =
      writeCheckerboard(mm, std::min(4096, std::max(1024, 32 * tiles)), "_geodesic_barycentric.png", 8 * tiles);
  if (!texture.empty()) out->cm.textures.push_back(texture);
  ctx.log("Geodesic barycentric parameterisation: " +
          baseLine(p.base.baseVertices, static_cast<int>(r->base.baseVertex.size()), r->base.addedSamples, triangles) +
          "; the input cut into one disk per base triangle (" + std::to_string(r->pieces.splitEdges) +
          " edges split) on layer \"" + label.toStdString() + "\"");
  ctx.log("Pieces: " + pieceLine(r->heronPieces, r->smoothedPieces, r->repairedPieces) + "; no flipped triangle");
  ctx.log("Vertex quality: the base triangle; wedge texture coordinates: one " + std::to_string(tiles) + " x " +
          std::to_string(tiles) + " grid tile per base triangle" +
          (texture.empty() ? std::string(" (the checkerboard could not be written)") : "; checkerboard " + texture));
  ctx.log("Time: " + formatDuration(millisecondsSince(start)));
  return Status::ok();
}

}  // namespace gr::filters
