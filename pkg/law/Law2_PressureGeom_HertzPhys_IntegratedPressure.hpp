// Law2: the normal load of one triangle contact (Section 2.4): force Fn along n12 and moment Mn about the
// circle's centre c, from the pressure of Eq. 9 over the contact circle Omega intersected with S.
//   quadrature regime (Eqs. 11-13): Dunavant's 16-point rule on each triangle of a fan over S;
//   direct regime (Eq. 14, when pi a^2 < gamma A_S / (N_S N_Q)): the whole-circle force of Eq. 7 scaled by
//   the exact area fraction A(S n Omega) / A(Omega), acting at c_eff.
// A_S / (N_S N_Q) is the mean area per quadrature point over S's N_S fan triangles; for a triangular S
// it is the paper's A_j / N_Q. An elliptical contact is integrated the same way over T(S), where its pressure is
// circular (PressureGeom.hpp); areas are kept, and the moment is mapped back to the plane.
#pragma once

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

enum class Regime { Quadrature, Direct };
enum class RegimeChoice { Auto, Quadrature, Direct };

struct PressureOptions {
  Real gamma = 10;  // expected number of quadrature points inside the contact circle (Eq. 14)
  RegimeChoice regime = RegimeChoice::Auto;
  CurvatureModel curvature = CurvatureModel::Mean;  // circle (the paper) or ellipse (EllipticalContact.hpp)
};

struct NormalLoad {
  Real force;        // Fn >= 0 along n12, acting on body 2 (body 1 receives -Fn n12) [N]
  Vector2r moment;   // Mn in plane coordinates (t1, t2): sum of r x (p dA n12) about c [N m]
  Regime regime;
  Real elasticForce = 0;  // the undamped part of Fn: the same integral at ddelta/dt = 0 [N]; Fn - it is damping
};

NormalLoad Law2_PressureGeom_HertzPhys_IntegratedPressure(const PressureGeom& geom, const HertzPhys& phys,
                                                          const PressureOptions& options);

}  // namespace roundedmesh
