#include "tests/support/segmentation_figures.h"

#include <Eigen/Geometry>
#include <algorithm>

#include <cmath>

#include "tests/support/test_support.h"

namespace gr::test {
namespace {

constexpr double kPi = 3.14159265358979323846;

double faceArea(const TriMesh& m, int f) {
  const Tri& t = m.triangles[f];
  return 0.5 * (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).norm();
}

/// Dihedral angle (degrees) between the two faces of corner c's edge.
double dihedralDegrees(const TriMesh& m, int c) {
  const auto normal = [&](int f) {
    const Tri& t = m.triangles[f];
    return Vec3((m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]).normalized());
  };
  const double cosine = std::clamp(normal(TriMesh::face(c)).dot(normal(TriMesh::face(m.oppositeCorner[c]))), -1.0, 1.0);
  return std::acos(cosine) * 180.0 / kPi;
}

double edgeLength(const TriMesh& m, int c) {
  return (m.positions[m.vertex(TriMesh::next(c))] - m.positions[m.vertex(TriMesh::prev(c))]).norm();
}

}  // namespace

SegmentationFigures segmentationFigures(const TriMesh& m, const std::vector<int>& region) {
  SegmentationFigures fig;
  fig.regions = region.empty() ? 0 : *std::max_element(region.begin(), region.end()) + 1;
  const int regions = fig.regions;
  std::vector<std::vector<Tri>> faces(regions);
  std::vector<double> area(regions, 0.0), perimeter(regions, 0.0);
  double boundary = 0.0, boundarySharp = 0.0, sharp = 0.0;
  for (int f = 0; f < m.faceCount(); ++f) {
    faces[region[f]].push_back(m.triangles[f]);
    area[region[f]] += faceArea(m, f);
    for (int c = 3 * f; c < 3 * f + 3; ++c) {
      const int o = m.oppositeCorner[c];
      const bool cut = o < 0 || region[TriMesh::face(o)] != region[f];
      const double len = edgeLength(m, c);
      if (cut) perimeter[region[f]] += len;
      if (o < 0 || o < c) continue;  // each interior edge once, from its larger corner
      const bool isSharp = dihedralDegrees(m, c) > 60.0;
      if (isSharp) sharp += len;
      if (cut) boundary += len;
      if (cut && isSharp) boundarySharp += len;
    }
  }
  double mean = 0.0, iq = 0.0;
  int used = 0;
  for (int r = 0; r < regions; ++r) {
    if (faces[r].empty()) {
      ++fig.empty;
      continue;
    }
    ++used;
    const Recount rc = recount(faces[r], m.vertexCount());
    // (Not rc.simpleBoundary: it reads the faces' orientation, which some inputs do not agree on.)
    const bool disk = rc.components == 1 && rc.eulerCharacteristic == 1 && rc.boundaryLoops == 1 &&
                      rc.manifoldVertices && rc.manifoldEdges;
    if (!disk) ++fig.nonDisks;
    mean += area[r];
    if (perimeter[r] > 0.0) iq += 4.0 * kPi * area[r] / (perimeter[r] * perimeter[r]);
  }
  if (used == 0) return fig;
  mean /= used;
  double var = 0.0;
  for (int r = 0; r < regions; ++r)
    if (!faces[r].empty()) var += (area[r] - mean) * (area[r] - mean);
  fig.areaCv = std::sqrt(var / used) / mean;
  fig.meanIsoperimetric = iq / used;
  fig.boundaryOnSharp = boundary > 0.0 ? boundarySharp / boundary : 0.0;
  fig.sharpCovered = sharp > 0.0 ? boundarySharp / sharp : 0.0;
  return fig;
}

}  // namespace gr::test
