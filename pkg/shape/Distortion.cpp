#include "pkg/shape/Distortion.hpp"

#include <cmath>
#include <numeric>

namespace roundedmesh {

Real distortion(const TriangleSurface& surface) {
  const std::vector<Real> areas = triangleAreas(surface);
  const Real mean = std::accumulate(areas.begin(), areas.end(), Real(0)) / areas.size();
  Real variance = 0;
  for (Real area : areas) variance += (area - mean) * (area - mean);
  return std::sqrt(variance / areas.size()) / mean;
}

}  // namespace roundedmesh
