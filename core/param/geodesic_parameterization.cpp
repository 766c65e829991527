#include "core/param/geodesic_parameterization.h"

#include <Eigen/Geometry>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <string>

#include "core/base/two_threads.h"
#include "core/geodesic/fast_marching.h"
#include "core/geodesic/metric.h"
#include "core/mesh/face_geometry.h"
#include "core/mesh/orientation.h"
#include "core/param/geodesic_barycentric.h"

namespace gr {
namespace {

/// A piece of the cut surface: its faces, vertices (with, per vertex, its distance to the base
/// triangle's three corners) and boundary loop from corner 0.
struct Piece {
  std::vector<int> faces;
  std::vector<int> vertices;
  std::vector<std::array<double, 3>> distance;  // per entry of `vertices`
  std::vector<int> loop;                        // boundary vertices, counter-clockwise from corner 0
};

std::vector<Piece> collectPieces(const BasePieces& cut, const BaseDomain& base) {
  const TriMesh& mesh = cut.mesh;
  std::vector<Piece> pieces(base.triangles.size());
  for (int f = 0; f < mesh.faceCount(); ++f) pieces[cut.triangle[f]].faces.push_back(f);
  std::vector<int> seen(mesh.vertexCount(), -1);
  for (size_t t = 0; t < pieces.size(); ++t) {
    Piece& p = pieces[t];
    const int v0 = base.baseVertex[base.triangles[t][0]];
    int start = -1;
    for (int f : p.faces)
      for (int c = 3 * f; c < 3 * f + 3; ++c) {
        if (seen[mesh.vertex(c)] != static_cast<int>(t)) {
          seen[mesh.vertex(c)] = static_cast<int>(t);
          p.vertices.push_back(mesh.vertex(c));
        }
        if (cut.onCut[c] && mesh.vertex(TriMesh::next(c)) == v0) start = c;
      }
    p.distance.assign(p.vertices.size(), {kUnreached, kUnreached, kUnreached});
    p.loop.push_back(v0);
    for (int c = start;;) {  // the loop walk of base_pieces.cpp's assignPieces
      const int b = mesh.vertex(TriMesh::prev(c));
      if (b == v0) break;
      p.loop.push_back(b);
      int k = TriMesh::next(c);
      while (!cut.onCut[k]) k = TriMesh::next(mesh.oppositeCorner[k]);
      c = k;
    }
  }
  return pieces;
}

/// One front per base vertex on the cut surface, until it has reached every vertex of its pieces:
/// fills the pieces' distances and returns the base edges' lengths (the smaller way; +inf if unmet).
struct Fronts {
  std::vector<double> edgeLength;                          // per base edge, the smaller way; +inf if unmet
  std::vector<std::array<std::vector<double>, 2>> onPath;  // per base edge, d from its lower and higher end
};

Expected<Fronts> runFronts(const BasePieces& cut, const BaseDomain& base, std::vector<Piece>& pieces,
                           Progress progress) {
  const int nb = static_cast<int>(base.baseVertex.size());
  std::vector<std::vector<std::pair<int, int>>> star(nb);  // per base vertex: (triangle, its corner)
  for (size_t t = 0; t < base.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) star[base.triangles[t][k]].emplace_back(static_cast<int>(t), k);
  Fronts out;
  out.onPath.resize(cut.edges.size());
  const Metric metric = Metric::uniform();
  // The base vertices in two halves, the second on a helper thread with its own engine. A front
  // writes only its own corner's distances and its own end's side of each base edge; the edge
  // lengths (read from both ends) are kept per half and merged. 1.66M vertices, 5,000 base
  // vertices: 3.6 s on one thread.
  std::array<std::vector<double>, 2> length;
  std::array<Status, 2> failed;
  std::atomic<bool> stop{false};
  onTwoThreads([&](bool helper) {
    std::vector<double>& mine = length[helper];
    mine.assign(cut.edges.size(), kUnreached);
    FastMarcher marcher(cut.mesh, metric);
    for (int i = helper ? nb / 2 : 0, last = helper ? nb : nb / 2; i < last && !stop; ++i) {
      if (!helper && !progress.report(static_cast<double>(i) / last, "Geodesic distances to the base vertices"))
        stop = true;
      FastMarchingParams limit;
      for (const auto& [t, k] : star[i])
        limit.targets.insert(limit.targets.end(), pieces[t].vertices.begin(), pieces[t].vertices.end());
      marcher.reset();
      Status s = marcher.addSource(base.baseVertex[i], 0);
      if (s) s = marcher.propagate(limit);
      if (!s) {
        failed[helper] = s;
        stop = true;
        break;
      }
      const std::vector<double>& d = marcher.distance();
      for (const auto& [t, k] : star[i]) {
        Piece& p = pieces[t];
        for (size_t l = 0; l < p.vertices.size(); ++l) p.distance[l][k] = d[p.vertices[l]];
        for (int m = 1; m < 3; ++m) {  // the edges from i to the triangle's other corners
          const int j = base.triangles[t][(k + m) % 3];
          const int e = cut.triangleEdge[t][(k + 3 - m) % 3];
          mine[e] = std::min(mine[e], d[base.baseVertex[j]]);
          std::vector<double>& along = out.onPath[e][cut.edges[e].first == i ? 0 : 1];
          if (along.empty())
            for (int v : cut.path[e]) along.push_back(d[v]);
        }
      }
    }
  });
  for (const Status& s : failed)
    if (!s) return s;
  if (stop) return cancelled();
  out.edgeLength.resize(cut.edges.size());
  for (size_t e = 0; e < cut.edges.size(); ++e) out.edgeLength[e] = std::min(length[0][e], length[1][e]);
  return out;
}

/// A side's points keep their distance ratios only if each step along the path moves at least this
/// fraction of its arc length: a path that runs across the fronts' direction keeps the ratio nearly
/// constant, and its points would crowd (cylinder.off, 500 base vertices: faces squashed to 1e-11).
constexpr double kMinSideStep = 0.25;

/// Per vertex of the cut surface on a path (not a base vertex), where it sits on its base edge:
/// t in (0, 1) from the edge's lower base vertex, d_a / (d_a + d_b) from the two ends' fronts
/// (what Heron's coordinates give a point of the side), or by arc length where those do not
/// increase by kMinSideStep of the arc length at every step. Both pieces of the edge read the same
/// t: no crack.
std::vector<double> sidePositions(const BasePieces& cut, const Fronts& fronts) {
  std::vector<double> t(cut.mesh.vertexCount(), -1.0);
  for (size_t e = 0; e < cut.path.size(); ++e) {
    const std::vector<int>& path = cut.path[e];
    const size_t n = path.size();
    std::vector<double> arc(n, 0.0), at(n, 1.0);
    for (size_t k = 1; k < n; ++k)
      arc[k] = arc[k - 1] + (cut.mesh.positions[path[k - 1]] - cut.mesh.positions[path[k]]).norm();
    for (size_t k = 0; k < n; ++k) arc[k] /= arc[n - 1];
    const std::vector<double>&da = fronts.onPath[e][0], &db = fronts.onPath[e][1];
    bool even = da.size() == n && db.size() == n;
    at[0] = 0.0;
    for (size_t k = 1; even && k + 1 < n; ++k) {
      at[k] = da[k] / (da[k] + db[k]);
      even = std::isfinite(at[k]) && at[k] - at[k - 1] >= kMinSideStep * (arc[k] - arc[k - 1]);
    }
    even = even && at[n - 1] - at[n - 2] >= kMinSideStep * (arc[n - 1] - arc[n - 2]);
    for (size_t k = 1; k + 1 < n; ++k) t[path[k]] = even ? at[k] : arc[k];
  }
  return t;
}

double pathLength(const TriMesh& mesh, const std::vector<int>& path) {
  double s = 0.0;
  for (size_t k = 0; k + 1 < path.size(); ++k) s += (mesh.positions[path[k]] - mesh.positions[path[k + 1]]).norm();
  return s;
}

/// Per vertex of a piece's loop, its point on the domain's sides (sidePositions).
void pinSides(const Parameterization& par, const Piece& p, int t, const std::vector<double>& sideT,
              const std::array<Vec2, 3>& q, std::vector<Vec2>& uvOf, const std::vector<int>& local) {
  const Tri& bt = par.base.triangles[t];
  for (int c = 0; c < 3; ++c) uvOf[local[par.base.baseVertex[bt[c]]]] = q[c];
  int side = 0;  // the loop runs corner 0 -> 1 -> 2 -> 0
  for (int v : p.loop) {
    for (int c = 0; c < 3; ++c)
      if (v == par.base.baseVertex[bt[c]]) side = c;
    if (sideT[v] < 0.0) continue;
    const int e = par.pieces.triangleEdge[t][(side + 2) % 3];  // the edge from corner side to side + 1
    const double fromCorner = par.pieces.edges[e].first == bt[side] ? sideT[v] : 1.0 - sideT[v];
    uvOf[local[v]] = q[side] + fromCorner * (q[(side + 1) % 3] - q[side]);
  }
}

double signedArea(const Vec2& a, const Vec2& b, const Vec2& c) {
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x()));
}

