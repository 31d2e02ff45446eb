// The paper's viscous friction (Section 2.6), the engine's FrictionLaw::Viscous: the tangential force of one
// triangle contact, acting at c_eff, from the slip v_t (velocity of body 2 relative to body 1 there, tangential
// part):
//   criterion (Eq. 21): sliding if c |v_t| > mu F_Hertz, F_Hertz the damped sphere-sphere force of Eq. 7 for
//                       this pair's delta_s and R*: for a body whose triangles share one sphere, the body's
//                       total normal force, so every triangle of a contact switches together
//   no-slip (Eq. 20):   F_t = -c s v_t, s the triangle's share of c: as printed, its circle fraction
//                       A(S n Omega) / A(Omega); the engine divides that by the sum of the fractions over the body
//                       pair, so that a pair's no-slip force is -c v_t (Eq. 18) for any shape (doc/physics.md)
//   sliding (Eq. 19):   F_t = -mu F_n v_t / |v_t|, F_n this triangle's normal force (Eq. 12)
// F_t acts on body 2; body 1 receives -F_t (Eq. 22). With mu = 0 there is no force; with c = 0 no contact
// slides and the no-slip force is zero: this law's friction needs c > 0 (doc/physics.md).
#pragma once

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

struct TangentialLoad {
  Vector3r force = Vector3r::Zero();  // F_t on body 2, body 1's frame [N]
  bool sliding = false;
};

// A(S n Omega) / A(Omega): the fraction of its contact circle that a triangle contact covers (Eq. 14).
Real circleFraction(const PressureGeom& geom);

// share: the triangle's share s of c in the no-slip force; negative (the default) for its circle fraction, Eq. 20
// as printed.
TangentialLoad coulombFriction(const PressureGeom& geom, const NormalLoad& load, const HertzPhys& phys,
                               Real share = -1);

}  // namespace roundedmesh
