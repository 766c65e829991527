#include "core/geodesic/geodesic_lloyd.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "core/mesh/face_geometry.h"

namespace gr {
namespace {

/// A step shorter than this share of the square root of the cell's area ends the cell's descent.
constexpr double kStepTolerance = 0.01;
/// A barycentric coordinate above 1 minus this makes the point its vertex.
constexpr double kSnapToVertex = 1e-9;
/// Halvings of a step that does not lower the cell's energy before its descent ends (each costs a front).
constexpr int kHalvings = 1;
/// The new cells come from the accepted ones (LloydRun::boundedFronts) when the cells have at
/// least this many vertices on average. In smaller cells a source's first rings, which get
/// straight-line distances, reach past its cell: each front alone then lowers its neighbours'
/// values, which one front from all seeds, having accepted them, keeps (bunny00, the first
/// iteration's energies apart by 2e-3 at 10 vertices per cell, 1e-3 at 20, 6e-5 at 40 and 75).
constexpr int kBoundedFrontsCellVertices = 40;
/// Rounds of re-placing the seeds of vanished cells before giving up on that iteration's cells.
constexpr int kReseedRounds = 8;

std::vector<Vec3> vertexNormals(const TriMesh& mesh) {
  std::vector<Vec3> normal(mesh.vertexCount(), Vec3::Zero());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Vec3 n = areaNormal(mesh, f);
    for (int v : mesh.triangles[f]) normal[v] += n;
  }
  for (Vec3& n : normal) {
    const double len = n.norm();
    if (len > 0.0) n /= len;
  }
  return normal;
}

double meanP(const Metric& metric, int vertexCount) {
  if (metric.isUniform() || vertexCount == 0) return 1.0;
  double sum = 0.0;
  for (double p : metric.P) sum += p;
  return sum / vertexCount;
}

/// One run of Lloyd iterations: the mesh's per-vertex data, the cells of the current seeds, and
/// the descent of each cell.
class LloydRun {
 public:
  LloydRun(const TriMesh& mesh, const Metric& metric, FastMarcher& marcher, const LloydParams& params)
      : mesh_(mesh),
        metric_(metric),
        marcher_(marcher),
        params_(params),
        mass_(lloydVertexMass(mesh, metric, params.metricArea)),
        normal_(vertexNormals(mesh)),
        region_(mesh.vertexCount(), -1),
        discretisationMargin_(0.5 * mesh.meanEdgeLength() * meanP(metric, mesh.vertexCount())) {}

  /// The cells and field of `seeds` (seeds of vanished cells are re-placed, counted in `reseeded`);
  /// the energy sum_x m_x U(x)^2. `nearAccepted`: the seeds are the accepted ones moved (one
  /// index each), so their field may start from the accepted field (boundedFronts).
  Expected<double> voronoi(std::vector<SurfacePoint>& seeds, int* reseeded, bool nearAccepted = false);
  /// The same from the field the marcher holds (LloydParams::marcherHoldsSeedsField), if every
  /// seed has a cell there; else from a front.
  Expected<double> voronoiFromMarcher(std::vector<SurfacePoint>& seeds, int* reseeded);
  /// The energy sum_x m_x U(x)^2 of the current field.
  double energy() const;
  /// Keeps the current seeds and field as the accepted ones, from which the next are computed.
  void accept(const std::vector<SurfacePoint>& seeds) {
    acceptedSeeds_ = seeds;
    acceptedDistance_ = distance_;
    acceptedCell_ = cell_;
  }
  /// Moves `seed` (of cell i) down the cell's energy; descent steps at most params_.descentSteps.
  Status descend(int i, SurfacePoint& seed);
  /// The point of cell i's faces nearest to `from` + omega (`to` - `from`).
  SurfacePoint beyond(int i, const SurfacePoint& from, const SurfacePoint& to, double omega) const {
    const Vec3 a = from.position(mesh_), b = to.position(mesh_);
    return nearestOnCell(i, a + omega * (b - a));
  }
  const std::vector<double>& distance() const { return distance_; }
  const std::vector<int>& cell() const { return cell_; }

