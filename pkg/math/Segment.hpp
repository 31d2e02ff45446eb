// The point of the segment from a to b nearest p, in a plane [m].
#pragma once

#include <algorithm>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

inline Vector2r closestOnSegment(const Vector2r& p, const Vector2r& a, const Vector2r& b) {
  const Real along = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), Real(0), Real(1));
  return a + along * (b - a);
}

}  // namespace roundedmesh
