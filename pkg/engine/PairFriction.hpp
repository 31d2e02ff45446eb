// The friction of one pair (doc/physics.md, "Friction"), for rounded bodies (PairLoad.hpp) and sphere bodies
// (SpherePair.hpp) alike: the pair's tangential spring (FrictionLaw::Spring, TangentialSpring.hpp), which lasts as
// long as the pair touches, or the paper's viscous law at each contact (FrictionLaw::Viscous, CoulombFriction.hpp,
// Eqs. 19-21).
// Frames: R_WB turns body 1's axes into the world's; a vector named ..._B is in body 1's frame (origin at its
// position), ..._W in the world's.
#pragma once

#include <vector>

#include "pkg/engine/ContactData.hpp"
#include "pkg/law/PairLaw.hpp"

namespace roundedmesh {

// One triangle contact's normal load and where it acts (body 1's frame), kept while the pair's friction is found.
struct ContactShare {
  NormalLoad load;
  Vector3r point_B;  // where Fn acts: c + (-Mn_y, Mn_x) / Fn, or c_eff if Fn = 0
};

// The spring lets go (its pair no longer touches, or has no spring now): what it held is dissipated within the
// step of dt [s] (added to summary.frictionPower).
void releaseSpring(TangentialSpring& spring, Real dt, PairSummary& summary);

// A pair that has no spring now (frictionless materials, or the viscous law) lets go of the one it had.
void dropUnusedSpring(const PairLaw& law, TangentialSpring* spring, Real dt, PairSummary& summary);

// The pair's contact as its spring sees it (global frame): normal from body 1 to body 2, slip and spin (about the
// normal) of body 2 relative to body 1, the contact frame's spin from both bodies' angular velocities, the normal
// force N [N] and k_t [N/m]. No twist (polar moment 0) unless the caller sets it.
SpringContact springContact(const Vector3r& normal_W, const Vector3r& slip_W, Real spin, const BodyState& s1,
                            const BodyState& s2, Real normalForce, Real stiffness);

// The viscous law on each triangle contact at c_eff, the circle fractions shared out so that they sum to 1 over the
// pair: adds it to onBody_B and to the result's summary and statistics, and each triangle's to `listed` (global).
void viscousFriction(const std::vector<PressureGeom>& geoms, const std::vector<ContactShare>& shares,
                     const HertzPhys& phys, const Matrix3r& R_WB, Wrench& onBody_B, PairResult& result,
                     TriangleContact* listed);

// The pair's tangential spring at its centre of pressure centre_B with normal normal_B: brings `spring` to this
// step of dt [s], adds its load to onBody_B and the result's summary, and each triangle contact's share to `listed`
// (global frame). normalStiffness: the pair's dFn/d(delta) [N/m].
void springFriction(const std::vector<ContactShare>& shares, Real normalForce, Real normalStiffness,
                    const Vector3r& centre_B, const Vector3r& normal_B, const RelativeMotion& motion_B,
                    const BodyState& s1, const BodyState& s2, const HertzPhys& phys, Real dt, const Matrix3r& R_WB,
                    TangentialSpring& spring, Wrench& onBody_B, PairResult& result, TriangleContact* listed);

}  // namespace roundedmesh
