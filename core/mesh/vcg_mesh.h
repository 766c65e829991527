// CoreMesh: the core's vcglib mesh type, and file I/O through vcglib (OFF, PLY, OBJ, STL).
//
// The core loads, checks and writes meshes with vcglib; algorithms then run on the TriMesh
// built by toTriMesh(). Per-vertex quality and colour are kept so test and benchmark code can
// read the output of MeshLab (a PLY with quality) with the same code.
#pragma once

#include <string>

#include <vcg/complex/complex.h>

#include "core/base/status.h"
#include "core/mesh/tri_mesh.h"

namespace gr {

class CoreVertex;
class CoreFace;
struct CoreUsedTypes : public vcg::UsedTypes<vcg::Use<CoreVertex>::AsVertexType, vcg::Use<CoreFace>::AsFaceType> {};
class CoreVertex : public vcg::Vertex<CoreUsedTypes, vcg::vertex::Coord3d, vcg::vertex::Normal3d, vcg::vertex::Qualityd,
                                      vcg::vertex::Color4b, vcg::vertex::BitFlags> {};
class CoreFace : public vcg::Face<CoreUsedTypes, vcg::face::VertexRef, vcg::face::Normal3d, vcg::face::BitFlags> {};
class CoreMesh : public vcg::tri::TriMesh<std::vector<CoreVertex>, std::vector<CoreFace>> {};

/// What a file held besides geometry (vcglib's io mask bits, decoded).
struct LoadedAttributes {
  bool vertexQuality = false;
  bool vertexColor = false;
};

/// Loads a mesh file into `m` (cleared first). InvalidInput with vcglib's message on failure.
Status loadMesh(const std::string& path, CoreMesh& m, LoadedAttributes* attributes = nullptr);
/// Saves `m`; quality and colour are written when asked (PLY keeps both).
Status saveMesh(const CoreMesh& m, const std::string& path, bool withQuality = false, bool withColor = false);
/// Loads a file straight into a TriMesh.
Expected<TriMesh> loadTriMesh(const std::string& path);
/// Copies a TriMesh into `m` (cleared first), with per-face normals.
void toCoreMesh(const TriMesh& mesh, CoreMesh& m);

}  // namespace gr
