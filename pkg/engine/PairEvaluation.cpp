#include "pkg/engine/PairEvaluation.hpp"

#include "pkg/engine/WeldedFacets.hpp"

namespace roundedmesh {
namespace {

// Body 0 of `model` against each other entity (body 1, or every partner), in the states given.
PairEvaluation evaluate(ContactModel& model, const std::vector<BodyState>& bodies,
                        const std::vector<BodyState>& partners, const EngineOptions& options, bool details) {
  options.validate();
  model.options = options;
  for (const RoundedBody& body : model.bodies) body.material.validate();
  for (const Partner& partner : model.partners) partner.material.validate();
  ContactData data;
  data.resize(model);
  data.bodyStates = bodies;
  data.partnerStates = partners;
  PairEvaluation out;
  std::vector<PressureGeom> scratch;
  const int others = static_cast<int>(model.bodies.size() + model.partners.size());
  for (int other = 1; other < others; ++other) {
    const PairResult r = resolvePair(model, data, {0, other}, scratch, details ? &out.contacts : nullptr);
    out.onFirst.force += r.onBody.force;
    out.onFirst.torque += r.onBody.torque;
    out.onPartners.push_back(r.onOther);
  }
  out.onSecond = out.onPartners.front();
  return out;
}

}  // namespace

PairEvaluation partnerContact(const RoundedBody& body, const BodyState& state, const PartnerShape& partner,
                              const BodyState& partnerState, const HertzMaterial& partnerMaterial,
                              const EngineOptions& options, bool details) {
  ContactModel model;
  model.bodies.push_back(body);
  model.partners.push_back({-1, partner, partnerMaterial});
  return evaluate(model, {state}, {partnerState}, options, details);
}

PairEvaluation surfaceContact(const RoundedBody& body, const BodyState& state, std::vector<Partner> partners,
                              const std::vector<BodyState>& partnerStates, const EngineOptions& options,
                              bool details) {
  ContactModel model;
  model.bodies.push_back(body);
  model.partners = std::move(partners);
  weldFacetPartners(model, partnerStates);
  return evaluate(model, {state}, partnerStates, options, details);
}

PairEvaluation planeContact(const RoundedBody& body, const BodyState& state, const Plane& plane,
                            const HertzMaterial& planeMaterial, const EngineOptions& options, bool details) {
  return partnerContact(body, state, plane, BodyState(), planeMaterial, options, details);
}

PairEvaluation sphereContact(const RoundedBody& body, const BodyState& state, const Sphere& sphere,
                             const BodyState& sphereState, const HertzMaterial& sphereMaterial,
                             const EngineOptions& options, bool details) {
  return partnerContact(body, state, sphere, sphereState, sphereMaterial, options, details);
}

PairEvaluation bodyContact(const RoundedBody& first, const BodyState& firstState, const RoundedBody& second,
                           const BodyState& secondState, const EngineOptions& options, bool details) {
  ContactModel model;
  model.bodies = {first, second};
  return evaluate(model, {firstState, secondState}, {}, options, details);
}

}  // namespace roundedmesh
