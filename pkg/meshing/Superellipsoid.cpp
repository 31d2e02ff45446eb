#include "pkg/meshing/Superellipsoid.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace roundedmesh {

ImplicitSolid implicitSolid(const Superellipsoid& s) {
  for (const auto& [name, value] : {std::pair<const char*, Real>{"a", s.a}, {"b", s.b}, {"c", s.c}})
    if (!(std::isfinite(value) && value > 0))
      throw std::invalid_argument(std::string("superellipsoid semi-axis ") + name + " must be positive and finite, got " +
                                  std::to_string(value));
  if (!(std::isfinite(s.exponent) && s.exponent >= 2))
    throw std::invalid_argument("superellipsoid exponent must be at least 2 (smooth), got " + std::to_string(s.exponent));
  // The solid lies in the box of the semi-axes; its thinnest part is its smallest diameter.
  return {[s](const Vector3r& x) {
            return std::pow(std::abs(x.x() / s.a), s.exponent) + std::pow(std::abs(x.y() / s.b), s.exponent) +
                   std::pow(std::abs(x.z() / s.c), s.exponent) - 1;
          },
          Vector3r::Zero(), 1.01 * std::sqrt(s.a * s.a + s.b * s.b + s.c * s.c), 2 * std::min({s.a, s.b, s.c})};
}

Real superellipsoidVolume(const Superellipsoid& s) {
  const Real g = std::tgamma(1 + 1 / s.exponent);
  return 8 * s.a * s.b * s.c * g * g * g / std::tgamma(1 + 3 / s.exponent);
}

}  // namespace roundedmesh
