// One contact evaluated once, without a scene, through the engine's own stages (resolvePair): a rounded body
// against a partner (a plane, a YADE Wall, Box, Facet or analytic Sphere), or against another rounded body. What
// rm.plane_contact, rm.partner_contact, rm.sphere_contact, rm.body_contact and rm.triangle_contacts return, for
// validation and for looking inside a contact. Forces [N] and torques [N m] global, each torque about its own body's position; with `details`, every
// triangle contact as resolvePair sees it. `options`: the engine's (EngineOptions.hpp); the spring of
// FrictionLaw::Spring starts here, so only its damping acts (a contact with no history). Throws std::invalid_argument naming a material parameter out of range.
#pragma once

#include <vector>

#include "pkg/engine/ContactStep.hpp"

namespace roundedmesh {

struct PairEvaluation {
  Wrench onFirst, onSecond;
  std::vector<Wrench> onPartners;         // surfaceContact: on each partner, about its position
  std::vector<TriangleContact> contacts;  // filled only with `details`
};

// Against any partner in `partnerState` (a Wall's position, a Box's or a Facet's pose, a sphere's centre).
PairEvaluation partnerContact(const RoundedBody& body, const BodyState& state, const PartnerShape& partner,
                              const BodyState& partnerState, const HertzMaterial& partnerMaterial,
                              const EngineOptions& options, bool details = false);

// Against several partners at once, as in a scene: the Facets among them welded into surfaces (WeldedFacets.hpp),
// each partner's pair resolved, the wrenches on the body summed into onFirst.
PairEvaluation surfaceContact(const RoundedBody& body, const BodyState& state, std::vector<Partner> partners,
                              const std::vector<BodyState>& partnerStates, const EngineOptions& options,
                              bool details = false);

PairEvaluation planeContact(const RoundedBody& body, const BodyState& state, const Plane& plane,
                            const HertzMaterial& planeMaterial, const EngineOptions& options, bool details = false);

PairEvaluation sphereContact(const RoundedBody& body, const BodyState& state, const Sphere& sphere,
                             const BodyState& sphereState, const HertzMaterial& sphereMaterial,
                             const EngineOptions& options, bool details = false);

PairEvaluation bodyContact(const RoundedBody& first, const BodyState& firstState, const RoundedBody& second,
                           const BodyState& secondState, const EngineOptions& options, bool details = false);

}  // namespace roundedmesh
