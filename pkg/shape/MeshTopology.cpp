#include "pkg/shape/MeshTopology.hpp"

#include <algorithm>
#include <utility>

namespace roundedmesh {

EdgeDefects findEdgeDefects(const std::vector<Triangle>& triangles) {
  // Every edge as (lower vertex, higher vertex, +1 if the triangle runs along it upwards, -1 if downwards).
  struct Use {
    int low, high, direction;
  };
  std::vector<Use> uses;
  uses.reserve(3 * triangles.size());
  for (const Triangle& t : triangles)
    for (int i = 0; i < 3; ++i) {
      const int from = t[i], to = t[(i + 1) % 3];
      uses.push_back({std::min(from, to), std::max(from, to), from < to ? 1 : -1});
    }
  std::sort(uses.begin(), uses.end(),
            [](const Use& a, const Use& b) { return std::make_pair(a.low, a.high) < std::make_pair(b.low, b.high); });

  EdgeDefects defects;
  auto note = [](EdgeDefect& defect, const Use& edge) {
    if (defect.count++ == 0) defect.first = {edge.low, edge.high};
  };
  for (std::size_t begin = 0; begin < uses.size();) {
    std::size_t end = begin;
    int directionSum = 0;
    while (end < uses.size() && uses[end].low == uses[begin].low && uses[end].high == uses[begin].high)
      directionSum += uses[end++].direction;
    const std::size_t bordering = end - begin;
    if (bordering == 1) note(defects.boundary, uses[begin]);
    else if (bordering > 2) note(defects.nonManifold, uses[begin]);
    else if (directionSum != 0) note(defects.misoriented, uses[begin]);
    begin = end;
  }
  return defects;
}

}  // namespace roundedmesh
