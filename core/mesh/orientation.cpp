#include "core/mesh/orientation.h"

#include <string>
#include <utility>

namespace gr {

Expected<TriMesh> orientCoherently(const TriMesh& mesh, std::vector<char>* flipped) {
  if (mesh.topology.nonManifoldEdges > 0)
    return nonManifold("cannot orient a mesh with " + std::to_string(mesh.topology.nonManifoldEdges) +
                       " non-manifold edges");
  const int nf = mesh.faceCount();
  // flip[f]: -1 not visited, else whether f must be flipped relative to its component's first face.
  std::vector<signed char> flip(nf, -1);
  std::vector<int> queue, componentFaces;
  for (int root = 0; root < nf; ++root) {
    if (flip[root] >= 0) continue;
    flip[root] = 0;
    queue.assign(1, root);
    componentFaces.clear();
    for (size_t head = 0; head < queue.size(); ++head) {
      const int f = queue[head];
      componentFaces.push_back(f);
      for (int k = 0; k < 3; ++k) {
        const int c = 3 * f + k, o = mesh.oppositeCorner[c];
        if (o < 0) continue;
        const int g = TriMesh::face(o);
        // Agreeing faces run the shared edge in opposite directions; `same` faces must differ in flip.
        const bool same = mesh.vertex(TriMesh::next(c)) == mesh.vertex(TriMesh::next(o));
        const signed char want = static_cast<signed char>(flip[f] ^ (same ? 1 : 0));
        if (flip[g] < 0) {
          flip[g] = want;
          queue.push_back(g);
        } else if (flip[g] != want) {
          return invalidInput(
              "the surface is not orientable (a Moebius strip or a Klein bottle): no oriented mesh of it "
              "exists");
        }
      }
    }
    // Keep the orientation of the majority of the component's faces.
    size_t flips = 0;
    for (int f : componentFaces) flips += flip[f];
    if (2 * flips > componentFaces.size())
      for (int f : componentFaces) flip[f] ^= 1;
  }
  std::vector<Tri> triangles = mesh.triangles;
  for (int f = 0; f < nf; ++f)
    if (flip[f]) std::swap(triangles[f][1], triangles[f][2]);
  if (flipped) flipped->assign(flip.begin(), flip.end());
  return buildTriMesh(mesh.positions, std::move(triangles));
}

}  // namespace gr
