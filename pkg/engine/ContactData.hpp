// What changes every step: the states the engine reads (filled by the caller, in the order of the
// model's bodies and partners), the candidate pairs of the broad phase, the wrenches the engine produces
// (force [N] and torque [N m] about each body's own position, global frame), contact counts, and scratch
// space reused from step to step.
#pragma once

#include <vector>

#include "pkg/engine/BodyState.hpp"
#include "pkg/engine/ContactModel.hpp"
#include "pkg/geom/PressureGeom.hpp"
#include "pkg/law/NodeForces.hpp"

namespace roundedmesh {

struct ContactStatistics {
  int bodyPairs = 0;           // pairs whose bounds overlap
  int quadratureContacts = 0;  // triangle contacts integrated by quadrature
  int directContacts = 0;      // triangle contacts in the direct regime
  int slidingContacts = 0;     // triangle contacts sliding (Eq. 21)

  ContactStatistics& operator+=(const ContactStatistics& other);
};

// A candidate of the broad phase: rounded body `body` against `other`, an index into the model's bodies
// (other < bodies.size()) or, past them, into its partners (other - bodies.size()).
struct BodyPair {
  int body;
  int other;
};

// The outcome of one pair: the wrench on each side (global frame, torque about each one's position).
struct PairResult {
  Wrench onBody, onOther;
  ContactStatistics statistics;
};

struct ContactData {
  std::vector<BodyState> bodyStates;
  std::vector<BodyState> partnerStates;
  std::vector<Wrench> bodyWrenches;
  std::vector<Wrench> partnerWrenches;
  ContactStatistics statistics;

  std::vector<BodyPair> pairs;                    // broad phase output
  std::vector<PairResult> pairResults;            // narrow phase output, one per pair
  std::vector<std::vector<PressureGeom>> geoms;   // scratch: one per thread

  // Sizes every array for `model`; states are left for the caller to fill.
  void resize(const ContactModel& model);
};

}  // namespace roundedmesh
