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

// Infinite for two rigid sides, which have no Hertz contact (the scene refuses them), and for two sides that
// do not move under forces.
Real pairLimit(Side a, Side b, Real impactSpeed) {
  if (std::isinf(a.material->young) && std::isinf(b.material->young)) return std::numeric_limits<Real>::infinity();
  if (!(a.mass > 0)) std::swap(a, b);
  if (!(a.mass > 0)) return std::numeric_limits<Real>::infinity();
  const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(*a.material, *b.material);
  const Real mass = b.mass > 0 ? a.mass * b.mass / (a.mass + b.mass) : a.mass;
  const Real radius = std::isinf(b.radius) ? a.radius : a.radius * b.radius / (a.radius + b.radius);
  const Real overlap = kDeepestOverlap * std::min(a.radius, b.radius);
  return std::min(criticalTimeStep(mass, phys.effectiveModulus, radius, phys.damping, overlap),
                  impactTimeStep(mass, phys.effectiveModulus, radius, overlap, impactSpeed));
}

Real partnerRadius(const PartnerShape& shape) {
  if (const Sphere* sphere = std::get_if<Sphere>(&shape)) return sphere->radius;
  return std::numeric_limits<Real>::infinity();
}

}  // namespace

StabilityLimit stabilityLimit(const ContactModel& model, const std::vector<Real>& bodyMasses,
                              const std::vector<Real>& partnerMasses, Real impactSpeed) {
  StabilityLimit limit;
  const int bodyCount = static_cast<int>(model.bodies.size());
  // Every side as an engine index (bodies, then partners), and which ones move through the engine's contacts:
  // rounded bodies and sphere bodies.
  const int count = bodyCount + static_cast<int>(model.partners.size());
  auto side = [&](int i) -> Side {
    if (i < bodyCount) return {bodyMasses[i], model.bodies[i].equivalentRadius, &model.bodies[i].material};
    const Partner& partner = model.partners[i - bodyCount];
    return {partnerMasses[i - bodyCount], partnerRadius(partner.shape), &partner.material};
  };
  auto isBody = [&](int i) { return i < bodyCount || model.partners[i - bodyCount].sphereBody; };
  // Bodies alike in mass, size and material have the same limit: each kind is checked once.
  std::vector<int> kinds;
  for (int b = 0; b < count; ++b) {
    if (!isBody(b)) continue;
    const Side s = side(b);
    const bool seen = std::any_of(kinds.begin(), kinds.end(), [&](int k) {
      const Side o = side(k);
      return (k < bodyCount) == (b < bodyCount) && o.mass == s.mass && o.radius == s.radius &&
             std::tie(o.material->young, o.material->poisson, o.material->damping) ==
                 std::tie(s.material->young, s.material->poisson, s.material->damping);
    });
    if (!seen) kinds.push_back(b);
  }
  auto consider = [&](Real dt, int b, int other) {
    if (dt < limit.timeStep) limit = {dt, b, other};
  };
  for (int b : kinds) {
    for (int k : kinds)
      if (k >= b) consider(pairLimit(side(b), side(k), impactSpeed), b, k);
    // Partners other than bodies: a sphere body meets them all, a rounded body every partner.
    for (int p = bodyCount; p < count; ++p)
      if (b < bodyCount || !isBody(p)) consider(pairLimit(side(b), side(p), impactSpeed), b, p);
  }
  return limit;
}

}  // namespace roundedmesh
