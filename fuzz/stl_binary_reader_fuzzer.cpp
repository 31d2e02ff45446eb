// The STL reader on binary files: the input is the file after its 80-byte header (triangle count, then 50
// bytes per triangle), behind a header that does not start with "solid", so that CGAL takes the binary parser
// first. Seeds: tests/data/*.stl without their header.
#include <vector>

#include "fuzz/FuzzSupport.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> file(80, ' ');
  file.insert(file.end(), data, data + size);
  roundedmesh::fuzz::fuzzMeshReader(file.data(), file.size(), "stl");
  return 0;
}
