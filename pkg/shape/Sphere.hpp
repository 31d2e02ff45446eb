// YADE's Sphere as a contact partner: an analytic sphere of `radius` [m] centred at the body's position.
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct Sphere {
  Real radius;
};

}  // namespace roundedmesh
