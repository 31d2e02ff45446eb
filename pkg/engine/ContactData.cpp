#include "pkg/engine/ContactData.hpp"

#include <algorithm>

namespace roundedmesh {

PairStageTimes& PairStageTimes::operator+=(const PairStageTimes& other) {
  lists += other.lists;
  nearSearch += other.nearSearch;
  narrowPhase += other.narrowPhase;
  law += other.law;
  core += other.core;
  return *this;
}

ContactStatistics& ContactStatistics::operator+=(const ContactStatistics& other) {
  bodyPairs += other.bodyPairs;
  touchingPairs += other.touchingPairs;
  narrowPhase += other.narrowPhase;
  quadratureContacts += other.quadratureContacts;
  directContacts += other.directContacts;
  exactContacts += other.exactContacts;
  sphereContacts += other.sphereContacts;
  coreContacts += other.coreContacts;
  slidingContacts += other.slidingContacts;
  neighbourRebuilds += other.neighbourRebuilds;
  candidateRebuilds += other.candidateRebuilds;
  nearRebuilds += other.nearRebuilds;
  nearPairsScanned += other.nearPairsScanned;
  cpu += other.cpu;
  return *this;
}

void ContactData::resize(const ContactModel& model) {
  bodyStates.resize(model.bodies.size());
  partnerStates.resize(model.partners.size());
  bodyClumps.resize(model.bodies.size(), -1);
  partnerClumps.resize(model.partners.size(), -1);
  bodyWrenches.resize(model.bodies.size());
  partnerWrenches.resize(model.partners.size());
  bodyMasses.resize(model.bodies.size());
  partnerMasses.resize(model.partners.size());
  bodyInertias.resize(model.bodies.size(), Vector3r::Zero());
  partnerInertias.resize(model.partners.size(), Vector3r::Zero());
  residences.resize(model.bodies.size() + model.partners.size(), Residence::Own);
}

namespace {

bool pairBefore(const BodyPair& a, const BodyPair& b) {
  return a.body < b.body || (a.body == b.body && a.other < b.other);
}

}  // namespace

std::vector<std::pair<BodyPair, TangentialSpring>> ContactData::activeSprings() const {
  std::vector<std::pair<BodyPair, TangentialSpring>> active;
  for (size_t n = 0; n < springs.size() && n < neighbours.size(); ++n)
    if (springs[n].active()) active.push_back({{neighbours[n].body, neighbours[n].other}, springs[n]});
  // Springs restored but not yet handed to their pairs are still the scene's.
  for (const auto& restored : restoredSprings) active.push_back(restored);
  std::sort(active.begin(), active.end(), [](const auto& a, const auto& b) { return pairBefore(a.first, b.first); });
  return active;
}

void ContactData::restoreSprings(std::vector<std::pair<BodyPair, TangentialSpring>> given) {
  std::sort(given.begin(), given.end(), [](const auto& a, const auto& b) { return pairBefore(a.first, b.first); });
  restoredSprings = std::move(given);
  neighbours.clear();
  neighbourBoxes.clear();
  candidateLists.clear();
  springs.clear();
}

}  // namespace roundedmesh