/// Heron's coordinates (smoothed or not) are kept only if no face shrinks to less than this share
/// of its part of the domain (its share of the piece's area in 3D): a face squashed further would
/// be flat once MeshLab holds its texture coordinates in floats (anchor.off, 500 base vertices:
/// two faces at 1e-11 of the domain, 0 in float). The mean value map is judged by orientation alone.
constexpr double kHeronMinAreaShare = 1e-4;

/// The faces of piece p that are not counter-clockwise in the domain (of area `domainArea`) or,
/// with `minShare` > 0, smaller than minShare times their share of the piece's 3D area.
/// Where a piece's domain lands in tiledUv's texture, to judge its faces as MeshLab will hold
/// them: texture coordinates rounded to float.
struct Tile {
  Vec2 q0;
  Eigen::Matrix2d toUv;  // domain point - q0 -> the (u, v) of the base triangle's corners 1 and 2
  Vec2 origin;
  double size = 1.0;
};

/// tiledUv's grid: g x g tiles for `triangles` base triangles.
int tileGrid(int triangles) {
  return std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(triangles)))));
}

Vec2 tileOrigin(int t, int g, double margin) { return Vec2((t % g + margin) / g, (t / g + margin) / g); }

Tile tileOf(int t, int triangles, const std::array<Vec2, 3>& q) {
  Tile tile;
  tile.q0 = q[0];
  Eigen::Matrix2d frame;
  frame << q[1] - q[0], q[2] - q[0];
  tile.toUv = frame.inverse();
  const int g = tileGrid(triangles);
  tile.origin = tileOrigin(t, g, kTileMargin);
  tile.size = (1.0 - 2.0 * kTileMargin) / g;
  return tile;
}

