#include "core/field/color_gradient.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/mesh/face_geometry.h"

namespace gr {

double rgbIntensity(double red, double green, double blue) { return 0.299 * red + 0.587 * green + 0.114 * blue; }

Expected<GradientResult> gradientMagnitude(const TriMesh& mesh, const std::vector<double>& field) {
  const int n = mesh.vertexCount();
  if (n == 0 || mesh.faceCount() == 0) return invalidInput("the mesh has no vertices or no faces");
  if (static_cast<int>(field.size()) != n)
    return invalidInput("the field has " + std::to_string(field.size()) + " values for " + std::to_string(n) +
                        " vertices");
  for (int v = 0; v < n; ++v)
    if (!std::isfinite(field[v])) return invalidInput("the field is not finite at vertex " + std::to_string(v));

  GradientResult result;
  std::vector<double> weightedSum(n, 0.0), areaSum(n, 0.0);
  for (const Tri& t : mesh.triangles) {
    const Vec3& p0 = mesh.positions[t[0]];
    const Vec3& p1 = mesh.positions[t[1]];
    const Vec3& p2 = mesh.positions[t[2]];
    const double twiceArea = areaNormal(mesh, t).norm();
    if (!(twiceArea > 0.0)) {
      ++result.zeroAreaFaces;
      continue;
    }
    // |grad I| * 2A = |I0 e0 + I1 e1 + I2 e2|, e_k the edge facing p_k; as e0 + e1 + e2 = 0 this is
    // |(I1 - I0) e1 + (I2 - I0) e2|: exactly 0 for a constant field. area * |grad I| = that / 2.
    const double i0 = field[t[0]];
    const Vec3 w = (field[t[1]] - i0) * (p0 - p2) + (field[t[2]] - i0) * (p1 - p0);
    const double areaTimesGradient = 0.5 * w.norm();
    const double area = 0.5 * twiceArea;
    for (int k = 0; k < 3; ++k) {
      weightedSum[t[k]] += areaTimesGradient;
      areaSum[t[k]] += area;
    }
  }
  result.magnitude.assign(n, 0.0);
  for (int v = 0; v < n; ++v) {
    if (areaSum[v] > 0.0) result.magnitude[v] = weightedSum[v] / areaSum[v];
    result.maxMagnitude = std::max(result.maxMagnitude, result.magnitude[v]);
  }
  return result;
}

}  // namespace gr
