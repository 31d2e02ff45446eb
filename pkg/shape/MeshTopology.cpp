#include "pkg/shape/MeshTopology.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <tuple>

namespace roundedmesh {
namespace {

struct DirectedEdge {
  int from, to, triangle;
  bool operator<(const DirectedEdge& o) const { return std::tie(from, to, triangle) < std::tie(o.from, o.to, o.triangle); }
};

std::string edgeName(int a, int b) { return "edge " + std::to_string(a) + "-" + std::to_string(b); }

}  // namespace

void requireClosedOrientedSurface(const std::vector<Triangle>& triangles) {
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * triangles.size());
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int i = 0; i < 3; ++i) edges.push_back({triangles[t][i], triangles[t][(i + 1) % 3], t});
  std::sort(edges.begin(), edges.end());

  auto range = [&](int from, int to) {
    const auto first = std::lower_bound(edges.begin(), edges.end(), DirectedEdge{from, to, -1});
    auto last = first;
    while (last != edges.end() && last->from == from && last->to == to) ++last;
    return std::make_pair(first, last);
  };
  for (auto e = edges.begin(); e != edges.end();) {
    const auto [first, last] = range(e->from, e->to);
    const auto [reverseFirst, reverseLast] = range(e->to, e->from);
    const std::string name = edgeName(e->from, e->to);
    if (last - first > 1)
      throw std::invalid_argument("mesh: triangles " + std::to_string(first->triangle) + " and " +
                                  std::to_string((first + 1)->triangle) + " run along " + name +
                                  " in the same direction: the surface is not consistently oriented (or not "
                                  "manifold there)");
    if (reverseFirst == reverseLast)
      throw std::invalid_argument("mesh: the surface is not closed: " + name + " borders only triangle " +
                                  std::to_string(e->triangle));
    if (reverseLast - reverseFirst > 1)
      throw std::invalid_argument("mesh: " + name + " borders more than two triangles (" +
                                  std::to_string(e->triangle) + ", " + std::to_string(reverseFirst->triangle) +
                                  ", " + std::to_string((reverseFirst + 1)->triangle) + "): not manifold");
    e = last;
  }
}

}  // namespace roundedmesh