Vec2 textureOf(const Tile& tile, const Vec2& domainPoint) {
  const Vec2 uv = tile.origin + tile.size * (tile.toUv * (domainPoint - tile.q0));
  return Vec2(roundedToFloat(uv.x()), roundedToFloat(uv.y()));
}

std::vector<int> badFaces(const TriMesh& mesh, const Piece& p, const std::vector<Vec2>& uvOf,
                          const std::vector<int>& local, double domainArea, double minShare, const Tile& tile) {
  auto area3 = [&](int f) {
    const Tri& t = mesh.triangles[f];
    return (mesh.positions[t[1]] - mesh.positions[t[0]]).cross(mesh.positions[t[2]] - mesh.positions[t[0]]).norm();
  };
  double total = 0.0;
  if (minShare > 0.0)
    for (int f : p.faces) total += area3(f);
  std::vector<int> bad;
  for (int f : p.faces) {
    const Tri& t = mesh.triangles[f];
    double least = 1e-14 * domainArea;
    if (minShare > 0.0 && total > 0.0) least = std::max(least, minShare * domainArea * area3(f) / total);
    const Vec2 &a = uvOf[local[t[0]]], &b = uvOf[local[t[1]]], &c = uvOf[local[t[2]]];
    if (!(signedArea(a, b, c) > least) ||
        !surelyCounterClockwise(textureOf(tile, a), textureOf(tile, b), textureOf(tile, c)))
      bad.push_back(f);
  }
  return bad;
}

bool folded(const TriMesh& mesh, const Piece& p, const std::vector<Vec2>& uvOf, const std::vector<int>& local,
            double domainArea, const Tile& tile, double minShare = 0.0) {
  return !badFaces(mesh, p, uvOf, local, domainArea, minShare, tile).empty();
}

