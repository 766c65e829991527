// Writes issue 17's CAD-like acceptance meshes (tests/support/cad_meshes.h, default parameters)
// as OFF files into a directory, for meshlabserver tests and benchmarks:
//   write_cad_meshes <directory>      # cad_gear.off, cad_hole_plate.off, cad_cylinder.off, cad_bracket.off
#include <cstdio>
#include <filesystem>
#include <string>

#include "tests/support/cad_meshes.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <directory>\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  for (const gr::test::CadMesh& m : gr::test::cadMeshes()) {
    const std::string path = dir + "/" + m.name + ".off";
    if (!gr::test::writeOff(m.mesh, path)) {
      std::fprintf(stderr, "cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("%s: %d vertices, %d faces, genus %d\n", path.c_str(), m.mesh.vertexCount(), m.mesh.faceCount(),
                m.genus);
  }
  return 0;
}
