// The OFF reader (CGAL's, through readMeshFile) and the body made of what it accepts. Seeds: tests/data/*.off.
#include "fuzz/FuzzSupport.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  roundedmesh::fuzz::fuzzMeshReader(data, size, "off");
  return 0;
}
