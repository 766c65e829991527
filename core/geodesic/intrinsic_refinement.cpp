#include "core/geodesic/intrinsic_refinement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <queue>
#include <string>
#include <utility>

#include "core/base/math.h"
#include "core/geodesic/intrinsic_triangulation.h"
#include "core/mesh/orientation.h"

namespace gr {
namespace {

/// A vertex whose angle sum is below this is a needle tip: its faces are left alone.
constexpr double kNeedleAngleSum = kPi / 3.0;
/// A face whose circumradius is below this times the input's mean edge length is left alone.
constexpr double kTinyCircumradius = 1e-5;
/// A circumcentre this close to an edge (barycentric coordinate) is inserted on the edge.
constexpr double kOnEdge = 1e-9;
/// Full rescans for faces the queue missed (rounding) before giving up.
constexpr int kRescans = 5;
/// Faces looked through for boundary edges a new point would encroach.
constexpr size_t kCavityFaces = 64;
/// Rounds of splits that make the output simplicial.
constexpr int kSimplicialRounds = 20;
/// With a length bound L, the default budget also has this many points per equilateral triangle
/// of side L that the surface's area holds (a Delaunay refinement under a length bound inserts
/// about one: star.off at 2% of its diagonal 2,320 points for 2,285 such triangles).
constexpr double kPointsPerBoundTriangle = 2.0;

Status checkInput(const TriMesh& input, const IntrinsicRefinementParams& p) {
  if (input.faceCount() == 0) return invalidInput("intrinsic Delaunay refinement: the mesh has no faces");
  if (!input.topology.isManifold())
    return nonManifold("intrinsic Delaunay refinement needs a manifold mesh; this one has " +
                       input.topology.nonManifoldCounts());
  if (!(p.minAngleDegrees >= 0.0 && p.minAngleDegrees < 60.0))
    return invalidInput("intrinsic Delaunay refinement: minAngleDegrees is " + std::to_string(p.minAngleDegrees) +
                        ", it must be in [0, 60)");
  if (!(p.maxEdgeLength > 0.0))
    return invalidInput("intrinsic Delaunay refinement: maxEdgeLength is " + std::to_string(p.maxEdgeLength) +
                        ", it must be > 0 (+inf for no bound)");
  if (p.maxInsertions < -1)
    return invalidInput("intrinsic Delaunay refinement: maxInsertions is " + std::to_string(p.maxInsertions) +
                        ", it must be >= 0 (or -1 for the default budget)");
  return Status::ok();
}

/// Circumcentre of a triangle laid out in the plane.
Vec2 circumcentre(const std::array<Vec2, 3>& p) {
  const Vec2 b = p[1] - p[0], c = p[2] - p[0];
  const double d = 2.0 * cross2(b, c);
  const Vec2 u((c.y() * b.squaredNorm() - b.y() * c.squaredNorm()) / d,
               (b.x() * c.squaredNorm() - c.x() * b.squaredNorm()) / d);
  return p[0] + u;
}

bool inCircumdisk(const std::array<Vec2, 3>& p, const Vec2& q) {
  const Vec2 c = circumcentre(p);
  const double r = (p[0] - c).norm();
  return std::isfinite(r) && (q - c).norm() < r * (1.0 - 1e-12);
}

/// Ruppert's test before inserting the point q of face f (in f's layout): the faces whose
/// circumdisk holds q (the cavity the Delaunay flips will empty, grown from f across edges and
/// unfolded into f's frame) are looked through for a boundary edge that q sees at more than 90
/// degrees (q in its diametral disk). Returns that boundary halfedge, or -1.
int encroachedBoundaryEdge(const SignpostMesh& m, int f, const Vec2& q) {
  struct Laid {
    int face;
    std::array<Vec2, 3> p;
  };
  std::vector<Laid> work = {{f, m.layout(f)}};
  std::vector<int> seen = {f};
  while (!work.empty() && seen.size() < kCavityFaces) {
    const Laid here = work.back();
    work.pop_back();
    for (int k = 0; k < 3; ++k) {
      const int h = 3 * here.face + k, twin = m.he[h].twin;
      const Vec2 &a = here.p[k], &b = here.p[(k + 1) % 3];
      if (twin < 0) {
        if ((a - q).dot(b - q) < 0.0) return h;
        continue;
      }
      const int g = SignpostMesh::face(twin), j = twin % 3;
      if (std::find(seen.begin(), seen.end(), g) != seen.end()) continue;
      Laid next{g, {}};  // the twin runs b -> a; its face's third vertex is unfolded across
      next.p[j] = b;
      next.p[(j + 1) % 3] = a;
      next.p[(j + 2) % 3] =
          unfold(a, b, here.p[(k + 2) % 3], m.length(SignpostMesh::next(twin)), m.length(SignpostMesh::prev(twin)));
      if (!inCircumdisk(next.p, q)) continue;
      seen.push_back(g);
      work.push_back(next);
    }
  }
  return -1;
}

/// The default budget (IntrinsicRefinementParams::maxInsertions = -1): 10 V + 1000 points, plus,
/// under a length bound L, kPointsPerBoundTriangle per equilateral triangle of side L in the
/// surface's area (a small mesh of a large surface needs more points than its vertex count says).
int defaultBudget(const IntrinsicTriangulation& tri, double maxLength) {
  double budget = 10.0 * tri.inputVertexCount() + 1000.0;
  if (std::isfinite(maxLength)) {
    const SignpostMesh& m = tri.mesh();
    double area = 0.0;
    for (int f = 0; f < m.faceCount(); ++f) {
      const std::array<Vec2, 3> p = m.layout(f);
      area += 0.5 * std::abs(cross2(p[1] - p[0], p[2] - p[0]));
    }
    budget += kPointsPerBoundTriangle * area / (0.25 * std::sqrt(3.0) * maxLength * maxLength);
  }
  return static_cast<int>(std::min(budget, 0.5 * std::numeric_limits<int>::max()));
}

/// The refinement loop: a priority queue of faces to refine, largest first (boundary faces before
/// all others), stamped so that entries of faces changed since they were queued are skipped.
class Refiner {
 public:
  Refiner(IntrinsicTriangulation& tri, const IntrinsicRefinementParams& params, double meanEdge, Progress& progress)
      : tri_(tri), progress_(progress) {
    minAngle_ = params.minAngleDegrees * kPi / 180.0;
    minTanHalfSquared_ = std::tan(0.5 * minAngle_) * std::tan(0.5 * minAngle_);
    maxLength_ = params.maxEdgeLength;
    tinyRadius_ = kTinyCircumradius * meanEdge;
    budget_ = params.maxInsertions >= 0 ? params.maxInsertions : defaultBudget(tri, maxLength_);
  }

