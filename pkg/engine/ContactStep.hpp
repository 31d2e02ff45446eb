// One contact step (doc/architecture.md, "One time step inside YADE"): a short sequence of stages, each a call
// with a clear input and output that can be tested alone, in the manner of MuJoCo's mj_step. The caller (the
// binding, py/module/ExposeEngine.cpp, or a test) fills data's states, masses and time step (ContactData::resize
// sizes them), calls contactStep, and applies data's wrenches to the bodies if the report keeps the step.
//   1. checkTimeStep    data.timeStep against the stability limit of every pair the bodies can form
//                       (CriticalTimeStep.hpp), for the masses and inertias read with the states; checked again
//                       whenever the time step, a mass or a moment of inertia changes -> report.unstable. A step
//                       above the limit stops here, computing nothing.
//   2. broadPhase       the pairs whose bounds overlap (BroadPhase.hpp) -> data.pairs
//   3. resolvePairs     every pair, in parallel: its candidate list and Ig2 (PairGeometry.hpp), then Law2, node
//                       forces and friction (PairLoad.hpp); a sphere body's contact as one (SpherePair.hpp)
//                       -> data.pairResults
//   4. sumWrenches      the pair wrenches summed per body in pair order, so that the result is the same for any
//                       thread count -> data.bodyWrenches, data.partnerWrenches
//   5. checkStopRules   a centre through a face, or an overlap past stopOverlap that grows (StopRules.hpp)
//                       -> report.stops. A step that breaks one stops here and is not kept: redoing it stops again.
//   6. commitStep       the step becomes the one the next is compared with
//   7. reportStep       the body fastest for its contact depth, the deepest pair for its size, the pairs that
//                       start deeper than a Hertz contact (on the first step), the contacts' energies -> the report
// contactForces is stages 2-4: the forces alone, for tests and benchmarks of the contacts.
#pragma once

#include <optional>
#include <vector>

#include "pkg/engine/ContactData.hpp"
#include "pkg/engine/CriticalTimeStep.hpp"
#include "pkg/engine/StopRules.hpp"

namespace roundedmesh {

// A body that moves more than this fraction of its contact depth (kDeepestOverlap of its size) in one step is
// reported (doc/physics.md, "Deep overlaps and fast impacts"): an impact reaching that depth is integrated with its
// energy off by up to about 2.5 %, at one full depth per step by 15 %, and past 1.5 the step is unstable for it.
constexpr Real kFastStep = 0.5;

// A pair overlapping by more than kDeepestOverlap of its smaller side's size (StopRules.hpp, sideSize).
struct DeepPair {
  int body, other;  // engine indices, as in BodyPair
  Real overlap;     // PairSummary::depth [m]
  Real size;        // the smaller side's size [m]
};

// What the contacts of a kept step hold and lose (doc/physics.md, "Energy").
struct ContactEnergy {
  Real elastic = 0;       // [J]
  Real dampingPower = 0;  // normal damping [W]
  Real frictionPower = 0; // friction [W]
};

struct StepReport {
  // Stage 1: the limit data.timeStep exceeds; the step computed nothing.
  std::optional<StabilityLimit> unstable;
  // Stage 5: why the step was not kept, worst first (empty: it was kept). For the first: the relative speed of its
  // pair [m/s], and the scene's time step that resolves impacts at that speed [s] (CriticalTimeStep.hpp).
  std::vector<StopReason> stops;
  Real stopSpeed = 0;
  Real stopTimeStep = 0;
  // Stage 7, a kept step: the body that moves the largest fraction of its contact depth in a step, and when that
  // fraction exceeds kFastStep, the scene's time step that resolves impacts at its speed [s] (else 0).
  FastBody fastest;
  Real fastTimeStep = 0;
  // The pairs deeper than a Hertz contact, on the first step kept since data was made: bodies placed inside each
  // other, not in contact. Deepest for its size first.
  std::vector<DeepPair> deepStarts;
  // The pair that overlaps most for its size in this step (overlap 0, body -1 if none touches).
  DeepPair deepest{-1, -1, 0, 1};
  ContactEnergy energy;

  bool kept() const { return !unstable && stops.empty(); }
};

StepReport contactStep(const ContactModel& model, ContactData& data);

// A time step up to this fraction above the stability limit counts as at the limit.
constexpr Real kLimitRoundOff = 1e-9;

// Stage 1: nullopt if data.timeStep is within the limit (or was for the same masses), else the limit.
std::optional<StabilityLimit> checkTimeStep(const ContactModel& model, ContactData& data);

// Stages 2-4.
void contactForces(const ContactModel& model, ContactData& data);

// Stage 3 for one pair: pairGeometry, then pairLoad; for a sphere body against a partner, resolveSpherePair.
// `candidates`: the pair's list kept between steps, brought up to date here; without it, the candidate triangle
// pairs are found afresh, for contacts up to kDeepestOverlap of the smaller body deep. With `contacts`, also appends
// every triangle contact of the pair. `spring`: as for pairLoad. `scratch`: the triangle contacts, reused.
PairResult resolvePair(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                       std::vector<PressureGeom>& scratch, std::vector<TriangleContact>* contacts = nullptr,
                       CandidateList* candidates = nullptr, TangentialSpring* spring = nullptr);

}  // namespace roundedmesh
