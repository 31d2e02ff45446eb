// Kinematic state of a body as YADE's State holds it: position of the centre of mass [m], orientation
// (body frame -> global), velocity [m/s] and angular velocity [rad/s], both global.
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct BodyState {
  Vector3r position = Vector3r::Zero();
  Quaternionr orientation = Quaternionr::Identity();
  Vector3r velocity = Vector3r::Zero();
  Vector3r angularVelocity = Vector3r::Zero();
};

}  // namespace roundedmesh
