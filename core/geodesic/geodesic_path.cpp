#include "core/geodesic/geodesic_path.h"

#include <cmath>
#include <limits>
#include <string>

namespace gr {
namespace {

/// Where a straight walk inside a face ends.
struct Exit {
  bool valid = false;
  Vec3 bary;        ///< exit point in the face's barycentric coordinates
  double u = 0.0;   ///< interpolated U there
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

}  // namespace

Expected<GeodesicPath> geodesicPath(const TriMesh& mesh, const std::vector<double>& U, const SurfacePoint& start,
                                    const GeodesicPathParams& params) {
  if (static_cast<int>(U.size()) != mesh.vertexCount())
    return invalidInput("the distance field has " + std::to_string(U.size()) + " values for " +
                        std::to_string(mesh.vertexCount()) + " vertices");
  if (start.vertex >= mesh.vertexCount() || (start.vertex < 0 && (start.face < 0 || start.face >= mesh.faceCount())))
    return invalidInput("the start point is not on the mesh");

  GeodesicPath path;
  auto append = [&](const Vec3& p, double u) {
    if (!path.points.empty()) path.length += (p - path.points.back()).norm();
    path.points.push_back(p);
    path.values.push_back(u);
  };

  // State: at a vertex (vertex >= 0), or at barycentric point `bary` of `face`.
  int vertex = start.vertex, face = start.face;
  Vec3 bary = start.bary;
  if (vertex >= 0) {
    if (!std::isfinite(U[vertex])) return invalidInput("the start vertex " + std::to_string(vertex) + " is not reached by the field");
    append(mesh.positions[vertex], U[vertex]);
  } else {
    const Tri& t = mesh.triangles[face];
    for (int v : t)
      if (!std::isfinite(U[v])) return invalidInput("the start face " + std::to_string(face) + " is not reached by the field");
    append(pointOf(mesh, face, bary), bary.dot(Vec3(U[t[0]], U[t[1]], U[t[2]])));
  }

  for (int step = 0; step < params.maxSteps; ++step) {
    if (vertex >= 0) {
      if (U[vertex] <= 0.0) {
        path.endVertex = vertex;
        return path;
      }
      // Leave through the face whose corner contains -grad U (lowest exit), else along an edge.
      Exit best;
      int bestFace = -1;
      for (const int* c = mesh.cornersBegin(vertex); c != mesh.cornersEnd(vertex); ++c) {
        Vec3 b = Vec3::Zero();
        b[*c % 3] = 1.0;
        const Exit e = walkFace(mesh, U, TriMesh::face(*c), b);
        if (e.valid && (bestFace < 0 || e.u < best.u)) {
          best = e;
          bestFace = TriMesh::face(*c);
        }
      }
      if (bestFace >= 0) {
        face = bestFace;
        bary = best.bary;
        vertex = -1;
        append(pointOf(mesh, face, bary), best.u);
      } else {
        int lowest = -1;
        for (const int* c = mesh.cornersBegin(vertex); c != mesh.cornersEnd(vertex); ++c)
          for (int w : {mesh.vertex(TriMesh::next(*c)), mesh.vertex(TriMesh::prev(*c))})
            if (U[w] < U[vertex] && (lowest < 0 || U[w] < U[lowest])) lowest = w;
        if (lowest < 0)
          return Status{StatusCode::NotConverged,
                        "the distance field has a local minimum at vertex " + std::to_string(vertex)};
        vertex = lowest;
        append(mesh.positions[vertex], U[vertex]);
      }
      continue;
    }

    // On the boundary of `face` (or inside it, at the start): where does the point lie?
    int zeros = 0, nonzero = -1;
    for (int k = 0; k < 3; ++k) {
      if (bary[k] <= 1e-12) ++zeros;
      else nonzero = k;
    }
    if (zeros == 2) {  // at a vertex
      vertex = mesh.triangles[face][nonzero];
      continue;
    }
    // Cross into the neighbouring face when on an edge, then walk.
    int walkFaceId = face;
    Vec3 walkBary = bary;
    if (zeros == 1) {
      int k = 0;
      while (bary[k] > 1e-12) ++k;
      const int opposite = mesh.oppositeCorner[3 * face + k];
      if (opposite >= 0) {
        const int g = TriMesh::face(opposite);
        walkFaceId = g;
        walkBary = Vec3::Zero();
        for (int j = 0; j < 3; ++j)
          if (j != k)
            for (int i = 0; i < 3; ++i)
              if (mesh.triangles[g][i] == mesh.triangles[face][j]) walkBary[i] = bary[j];
      }
    }
    Exit e = walkFace(mesh, U, walkFaceId, walkBary);
    int exitFace = walkFaceId;
    if (!e.valid && walkFaceId != face) {  // try the face we came from
      e = walkFace(mesh, U, face, bary);
      exitFace = face;
    }
    if (e.valid) {
      face = exitFace;
      bary = e.bary;
      append(pointOf(mesh, face, bary), e.u);
      continue;
    }
    // -grad U leaves both faces: slide along the edge (or face) to its lowest vertex.
    int lowest = -1;
    for (int k = 0; k < 3; ++k)
      if (bary[k] > 1e-12) {
        const int v = mesh.triangles[face][k];
        if (lowest < 0 || U[v] < U[lowest]) lowest = v;
      }
    vertex = lowest;
    append(mesh.positions[vertex], U[vertex]);
  }
  return Status{StatusCode::NotConverged, "the geodesic path did not reach a source in " +
                                              std::to_string(params.maxSteps) + " steps"};
}

}  // namespace gr
