// Law2: the normal load of one triangle contact (Section 2.4): force Fn along n12 and moment Mn about the
// circle's centre c, from the pressure of Eq. 9 over the contact circle Omega intersected with S.
//   quadrature regime (Eqs. 11-13): Dunavant's 16-point rule on each triangle of a fan over S;
//   direct regime (Eq. 14, when pi a^2 < gamma A_S / (N_S N_Q)): the whole-circle force of Eq. 7 scaled by
//   the exact area fraction A(S n Omega) / A(Omega), acting at c_eff;
//   exact regime (beyond the paper, an option: regime='exact'): the integrals over S n Omega in closed form
//   (DiskPolygonIntegrals.hpp), force, moment and the contact's elastic energy, with no quadrature error and no
//   switch between regimes.
// A_S / (N_S N_Q) is the mean area per quadrature point over S's N_S fan triangles; for a triangular S
// it is the paper's A_j / N_Q. An elliptical contact is integrated the same way over T(S), where its pressure is
// circular (PressureGeom.hpp); areas are kept, and the moment is mapped back to the plane.
// The damping (Eq. 7) scales the elastic pressure by one factor, 1 + A ddelta/dt / delta, with ddelta/dt taken at
// the load's centre of pressure: there the load acts, so its damping part dissipates (F_d ddelta/dt >= 0) however
// the bodies turn. At c, the paper's point, a spinning body's faceted contacts can push where the sides part and feed
// the spin (doc/physics.md, "Damping").
#pragma once

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/math/DiskPolygonIntegrals.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

enum class Regime { Quadrature, Direct, Exact };
enum class RegimeChoice { Auto, Quadrature, Direct, Exact };

// How a triangle contact's elastic force acts on the bodies: the paper's, its integrated pressure at its centre of
// pressure (Eq. 15); or the exact gradient of its energy (ContactEnergyGradient.hpp, beyond the paper, an option),
// which integrates in closed form (the exact regime).
enum class NormalLaw { Pressure, Energy };

struct PressureOptions {
  Real gamma = 10;  // expected number of quadrature points inside the contact circle (Eq. 14)
  RegimeChoice regime = RegimeChoice::Auto;
  CurvatureModel curvature = CurvatureModel::Mean;  // circle (the paper) or ellipse (EllipticalContact.hpp)
  NormalLaw normal = NormalLaw::Pressure;
};

struct NormalLoad {
  Real force;        // Fn >= 0 along n12, acting on body 2 (body 1 receives -Fn n12) [N]
  Vector2r moment;   // Mn in plane coordinates (t1, t2): sum of r x (p dA n12) about c [N m]
  Regime regime;
  Real elasticForce = 0;  // the undamped part of Fn: the same integral at ddelta/dt = 0 [N]; Fn - it is damping
  Vector2r elasticMoment = Vector2r::Zero();  // the undamped part of Mn [N m]
  Real overlapRate = 0;   // ddelta/dt at the centre of pressure, which the damping is proportional to [m/s]
  // The contact's elastic energy [J]: (2/5) F_elastic delta_s (doc/physics.md, "Energy"), or in the exact regime the
  // integral over S n Omega of the energy density e = (4 E* / (3 pi R*^2)) (a^2 - r^2)^(3/2), whose
  // delta_s-derivative at fixed S is the elastic pressure.
  Real elasticEnergy = 0;
};

// Where the load acts, in plane coordinates relative to c [m]: (-Mn_y, Mn_x) / Fn, for Fn > 0.
inline Vector2r centreOfPressure(const NormalLoad& load) {
  return Vector2r(-load.moment.y(), load.moment.x()) / load.force;
}

// Law2: the damped load, dampedLoad(elasticLoad(...)).
NormalLoad Law2_PressureGeom_HertzPhys_IntegratedPressure(const PressureGeom& geom, const HertzPhys& phys,
                                                          const PressureOptions& options);
// Law2's two halves, for the engine, which damps a pair's contacts together (DampedLoads.hpp):
// the elastic load, the pressure at ddelta/dt = 0 integrated (force, moment, regime, elastic energy);
NormalLoad elasticLoad(const PressureGeom& geom, const HertzPhys& phys, const PressureOptions& options);
// that load kept as its elastic part and scaled by Eq. 7's damping at its centre of pressure (at c unless Fn > 0).
NormalLoad dampedLoad(NormalLoad elastic, const PressureGeom& geom, const HertzPhys& phys);

// The exact regime's parts, for the engine, which integrates a pair's contacts together in lanes
// (DiskPolygonBatch.hpp):
// whether the options integrate in closed form (regime='exact', or the energy law);
inline bool integratesExactly(const PressureOptions& options) {
  return options.regime == RegimeChoice::Exact || options.normal == NormalLaw::Energy;
}
// and the elastic load from the integrals over circlePolygon(geom) (S, or T(S) for an ellipse) with the disc of
// radius geom.contactRadius.
NormalLoad exactLoad(const DiskPolygonIntegrals& integrals, const PressureGeom& geom, const HertzPhys& phys);

}  // namespace roundedmesh
