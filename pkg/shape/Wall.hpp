// YADE's Wall: an infinite plane through the body's position, normal to global axis `axis` (0, 1, 2).
// sense +1 or -1: only the positive or negative side interacts; 0: both, the side being the one where
// the other body's centre lies (as in YADE's Ig2_Wall_Sphere_ScGeom).
#pragma once

#include "pkg/shape/Plane.hpp"

namespace roundedmesh {

struct Wall {
  int axis;
  int sense;
};

// The plane that `wall` at `wallPosition` presents to a body centred at `bodyPosition` (global frame).
inline Plane wallPlane(const Wall& wall, const Vector3r& wallPosition, const Vector3r& bodyPosition) {
  Real side = wall.sense;
  if (side == 0) side = bodyPosition[wall.axis] >= wallPosition[wall.axis] ? 1 : -1;
  return {wallPosition, side * Vector3r::Unit(wall.axis)};
}

}  // namespace roundedmesh
