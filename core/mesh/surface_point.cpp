#include "core/mesh/surface_point.h"

namespace gr {

Vec3 SurfacePoint::position(const TriMesh& mesh) const { return interpolate(mesh, *this, mesh.positions); }

}  // namespace gr
