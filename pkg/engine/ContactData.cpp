#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

ContactStatistics& ContactStatistics::operator+=(const ContactStatistics& other) {
  bodyPairs += other.bodyPairs;
  quadratureContacts += other.quadratureContacts;
  directContacts += other.directContacts;
  slidingContacts += other.slidingContacts;
  return *this;
}

void ContactData::resize(const ContactModel& model) {
  bodyStates.resize(model.bodies.size());
  partnerStates.resize(model.partners.size());
  bodyWrenches.resize(model.bodies.size());
  partnerWrenches.resize(model.partners.size());
}

}  // namespace roundedmesh
