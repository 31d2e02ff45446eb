// YADE's Box: a rigid cuboid with half-sizes `halfExtents` [m] along its local axes, centred at the
// body's position and turned by its orientation. Its six faces are finite planes (Section 2.3).
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct Box {
  Vector3r halfExtents;
};

}  // namespace roundedmesh
