// IPhys of a Hertz contact between two materials (Ip2_HertzMaterial_HertzMaterial_HertzPhys):
//   E* = ((1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j)^-1   (Eq. 3)      A = (A_i + A_j) / 2   (Eq. 7)
//   mu = min(mu_i, mu_j)  (YADE's rule: a frictionless body stays frictionless)      c = (c_i + c_j) / 2
//   k_t / k_n = 4 G* / E*, G* = ((2 - nu_i)/G_i + (2 - nu_j)/G_j)^-1, G = E / (2 (1 + nu))   (Mindlin: k_t = 8 G* a,
//   k_n = 2 E* a): 2 (1 - nu) / (2 - nu) for two bodies of one material, 0.75 at nu = 0.4
// The combined radius R* (Eq. 3) belongs to each triangle pair and lives in PressureGeom.
#pragma once

#include "pkg/material/HertzMaterial.hpp"

namespace roundedmesh {

struct HertzPhys {
  Real effectiveModulus;  // E* [Pa]
  Real damping;           // A [s]
  Real friction = 0;           // mu
  Real tangentialDamping = 0;  // c [N s/m]
  Real stiffnessRatio = 0;     // k_t / k_n of the tangential spring (TangentialSpring.hpp)
};

HertzPhys Ip2_HertzMaterial_HertzMaterial_HertzPhys(const HertzMaterial& a, const HertzMaterial& b);

}  // namespace roundedmesh