 private:
  Status runFrom(const SurfacePoint& seed, int seedIndex);
  /// The field of `seeds`, the accepted seeds moved, from the accepted field: each vertex starts at
  /// an upper bound of its distance to its accepted cell's moved seed (its accepted distance plus
  /// a bound on how far that seed moved, plus a margin for the discretisation), then each seed's
  /// front runs alone where it goes below (FastMarcher::startFromBound).
  Status boundedFronts(const std::vector<SurfacePoint>& seeds);
  /// An upper bound on how far (in the metric) accepted seed i moved to `to`: through a vertex of
  /// `to`'s face (or `to` itself) in accepted cell i, then straight; +inf if there is none.
  double moveBound(int i, const SurfacePoint& to) const;
  /// Cell i's energy from the field d (the cells' field or a run inside the cell); +inf if a
  /// vertex of the cell reached before (count `expectReached`, -1 = any) is not reached.
  double cellEnergy(const std::vector<double>& d, int i, int expectReached, int* reached) const;
  /// The descent's target from w: the mean of log_w(x) over the cell, in mesh units, from the
  /// field d of w.
  Vec3 meanLog(const std::vector<double>& d, int i, const SurfacePoint& w) const;
  SurfacePoint nearestOnCell(int i, const Vec3& p) const;
  void buildCellLists(int cells);

