#include "core/atlas/texture_atlas.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <new>
#include <string>
#include <system_error>
#include <thread>

#include <Eigen/Geometry>

#include "core/flatten/arap_relaxation.h"
#include "core/mesh/face_geometry.h"

namespace gr {
namespace {

/// A small chart gets at most one base point per this many vertices (B = 100 on a chart of 120
/// vertices makes nearly every vertex a base, and LLE on single edges folds).
constexpr int kVerticesPerBase = 5;
/// Beyond kMinBases, a chart needs no more than one base point per this many vertices: its map
/// is relaxed by ARAP after the Nystrom extension, and the bases' fronts are most of the LLE's
/// time. bunny00's 30 charts (about 1,250 vertices each) with 25 bases instead of 100: stretch
/// 1.0018 and mean conformal 1.0360 either way, packing 0.595 / 0.594, 0.5 s less CPU time.
constexpr int kVerticesPerBaseLarge = 50;
constexpr int kMinBases = 25;
/// Rounds of splitting unsure pieces and packing again before the atlas is refused (Degenerate).
constexpr int kSplitRounds = 2;
/// A region with no map fit for the atlas is cut into this many (its own segmentation), each
/// flattened again, at most kSplitDepth times over, before its faces are laid out apart.
constexpr int kSplitParts = 4;
constexpr int kSplitDepth = 3;
constexpr int kSplitIterations = 4;  ///< Lloyd iterations of that segmentation (a few: parts need not be even)

/// A region's faces as a mesh of its own: local vertex i is input vertex inputVertex[i].
struct Patch {
  TriMesh mesh;
  std::vector<int> inputVertex;
};

Expected<Patch> extractPatch(const TriMesh& mesh, const std::vector<int>& faces, std::vector<int>& localOf) {
  Patch p;
  std::vector<Tri> triangles;
  triangles.reserve(faces.size());
  for (int f : faces) {
    Tri t;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.triangles[f][k];
      if (localOf[v] < 0) {
        localOf[v] = static_cast<int>(p.inputVertex.size());
        p.inputVertex.push_back(v);
      }
      t[k] = localOf[v];
    }
    triangles.push_back(t);
  }
  std::vector<Vec3> positions;
  positions.reserve(p.inputVertex.size());
  for (int v : p.inputVertex) positions.push_back(mesh.positions[v]);
  for (int v : p.inputVertex) localOf[v] = -1;  // ready for the next region
  Expected<TriMesh> m = buildTriMesh(std::move(positions), std::move(triangles));
  if (!m) return m.status();
  p.mesh = std::move(*m);
  return p;
}

/// A triangle laid out in the plane with its 3D side lengths, counter-clockwise; a sliver (twice
/// its area below 1e-3 of its longest side squared) or a degenerate one as an equilateral
/// triangle of its longest side (or of side `fallback` if that is 0): a UV triangle that floating
/// point cannot turn over once scaled into the atlas. `fat`: every triangle so.
std::array<Vec2, 3> layoutTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double fallback, bool fat = false) {
  const double ab = (b - a).norm(), ac = (c - a).norm(), longest = std::max({ab, ac, (c - b).norm()});
  const Vec3 n = (b - a).cross(c - a);
  if (fat || !(n.norm() > 1e-3 * longest * longest)) {
    const double side = longest > 0.0 ? longest : fallback;
    return {Vec2(0, 0), Vec2(side, 0), Vec2(0.5 * side, 0.5 * std::sqrt(3.0) * side)};
  }
  const double x = (c - a).dot(b - a) / ab;
  return {Vec2(0, 0), Vec2(ab, 0), Vec2(x, n.norm() / ab)};
}

/// A piece to pack: faces of the input with their UVs per corner (3 per face, in `faces` order).
struct Piece {
  std::vector<int> faces;
  std::vector<Vec2> cornerUv;
  int chart = -1;
};