/// The interior vertices placed by mean value coordinates (Floater 2003) with the loop fixed, or
/// with `uniform`, by Tutte's (every weight 1): both one-to-one in exact arithmetic; Tutte's
/// also where degenerate faces leave a mean value weight undefined.
Status meanValueMap(const TriMesh& mesh, const Piece& p, const std::vector<char>& inside, std::vector<Vec2>& uvOf,
                    const std::vector<int>& local, bool uniform) {
  std::vector<int> unknown(p.vertices.size(), -1);
  int n = 0;
  for (size_t l = 0; l < p.vertices.size(); ++l)
    if (inside[l]) unknown[l] = n++;
  if (n == 0) return Status::ok();
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(n, 2);
  for (size_t l = 0; l < p.vertices.size(); ++l) {
    if (!inside[l]) continue;
    const int v = p.vertices[l], row = unknown[l];
    const Vec3& pv = mesh.positions[v];
    double diagonal = 0.0;
    auto add = [&](int w, double weight) {
      diagonal += weight;
      const int lw = local[w];
      if (unknown[lw] >= 0)
        entries.emplace_back(row, unknown[lw], -weight);
      else
        rhs.row(row) += weight * uvOf[lw].transpose();
    };
    for (const int* c = mesh.cornersBegin(v); c != mesh.cornersEnd(v); ++c) {
      const int a = mesh.vertex(TriMesh::next(*c)), b = mesh.vertex(TriMesh::prev(*c));
      const Vec3 e1 = mesh.positions[a] - pv, e2 = mesh.positions[b] - pv;
      const double l1 = e1.norm(), l2 = e2.norm();
      const double halfTan = e1.cross(e2).norm() / (l1 * l2 + e1.dot(e2));
      const double w1 = halfTan / l1, w2 = halfTan / l2;
      const bool usable = !uniform && std::isfinite(w1) && std::isfinite(w2) && w1 > 0.0 && w2 > 0.0;
      add(a, usable ? w1 : 1.0);
      add(b, usable ? w2 : 1.0);
    }
    entries.emplace_back(row, row, diagonal);
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
  lu.compute(a);
  if (lu.info() != Eigen::Success)
    return internalError("geodesic parameterisation: a piece's mean value system is singular");
  const Eigen::MatrixX2d x = lu.solve(rhs);
  for (size_t l = 0; l < p.vertices.size(); ++l)
    if (inside[l]) uvOf[l] = x.row(unknown[l]).transpose();
  return Status::ok();
}

struct PieceOutcome {
  bool heron = false;     // Heron's coordinates everywhere
  bool smoothed = false;  // Heron's, with a band around the folds mapped by mean value coordinates
  bool repaired = false;  // mean value coordinates everywhere
};

/// Rings of vertices around the folded faces remapped by mean value coordinates, the rest of
/// the piece keeping Heron's coordinates (Lee et al. 1998's relaxation, confined to the folds),
/// before the whole piece is; each try is checked.
constexpr int kSmoothingRings[] = {2, 6, 18};

/// Per vertex of piece p: inside it and within `rings` edges of a face of `folds`.
std::vector<char> bandAroundFolds(const TriMesh& mesh, const Piece& p, const std::vector<int>& folds,
                                  const std::vector<int>& local, const std::vector<char>& inside, int rings) {
  std::vector<char> band(p.vertices.size(), 0);
  std::vector<int> front;
  for (int f : folds) {
    const Tri& t = mesh.triangles[f];
    for (int v : t)
      if (!band[local[v]]) {
        band[local[v]] = 1;
        front.push_back(v);
      }
  }
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for (int v : front)
      for (const int* c = mesh.cornersBegin(v); c != mesh.cornersEnd(v); ++c)
        for (int w : {mesh.vertex(TriMesh::next(*c)), mesh.vertex(TriMesh::prev(*c))})
          if (local[w] >= 0 && local[w] < static_cast<int>(p.vertices.size()) && p.vertices[local[w]] == w &&
              !band[local[w]]) {
            band[local[w]] = 1;
            next.push_back(w);
          }
    front = std::move(next);
  }
  for (size_t l = 0; l < band.size(); ++l) band[l] = band[l] && inside[l];
  return band;
}