  /// Refines until no face needs it or the budget is spent (flips refusing to make the
  /// triangulation non-simplicial once keepSimplicial() was called); can be called again.
  Status run();
  void keepSimplicial() { keepSimplicial_ = true; }
  bool budgetExhausted() const { return exhausted_; }

 private:
  struct Entry {
    double key;
    int face;
    int stamp;
    bool operator<(const Entry& o) const { return key < o.key; }
  };
  bool needsRefinement(int f) const;
  /// Inserts the circumcentre of f, or splits the boundary edge in its way; false if it failed.
  bool refineFace(int f);
  bool insertAt(const TraceResult& r);
  /// Stamps the faces changed since the last call and queues those to refine.
  void absorbChanges();
  void consider(int f);
  bool rescan();
  double circumradius(int f) const;

  IntrinsicTriangulation& tri_;
  Progress& progress_;
  double minAngle_ = 0.0, maxLength_ = kUnbounded, tinyRadius_ = 0.0;
  double minTanHalfSquared_ = 0.0;  ///< tan^2(minAngle_ / 2): the same test as the angle, cheaper
  int budget_ = 0, insertions_ = 0;
  bool keepSimplicial_ = false, exhausted_ = false;
  std::priority_queue<Entry> queue_;
  std::vector<int> stamp_, failedStamp_;
};

double Refiner::circumradius(int f) const {
  const SignpostMesh& m = tri_.mesh();
  const double a = m.length(3 * f), b = m.length(3 * f + 1), c = m.length(3 * f + 2);
  const std::array<Vec2, 3> p = m.layout(f);
  const double twiceArea = cross2(p[1] - p[0], p[2] - p[0]);
  return twiceArea > 0.0 ? a * b * c / (2.0 * twiceArea) : kUnbounded;
}

bool Refiner::needsRefinement(int f) const {
  const SignpostMesh& m = tri_.mesh();
  bool tooLong = false, smallAngle = false, needle = false;
  for (int k = 0; k < 3; ++k) {
    const int h = 3 * f + k;
    tooLong = tooLong || m.length(h) > maxLength_;
    const SignpostVertex& v = m.vert[m.tail(h)];
    if (v.angleSum < kNeedleAngleSum) needle = true;
    // A corner whose two sides are one edge (a vertex of degree one) cannot be split either.
    const bool loopCorner = m.he[h].twin == SignpostMesh::prev(h);
    if (!loopCorner && m.cornerTanHalfSquared(h) < minTanHalfSquared_) smallAngle = true;
  }
  if (!tooLong && (!smallAngle || needle)) return false;
  return circumradius(f) >= tinyRadius_;
}

void Refiner::consider(int f) {
  if (!needsRefinement(f)) return;
  const SignpostMesh& m = tri_.mesh();
  bool boundary = false;
  for (int k = 0; k < 3; ++k) boundary = boundary || m.he[3 * f + k].twin < 0;
  const std::array<Vec2, 3> p = m.layout(f);
  const double area = 0.5 * cross2(p[1] - p[0], p[2] - p[0]);
  queue_.push({boundary ? kUnbounded : area, f, stamp_[f]});
}

void Refiner::absorbChanges() {
  std::vector<int> changed = tri_.takeChangedFaces();
  const size_t faces = tri_.mesh().tri.size();
  stamp_.resize(faces, 0);
  failedStamp_.resize(faces, -1);
  for (int f : changed) ++stamp_[f];
  std::sort(changed.begin(), changed.end());
  changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
  for (int f : changed) consider(f);
}

bool Refiner::insertAt(const TraceResult& r) {
  const SignpostMesh& m = tri_.mesh();
  if (r.stop == TraceStop::Boundary) return tri_.splitEdge(r.halfedge, 0.5) >= 0;
  if (r.stop != TraceStop::Reached) return false;
  // Ruppert: a point in the diametral disk of a boundary edge it would join splits that edge.
  const std::array<Vec2, 3> p = m.layout(r.face);
  const Vec2 q = r.bary[0] * p[0] + r.bary[1] * p[1] + r.bary[2] * p[2];
  if (const int h = encroachedBoundaryEdge(m, r.face, q); h >= 0) return tri_.splitEdge(h, 0.5) >= 0;
  int i = 0;
  r.bary.minCoeff(&i);
  if (r.bary[i] < kOnEdge) {  // on the edge facing vertex i: from vertex i+1 to vertex i+2
    const int h = 3 * r.face + (i + 1) % 3;
    const double t = r.bary[(i + 2) % 3] / (r.bary[(i + 1) % 3] + r.bary[(i + 2) % 3]);
    return tri_.splitEdge(h, m.he[h].twin < 0 ? 0.5 : t) >= 0;
  }
  return tri_.insertVertex(r.face, r.bary) >= 0;
}

bool Refiner::refineFace(int f) {
  const SignpostMesh& m = tri_.mesh();
  const std::array<Vec2, 3> p = m.layout(f);
  const Vec2 centroid = (p[0] + p[1] + p[2]) / 3.0;
  const Vec2 toCentre = circumcentre(p) - centroid;
  const double length = toCentre.norm();
  if (!std::isfinite(length)) return false;
  TraceOptions options;
  options.throughVertices = false;
  options.maxFaces = 4 * m.faceCount() + 64;
  const Vec2 direction = length > 0.0 ? Vec2(toCentre / length) : Vec2(1.0, 0.0);
  const TraceResult r = traceFromFacePoint(m, f, Vec3::Constant(1.0 / 3.0), direction, length, options);
  return insertAt(r);
}

bool Refiner::rescan() {
  bool any = false;
  for (int f = 0; f < tri_.mesh().faceCount(); ++f)
    if (failedStamp_[f] != stamp_[f] && needsRefinement(f)) {
      consider(f);
      any = true;
    }
  return any;
}

Status Refiner::run() {
  tri_.flipToDelaunay(keepSimplicial_);
  absorbChanges();
  for (int rescans = 0; rescans <= kRescans && insertions_ < budget_; ++rescans) {
    while (!queue_.empty() && insertions_ < budget_) {
      const Entry e = queue_.top();
      queue_.pop();
      if (e.stamp != stamp_[e.face] || failedStamp_[e.face] == e.stamp || !needsRefinement(e.face)) continue;
      if (!refineFace(e.face)) {
        failedStamp_[e.face] = e.stamp;
        continue;
      }
      ++insertions_;
      tri_.flipToDelaunay(keepSimplicial_);
      absorbChanges();
      if (!progress_.report(static_cast<double>(insertions_) / budget_, "intrinsic Delaunay refinement"))
        return cancelled();
    }
    if (insertions_ >= budget_ || !rescan()) break;
  }
  exhausted_ = insertions_ >= budget_ && rescan();
  return Status::ok();
}

/// Splits the edges that keep the triangulation from being simplicial and flips back to Delaunay
/// without recreating such edges, until there is none (at most kSimplicialRounds rounds); false
/// if some are left. Edges whose flip would recreate one stay as they are, not Delaunay (near
/// sharp cones, where the intrinsic Delaunay triangulation is not simplicial).
bool makeSimplicial(IntrinsicTriangulation& tri) {
  for (int round = 0; round < kSimplicialRounds; ++round) {
    tri.queueAllEdges();  // flips refused in the last round may be possible after its splits
    tri.flipToDelaunay(true);
    const std::vector<int> edges = tri.nonSimplicialEdges();
    if (edges.empty()) return true;
    for (int h : edges)  // earlier splits renumber halfedges: check again before each split
      if (h < static_cast<int>(tri.mesh().he.size()) && tri.isNonSimplicial(h) && tri.splitEdge(h, 0.5) < 0)
        tri.splitEdge(h, 0.4);
  }
  tri.queueAllEdges();
  tri.flipToDelaunay(true);
  return tri.nonSimplicialEdges().empty();
}

/// The smallest corner angle of the intrinsic triangles and the faces with one below `bound`.
std::pair<double, int> angleFigures(const SignpostMesh& m, double bound) {
  double smallest = kPi;
  int below = 0;
  for (int f = 0; f < m.faceCount(); ++f) {
    const double a = std::min({m.cornerAngle(3 * f), m.cornerAngle(3 * f + 1), m.cornerAngle(3 * f + 2)});
    smallest = std::min(smallest, a);
    if (a < bound) ++below;
  }
  return {smallest, below};
}

bool sameTopology(const Topology& a, const Topology& b) {
  return a.components == b.components && a.genus == b.genus && a.boundaryLoops == b.boundaryLoops &&
         a.eulerCharacteristic == b.eulerCharacteristic && a.isManifold() == b.isManifold() &&
         a.isolatedVertices == b.isolatedVertices;
}

/// The TriMesh, lengths and origins of the intrinsic triangulation of `oriented` (the input with
/// the faces in `flipped` turned); origins are given in the input's own corner order.
Expected<RefinedSurface> buildOutput(const IntrinsicTriangulation& tri, const TriMesh& input, const TriMesh& oriented,
                                     const std::vector<char>& flipped) {
  const SignpostMesh& m = tri.mesh();
  RefinedSurface out;
  out.origin = tri.origin();
  std::vector<Vec3> positions(m.vertexCount());
  for (int v = 0; v < m.vertexCount(); ++v) {
    positions[v] = out.origin[v].position(oriented);
    SurfacePoint& o = out.origin[v];
    if (o.vertex < 0 && !flipped.empty() && flipped[o.face]) std::swap(o.bary[1], o.bary[2]);
  }
  Expected<TriMesh> mesh = buildTriMesh(std::move(positions), m.tri);
  if (!mesh)
    return internalError("intrinsic Delaunay refinement: the output is no mesh (" + mesh.status().message + ")");
  if (!sameTopology(mesh->topology, input.topology))
    return internalError("intrinsic Delaunay refinement changed the topology: " +
                         std::to_string(mesh->topology.components) + " components, genus " +
                         std::to_string(mesh->topology.genus) + ", " + std::to_string(mesh->topology.boundaryLoops) +
                         " boundary loops instead of " + std::to_string(input.topology.components) + ", " +
                         std::to_string(input.topology.genus) + ", " + std::to_string(input.topology.boundaryLoops));
  out.mesh = std::move(mesh.value());
  out.cornerLength.resize(3 * m.faceCount());
  for (int c = 0; c < 3 * m.faceCount(); ++c) out.cornerLength[c] = m.length(SignpostMesh::next(c));
  out.inputVertexCount = tri.inputVertexCount();
  out.insertedPoints = m.vertexCount() - tri.inputVertexCount();
  out.mollification = tri.mollification();
  out.flips = tri.flipCount();
  return out;
}

}  // namespace

Expected<RefinedSurface> refineIntrinsicDelaunay(const TriMesh& input, const IntrinsicRefinementParams& params,
                                                 Progress progress) {
  if (Status s = checkInput(input, params); !s) return s;
  const TriMesh* oriented = &input;
  TriMesh turned;
  std::vector<char> flipped;
  if (input.topology.inconsistentEdges > 0) {
    Expected<TriMesh> o = orientCoherently(input, &flipped);
    if (!o) return o.status();
    turned = std::move(o.value());
    oriented = &turned;
  }
  IntrinsicTriangulation tri(*oriented);
  Refiner refiner(tri, params, input.meanEdgeLength(), progress);
  if (params.flipOnly) tri.flipToDelaunay();
  // Refine; make simplicial (splits may leave small angles); refine again without undoing that.
  for (int pass = 0; pass < 2; ++pass) {
    if (!params.flipOnly)
      if (Status s = refiner.run(); !s) return s;
    const int before = tri.mesh().vertexCount();
    if (!makeSimplicial(tri))
      return internalError("intrinsic Delaunay refinement: " + std::to_string(tri.nonSimplicialEdges().size()) +
                           " edges still join a vertex to itself or repeat another edge after " +
                           std::to_string(kSimplicialRounds) + " rounds of splits");
    if (tri.mesh().vertexCount() == before) break;  // nothing was split: nothing to refine again
    refiner.keepSimplicial();
  }
  Expected<RefinedSurface> out = buildOutput(tri, input, *oriented, flipped);
  if (!out) return out;
  const auto [smallest, below] = angleFigures(tri.mesh(), params.minAngleDegrees * kPi / 180.0);
  out->smallestAngleDegrees = smallest * 180.0 / kPi;
  out->facesBelowMinAngle = below;
  out->budgetExhausted = refiner.budgetExhausted();
  return out;
}

}  // namespace gr
