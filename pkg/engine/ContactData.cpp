#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

ContactStatistics& ContactStatistics::operator+=(const ContactStatistics& other) {
  bodyPairs += other.bodyPairs;
  touchingPairs += other.touchingPairs;
  narrowPhase += other.narrowPhase;
  quadratureContacts += other.quadratureContacts;
  directContacts += other.directContacts;
  sphereContacts += other.sphereContacts;
  slidingContacts += other.slidingContacts;
  neighbourRebuilds += other.neighbourRebuilds;
  candidateRebuilds += other.candidateRebuilds;
  nearRebuilds += other.nearRebuilds;
  return *this;
}

void ContactData::resize(const ContactModel& model) {
  bodyStates.resize(model.bodies.size());
  partnerStates.resize(model.partners.size());
  bodyClumps.resize(model.bodies.size(), -1);
  partnerClumps.resize(model.partners.size(), -1);
  bodyWrenches.resize(model.bodies.size());
  partnerWrenches.resize(model.partners.size());
}

}  // namespace roundedmesh
