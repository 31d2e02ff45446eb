// Tangential force of one triangle contact (Section 2.6), acting at c_eff, from the slip v_t (velocity of
// body 2 relative to body 1 there, tangential part):
//   criterion (Eq. 21): sliding if c |v_t| > mu F_Hertz, F_Hertz the damped sphere-sphere force of Eq. 7 for
//                       this pair's delta_s and R*: for a body whose triangles share one sphere, the body's
//                       total normal force, so every triangle of a contact switches together
//   no-slip (Eq. 20):   F_t = -c (A(S n Omega) / A(Omega)) v_t, the fractions summing to 1 over a contact
//   sliding (Eq. 19):   F_t = -mu F_n v_t / |v_t|, F_n this triangle's normal force (Eq. 12)
// F_t acts on body 2; body 1 receives -F_t (Eq. 22). With c = 0 the no-slip force is zero and no contact
// slides: the model's friction needs c > 0 (doc/physics.md).
#pragma once

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

struct TangentialLoad {
  Vector3r force = Vector3r::Zero();  // F_t on body 2, body 1's frame [N]
  bool sliding = false;
};

TangentialLoad coulombFriction(const PressureGeom& geom, const NormalLoad& load, const HertzPhys& phys);

}  // namespace roundedmesh