/// The faces of `patch` (a disk) in kSplitParts regions of its own segmentation, as faces of the
/// input (`faces`, in the patch's order); empty if it cannot be split so.
std::vector<std::vector<int>> splitRegion(const Patch& patch, const std::vector<int>& faces) {
  SegmentationParams p;
  p.regions = kSplitParts;
  p.lloyd.iterations = kSplitIterations;
  const Expected<SegmentationResult> parts = segmentSurface(patch.mesh, {}, p);
  if (!parts || parts->regions < 2) return {};
  std::vector<std::vector<int>> facesOf(parts->regions);
  for (size_t j = 0; j < faces.size(); ++j) facesOf[parts->faceRegion[j]].push_back(faces[j]);
  return facesOf;
}

/// The pieces of one region: one chart; or, when no map of it is one-to-one and fit for the
/// atlas, the pieces of kSplitParts smaller regions it is cut into (up to kSplitDepth times: a
/// 6,500-face chart of ogre.obj whose Tutte map is not fit gets four that are); or its faces apart.
Expected<std::vector<Piece>> regionPieces(const TriMesh& mesh, const std::vector<int>& faces,
                                          const LleFlatteningParams& params, std::vector<int>& localOf,
                                          AtlasChart& chart, Progress progress, int depth = 0) {
  Expected<Patch> patch = extractPatch(mesh, faces, localOf);
  if (!patch) return patch.status();
  if (depth == 0) {
    chart.faces = static_cast<int>(faces.size());
    chart.vertices = patch->mesh.vertexCount();
  }
  Expected<ChartMap> map = flattenChart(patch->mesh, params, progress);
  if (!map) return map.status();
  chart.tutte = chart.tutte || map->tutte;
  chart.foldedBeforeRepair += map->foldedBeforeRepair;
  std::vector<Piece> pieces;
  if (!map->uv.empty()) {
    Piece piece{faces, {}};
    for (const Tri& t : patch->mesh.triangles)
      for (int k = 0; k < 3; ++k) piece.cornerUv.push_back(map->uv[t[k]]);
    pieces.push_back(std::move(piece));
    return pieces;
  }
  const std::vector<std::vector<int>> parts =
      depth < kSplitDepth && static_cast<int>(faces.size()) >= kSplitParts * kSplitParts
          ? splitRegion(*patch, faces)
          : std::vector<std::vector<int>>();
  if (!parts.empty()) {
    ++chart.splits;
    for (const std::vector<int>& part : parts) {
      Expected<std::vector<Piece>> more = regionPieces(mesh, part, params, localOf, chart, progress, depth + 1);
      if (!more) return more.status();
      for (Piece& piece : *more) pieces.push_back(std::move(piece));
    }
    return pieces;
  }
  chart.facesApart = true;
  const double side = patch->mesh.meanEdgeLength();
  for (int f : faces) {
    const Tri& t = mesh.triangles[f];
    const auto uv = layoutTriangle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]], side);
    pieces.push_back({{f}, {uv[0], uv[1], uv[2]}});
  }
  return pieces;
}

/// Every region's pieces, the regions shared out over the cores (they are independent; each
/// thread has its own scratch). Progress is reported, and cancellation read, by the calling
/// thread only. The result does not depend on the number of threads.
Expected<std::vector<Piece>> flattenRegions(const TriMesh& mesh, const std::vector<std::vector<int>>& facesOf,
                                            const LleFlatteningParams& params, std::vector<AtlasChart>& charts,
                                            Progress& progress) {
  const int regions = static_cast<int>(facesOf.size());
  std::vector<std::vector<Piece>> piecesOf(regions);
  std::vector<Status> statusOf(regions);
  std::atomic<int> next{0}, done{0};
  std::atomic<bool> stop{false};
  const auto work = [&](bool reports) {
    std::vector<int> localOf(mesh.vertexCount(), -1);
    for (int c = next++; c < regions && !stop; c = next++) {
      try {
        Expected<std::vector<Piece>> more = regionPieces(mesh, facesOf[c], params, localOf, charts[c], Progress());
        if (more)
          piecesOf[c] = std::move(*more);
        else
          statusOf[c] = more.status();
      } catch (const std::bad_alloc&) {
        statusOf[c] = outOfMemory();
      }
      if (!statusOf[c]) stop = true;
      ++done;
      if (reports && !progress.report(0.5 + 0.45 * done / regions, "Texture atlas: flattening the charts")) stop = true;
    }
  };
  std::vector<std::thread> helpers;
  try {
    for (unsigned i = 1; i < std::min<unsigned>(std::thread::hardware_concurrency(), regions); ++i)
      helpers.emplace_back(work, false);
  } catch (const std::system_error&) {
    // No more threads to be had: the ones started and this one share the regions.
  }
  work(true);
  for (std::thread& t : helpers) t.join();
  std::vector<Piece> pieces;
  for (int c = 0; c < regions; ++c) {
    if (!statusOf[c]) return statusOf[c];
    for (Piece& piece : piecesOf[c]) {
      piece.chart = c;
      pieces.push_back(std::move(piece));
    }
  }
  if (stop) return cancelled();
  return pieces;
}

