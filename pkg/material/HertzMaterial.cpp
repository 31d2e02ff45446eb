#include "pkg/material/HertzMaterial.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace roundedmesh {
namespace {

void require(bool ok, const char* parameter, Real value, const char* expectation) {
  if (ok) return;
  std::ostringstream message;
  message << parameter << " must be " << expectation << ", got " << value;
  throw std::invalid_argument(message.str());
}

}  // namespace

void HertzMaterial::validate() const {
  require(young > 0 && !std::isnan(young), "young", young, "positive (inf for a rigid body)");
  require(poisson > -1 && poisson < 0.5, "poisson", poisson, "in (-1, 0.5)");
  require(std::isfinite(density) && density > 0, "density", density, "positive and finite");
  require(std::isfinite(damping) && damping >= 0, "damping", damping, "non-negative and finite (seconds)");
  require(std::isfinite(friction) && friction >= 0, "friction", friction, "non-negative and finite");
  require(std::isfinite(tangentialDamping) && tangentialDamping >= 0, "tangential_damping", tangentialDamping,
          "non-negative and finite (N s/m)");
}

}  // namespace roundedmesh
