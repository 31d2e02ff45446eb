// The point of the segment from a to b nearest p, in a plane or in space [m].
#pragma once

#include <algorithm>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

template <int Dim>
Eigen::Matrix<Real, Dim, 1> closestOnSegment(const Eigen::Matrix<Real, Dim, 1>& p, const Eigen::Matrix<Real, Dim, 1>& a,
                                             const Eigen::Matrix<Real, Dim, 1>& b) {
  const Real along = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), Real(0), Real(1));
  return a + along * (b - a);
}

}  // namespace roundedmesh