/// Maps piece t onto its domain; writes the corners' (u, v).
Expected<PieceOutcome> mapPiece(const Parameterization& par, const Piece& p, int t, const std::array<Vec2, 3>& q,
                                const std::vector<double>& sideT, std::vector<int>& local,
                                std::vector<Vec2>& cornerUv) {
  const TriMesh& mesh = par.pieces.mesh;
  for (size_t l = 0; l < p.vertices.size(); ++l) local[p.vertices[l]] = static_cast<int>(l);
  std::vector<char> inside(p.vertices.size(), 1);
  for (int v : p.loop) inside[local[v]] = 0;
  std::vector<Vec2> uvOf(p.vertices.size(), Vec2::Zero());
  pinSides(par, p, t, sideT, q, uvOf, local);
  const std::array<int, 3>& te = par.pieces.triangleEdge[t];  // edges facing corners 0, 1, 2
  const double l12 = par.edgeLength[te[0]], l20 = par.edgeLength[te[1]], l01 = par.edgeLength[te[2]];
  const Tile tile = tileOf(t, static_cast<int>(par.base.triangles.size()), q);
  PieceOutcome out;
  out.heron = true;
  for (size_t l = 0; l < p.vertices.size(); ++l) {
    if (!inside[l]) continue;
    const auto& d = p.distance[l];
    const HeronCoordinates h = heronCoordinates(d[0], d[1], d[2], l01, l12, l20);
    if (!h.valid) out.heron = false;
    uvOf[l] = h.weights[0] * q[0] + h.weights[1] * q[1] + h.weights[2] * q[2];
  }
  const double area = signedArea(q[0], q[1], q[2]);
  const std::vector<int> folds =
      out.heron ? badFaces(mesh, p, uvOf, local, area, kHeronMinAreaShare, tile) : std::vector<int>();
  if (!folds.empty()) {
    out.heron = false;
    for (int rings : kSmoothingRings) {
      const std::vector<char> band = bandAroundFolds(mesh, p, folds, local, inside, rings);
      std::vector<Vec2> tried = uvOf;
      if (meanValueMap(mesh, p, band, tried, local, false) &&
          !folded(mesh, p, tried, local, area, tile, kHeronMinAreaShare)) {
        uvOf = std::move(tried);
        out.smoothed = true;
        break;
      }
    }
  }
  if (!out.heron && !out.smoothed) {
    out.repaired = true;
    if (Status s = meanValueMap(mesh, p, inside, uvOf, local, false); !s || folded(mesh, p, uvOf, local, area, tile))
      if (Status u = meanValueMap(mesh, p, inside, uvOf, local, true); !u) return u;
    if (folded(mesh, p, uvOf, local, area, tile))
      return degenerate("geodesic parameterisation: the piece of base triangle " + std::to_string(t) +
                        " is folded after its mean value map");
  }
  for (int f : p.faces)
    for (int k = 0; k < 3; ++k) cornerUv[3 * f + k] = tile.toUv * (uvOf[local[mesh.triangles[f][k]]] - tile.q0);
  return out;
}

}  // namespace

/// Below this shape quality a base triangle's domain is the equilateral triangle: three base
/// vertices along a straight boundary have geodesic sides that make a flat triangle, onto which
/// no map of their piece is one-to-one.
constexpr double kFlatDomain = 0.05;

std::array<Vec2, 3> triangleDomain(double l01, double l12, double l20) {
  // Shape quality 4 sqrt(3) area / (sum of squared sides): 1 for the equilateral triangle.
  const double quality = 4.0 * std::sqrt(3.0) * heronArea(l01, l12, l20) / (l01 * l01 + l12 * l12 + l20 * l20);
  if (!(quality > kFlatDomain)) {
    const double s = (std::isfinite(l01 + l12 + l20) && l01 + l12 + l20 > 0.0) ? (l01 + l12 + l20) / 3.0 : 1.0;
    return {Vec2(0.0, 0.0), Vec2(s, 0.0), Vec2(0.5 * s, std::sqrt(0.75) * s)};
  }
  const double x = (l01 * l01 + l20 * l20 - l12 * l12) / (2.0 * l01);
  return {Vec2(0.0, 0.0), Vec2(l01, 0.0), Vec2(x, std::sqrt(std::max(0.0, l20 * l20 - x * x)))};
}

