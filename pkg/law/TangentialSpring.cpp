#include "pkg/law/TangentialSpring.hpp"

#include <cmath>

namespace roundedmesh {

Vector3r carriedToNormal(const Vector3r& v, const Vector3r& from, const Vector3r& to) {
  const Vector3r axis = from.cross(to);  // sin(angle) times the unit axis
  const Real cosine = from.dot(to);
  if (!(cosine > -1 + 1e-12)) return Vector3r::Zero();
  // Rodrigues' formula with |axis| = sin, 1 - cos = sin^2 / (1 + cos).
  return v + axis.cross(v) + axis.cross(axis.cross(v)) / (1 + cosine);
}

SpringLoad tangentialSpring(const SpringContact& contact, const HertzPhys& phys, Real dt, TangentialSpring& spring) {
  SpringLoad out;
  const Vector3r& n = contact.normal;
  const Real previousEnergy = spring.energy;
  Vector3r u = Vector3r::Zero();
  Real theta = 0;
  if (spring.active()) {
    u = carriedToNormal(spring.displacement, spring.normal, n);
    const Real angle = contact.frameSpin * dt;
    if (angle != 0) u = std::cos(angle) * u + std::sin(angle) * n.cross(u);
    theta = spring.twist;
  }
  u += dt * contact.slip;
  u -= u.dot(n) * n;
  theta += dt * contact.spin;

  const Real k = contact.stiffness, c = phys.tangentialDamping, J = contact.polarMoment;
  Vector3r force = -k * u - c * contact.slip;
  Real torque = J > 0 ? -k * J * theta - c * J * contact.spin : 0;
  const Real forceLimit = phys.friction * contact.normalForce;
  const Real torqueLimit = forceLimit * contact.meanRadius;
  if (!(forceLimit > 0)) {
    out.sliding = !force.isZero(0) || torque != 0;
    force.setZero();
    torque = 0;
  } else {
    const Real yield = force.squaredNorm() / (forceLimit * forceLimit) +
                       (torqueLimit > 0 ? torque * torque / (torqueLimit * torqueLimit) : 0);
    if (yield > 1) {
      const Real scale = 1 / std::sqrt(yield);
      force *= scale;
      torque *= scale;
      out.sliding = true;
    }
  }
  if (out.sliding) {
    // The spring holds the capped load alone: reset to it.
    u = k > 0 ? Vector3r(-force / k) : Vector3r::Zero();
    theta = k * J > 0 ? -torque / (k * J) : 0;
  }
  if (!(J > 0)) theta = 0;
  spring.displacement = u;
  spring.twist = theta;
  spring.normal = n;
  spring.energy = 0.5 * k * (u.squaredNorm() + J * theta * theta);
  out.force = force;
  out.torque = torque;
  out.dissipatedPower = -(force.dot(contact.slip) + torque * contact.spin);
  if (dt > 0) out.dissipatedPower -= (spring.energy - previousEnergy) / dt;
  return out;
}

}  // namespace roundedmesh
