#include "pkg/engine/PairFriction.hpp"

namespace roundedmesh {

void releaseSpring(TangentialSpring& spring, Real dt, PairSummary& summary) {
  if (dt > 0) summary.frictionPower += spring.energy / dt;
  spring = TangentialSpring();
}

void dropUnusedSpring(const PairLaw& law, TangentialSpring* spring, Real dt, PairSummary& summary) {
  if ((!law.frictional() || law.viscous()) && spring && spring->active())
    releaseSpring(*spring, dt, summary);
}

SpringContact springContact(const Vector3r& normal_W, const Vector3r& slip_W, Real spin, const BodyState& s1,
                            const BodyState& s2, Real normalForce, Real stiffness) {
  SpringContact contact;
  contact.normal = normal_W;
  contact.slip = slip_W;
  contact.spin = spin;
  contact.frameSpin = 0.5 * (s1.angularVelocity + s2.angularVelocity).dot(normal_W);
  contact.normalForce = normalForce;
  contact.stiffness = stiffness;
  return contact;
}

void viscousFriction(const std::vector<PressureGeom>& geoms, const std::vector<ContactShare>& shares,
                     const HertzPhys& phys, const Matrix3r& R_WB, Wrench& onBody_B, PairResult& result,
                     TriangleContact* listed) {
  thread_local std::vector<Real> fraction;
  fraction.resize(geoms.size());
  Real fractions = 0;
  for (size_t k = 0; k < geoms.size(); ++k) fractions += fraction[k] = circleFraction(geoms[k]);
  for (size_t k = 0; k < geoms.size(); ++k) {
    const PressureGeom& geom = geoms[k];
    const TangentialLoad friction =
        coulombFriction(geom, shares[k].load, phys, fractions > 0 ? fraction[k] / fractions : 0);
    const Vector3r point_B = planePoint(geom, geom.effectivePoint);
    onBody_B.force -= friction.force;
    onBody_B.torque -= point_B.cross(friction.force);
    result.summary.frictionPower -= friction.force.dot(geom.slip);
    if (friction.sliding) {
      ++result.statistics.slidingContacts;
      result.summary.sliding = true;
    }
    if (listed) listed[k].friction = {R_WB * friction.force, friction.sliding};
  }
}

void springFriction(const std::vector<ContactShare>& shares, Real normalForce, Real normalStiffness,
                    const Vector3r& centre_B, const Vector3r& normal_B, const RelativeMotion& motion_B,
                    const BodyState& s1, const BodyState& s2, const HertzPhys& phys, Real dt, const Matrix3r& R_WB,
                    TangentialSpring& spring, Wrench& onBody_B, PairResult& result, TriangleContact* listed) {
  Real polar = 0, radius = 0;
  if (normalForce > 0) {
    for (const ContactShare& share : shares) {
      Vector3r r = share.point_B - centre_B;
      r -= r.dot(normal_B) * normal_B;
      polar += share.load.force * r.squaredNorm();
      radius += share.load.force * r.norm();
    }
    polar /= normalForce;
    radius /= normalForce;
  }
  const Vector3r v_B = motion_B.at(centre_B);
  SpringContact contact = springContact(R_WB * normal_B, R_WB * (v_B - v_B.dot(normal_B) * normal_B),
                                        motion_B.angular.dot(normal_B), s1, s2, normalForce,
                                        phys.stiffnessRatio * normalStiffness);
  contact.polarMoment = polar;
  contact.meanRadius = radius;
  const SpringLoad load = tangentialSpring(contact, phys, dt, spring);
  const Vector3r force_B = R_WB.transpose() * load.force;
  onBody_B.force -= force_B;
  onBody_B.torque -= centre_B.cross(force_B) + load.torque * normal_B;
  result.summary.frictionPower += load.dissipatedPower;
  result.summary.elasticEnergy += spring.energy;
  result.summary.sliding = load.sliding;
  if (load.sliding) result.statistics.slidingContacts += static_cast<int>(shares.size());
  if (listed) {
    for (size_t k = 0; k < shares.size(); ++k) {
      const Real w = normalForce > 0 ? shares[k].load.force / normalForce : 0;
      Vector3r r = shares[k].point_B - centre_B;
      r -= r.dot(normal_B) * normal_B;
      const Vector3r twist =
          polar > 0 ? Vector3r(load.torque / polar * contact.normal.cross(R_WB * r)) : Vector3r::Zero();
      listed[k].friction = {w * (load.force + twist), load.sliding};
    }
  }
}

}  // namespace roundedmesh
