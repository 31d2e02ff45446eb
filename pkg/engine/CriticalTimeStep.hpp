// Largest stable time step of YADE's leap-frog (forces from positions at t and velocities at t - dt/2)
// for the damped Hertz contact of Eq. 7 linearised at overlap delta:
//   k = dF/d(delta) = 2 E* sqrt(R* delta),   c = dF/d(ddelta/dt) = (2/3) A k,
//   omega = sqrt(k/m),   zeta = c / (2 m omega) = A omega / 3,
//   dt_crit = (2 / omega) (sqrt(1 + zeta^2) - zeta)
// (the linear scheme's amplification matrix has spectral radius 1 there).
// Inputs: mass m [kg] (the reduced mass of the pair), E* [Pa], R* [m], A [s], delta [m]. Output [s].
#pragma once

#include <cmath>
#include <limits>

#include <vector>

#include "pkg/engine/ContactModel.hpp"

namespace roundedmesh {

inline Real criticalTimeStep(Real mass, Real effectiveModulus, Real radius, Real damping, Real overlap) {
  const Real stiffness = 2 * effectiveModulus * std::sqrt(radius * overlap);
  const Real omega = std::sqrt(stiffness / mass);
  const Real zeta = damping * omega / 3;
  return 2 / omega * (std::sqrt(1 + zeta * zeta) - zeta);
}

// The scene's limit: criticalTimeStep over every pair a rounded body or a sphere body can form (with another
// body or a partner), each rounded body taken as a sphere of its volume-equivalent radius r, a partner as a
// plane or its sphere: R* = r1 r2 / (r1 + r2), reduced mass, at an overlap of min(r1, r2) / 10, the deepest a Hertz
// contact is meant to go. An estimate for compact bodies: triangles much flatter than r, or an elongated
// body's lower effective mass when a contact also turns it, lower the true limit.
// bodyMasses[b]: the rounded bodies' masses [kg]; partnerMasses[p]: the mass of a partner that moves
// under forces, 0 for a driven or fixed one (also for a sphere body).
struct StabilityLimit {
  Real timeStep = std::numeric_limits<Real>::infinity();  // [s]
  int body = -1;   // index of the limiting body: a rounded body (< bodies.size()) or, past them, a sphere body
  int other = -1;  // the other side: a rounded body or, past them, a partner
};

StabilityLimit stabilityLimit(const ContactModel& model, const std::vector<Real>& bodyMasses,
                              const std::vector<Real>& partnerMasses);

}  // namespace roundedmesh
