#include "pkg/engine/ContactStep.hpp"

#include <algorithm>

#include <omp.h>

#include "pkg/common/StageClock.hpp"
#include "pkg/engine/BroadPhase.hpp"
#include "pkg/engine/CorePair.hpp"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/engine/PairLoad.hpp"
#include "pkg/engine/SpherePair.hpp"

namespace roundedmesh {
namespace {

// Stage 3, every pair in parallel, each with its own list and spring -> data.pairResults (and data.pairContacts).
void resolvePairs(const ContactModel& model, ContactData& data) {
  const int threads = model.options.resolvedThreads();
  if (data.geoms.size() < static_cast<size_t>(threads)) data.geoms.resize(threads);
  const int pairCount = static_cast<int>(data.pairs.size());
  data.pairResults.resize(pairCount);
  data.pairContacts.resize(data.keepTriangleContacts ? pairCount : 0);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 4) if (pairCount > 1)
  for (int k = 0; k < pairCount; ++k) {
    const BodyPair& pair = data.pairs[k];
    std::vector<TriangleContact>* contacts = nullptr;
    if (data.keepTriangleContacts) {
      contacts = &data.pairContacts[k];
      contacts->clear();
    }
    data.pairResults[k] = resolvePair(model, data, pair, data.geoms[omp_get_thread_num()], contacts,
                                      &data.candidateLists[pair.neighbour], &data.springs[pair.neighbour]);
  }
}

// Stage 4, in pair order -> data.bodyWrenches, data.partnerWrenches, data.statistics.
void sumWrenches(const ContactModel& model, ContactData& data) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  for (Wrench& w : data.bodyWrenches) w = Wrench();
  for (Wrench& w : data.partnerWrenches) w = Wrench();
  auto wrench = [&](int index) -> Wrench& {
    return index < bodyCount ? data.bodyWrenches[index] : data.partnerWrenches[index - bodyCount];
  };
  for (size_t k = 0; k < data.pairs.size(); ++k) {
    const PairResult& r = data.pairResults[k];
    Wrench& body = wrench(data.pairs[k].body);
    Wrench& otherWrench = wrench(data.pairs[k].other);
    body.force += r.onBody.force;
    body.torque += r.onBody.torque;
    otherWrench.force += r.onOther.force;
    otherWrench.torque += r.onOther.torque;
    data.statistics += r.statistics;
  }
}

// The scene's time step for impacts at `speed` [m/s] (stabilityLimit with an impact speed).
Real impactLimit(const ContactModel& model, const ContactData& data, Real speed) {
  return stabilityLimit(model, data.bodyMasses, data.partnerMasses, data.bodyInertias, data.partnerInertias, speed)
      .timeStep;
}

// Stage 7.
void reportStep(const ContactModel& model, const ContactData& data, bool first, StepReport& report) {
  report.fastest = fastestBody(model, data, data.timeStep);
  if (report.fastest.fraction > kFastStep) report.fastTimeStep = impactLimit(model, data, report.fastest.speed);
  for (size_t k = 0; k < data.pairs.size(); ++k) {
    const PairSummary& s = data.pairResults[k].summary;
    // A pair of two workers' bodies is computed on both (ContactData::residences): half its energy is this
    // process's, so that the energies of all processes add up to the scene's.
    const BodyPair& pair = data.pairs[k];
    const bool shared = data.residences[pair.body] == Residence::Image || data.residences[pair.other] == Residence::Image;
    const Real share = shared ? 0.5 : 1.0;
    report.energy.elastic += share * s.elasticEnergy;
    report.energy.dampingPower += share * s.dampingPower;
    report.energy.frictionPower += share * s.frictionPower;
  }
  for (const PairRecord& r : data.keptRecords) {
    const Real size = std::min(sideSize(model, r.body), sideSize(model, r.other));
    if (r.overlap / size > report.deepest.overlap / report.deepest.size) report.deepest = {r.body, r.other, r.overlap, size};
    if (first && r.overlap > kDeepestOverlap * size) report.deepStarts.push_back({r.body, r.other, r.overlap, size});
  }
  if (!first) return;
  std::stable_sort(report.deepStarts.begin(), report.deepStarts.end(),
                   [](const DeepPair& a, const DeepPair& b) { return a.overlap / a.size > b.overlap / b.size; });
}

}  // namespace

StepReport contactStep(const ContactModel& model, ContactData& data) {
  StepReport report;
  report.unstable = checkTimeStep(model, data);  // 1
  if (report.unstable) return report;
  contactForces(model, data);                     // 2-4
  report.stops = checkStopRules(model, data);     // 5
  if (!report.stops.empty()) {
    const StopReason& worst = report.stops.front();
    report.stopSpeed = (data.state(worst.body).velocity - data.state(worst.other).velocity).norm();
    report.stopTimeStep = impactLimit(model, data, report.stopSpeed);
    return report;
  }
  const bool first = !data.kept;
  commitStep(data);                               // 6
  reportStep(model, data, first, report);         // 7
  return report;
}

std::optional<StabilityLimit> checkTimeStep(const ContactModel& model, ContactData& data) {
  ContactData::CheckedTimeStep& checked = data.checkedTimeStep;
  if (checked.timeStep == data.timeStep && checked.bodyMasses == data.bodyMasses &&
      checked.partnerMasses == data.partnerMasses && checked.bodyInertias == data.bodyInertias &&
      checked.partnerInertias == data.partnerInertias)
    return std::nullopt;
  const StabilityLimit limit =
      stabilityLimit(model, data.bodyMasses, data.partnerMasses, data.bodyInertias, data.partnerInertias);
  // O.dt set to the limit in one process stays within it in another: a mesh restored from a saved scene, with
  // vertices rounded at 1e-15 of its size, may move the recomputed limit by some ulps.
  if (data.timeStep > (1 + kLimitRoundOff) * limit.timeStep) return limit;
  checked = {data.timeStep, data.bodyMasses, data.partnerMasses, data.bodyInertias, data.partnerInertias};
  return std::nullopt;
}

void contactForces(const ContactModel& model, ContactData& data) {
  data.statistics = ContactStatistics();
  const double start = omp_get_wtime();
  broadPhase(model, data);     // 2
  const double broad = omp_get_wtime();
  resolvePairs(model, data);   // 3
  const double resolved = omp_get_wtime();
  sumWrenches(model, data);    // 4
  data.times = {broad - start, resolved - broad, omp_get_wtime() - resolved};
}

PairResult resolvePair(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                       std::vector<PressureGeom>& scratch, std::vector<TriangleContact>* contacts,
                       CandidateList* candidates, TangentialSpring* spring) {
  if (pair.body >= static_cast<int>(model.bodies.size())) return resolveSpherePair(model, data, pair, spring);
  ContactStatistics statistics;
  pairGeometry(model, data, pair, scratch, statistics, candidates);
  StageClock clock(model.options.timing == Timing::Stages);
  PairResult result = pairLoad(model, data, pair, scratch, contacts, spring);
  statistics.cpu.law += clock.lap();
  const CoreLoad core = corePair(model, data, pair, result.summary);
  statistics.cpu.core += clock.lap();
  result.statistics += statistics;
  if (core.contacts > 0) {
    result.onBody.force += core.force;
    result.onBody.torque += core.torque;
    result.onOther = reaction(result.onBody, data.state(pair.body).position, data.state(pair.other).position);
    result.summary.elasticEnergy += core.energy;
    result.statistics.coreContacts += core.contacts;
  }
  return result;
}

}  // namespace roundedmesh
