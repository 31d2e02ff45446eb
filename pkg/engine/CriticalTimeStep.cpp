#include "pkg/engine/CriticalTimeStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {
namespace {

// What the limit of a pair depends on, for one side: mass [kg] (0: does not move under forces), radius of
// the sphere standing for it [m] (infinite for a flat partner), material.
struct Side {
  Real mass;
  Real radius;
  const HertzMaterial* material;
};

// Infinite for two rigid sides, which have no Hertz contact (the scene refuses them).
Real pairLimit(const Side& a, const Side& b) {
  if (std::isinf(a.material->young) && std::isinf(b.material->young)) return std::numeric_limits<Real>::infinity();
  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(*a.material, *b.material);
  const Real mass = b.mass > 0 ? a.mass * b.mass / (a.mass + b.mass) : a.mass;
  const Real radius = std::isinf(b.radius) ? a.radius : a.radius * b.radius / (a.radius + b.radius);
  return criticalTimeStep(mass, phys.effectiveModulus, radius, phys.damping, kDeepestOverlap * std::min(a.radius, b.radius));
}

Real partnerRadius(const PartnerShape& shape) {
  if (const Sphere* sphere = std::get_if<Sphere>(&shape)) return sphere->radius;
  return std::numeric_limits<Real>::infinity();
}

}  // namespace

StabilityLimit stabilityLimit(const ContactModel& model, const std::vector<Real>& bodyMasses,
                              const std::vector<Real>& partnerMasses) {
  StabilityLimit limit;
  const int bodyCount = static_cast<int>(model.bodies.size());
  // Bodies alike in mass, size and material have the same limit: each kind is checked once.
  std::vector<int> kinds;
  for (int b = 0; b < bodyCount; ++b) {
    const RoundedBody& body = model.bodies[b];
    const bool seen = std::any_of(kinds.begin(), kinds.end(), [&](int k) {
      const RoundedBody& other = model.bodies[k];
      return bodyMasses[k] == bodyMasses[b] && other.equivalentRadius == body.equivalentRadius &&
             std::tie(other.material.young, other.material.poisson, other.material.damping) ==
                 std::tie(body.material.young, body.material.poisson, body.material.damping);
    });
    if (!seen) kinds.push_back(b);
  }
  auto consider = [&](Real dt, int b, int other) {
    if (dt < limit.timeStep) limit = {dt, b, other};
  };
  for (int b : kinds) {
    const Side side{bodyMasses[b], model.bodies[b].equivalentRadius, &model.bodies[b].material};
    for (int k : kinds)
      if (k >= b)
        consider(pairLimit(side, {bodyMasses[k], model.bodies[k].equivalentRadius, &model.bodies[k].material}), b, k);
    for (int p = 0; p < static_cast<int>(model.partners.size()); ++p) {
      const Partner& partner = model.partners[p];
      consider(pairLimit(side, {partnerMasses[p], partnerRadius(partner.shape), &partner.material}), b, bodyCount + p);
    }
  }
  return limit;
}

}  // namespace roundedmesh
