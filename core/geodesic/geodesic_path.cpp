#include "core/geodesic/geodesic_path.h"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace gr {
namespace {

/// Where a straight walk inside a face ends.
struct Exit {
  bool valid = false;
  Vec3 bary;       ///< exit point in the face's barycentric coordinates
  double u = 0.0;  ///< interpolated U there
};

/// Barycentric change per unit step along -grad U in face f, or false for a degenerate face.
bool descentInBary(const TriMesh& m, const std::vector<double>& U, int f, Vec3& db) {
  const Tri& t = m.triangles[f];
  const Vec3 e1 = m.positions[t[1]] - m.positions[t[0]], e2 = m.positions[t[2]] - m.positions[t[0]];
  const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2);
  const double det = a11 * a22 - a12 * a12;
  if (!(det > 1e-14 * a11 * a22)) return false;
  const double r1 = U[t[1]] - U[t[0]], r2 = U[t[2]] - U[t[0]];
  // grad = alpha e1 + beta e2 with grad.e1 = r1, grad.e2 = r2; the descent is -grad, and a
  // displacement alpha e1 + beta e2 changes the barycentric coordinates by (-alpha-beta, alpha, beta).
  const double alpha = -(r1 * a22 - r2 * a12) / det, beta = -(r2 * a11 - r1 * a12) / det;
  db = Vec3(-alpha - beta, alpha, beta);
  return std::isfinite(alpha) && std::isfinite(beta);
}

/// Walks from barycentric point b of face f along -grad U to the face's boundary.
Exit walkFace(const TriMesh& m, const std::vector<double>& U, int f, const Vec3& b) {
  Exit e;
  Vec3 db;
  if (!descentInBary(m, U, f, db)) return e;
  double t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k)
    if (db[k] < 0.0) t = std::min(t, b[k] / -db[k]);
  if (!std::isfinite(t) || t <= 1e-12) return e;  // -grad U points out of the face here
  e.bary = (b + t * db).cwiseMax(0.0);
  e.bary /= e.bary.sum();
  const Tri& tri = m.triangles[f];
  e.u = e.bary[0] * U[tri[0]] + e.bary[1] * U[tri[1]] + e.bary[2] * U[tri[2]];
  e.valid = e.u < b.dot(Vec3(U[tri[0]], U[tri[1]], U[tri[2]]));  // strictly downhill
  return e;
}

Vec3 pointOf(const TriMesh& m, int f, const Vec3& b) {
  const Tri& t = m.triangles[f];
  return b[0] * m.positions[t[0]] + b[1] * m.positions[t[1]] + b[2] * m.positions[t[2]];
}

/// The checks of geodesicPath's input: one U per vertex, a start on the mesh.
Status checkPathInput(const TriMesh& mesh, const std::vector<double>& U, const SurfacePoint& start) {
  if (static_cast<int>(U.size()) != mesh.vertexCount())
    return invalidInput("the distance field has " + std::to_string(U.size()) + " values for " +
                        std::to_string(mesh.vertexCount()) + " vertices");
  if (start.vertex >= mesh.vertexCount() || (start.vertex < 0 && (start.face < 0 || start.face >= mesh.faceCount())))
    return invalidInput("the start point is not on the mesh");
  return Status::ok();
}

/// The descent on U from a start point: its state, at a vertex (vertex_ >= 0) or at barycentric
/// point bary_ of face_, and the path so far. Each step moves the state and appends the point.
class Descent {
 public:
  Descent(const TriMesh& mesh, const std::vector<double>& U) : mesh_(mesh), U_(U) {}

  /// Places the descent at `start` (on the mesh) and appends it; InvalidInput if U is not finite there.
  Status begin(const SurfacePoint& start);
  bool atVertex() const { return vertex_ >= 0; }
  /// At a vertex with U <= 0: the path has reached a source.
  bool atSource() const { return U_[vertex_] <= 0.0; }
  /// One step from the current vertex (not a source); false when U has a local minimum there.
  bool stepFromVertex();
  /// One step from the current point in a face (on its boundary, or inside it at the start).
  void stepFromFace();
  /// The path, ending at the current vertex.
  GeodesicPath finish() {
    path_.endVertex = vertex_;
    return std::move(path_);
  }
  int vertex() const { return vertex_; }

 private:
  void append(const Vec3& p, double u) {
    if (!path_.points.empty()) path_.length += (p - path_.points.back()).norm();
    path_.points.push_back(p);
    path_.values.push_back(u);
  }
  /// Leaves the vertex through the face whose corner contains -grad U (lowest exit); false if none does.
  bool leaveThroughFace();
  /// Steps along an edge to the lowest neighbour below the vertex; false if there is none.
  bool stepToLowestNeighbour();
  /// Where the walk from a point on an edge starts: the same point in the face across the edge
  /// (unchanged at a boundary edge, or inside the face).
  void crossEdge(int& walkFaceId, Vec3& walkBary) const;
  /// Slides to the lowest vertex of the edge (or face) the point lies on.
  void slideToLowestVertex();

  const TriMesh& mesh_;
  const std::vector<double>& U_;
  GeodesicPath path_;
  int vertex_ = -1, face_ = -1;
  Vec3 bary_;
};

