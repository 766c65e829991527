// Magnitude of the surface gradient of a per-vertex scalar (e.g. colour intensity), per vertex.
//
// Paper §3.3: a picture I mapped on the surface drives the speed F = 1 / (1 + mu |grad I|), which
// puts more vertices where the intensity varies fast. I is interpolated linearly in each face; its
// gradient there is constant and lies in the face's plane:
//
//          p0            grad I = (I0 e0 + I1 e1 + I2 e2) turned by 90° in the plane / (2A),
//         /  \   e1      where e_k is the edge facing p_k (counter-clockwise: e0 = p2 - p1,
//     e2 /    \  |       e1 = p0 - p2, e2 = p1 - p0) and A the area; its length is
//       /      \ |       |I0 e0 + I1 e1 + I2 e2| / (2A).
//     p1 ------ p2 .
//          e0
//
// A vertex gets the area-weighted mean of the gradient *lengths* of its faces. Averaging the
// lengths rather than the vectors keeps a one-vertex-wide line of the picture visible (the face
// gradients on its two sides point in opposite directions and would cancel at the line); for a
// smooth I both give |grad I| up to O(h) on curved surfaces.
// Preconditions: a TriMesh from buildTriMesh; one finite value per vertex. Zero-area faces have no
// gradient and are skipped; a vertex with no face of positive area gets 0.
// Cost: O(F). Units: the field's unit per mesh unit.
#pragma once

#include <vector>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

/// Intensity of a gamma-encoded RGB colour: the ITU-R BT.601 luma Y' = 0.299 R' + 0.587 G' +
/// 0.114 B' (the weights sum to 1, so the result has the channels' unit: 8-bit channels give
/// 0..255, channels in [0, 1] give [0, 1]). The same weights as JPEG and most "to grey" filters.
double rgbIntensity(double red, double green, double blue);

struct GradientResult {
  std::vector<double> magnitude;  ///< per vertex, area-weighted mean of |grad I| over its faces
  double maxMagnitude = 0.0;      ///< largest of `magnitude`
  int zeroAreaFaces = 0;          ///< faces skipped because their gradient is undefined
};

/// |grad field| per vertex. Fails (InvalidInput) on a mesh without vertices or faces, a field
/// whose size is not the vertex count, or a non-finite value (the message names the vertex).
Expected<GradientResult> gradientMagnitude(const TriMesh& mesh, const std::vector<double>& field);

}  // namespace gr