/// How far apart, in the unit square, a chart's boundary edges must stay at the UVs written: far
/// below a texel, far above float rounding (2^-24), so that no exact judge sees them cross.
constexpr double kWrittenClearance = 1e-6;

/// Whether the piece's boundary, at the UVs written, runs into itself or comes closer to itself
/// than kWrittenClearance (a chart map whose boundary nearly touches itself, then rounded).
bool boundaryTouches(const TriMesh& mesh, const Piece& piece, const std::vector<Vec2>& cornerUv,
                     std::vector<int>& localOf) {
  if (piece.faces.size() < 2) return false;
  Expected<Patch> patch = extractPatch(mesh, piece.faces, localOf);
  if (!patch) return true;
  std::vector<Vec2> uv(patch->mesh.vertexCount(), Vec2::Zero());
  for (size_t j = 0; j < piece.faces.size(); ++j)
    for (int k = 0; k < 3; ++k) uv[patch->mesh.triangles[j][k]] = cornerUv[3 * piece.faces[j] + k];
  return boundaryContacts(patch->mesh, uv, kWrittenClearance) > 0;
}

/// Pieces with a face that scaling and moving into the atlas left not surely counter-clockwise
/// (a chart map with triangles near zero area), or whose boundary runs into itself at the UVs
/// written: split into their faces, laid out one by one (a face already alone, thin, is laid out
/// as an equilateral triangle of its longest side). Returns how many pieces were split.
int splitUnsurePieces(const TriMesh& mesh, std::vector<Piece>& pieces, const std::vector<Vec2>& cornerUv,
                      std::vector<AtlasChart>& charts) {
  std::vector<Piece> kept;
  std::vector<int> localOf(mesh.vertexCount(), -1);
  int split = 0;
  for (Piece& piece : pieces) {
    bool sure = true;
    for (int f : piece.faces)
      sure = sure && surelyCounterClockwise(cornerUv[3 * f], cornerUv[3 * f + 1], cornerUv[3 * f + 2]);
    sure = sure && !boundaryTouches(mesh, piece, cornerUv, localOf);
    if (sure) {
      kept.push_back(std::move(piece));
      continue;
    }
    ++split;
    charts[piece.chart].facesApart = true;
    const bool alone = piece.faces.size() == 1;  // a thin face laid out alone: made fat
    for (int f : piece.faces) {
      const Tri& t = mesh.triangles[f];
      const auto uv = layoutTriangle(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]],
                                     mesh.meanEdgeLength(), alone);
      kept.push_back({{f}, {uv[0], uv[1], uv[2]}, piece.chart});
    }
  }
  pieces = std::move(kept);
  return split;
}

/// Every piece turned to its minimal rectangle, packed; the UVs written per input corner.
Status packPieces(std::vector<Piece>& pieces, const AtlasParams& params, AtlasResult& r) {
  std::vector<ChartRectangle> rectangles;
  rectangles.reserve(pieces.size());
  for (Piece& piece : pieces) rectangles.push_back(alignToMinimalRectangle(piece.cornerUv));
  Expected<ChartPacking> packing = packCharts(rectangles, double(params.gutter) / params.textureSize);
  if (!packing) return packing.status();
  double area = 0.0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const Piece& piece = pieces[i];
    for (size_t j = 0; j < piece.faces.size(); ++j) {
      for (int k = 0; k < 3; ++k) {
        const Vec2 uv = (packing->offset[i] + packing->scale * piece.cornerUv[3 * j + k])
                            .cwiseMax(Vec2::Zero())
                            .cwiseMin(Vec2::Ones());
        // Rounded to float, as MeshLab holds texture coordinates: the orientation checks below
        // judge what the mesh will carry.
        r.cornerUv[3 * piece.faces[j] + k] = Vec2(roundedToFloat(uv.x()), roundedToFloat(uv.y()));
      }
      const int f = piece.faces[j];
      const Vec2 a = r.cornerUv[3 * f + 1] - r.cornerUv[3 * f], b = r.cornerUv[3 * f + 2] - r.cornerUv[3 * f];
      area += 0.5 * std::abs(a.x() * b.y() - a.y() * b.x());
    }
  }
  r.packing = area;
  return Status::ok();
}