  const TriMesh& mesh_;
  const Metric& metric_;
  FastMarcher& marcher_;
  const LloydParams& params_;
  std::vector<double> mass_;
  std::vector<Vec3> normal_;
  std::vector<double> distance_;
  std::vector<int> cell_;
  std::vector<int> vertexBegin_, vertices_;  ///< per cell, its vertices (CSR)
  std::vector<int> faceBegin_, faces_;       ///< per cell, the faces with a vertex in it (CSR)
  std::vector<double> cellArea_;             ///< per cell, its mass
  std::vector<int> region_;                  ///< per vertex, the stamp of the last cell it is near
  int stamp_ = 0;
  /// Added to each bound of boundedFronts: half a mean edge length (in the metric's mean P), so
  /// that a moved seed's front goes below its own cell's bound though its discretisation differs
  /// a little (bunny00, 500 seeds: the fields then equal the multi-source fronts' to 1e-16 after
  /// the first iteration; with no margin 1e-4 of the energy apart).
  double discretisationMargin_;
  std::vector<SurfacePoint> acceptedSeeds_;  ///< see accept()
  std::vector<double> acceptedDistance_;
  std::vector<int> acceptedCell_;
  std::vector<double> bound_;  ///< boundedFronts' per-vertex bound (kept to reuse its memory)
};

double LloydRun::moveBound(int i, const SurfacePoint& to) const {
  const Vec3 p = to.position(mesh_);
  const auto through = [&](int x, double pMax) {
    if (acceptedCell_[x] != i) return kUnreached;
    return acceptedDistance_[x] + pMax * (mesh_.positions[x] - p).norm();
  };
  if (to.vertex >= 0) return through(to.vertex, 0.0);
  const Tri& t = mesh_.triangles[to.face];
  double pMax = 1.0;
  if (!metric_.isUniform()) pMax = std::max({metric_.P[t[0]], metric_.P[t[1]], metric_.P[t[2]]});
  return std::min({through(t[0], pMax), through(t[1], pMax), through(t[2], pMax)});
}

Status LloydRun::boundedFronts(const std::vector<SurfacePoint>& seeds) {
  const int n = static_cast<int>(seeds.size()), nv = mesh_.vertexCount();
  std::vector<double> slack(n);
  for (int i = 0; i < n; ++i) slack[i] = moveBound(i, seeds[i]) + discretisationMargin_;
  bound_.resize(nv);
  for (int v = 0; v < nv; ++v) {
    const int c = acceptedCell_[v];
    bound_[v] = c >= 0 ? acceptedDistance_[v] + slack[c] : kUnreached;
  }
  if (Status s = marcher_.startFromBound(bound_, acceptedCell_); !s) return s;
  for (int i = 0; i < n; ++i) {
    if (Status s = marcher_.addSource(seeds[i], i); !s) return s;
    if (Status s = marcher_.propagate(); !s) return s;
  }
  return Status::ok();
}

Expected<double> LloydRun::voronoiFromMarcher(std::vector<SurfacePoint>& seeds, int* reseeded) {
  const int n = static_cast<int>(seeds.size());
  distance_ = marcher_.distance();
  cell_ = marcher_.cell();
  for (int c : cell_)
    if (c >= n) return voronoi(seeds, reseeded);
  buildCellLists(n);
  for (int i = 0; i < n; ++i)
    if (vertexBegin_[i + 1] == vertexBegin_[i]) return voronoi(seeds, reseeded);
  return energy();
}

Expected<double> LloydRun::voronoi(std::vector<SurfacePoint>& seeds, int* reseeded, bool nearAccepted) {
  const int n = static_cast<int>(seeds.size());
  for (int round = 0;; ++round) {
    const bool bounded = nearAccepted && static_cast<int>(acceptedSeeds_.size()) == n &&
                         mesh_.vertexCount() >= kBoundedFrontsCellVertices * n;
    if (round == 0 && bounded) {
      if (Status s = boundedFronts(seeds); !s) return s;
    } else {
      marcher_.reset();
      for (int i = 0; i < n; ++i)
        if (Status s = marcher_.addSource(seeds[i], i); !s) return s;
      if (Status s = marcher_.propagate(); !s) return s;
    }
    distance_ = marcher_.distance();
    cell_ = marcher_.cell();
    buildCellLists(n);
    // Vanished cells: their seeds go to the vertices farthest from all seeds.
    std::vector<int> empty;
    for (int i = 0; i < n; ++i)
      if (vertexBegin_[i + 1] == vertexBegin_[i]) empty.push_back(i);
    if (empty.empty() || round == kReseedRounds) break;
    std::vector<int> order(mesh_.vertexCount());
    for (int v = 0; v < mesh_.vertexCount(); ++v) order[v] = v;
    std::partial_sort(order.begin(), order.begin() + std::min<size_t>(empty.size(), order.size()), order.end(),
                      [&](int a, int b) {
                        const double ua = std::isfinite(distance_[a]) ? distance_[a] : -1.0;
                        const double ub = std::isfinite(distance_[b]) ? distance_[b] : -1.0;
                        return ua > ub;
                      });
    for (size_t k = 0; k < empty.size() && k < order.size(); ++k) seeds[empty[k]] = SurfacePoint::atVertex(order[k]);
    *reseeded += static_cast<int>(empty.size());
  }
  return energy();
}

double LloydRun::energy() const {
  double e = 0.0;
  for (int v = 0; v < mesh_.vertexCount(); ++v)
    if (std::isfinite(distance_[v])) e += mass_[v] * distance_[v] * distance_[v];
  return e;
}

void LloydRun::buildCellLists(int cells) {
  vertexBegin_.assign(cells + 1, 0);
  faceBegin_.assign(cells + 1, 0);
  cellArea_.assign(cells, 0.0);
  for (int v = 0; v < mesh_.vertexCount(); ++v)
    if (cell_[v] >= 0) {
      ++vertexBegin_[cell_[v] + 1];
      cellArea_[cell_[v]] += mass_[v];
    }
  const auto facesCells = [&](int f, auto&& visit) {  // the distinct cells of f's vertices
    const Tri& t = mesh_.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int c = cell_[t[k]];
      if (c >= 0 && (k == 0 || c != cell_[t[0]]) && (k < 2 || c != cell_[t[1]])) visit(c);
    }
  };
  for (int f = 0; f < mesh_.faceCount(); ++f) facesCells(f, [&](int c) { ++faceBegin_[c + 1]; });
  for (int i = 0; i < cells; ++i) {
    vertexBegin_[i + 1] += vertexBegin_[i];
    faceBegin_[i + 1] += faceBegin_[i];
  }
  vertices_.resize(vertexBegin_[cells]);
  faces_.resize(faceBegin_[cells]);
  std::vector<int> vfill(vertexBegin_.begin(), vertexBegin_.end() - 1);
  std::vector<int> ffill(faceBegin_.begin(), faceBegin_.end() - 1);
  for (int v = 0; v < mesh_.vertexCount(); ++v)
    if (cell_[v] >= 0) vertices_[vfill[cell_[v]]++] = v;
  for (int f = 0; f < mesh_.faceCount(); ++f) facesCells(f, [&](int c) { faces_[ffill[c]++] = f; });
}

