// One contact step (architecture.md, "One time step inside YADE"), as a sequence of stages:
//   1. broadPhase: the world boxes of bodies and partners against the neighbour list (a Verlet list of the
//      pairs whose boxes, grown by half the skin, overlapped when it was built; rebuilt by sweep and prune
//      when a box leaves its grown box) -> data.pairs, the pairs whose bounds overlap now, each with a
//      rounded body on its first side, or a sphere body when both sides are partners (other partners never
//      touch each other here, nor members of one clump);
//   2. resolvePair for every pair, in parallel, in the rounded body's frame: the pair's candidate triangle
//      pairs (kept between steps, rebuilt from the triangle trees when the relative motion exceeds the skin)
//      -> Ig2 (triangle contact geometry) -> Law2 (normal load, Eqs. 12-14) -> node forces (Eq. 15) -> friction:
//      the pair's tangential spring at its centre of pressure (kept between steps), or the paper's viscous law
//      (Eqs. 19-21) at each c_eff -> the wrench on the body (Eqs. 16-17, 22-23) and the equal and opposite one on
//      the other side -> data.pairResults;
//   3. the pair wrenches summed per body in pair order, so the result is the same for any thread count.
// Input: model, and data.bodyStates / data.partnerStates. Output: data.bodyWrenches,
// data.partnerWrenches, data.statistics, data.times.
#pragma once

#include <vector>

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

void RoundedMeshEngine(const ContactModel& model, ContactData& data);

// Stage 1. Conservative: a pair is left out only if no triangle's cap of the body can reach the other, or if
// both belong to one clump.
void broadPhase(const ContactModel& model, ContactData& data);

// Velocity of body 2's material relative to body 1's, in body 1's frame (toBody: global -> body 1's axes),
// about body 1's position.
RelativeMotion relativeMotion(const BodyState& s1, const BodyState& s2, const Matrix3r& toBody);

// The other side's wrench when `onBody` (torque about bodyPosition) acts on the body: the opposite forces at the
// same points, torque about otherPosition (Eq. 22).
Wrench reaction(const Wrench& onBody, const Vector3r& bodyPosition, const Vector3r& otherPosition);

// Stage 2, geometry, for one pair (Ig2 in the body's frame): its triangle contacts -> geoms, the funnel's
// counts -> statistics. `candidates`: as for resolvePair.
void pairGeometry(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                  std::vector<PressureGeom>& geoms, ContactStatistics& statistics, CandidateList* candidates = nullptr);

// Stage 2, load, for one pair's triangle contacts (Law2, node forces, friction): the wrench on each side.
// With `contacts`, also appends every triangle contact. `spring`: the pair's tangential spring kept between steps,
// brought to this step (it moves by data.timeStep) or, if the pair no longer touches, reset; without it, the
// spring starts and ends in this evaluation (a contact with no history: only its damping acts).
PairResult pairLoad(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                    const std::vector<PressureGeom>& geoms, std::vector<TriangleContact>* contacts = nullptr,
                    TangentialSpring* spring = nullptr);

// Stage 2 for one pair: pairGeometry, then pairLoad; for a sphere body against a partner, resolveSpherePair. `candidates`: the pair's list kept between steps,
// brought up to date here; without it, the candidate triangle pairs are found afresh, for contacts up to kDeepestOverlap of the smaller body
// deep. With `contacts`, also appends every triangle contact of the pair. `spring`: as for pairLoad.
PairResult resolvePair(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                       std::vector<PressureGeom>& scratch, std::vector<TriangleContact>* contacts = nullptr,
                       CandidateList* candidates = nullptr, TangentialSpring* spring = nullptr);

}  // namespace roundedmesh
