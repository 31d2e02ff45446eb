#include "pkg/phys/HertzPhys.hpp"

#include <algorithm>
#include <stdexcept>

namespace roundedmesh {

HertzPhys Ip2_HertzMaterial_HertzMaterial_HertzPhys(const HertzMaterial& a, const HertzMaterial& b) {
  const Real compliance = a.compliance() + b.compliance();
  if (!(compliance > 0)) throw std::invalid_argument("young: two rigid bodies (infinite moduli) cannot be in Hertz contact");
  return {1 / compliance, 0.5 * (a.damping + b.damping), std::min(a.friction, b.friction),
          0.5 * (a.tangentialDamping + b.tangentialDamping),
          4 * compliance / (a.shearCompliance() + b.shearCompliance())};
}

}  // namespace roundedmesh