Expected<Parameterization> parameterizeOverBase(const TriMesh& input, const ParameterizationParams& params,
                                                Progress progress) {
  if (input.faceCount() == 0) return invalidInput("geodesic parameterisation: the mesh has no faces");
  if (!input.topology.isManifold())
    return nonManifold("geodesic parameterisation: the mesh has " + input.topology.nonManifoldCounts());
  if (const int loose = input.looseFaceCount(); TriMesh::looksLikeTriangleSoup(loose, input.faceCount()))
    return invalidInput("geodesic parameterisation: " + std::to_string(loose) + " of the " +
                        std::to_string(input.faceCount()) +
                        " faces share no edge with another face (a triangle soup, as an STL file read without "
                        "merging its vertices gives); run 'Cleaning and Repairing > Merge Close Vertices' first");
  Parameterization par;
  Expected<TriMesh> oriented = orientCoherently(input, &par.flipped);
  if (!oriented) return oriented.status();
  par.input = std::move(*oriented);
  Expected<BaseDomain> base = buildBaseDomain(par.input, params.base, progress.sub(0.0, 0.4));
  if (!base) return base.status();
  par.base = std::move(*base);
  Expected<BasePieces> cut = cutIntoBasePieces(par.input, par.base, progress.sub(0.4, 0.6));
  if (!cut) return cut.status();
  par.pieces = std::move(*cut);
  std::vector<Piece> pieces = collectPieces(par.pieces, par.base);
  Expected<Fronts> fronts = runFronts(par.pieces, par.base, pieces, progress.sub(0.6, 0.9));
  if (!fronts) return fronts.status();
  par.edgeLength = fronts->edgeLength;
  const std::vector<double> sideT = sidePositions(par.pieces, *fronts);
  for (size_t e = 0; e < par.edgeLength.size(); ++e)
    if (!std::isfinite(par.edgeLength[e])) par.edgeLength[e] = pathLength(par.pieces.mesh, par.pieces.path[e]);
  par.cornerUv.assign(3 * par.pieces.mesh.faceCount(), Vec2::Zero());
  std::vector<int> local(par.pieces.mesh.vertexCount(), -1);
  for (size_t t = 0; t < pieces.size(); ++t) {
    if (!progress.report(0.9 + 0.1 * t / pieces.size(), "Mapping the pieces onto their base triangles"))
      return cancelled();
    const std::array<int, 3>& te = par.pieces.triangleEdge[t];
    const std::array<Vec2, 3> q = triangleDomain(par.edgeLength[te[2]], par.edgeLength[te[0]], par.edgeLength[te[1]]);
    Expected<PieceOutcome> mapped = mapPiece(par, pieces[t], static_cast<int>(t), q, sideT, local, par.cornerUv);
    if (!mapped) return mapped.status();
    par.heronPieces += mapped->heron;
    par.smoothedPieces += mapped->smoothed;
    par.repairedPieces += mapped->repaired;
  }
  return par;
}

std::vector<Vec2> tiledUv(const Parameterization& par) {
  const int g = tileGrid(static_cast<int>(par.base.triangles.size()));
  const double size = (1.0 - 2.0 * kTileMargin) / g;
  std::vector<Vec2> uv(par.cornerUv.size());
  for (size_t c = 0; c < uv.size(); ++c)
    uv[c] = tileOrigin(par.pieces.triangle[c / 3], g, kTileMargin) + size * par.cornerUv[c];
  return uv;
}

std::vector<SurfacePoint> cutVertexOrigins(const Parameterization& par) {
  const TriMesh& cut = par.pieces.mesh;
  std::vector<SurfacePoint> origin(cut.vertexCount());
  for (int v = 0; v < par.input.vertexCount(); ++v) origin[v] = SurfacePoint::atVertex(v);
  for (int f = 0; f < cut.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      Vec3 b = par.pieces.cornerBary[3 * f + k];
      if (par.flipped[par.pieces.originalFace[f]]) std::swap(b[1], b[2]);  // corners 1, 2 as given
      origin[cut.triangles[f][k]] = SurfacePoint::inFace(par.pieces.originalFace[f], b);
    }
  return origin;
}

std::vector<int> baseTriangleOfVertex(const Parameterization& par) {
  const TriMesh& cut = par.pieces.mesh;
  std::vector<int> triangle(cut.vertexCount(), -1);
  for (int f = 0; f < cut.faceCount(); ++f)
    for (int v : cut.triangles[f])
      if (triangle[v] < 0) triangle[v] = par.pieces.triangle[f];
  return triangle;
}

}  // namespace gr
