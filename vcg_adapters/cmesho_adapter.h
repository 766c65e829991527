// MeshLab's CMeshO to and from the core: selection as sources, quality as a field,
// distances and labels written back as quality and colour. No geometry here.
//
// toCore() skips deleted elements and keeps the index map, so every per-vertex array the core
// returns (indexed by core vertex) can be written back to the right CMeshO vertex.
#pragma once

#include <common/ml_mesh_type.h>

#include <vector>

#include "core/base/status.h"
#include "core/mesh/surface_point.h"
#include "core/mesh/tri_mesh.h"
#include "core/mesh/vcg_convert.h"

namespace gr::adapters {

/// The core's view of a CMeshO: the compact mesh plus the index map back to it.
struct CoreView {
  TriMesh mesh;
  VcgIndexMap map;
};

/// Builds the core mesh (fails on no faces, NaN coordinates, faces repeating a vertex).
Expected<CoreView> toCore(const CMeshO& m);

/// Core indices of the selected (non-deleted) vertices, in vertex order.
std::vector<int> selectedVertices(const CMeshO& m, const CoreView& view);

/// Per-vertex quality, per core vertex.
std::vector<double> vertexQuality(const CMeshO& m, const CoreView& view);

/// Per-vertex colour intensity (BT.601 luma of the 8-bit RGB, 0..255), per core vertex.
std::vector<double> vertexColorIntensity(const CMeshO& m, const CoreView& view);

/// Writes one value per core vertex into vertex quality; non-finite values become `missing`.
void writeVertexQuality(CMeshO& m, const CoreView& view, const std::vector<double>& values, double missing);

/// Colours vertices by a red-to-blue ramp over [lo, hi]; vertices with a non-finite value get
/// `missingColor`.
void colorByRamp(CMeshO& m, const CoreView& view, const std::vector<double>& values, double lo, double hi,
                 vcg::Color4b missingColor = vcg::Color4b::LightGray);

/// Colours vertices by label (distinct colours for labels 0..labelCount-1); label -1 gets
/// `missingColor`.
void colorByLabel(CMeshO& m, const CoreView& view, const std::vector<int>& labels, int labelCount,
                  vcg::Color4b missingColor = vcg::Color4b::LightGray);

/// Fills `out` (cleared first) with a core mesh; vertex i of `mesh` becomes vertex i of `out`.
/// Colour and quality of output vertex i are interpolated on `in` at originOf[i], a point of the
/// input's core mesh (`view`), when copyColor / copyQuality are set.
void writeMesh(const TriMesh& mesh, CMeshO& out, const CMeshO& in, const CoreView& view,
               const std::vector<SurfacePoint>& originOf, bool copyColor, bool copyQuality);

}  // namespace gr::adapters