Status LloydRun::runFrom(const SurfacePoint& seed, int seedIndex) {
  marcher_.reset();
  if (Status s = marcher_.addSource(seed, seedIndex); !s) return s;
  FastMarchingParams run;
  run.region = &region_;
  run.regionLabel = stamp_;
  return marcher_.propagate(run);
}

double LloydRun::cellEnergy(const std::vector<double>& d, int i, int expectReached, int* reached) const {
  double e = 0.0;
  int count = 0;
  for (int k = vertexBegin_[i]; k < vertexBegin_[i + 1]; ++k) {
    const int x = vertices_[k];
    if (!std::isfinite(d[x])) continue;
    e += mass_[x] * d[x] * d[x];
    ++count;
  }
  if (reached) *reached = count;
  if (expectReached >= 0 && count < expectReached) return kUnreached;
  return e;
}

Vec3 LloydRun::meanLog(const std::vector<double>& d, int i, const SurfacePoint& w) const {
  const Vec3 pw = w.position(mesh_);
  Vec3 n = interpolate(mesh_, w, normal_);
  n = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
  Vec3 sum = Vec3::Zero();
  double mass = 0.0;
  for (int k = vertexBegin_[i]; k < vertexBegin_[i + 1]; ++k) {
    const int x = vertices_[k];
    if (!std::isfinite(d[x])) continue;
    Vec3 r = mesh_.positions[x] - pw;
    r -= r.dot(n) * n;
    const double len = r.norm();
    if (len > 0.0) sum += mass_[x] * d[x] / len * r;
    mass += mass_[x];
  }
  if (!(mass > 0.0)) return Vec3::Zero();
  const double P = metric_.isUniform() ? 1.0 : interpolate(mesh_, w, metric_.P);
  return sum / (mass * P);
}

SurfacePoint LloydRun::nearestOnCell(int i, const Vec3& p) const {
  int bestFace = -1;
  Vec3 bestBary(1.0, 0.0, 0.0);
  double best = kUnreached;
  for (int k = faceBegin_[i]; k < faceBegin_[i + 1]; ++k) {
    const Tri& t = mesh_.triangles[faces_[k]];
    const Vec3& a = mesh_.positions[t[0]];
    const Vec3& b = mesh_.positions[t[1]];
    const Vec3& c = mesh_.positions[t[2]];
    // The face lies in the ball around a through its farthest vertex: skipped when even that
    // ball is farther than the best so far.
    const double reach = std::sqrt(std::max((b - a).squaredNorm(), (c - a).squaredNorm()));
    const double toA = (p - a).norm() - reach;
    if (toA > 0.0 && toA * toA >= best) continue;
    const Vec3 bary = closestPointBarycentric(p, a, b, c);
    const double dist = (bary[0] * a + bary[1] * b + bary[2] * c - p).squaredNorm();
    if (dist < best) {
      best = dist;
      bestFace = faces_[k];
      bestBary = bary;
    }
  }
  for (int k = 0; k < 3; ++k)
    if (bestBary[k] > 1.0 - kSnapToVertex) return SurfacePoint::atVertex(mesh_.triangles[bestFace][k]);
  return SurfacePoint::inFace(bestFace, bestBary);
}