Status checkAtlasParams(const TriMesh& mesh, const AtlasParams& p) {
  if (p.textureSize < 16) return invalidInput("texture atlas: TextureSize must be at least 16 texels");
  if (p.gutter < 0) return invalidInput("texture atlas: Gutter must be >= 0 texels");
  if (2 * p.gutter >= p.textureSize) return invalidInput("texture atlas: the Gutter leaves no room in the texture");
  if (p.flattening.basePoints < 4 || p.flattening.neighbours < 3 || p.flattening.neighbours >= p.flattening.basePoints)
    return invalidInput("texture atlas: Base points must be >= 4 and Neighbours between 3 and Base points - 1");
  if (mesh.topology.inconsistentEdges > 0)
    return invalidInput("texture atlas: the faces are not coherently oriented (" +
                        std::to_string(mesh.topology.inconsistentEdges) +
                        " edges between faces of opposite orientation); re-orient them first (Filters > Normals, "
                        "Curvatures and Orientation > Re-Orient all faces coherentely)");
  // Non-manifold vertices are fine: the segmentation splits them, and no chart holds two fans.
  if (mesh.topology.nonManifoldEdges > 0)
    return nonManifold("texture atlas: the mesh has " + mesh.topology.nonManifoldCounts() +
                       "; clean it first (Filters > Cleaning and Repairing)");
  return Status::ok();
}

/// A one-to-one map can still be useless in an atlas: a long thin spiral or a spike that makes
/// its bounding rectangle huge (packing then shrinks every other chart to nothing), or a needle
/// (a chart of 12 faces on cactus.off, 96 long and 0.0002 wide). A chart's map must fill at least
/// kMinimumFill of its minimal rectangle and have an L2 stretch (at its own area scale) of at
/// most kMaxChartStretch; else it is mapped again, or laid out by faces.
constexpr double kMinimumFill = 0.05;
constexpr double kMaxChartStretch = 4.0;

/// If `uv` is fit for the atlas (one-to-one, compact, not stretched), scales it so that its area
/// is the chart's 3D area (the atlas's one texel density) and returns true.
bool fitForAtlas(const TriMesh& patch, std::vector<Vec2>& uv) {
  if (!checkUvInjectivity(patch, uv).injective()) return false;
  std::vector<Vec2> cornerUv(3 * patch.faceCount());
  for (int c = 0; c < 3 * patch.faceCount(); ++c) cornerUv[c] = uv[patch.vertex(c)];
  const UvDistortion d = measureUvDistortion(patch, cornerUv);
  std::vector<Vec2> points = uv;
  const ChartRectangle r = alignToMinimalRectangle(points);
  if (!(d.areaUv >= kMinimumFill * r.width * r.height) || !(d.stretchL2 <= kMaxChartStretch)) return false;
  if (d.area3d > 0.0 && d.areaUv > 0.0)
    for (Vec2& q : uv) q *= std::sqrt(d.area3d / d.areaUv);
  return true;
}

}  // namespace

