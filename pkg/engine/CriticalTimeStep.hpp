// Largest stable time step of YADE's leap-frog (forces from positions at t and velocities at t - dt/2)
// for a linear oscillator x'' = -(k x + c v) / m:
//   omega = sqrt(k/m),   zeta = c / (2 m omega),   dt_crit = (2 / omega) (sqrt(1 + zeta^2) - zeta)
// (the scheme's amplification matrix has spectral radius 1 there), 2 m / c for k = 0.
// The normal contact is the damped Hertz contact of Eq. 7 linearised at overlap delta:
//   k = dF/d(delta) = 2 E* sqrt(R* delta),   c = dF/d(ddelta/dt) = (2/3) A k,   so zeta = A omega / 3;
// its mass is what a normal force at the contact point moves: 1/m_n = 1/m + max over the caps' corners and apexes x,
// with the cap's normal u there, of |I^-1/2 (x cross u)|^2 (m for a sphere; m / 18 for YADE's GTS horse, m / 6.4 for
// the gummy bear: a force on a limb turns the body). Heavily damped (zeta >> 1) the limit is about 2 m_n / c, so a
// limb's contact sets it: leaving rotation out overestimated it 11 times for two horses (doc/physics.md, "Time step").
// The tangential contact is the spring of TangentialSpring.hpp, k_t = (k_t/k_n) k, with the damping c of the
// materials (FrictionLaw::Spring), or the viscous no-slip force alone, k_t = 0 (FrictionLaw::Viscous); its mass is
// what a force at the contact point moves: 1/m_t = 1/m + max over contact points x and directions t of
// t^T [x]^T I^-1 [x] t (m/3.5 for a sphere), a bound for any contact point and direction.
//
// impactTimeStep: the step that resolves an impact at `speed` [m/s]: one that carries the bodies through at most
// kImpactFraction of the depth the impact reaches, the Hertz depth `overlap` [m] at most (deeper impacts are not
// Hertzian; the stop rules of StopRules.hpp watch them). An undamped Hertz impact integrated by the leap-frog with
// speed * dt = f times its depth (E = (8/15) E* sqrt(R*) depth^5/2 = m v^2 / 2) rebounds, over every phase of the
// step at which contact starts, with its energy within 0.03 % for f = 0.1 (0.25 % for 0.2, 2.5 % for 0.5, 15 % for
// 1; past about 1.5 the contact's stiffness at its depth makes the step unstable):
// tests/cpp/CriticalTimeStepTest.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "pkg/engine/ContactModel.hpp"

namespace roundedmesh {

// Inputs: mass [kg], stiffness [N/m], damping [N s/m]. Output [s]; infinite for k = c = 0.
inline Real leapFrogLimit(Real mass, Real stiffness, Real damping) {
  if (!(stiffness > 0)) return damping > 0 ? 2 * mass / damping : std::numeric_limits<Real>::infinity();
  const Real omega = std::sqrt(stiffness / mass);
  const Real zeta = damping / (2 * mass * omega);
  return 2 / omega * (std::sqrt(1 + zeta * zeta) - zeta);
}

// Fraction of the contact depth a body may move in one step at its impact speed (impactTimeStep).
constexpr Real kImpactFraction = 0.1;

inline Real impactTimeStep(Real mass, Real effectiveModulus, Real radius, Real overlap, Real speed) {
  if (!(speed > 0)) return std::numeric_limits<Real>::infinity();
  const Real depth = std::pow(15 * mass * speed * speed / (16 * effectiveModulus * std::sqrt(radius)), 0.4);
  return kImpactFraction * std::min(depth, overlap) / speed;
}

// The normal contact. Inputs: mass m [kg] (the reduced mass of the pair), E* [Pa], R* [m], A [s], delta [m].
// Output [s].
inline Real criticalTimeStep(Real mass, Real effectiveModulus, Real radius, Real damping, Real overlap) {
  const Real stiffness = 2 * effectiveModulus * std::sqrt(radius * overlap);
  return leapFrogLimit(mass, stiffness, 2.0 / 3.0 * damping * stiffness);
}

// The normal lever of a rounded body: max over its caps' corners and apexes x, with the cap's outward normal u there,
// of |I^-1/2 (x cross u)|^2 [1/kg], the most a unit normal force at a contact point accelerates that point along the
// normal through the body's turn (0 for a sphere, whose normals pass through its centre). Inputs: the mesh in its
// principal frame [m], its principal moments I [kg m^2]; 0 if one is not positive.
Real normalLever(const RoundedMesh& mesh, const Vector3r& inertia);

// The scene's limit: the normal and, with friction (mu > 0), the tangential limit over every pair a rounded body or
// a sphere body can form (with another body or a partner), each rounded body taken as a sphere of its
// volume-equivalent radius r, a partner as a plane or its sphere: R* = r1 r2 / (r1 + r2), reduced masses, at an
// overlap of min(r1, r2) / 10, the deepest a Hertz contact is meant to go. An estimate: triangles much flatter than r,
// or several contacts on one body, lower the true limit.
// bodyMasses[b]: the rounded bodies' masses [kg]; partnerMasses[p]: the mass of a partner that moves
// under forces, 0 for a driven or fixed one (also for a sphere body). bodyInertias, partnerInertias: their
// principal moments of inertia [kg m^2] (a rounded body's in its mesh's frame), for the tangential mass; empty (or
// zero for one side) leaves rotation out. A partner's contact points are taken at its farthest point (a Sphere's
// radius, a Box's corner, a Facet's farthest corner; Walls and Planes have none).
// With impactSpeed [m/s] > 0, the limit is also the impactTimeStep of every such pair at that speed.
struct StabilityLimit {
  Real timeStep = std::numeric_limits<Real>::infinity();  // [s]
  int body = -1;   // index of the limiting body: a rounded body (< bodies.size()) or, past them, a sphere body
  int other = -1;  // the other side: a rounded body or, past them, a partner
  bool tangential = false;  // the limit is the tangential contact's (friction), not the normal one's
};

StabilityLimit stabilityLimit(const ContactModel& model, const std::vector<Real>& bodyMasses,
                              const std::vector<Real>& partnerMasses, const std::vector<Vector3r>& bodyInertias = {},
                              const std::vector<Vector3r>& partnerInertias = {}, Real impactSpeed = 0);

}  // namespace roundedmesh