Status Descent::begin(const SurfacePoint& start) {
  vertex_ = start.vertex;
  face_ = start.face;
  bary_ = start.bary;
  if (vertex_ >= 0) {
    if (!std::isfinite(U_[vertex_]))
      return invalidInput("the start vertex " + std::to_string(vertex_) + " is not reached by the field");
    append(mesh_.positions[vertex_], U_[vertex_]);
  } else {
    const Tri& t = mesh_.triangles[face_];
    for (int v : t)
      if (!std::isfinite(U_[v]))
        return invalidInput("the start face " + std::to_string(face_) + " is not reached by the field");
    append(pointOf(mesh_, face_, bary_), bary_.dot(Vec3(U_[t[0]], U_[t[1]], U_[t[2]])));
  }
  return Status::ok();
}

bool Descent::stepFromVertex() { return leaveThroughFace() || stepToLowestNeighbour(); }

bool Descent::leaveThroughFace() {
  Exit best;
  int bestFace = -1;
  for (const int* c = mesh_.cornersBegin(vertex_); c != mesh_.cornersEnd(vertex_); ++c) {
    Vec3 b = Vec3::Zero();
    b[*c % 3] = 1.0;
    const Exit e = walkFace(mesh_, U_, TriMesh::face(*c), b);
    if (e.valid && (bestFace < 0 || e.u < best.u)) {
      best = e;
      bestFace = TriMesh::face(*c);
    }
  }
  if (bestFace < 0) return false;
  face_ = bestFace;
  bary_ = best.bary;
  vertex_ = -1;
  append(pointOf(mesh_, face_, bary_), best.u);
  return true;
}

bool Descent::stepToLowestNeighbour() {
  int lowest = -1;
  for (const int* c = mesh_.cornersBegin(vertex_); c != mesh_.cornersEnd(vertex_); ++c)
    for (int w : {mesh_.vertex(TriMesh::next(*c)), mesh_.vertex(TriMesh::prev(*c))})
      if (U_[w] < U_[vertex_] && (lowest < 0 || U_[w] < U_[lowest])) lowest = w;
  if (lowest < 0) return false;
  vertex_ = lowest;
  append(mesh_.positions[vertex_], U_[vertex_]);
  return true;
}

void Descent::stepFromFace() {
  // On the boundary of `face_` (or inside it, at the start): where does the point lie?
  int zeros = 0, nonzero = -1;
  for (int k = 0; k < 3; ++k) {
    if (bary_[k] <= 1e-12)
      ++zeros;
    else
      nonzero = k;
  }
  if (zeros == 2) {  // at a vertex
    vertex_ = mesh_.triangles[face_][nonzero];
    return;
  }
  // Cross into the neighbouring face when on an edge, then walk.
  int walkFaceId = face_;
  Vec3 walkBary = bary_;
  if (zeros == 1) crossEdge(walkFaceId, walkBary);
  Exit e = walkFace(mesh_, U_, walkFaceId, walkBary);
  int exitFace = walkFaceId;
  if (!e.valid && walkFaceId != face_) {  // try the face we came from
    e = walkFace(mesh_, U_, face_, bary_);
    exitFace = face_;
  }
  if (e.valid) {
    face_ = exitFace;
    bary_ = e.bary;
    append(pointOf(mesh_, face_, bary_), e.u);
    return;
  }
  slideToLowestVertex();  // -grad U leaves both faces
}

void Descent::crossEdge(int& walkFaceId, Vec3& walkBary) const {
  int k = 0;
  while (bary_[k] > 1e-12) ++k;
  const int opposite = mesh_.oppositeCorner[3 * face_ + k];
  if (opposite >= 0) {
    const int g = TriMesh::face(opposite);
    walkFaceId = g;
    walkBary = Vec3::Zero();
    for (int j = 0; j < 3; ++j)
      if (j != k)
        for (int i = 0; i < 3; ++i)
          if (mesh_.triangles[g][i] == mesh_.triangles[face_][j]) walkBary[i] = bary_[j];
  }
}

void Descent::slideToLowestVertex() {
  int lowest = -1;
  for (int k = 0; k < 3; ++k)
    if (bary_[k] > 1e-12) {
      const int v = mesh_.triangles[face_][k];
      if (lowest < 0 || U_[v] < U_[lowest]) lowest = v;
    }
  vertex_ = lowest;
  append(mesh_.positions[vertex_], U_[vertex_]);
}

}  // namespace

Expected<GeodesicPath> geodesicPath(const TriMesh& mesh, const std::vector<double>& U, const SurfacePoint& start,
                                    const GeodesicPathParams& params) {
  if (Status s = checkPathInput(mesh, U, start); !s) return s;
  Descent descent(mesh, U);
  if (Status s = descent.begin(start); !s) return s;
  for (int step = 0; step < params.maxSteps; ++step) {
    if (!descent.atVertex()) {
      descent.stepFromFace();
      continue;
    }
    if (descent.atSource()) return descent.finish();
    if (!descent.stepFromVertex())
      return Status{StatusCode::NotConverged,
                    "the distance field has a local minimum at vertex " + std::to_string(descent.vertex())};
  }
  return Status{StatusCode::NotConverged,
                "the geodesic path did not reach a source in " + std::to_string(params.maxSteps) + " steps"};
}

}  // namespace gr