Status LloydRun::descend(int i, SurfacePoint& seed) {
  if (vertexBegin_[i + 1] == vertexBegin_[i]) return Status::ok();
  const double scale = std::sqrt(std::max(cellArea_[i], 0.0));
  // The first step reads the seed's field from the cells' field (inside its cell it is the
  // front from this seed): no front of its own. With 0 steps it is the only one, not checked
  // here: the next iteration's energy accepts or undoes it.
  if (params_.descentSteps == 0) {  // one step, checked by the next cells' energy
    const Vec3 move = meanLog(distance_, i, seed);
    if (move.norm() > kStepTolerance * scale) seed = nearestOnCell(i, seed.position(mesh_) + move);
    return Status::ok();
  }
  // The region of the cell's fronts: its vertices and their neighbours (a one-ring margin).
  ++stamp_;
  for (int k = faceBegin_[i]; k < faceBegin_[i + 1]; ++k)
    for (int v : mesh_.triangles[faces_[k]]) region_[v] = stamp_;
  int reached = 0;
  double energy = cellEnergy(distance_, i, -1, &reached);
  for (int step = 0; step < params_.descentSteps; ++step) {
    const Vec3 move = meanLog(step == 0 ? distance_ : marcher_.distance(), i, seed);
    if (!(move.norm() > kStepTolerance * scale)) break;
    const Vec3 from = seed.position(mesh_);
    bool lowered = false;
    double t = 1.0;
    for (int h = 0; h <= kHalvings && !lowered; ++h, t *= 0.5) {
      const SurfacePoint candidate = nearestOnCell(i, from + t * move);
      if (Status s = runFrom(candidate, i); !s) return s;
      const double e = cellEnergy(marcher_.distance(), i, reached, nullptr);
      if (e < energy) {
        seed = candidate;
        energy = e;
        lowered = true;
      }
    }
    if (!lowered) break;  // the marcher holds a rejected candidate's field: the descent ends here
  }
  return Status::ok();
}

/// Moves each seed inside a face to the face's vertex of largest barycentric coordinate; whether
/// any moved.
bool moveSeedsToVertices(const TriMesh& mesh, std::vector<SurfacePoint>& seeds) {
  bool moved = false;
  for (SurfacePoint& p : seeds) {
    if (p.vertex >= 0) continue;
    int k = 0;
    for (int j = 1; j < 3; ++j)
      if (p.bary[j] > p.bary[k]) k = j;
    p = SurfacePoint::atVertex(mesh.triangles[p.face][k]);
    moved = true;
  }
  return moved;
}

Status checkLloydInput(const TriMesh& mesh, const Metric& metric, const FastMarcher& marcher,
                       const std::vector<SurfacePoint>& seeds, const LloydParams& params) {
  if (seeds.empty()) return invalidInput("geodesic Lloyd: no seed");
  if (params.iterations < 0 || params.descentSteps < 0 || !(params.tolerance >= 0.0) ||
      !(params.overRelaxation >= 1.0 && params.overRelaxation < 2.0))
    return invalidInput(
        "geodesic Lloyd: iterations must be >= 0, descent steps >= 0, the tolerance >= 0 and the over-relaxation in "
        "[1, 2)");
  if (!metric.isUniform() && static_cast<int>(metric.P.size()) != mesh.vertexCount())
    return invalidInput("geodesic Lloyd: the metric does not have one value per vertex");
  if (&marcher.mesh() != &mesh) return invalidInput("geodesic Lloyd: the fast marcher is on another mesh");
  for (const SurfacePoint& s : seeds) {
    const bool vertexOk = s.vertex >= 0 && s.vertex < mesh.vertexCount();
    const bool faceOk = s.vertex < 0 && s.face >= 0 && s.face < mesh.faceCount();
    if (!vertexOk && !faceOk) return invalidInput("geodesic Lloyd: a seed is not on the mesh");
  }
  return Status::ok();
}

}  // namespace

