// Mesh files through CGAL's readers and writers: OBJ, STL (ASCII and binary), OFF and PLY, and GTS through our
// own (GtsFile.hpp: CGAL has none), chosen by the file's extension. Reading scales the coordinates (e.g. 0.001
// for a file in millimetres) and passes the result through repairedSurface (SurfaceRepair.hpp); every error
// message starts with the path.
// Throws FileNotFound if the file does not exist, std::invalid_argument for anything else wrong with it.
#pragma once

#include <stdexcept>
#include <string>

#include "pkg/meshing/SurfaceRepair.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

struct FileNotFound : std::runtime_error {
  using std::runtime_error::runtime_error;
};

TriangleSurface readMeshFile(const std::string& path, Real scale = 1, const RepairOptions& repair = {});

// Writes with 17 significant digits in the text formats, so that OBJ, OFF, ASCII PLY and GTS read back
// bit for bit; STL stores single-precision floats (about 7 digits), as its format prescribes.
void writeMeshFile(const std::string& path, const TriangleSurface& surface);

}  // namespace roundedmesh
