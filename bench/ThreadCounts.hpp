// The thread counts a benchmark measures: those listed in ROUNDEDMESH_BENCH_THREADS (comma-separated, 1 to 1024, for
// machines larger than the 2-core ones the defaults suit), or `defaults`. Exits naming the variable on a bad list.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace roundedmesh {

inline std::vector<std::int64_t> threadCounts(std::vector<std::int64_t> defaults) {
  const char* listed = std::getenv("ROUNDEDMESH_BENCH_THREADS");
  if (!listed) return defaults;
  std::vector<std::int64_t> counts;
  std::stringstream items(listed);
  for (std::string item; std::getline(items, item, ',');) {
    char* end = nullptr;
    const long count = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || count < 1 || count > 1024) {
      std::cerr << "ROUNDEDMESH_BENCH_THREADS: expected thread counts from 1 to 1024 separated by commas, got '"
                << listed << "'\n";
      std::exit(2);
    }
    counts.push_back(count);
  }
  return counts;
}

}  // namespace roundedmesh
