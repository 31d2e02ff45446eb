// The STL reader on ASCII files: CGAL reads a file as ASCII only if it starts with "solid" and a separator,
// so the input gets that prefix unless it has it, and every input exercises the ASCII parser (and its
// fall-back to binary). Seeds: tests/data/*.stl.
#include <cstring>
#include <vector>

#include "fuzz/FuzzSupport.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char prefix[] = "solid ";
  std::vector<std::uint8_t> file;
  if (size < 6 || std::memcmp(data, prefix, 5) != 0) file.assign(prefix, prefix + 6);
  file.insert(file.end(), data, data + size);
  roundedmesh::fuzz::fuzzMeshReader(file.data(), file.size(), "stl");
  return 0;
}
