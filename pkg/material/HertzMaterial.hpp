// Material of a body in Hertz contact (Section 2.2, Table 1): Young's modulus E [Pa] (infinity for a rigid
// body), Poisson's ratio nu in (-1, 0.5), density [kg/m^3], normal damping constant A [s] of Eq. 7, the
// Coulomb friction coefficient mu and the tangential damping constant c [N s/m]: of the tangential spring-dashpot
// (TangentialSpring.hpp), or the viscous no-slip constant of Eqs. 18-21 (CoulombFriction.hpp).
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct HertzMaterial {
  Real young;
  Real poisson;
  Real density;
  Real damping = 0;
  Real friction = 0;
  Real tangentialDamping = 0;

  // Throws std::invalid_argument naming the first parameter out of range.
  void validate() const;
  // (1 - nu^2) / E, the body's share of 1/E* in Eq. 3; zero for a rigid body.
  Real compliance() const { return (1 - poisson * poisson) / young; }
  // (2 - nu) / G = 2 (2 - nu)(1 + nu) / E, the body's share of 1/G* in Mindlin's tangential stiffness 8 G* a.
  Real shearCompliance() const { return 2 * (2 - poisson) * (1 + poisson) / young; }
};

}  // namespace roundedmesh