Expected<ChartMap> flattenChart(const TriMesh& patch, const LleFlatteningParams& params, Progress progress) {
  ChartMap map;
  const auto accept = [&](std::vector<Vec2> uv) {
    if (!fitForAtlas(patch, uv)) return false;
    map.uv = std::move(uv);
    return true;
  };
  if (patch.vertexCount() == 3 && patch.faceCount() == 1) {  // one face: laid out as it is
    const Tri& t = patch.triangles[0];
    const auto uv =
        layoutTriangle(patch.positions[t[0]], patch.positions[t[1]], patch.positions[t[2]], patch.meanEdgeLength());
    std::vector<Vec2> layout(3);
    for (int k = 0; k < 3; ++k) layout[t[k]] = uv[k];
    if (accept(layout)) return map;
  }
  LleFlatteningParams p = params;
  const int v = patch.vertexCount();
  p.basePoints =
      std::min({p.basePoints, std::max(kMinBases, v / kVerticesPerBaseLarge), std::max(4, v / kVerticesPerBase)});
  p.neighbours = std::min(p.neighbours, p.basePoints - 1);
  if (p.basePoints >= 4) {
    Expected<LleFlatteningResult> r = flattenGeodesicLle(patch, p, progress);
    if (!r && r.status().code == StatusCode::Cancelled) return r.status();
    if (r) {
      map.tutte = r->tutte;
      map.foldedBeforeRepair = r->foldedBeforeRepair;
      if (accept(std::move(r->uv))) return map;
    }
  }
  if (!map.tutte && patch.vertexCount() >= 4) {  // LLE was refused or not one-to-one: Tutte's
    p.boundary = LleBoundary::Circle;
    Expected<LleFlatteningResult> r = flattenGeodesicLle(patch, p, progress);
    map.tutte = true;
    if (r) {  // relaxed from the circle (ARAP), else the circle itself
      std::vector<Vec2> uv = r->uv;
      ArapParams arap;
      arap.rounds = p.arapRounds;
      if (relaxAsRigidAsPossible(patch, uv, arap) && accept(std::move(uv))) return map;
      if (accept(std::move(r->uv))) return map;
    }
  }
  map.uv.clear();
  return map;
}

Expected<AtlasResult> buildTextureAtlas(const TriMesh& mesh, const AtlasParams& params, Progress progress) {
  if (Status s = checkAtlasParams(mesh, params); !s) return s;
  AtlasResult r;
  r.regionsAsked = params.segmentation.regions;
  SegmentationParams segmentation = params.segmentation;
  if (segmentation.regions >= 1)
    segmentation.regions = std::min(segmentation.regions, std::max(1, mesh.faceCount() / AtlasParams::kFacesPerChart));
  Expected<SegmentationResult> seg = segmentSurface(mesh, {}, segmentation, progress.sub(0.0, 0.5));
  if (!seg) return seg.status();
  r.segmentation = std::move(*seg);
  r.faceChart = r.segmentation.faceRegion;
  std::vector<std::vector<int>> facesOf(r.segmentation.regions);
  for (int f = 0; f < mesh.faceCount(); ++f) facesOf[r.faceChart[f]].push_back(f);
  r.charts.resize(facesOf.size());
  Expected<std::vector<Piece>> flattened = flattenRegions(mesh, facesOf, params.flattening, r.charts, progress);
  if (!flattened) return flattened.status();
  std::vector<Piece> pieces = std::move(*flattened);
  if (!progress.report(0.95, "Texture atlas: packing")) return cancelled();
  r.cornerUv.assign(3 * mesh.faceCount(), Vec2::Zero());
  if (Status s = packPieces(pieces, params, r); !s) return s;
  // Unsure pieces split and everything packed again, until all are sure; a fat face alone can
  // only stay unsure far below a texel: refused rather than shipped turned over.
  for (int round = 0; splitUnsurePieces(mesh, pieces, r.cornerUv, r.charts) > 0; ++round) {
    if (round == kSplitRounds)
      return degenerate(
          "texture atlas: a face is too small for the texture's precision even on its own; remove tiny "
          "faces first (Filters > Cleaning and Repairing)");
    if (Status s = packPieces(pieces, params, r); !s) return s;
  }
  for (const AtlasChart& chart : r.charts)
    r.repairedCharts += chart.tutte || chart.facesApart || chart.foldedBeforeRepair > 0 || chart.splits > 0;
  r.pieces = static_cast<int>(pieces.size());
  r.distortion = measureUvDistortion(mesh, r.cornerUv);
  return r;
}

}  // namespace gr
