// The PLY reader (CGAL's, through readMeshFile) and the body made of what it accepts. Seeds: tests/data/*.ply.
#include "fuzz/FuzzSupport.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  roundedmesh::fuzz::fuzzMeshReader(data, size, "ply");
  return 0;
}
