// Transfer of a triangle's normal load to its corner nodes and to the bodies (Section 2.5).
//   Eq. 15: node forces F_1..3 along n12 with sum F_i = Fn and sum r_i x F_i n12 = Mn, r_i the projected
//           corners relative to c; Fn of either sign (a damping load pulls while the sides part). Its unique solution is F_i = Fn * lambda_i, lambda the barycentric
//           coordinates of the centre of pressure (-Mn_y, Mn_x) / Fn in the projected triangle, which is
//           how it is solved here: no 3x3 inverse, and bounded even for nearly edge-on triangles.
//   Eqs. 16-17: body 1 receives -F_i n12 at each corner x_i.
#pragma once

#include <array>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"

namespace roundedmesh {

struct Wrench {
  Vector3r force = Vector3r::Zero();
  Vector3r torque = Vector3r::Zero();  // about the reference point stated where the wrench is used
};

std::array<Real, 3> nodeForces(const std::array<Vector2r, 3>& nodes, const NormalLoad& load);

// Adds Eqs. 16-17 for one triangle contact to body 1's wrench, torque about body 1's frame origin.
// corners: the triangle's corners in body 1's frame.
void addNodeForcesToBody(const std::array<Vector3r, 3>& corners, const std::array<Real, 3>& forces,
                         const Vector3r& normal, Wrench& body1);

}  // namespace roundedmesh
