#include "pkg/shape/Icosphere.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace roundedmesh {

RoundedMesh icosphere(Real radius, int subdivisions) {
  if (!(std::isfinite(radius) && radius > 0))
    throw std::invalid_argument("radius must be positive and finite, got " + std::to_string(radius));
  if (subdivisions < 0 || subdivisions > 8)
    throw std::invalid_argument("subdivisions must be between 0 and 8, got " + std::to_string(subdivisions));

  const Real phi = (1 + std::sqrt(Real(5))) / 2;
  std::vector<Vector3r> unit = {{-1, phi, 0}, {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0},
                                {0, -1, phi}, {0, 1, phi},  {0, -1, -phi}, {0, 1, -phi},
                                {phi, 0, -1}, {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
  for (Vector3r& v : unit) v.normalize();
  std::vector<Triangle> triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      unit.push_back((unit[i] + unit[j]).normalized());
      const int index = static_cast<int>(unit.size()) - 1;
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * triangles.size());
    for (const Triangle& t : triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
  }

  for (Vector3r& v : unit) v *= radius;
  const std::vector<Real> radii(triangles.size(), radius);
  return RoundedMesh(std::move(unit), std::move(triangles), radii);
}

}  // namespace roundedmesh
