// Hertz contact pressure with normal damping over a contact circle of radius a (Eq. 9), in the form whose
// integral over the circle is exactly the damped Hertz force of Eq. 7:
//   p(r) = (2 E* / (pi R*)) (1 + A ddelta/dt / delta) sqrt(a^2 - r^2),   r < a,  a^2 = delta R* (Eq. 5)
//   integral over the circle = (4/3) E* sqrt(R*) (delta^3/2 + A ddelta/dt delta^1/2)   (Eq. 7)
// The paper prints the damping term with 3 A instead of 2 A (Eq. 8), which integrates to 1.5 times the
// damping force of Eq. 7; doc/physics.md explains the choice. The pressure never pulls: a negative
// amplitude (fast separation) is clamped to zero. The elastic part, (2 E* / (pi R*)) sqrt(a^2 - r^2), is the
// pressure at ddelta/dt = 0: what the contact's elastic energy is computed from. Written with delta rather than
// a^2 / R*, the damping keeps Eq. 7's ratio A ddelta/dt / delta to the elastic force on an elliptical contact too,
// whose circle (PressureGeom::toCircle) has a^2 != delta R*. Law2 integrates the elastic part over S n Omega and
// damps it at the rate the sides approach at its centre of pressure
// (Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp).
#pragma once

#include <algorithm>
#include <cmath>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

struct HertzPressure {
  Real amplitude;        // (2 E* / (pi R*)) (1 + A ddelta/dt / delta), clamped at 0 [Pa/m]
  Real contactRadiusSq;  // a^2 [m^2]

  // Pressure at squared distance rSq from the circle's centre [Pa].
  Real at(Real rSq) const { return amplitude * std::sqrt(std::max(contactRadiusSq - rSq, Real(0))); }
  // The integral of sqrt(a^2 - r^2) over the whole circle, (2 pi / 3) a^3 [m^3].
  Real circleIntegral() const { return (2 * M_PI / 3) * contactRadiusSq * std::sqrt(contactRadiusSq); }
  // The pressure integrated over the whole circle: Eq. 7 [N].
  Real totalForce() const { return amplitude * circleIntegral(); }
};

// The elastic pressure's amplitude (2 E* / pi) / R* [Pa/m] of a contact of effective radius R* [m].
inline Real hertzElasticAmplitude(const HertzPhys& phys, Real radius) { return 2 * phys.effectiveModulus / (M_PI * radius); }

// The amplitude k of the contact's elastic energy density e = k (a^2 - r^2)^(3/2), whose delta-derivative is the
// elastic pressure: k = 4 E* / (3 pi R*^2) [Pa/m^2], the elastic pressure's amplitude times 2 / (3 R*).
inline Real hertzEnergyAmplitude(const HertzPhys& phys, Real radius) {
  return hertzElasticAmplitude(phys, radius) * 2 / (3 * radius);
}

// A Hertz contact's normal stiffness dF/d(delta) [N/m] from its elastic force F [N] at overlap delta [m]:
// (3/2) F / delta, since F grows as delta^(3/2) (Eq. 7); in closed form 2 E* sqrt(R* delta) (hertzStiffnessAt).
inline Real hertzStiffness(Real elasticForce, Real overlap) { return 1.5 * elasticForce / overlap; }
inline Real hertzStiffnessAt(const HertzPhys& phys, Real radius, Real overlap) {
  return 2 * phys.effectiveModulus * std::sqrt(radius * overlap);
}

// Eq. 7's damping as one factor on the elastic pressure, 1 + A (ddelta/dt) / delta, clamped at 0 so that the
// pressure never pulls. overlap delta [m], overlapRate ddelta/dt [m/s].
inline Real dampingFactor(const HertzPhys& phys, Real overlap, Real overlapRate) {
  return std::max(1 + phys.damping * overlapRate / overlap, Real(0));
}

// The pressure over the contact's whole circle, damped at the rate the sides approach at its centre c.
inline HertzPressure hertzPressure(const PressureGeom& geom, const HertzPhys& phys) {
  return {hertzElasticAmplitude(phys, geom.radius) * dampingFactor(phys, geom.sphereOverlap, geom.overlapRate),
          geom.contactRadius * geom.contactRadius};
}

}  // namespace roundedmesh
