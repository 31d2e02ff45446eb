#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

void ContactData::resize(const ContactModel& model) {
  bodyStates.resize(model.bodies.size());
  partnerStates.resize(model.partners.size());
  bodyWrenches.resize(model.bodies.size());
  partnerWrenches.resize(model.partners.size());
}

}  // namespace roundedmesh
