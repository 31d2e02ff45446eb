// Stage 2 for a sphere body (rm.add_sphere) against another partner: one contact over the whole contact
// circle (Ig2_Sphere_Partner_PressureGeom.hpp), loaded by the engine's own law in its direct regime, which for a
// circle wholly in S is the damped Hertz force of Eq. 7,
//   F = (4/3) E* sqrt(R*) (delta^3/2 + A ddelta/dt delta^1/2)   along n12, through both centres,
// and the rounded bodies' friction at c, whose moment turns the sphere: the pair's tangential spring
// (TangentialSpring.hpp; `spring` as for pairLoad, a single contact point, so without twist) or the paper's viscous
// law (CoulombFriction.hpp, Eqs. 19-21). E*, A, mu, c and k_t/k_n combine the two materials as for every pair
// (HertzPhys.hpp).
// Input: pair.body a sphere body, pair.other a partner (indices past the model's bodies). Output: the wrench on
// each side, global frame, each torque about its own position.
#pragma once

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

PairResult resolveSpherePair(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                             TangentialSpring* spring = nullptr);

}  // namespace roundedmesh
