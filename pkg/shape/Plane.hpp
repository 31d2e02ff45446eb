// An infinite rigid plane bounding a half-space: a point on it and the unit normal pointing out of the
// solid side, toward the bodies it supports.
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct Plane {
  Vector3r point;
  Vector3r normal;
};

}  // namespace roundedmesh
