#include "pkg/engine/CriticalTimeStep.hpp"

#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

StabilityLimit stabilityLimit(const ContactModel& model, const std::vector<Real>& bodyMasses,
                              const std::vector<Real>& partnerMasses) {
  StabilityLimit limit;
  for (int b = 0; b < static_cast<int>(model.bodies.size()); ++b) {
    const RoundedBody& body = model.bodies[b];
    for (int p = 0; p < static_cast<int>(model.partners.size()); ++p) {
      const HertzPhys phys = Ip2_HertzMaterial_HertzMaterial_HertzPhys(body.material, model.partners[p].material);
      const Real partnerMass = partnerMasses[p];
      const Real bodyMass = bodyMasses[b];
      const Real mass = partnerMass > 0 ? bodyMass * partnerMass / (bodyMass + partnerMass) : bodyMass;
      const Real r = body.equivalentRadius;
      const Real dt = criticalTimeStep(mass, phys.effectiveModulus, r, phys.damping, r / 10);
      if (dt < limit.timeStep) limit = {dt, b, p};
    }
  }
  return limit;
}

}  // namespace roundedmesh
