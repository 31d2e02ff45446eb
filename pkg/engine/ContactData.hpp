// What changes every step: the states the engine reads (filled by the caller, in the order of the
// model's bodies and partners), the wrenches it produces (force [N] and torque [N m] about each body's
// own position, global frame), contact counts, and scratch space reused from step to step.
#pragma once

#include <vector>

#include "pkg/engine/BodyState.hpp"
#include "pkg/engine/ContactModel.hpp"
#include "pkg/geom/PressureGeom.hpp"
#include "pkg/law/NodeForces.hpp"

namespace roundedmesh {

struct ContactStatistics {
  int bodyPairs = 0;           // body-partner pairs whose bounds overlap
  int quadratureContacts = 0;  // triangle contacts integrated by quadrature
  int directContacts = 0;      // triangle contacts in the direct regime
};

struct ContactData {
  std::vector<BodyState> bodyStates;
  std::vector<BodyState> partnerStates;
  std::vector<Wrench> bodyWrenches;
  std::vector<Wrench> partnerWrenches;
  ContactStatistics statistics;
  std::vector<PressureGeom> geoms;  // scratch: the contacts of one body pair

  // Sizes every array for `model`; states are left for the caller to fill.
  void resize(const ContactModel& model);
};

}  // namespace roundedmesh
