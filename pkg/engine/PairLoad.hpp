// Stage 3 of a contact step, load, for one pair's triangle contacts (PairGeometry.hpp): Law2 (normal load,
// Eqs. 12-14) -> node forces (Eq. 15) -> friction (PairFriction.hpp): the pair's tangential spring at its centre of
// pressure, or the paper's viscous law (Eqs. 19-21) at each c_eff -> the wrench on the body (Eqs. 16-17, 22-23) and
// the equal and opposite one on the other side.
#pragma once

#include <vector>

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

// The other side's wrench when `onBody` (torque about bodyPosition) acts on the body: the opposite forces at the
// same points, torque about otherPosition (Eq. 22).
Wrench reaction(const Wrench& onBody, const Vector3r& bodyPosition, const Vector3r& otherPosition);

// The wrench on each side (global frame, each torque about its own position). With `contacts`, also appends every
// triangle contact. `spring`: the pair's tangential spring kept between steps, brought to this step (it moves by
// data.timeStep) or, if the pair no longer touches, reset; without it, the spring starts and ends in this
// evaluation (a contact with no history: only its damping acts).
PairResult pairLoad(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                    const std::vector<PressureGeom>& geoms, std::vector<TriangleContact>* contacts = nullptr,
                    TangentialSpring* spring = nullptr);

}  // namespace roundedmesh