std::vector<double> lloydVertexMass(const TriMesh& mesh, const Metric& metric, bool metricArea) {
  std::vector<double> mass(mesh.vertexCount(), 0.0);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const double third = areaNormal(mesh, f).norm() / 6.0;
    for (int v : mesh.triangles[f]) mass[v] += third;
  }
  if (metricArea && !metric.isUniform())
    for (int v = 0; v < mesh.vertexCount(); ++v) mass[v] *= metric.P[v] * metric.P[v];
  return mass;
}

Expected<LloydResult> geodesicLloyd(const TriMesh& mesh, const Metric& metric, FastMarcher& marcher,
                                    std::vector<SurfacePoint> seeds, const LloydParams& params, Progress progress) {
  if (Status s = checkLloydInput(mesh, metric, marcher, seeds, params); !s) return s;
  LloydRun run(mesh, metric, marcher, params);
  LloydResult result;
  Expected<double> energy = params.marcherHoldsSeedsField ? run.voronoiFromMarcher(seeds, &result.reseeded)
                                                          : run.voronoi(seeds, &result.reseeded);
  if (!energy) return energy.status();
  run.accept(seeds);
  result.energy.push_back(*energy);
  const int n = static_cast<int>(seeds.size());
  std::vector<char> fixed(n, 0);
  if (params.keepBoundarySeeds) {
    const std::vector<char> boundary = boundaryVertexFlags(mesh);
    for (int i = 0; i < n; ++i) fixed[i] = seeds[i].vertex >= 0 && boundary[seeds[i].vertex];
  }
  for (int it = 0; it < params.iterations; ++it) {
    std::vector<SurfacePoint> centres = seeds;
    for (int i = 0; i < n; ++i) {
      if (!progress.report((it + double(i) / n) / params.iterations, "Geodesic Lloyd")) return cancelled();
      if (fixed[i]) continue;
      if (Status s = run.descend(i, centres[i]); !s) return s;
    }
    std::vector<SurfacePoint> moved = centres;
    if (params.overRelaxation > 1.0)
      for (int i = 0; i < n; ++i)
        if (!fixed[i]) moved[i] = run.beyond(i, seeds[i], centres[i], params.overRelaxation);
    int reseeded = 0;
    Expected<double> next = run.voronoi(moved, &reseeded, true);
    if (!next) return next.status();
    const double previous = result.energy.back();
    if (*next > previous && params.overRelaxation > 1.0) {  // redone without over-relaxation
      moved = centres;
      reseeded = 0;
      next = run.voronoi(moved, &reseeded, true);
      if (!next) return next.status();
    }
    if (*next > previous) {  // undone: back to the last accepted seeds' cells
      Expected<double> back = run.voronoi(seeds, &result.reseeded, true);  // the marcher holds their field
      if (!back) return back.status();
      result.undone = true;
      break;
    }
    seeds = std::move(moved);
    run.accept(seeds);
    result.reseeded += reseeded;
    result.energy.push_back(*next);
    ++result.iterations;
    if (previous - *next < params.tolerance * previous) break;
  }
  if (params.vertexSeeds && moveSeedsToVertices(mesh, seeds)) {
    Expected<double> snapped = run.voronoi(seeds, &result.reseeded, true);
    if (!snapped) return snapped.status();
    result.energy.push_back(*snapped);
  }
  result.seeds = std::move(seeds);
  result.distance = run.distance();
  result.cell = run.cell();
  return result;
}

}  // namespace gr
