// Stage 2 of a contact step (ContactStep.hpp): which pairs may touch. The world boxes of bodies and partners
// are checked against the neighbour list, a Verlet list of the pairs whose boxes, grown by half the skin
// (ListSkins::neighbours), overlapped when it was built; it is rebuilt by sweep and prune when a box leaves its
// grown box, each pair keeping its candidate list and tangential spring.
// Input: model, data.bodyStates / data.partnerStates. Output: data.pairs, the pairs whose bounds overlap now, each
// with a rounded body on its first side, or a sphere body when both sides are partners (other partners never
// touch each other here, nor members of one clump). Conservative: a pair is left out only if no triangle's cap of
// the body can reach the other, or if both belong to one clump. A pair left out lets go of its spring.
#pragma once

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

void broadPhase(const ContactModel& model, ContactData& data);

}  // namespace roundedmesh
