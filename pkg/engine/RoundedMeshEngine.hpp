// One contact step (architecture.md, "One time step inside YADE"), as a sequence of stages:
//   1. broad phase: each rounded body's bounding sphere against each partner;
//   2. per overlapping pair, in the rounded body's frame:
//      Ig2 (triangle contact geometry) -> Law2 (normal load, Eqs. 12-14) -> node forces (Eq. 15)
//      -> wrench on the body (Eqs. 16-17) and the equal and opposite one on the partner;
//   3. wrenches turned into the global frame and summed per body.
// Input: model, and data.bodyStates / data.partnerStates. Output: data.bodyWrenches,
// data.partnerWrenches, data.statistics.
#pragma once

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

void RoundedMeshEngine(const ContactModel& model, ContactData& data);

// Stage 1: can rounded body b touch partner p? Conservative: false only if no triangle's encompassing
// sphere reaches the partner.
bool boundsOverlap(const ContactModel& model, const ContactData& data, int b, int p);

// Stage 2 for one pair: the wrench on rounded body b (torque about its position) and on partner p
// (torque about the partner's position), global frame.
void resolvePair(const ContactModel& model, ContactData& data, int b, int p, Wrench& onBody, Wrench& onPartner);

}  // namespace roundedmesh
