// The GTS reader (our own parser, pkg/io/GtsFile.cpp, through readMeshFile) and the body made of what it accepts.
// Seeds: tests/data/*.gts.
#include "fuzz/FuzzSupport.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  roundedmesh::fuzz::fuzzMeshReader(data, size, "gts");
  return 0;
}
