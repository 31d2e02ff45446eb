#include "pkg/engine/SpherePair.hpp"

#include "pkg/common/Overloaded.hpp"
#include "pkg/engine/PairFriction.hpp"
#include "pkg/engine/PairGeometry.hpp"
#include "pkg/engine/PairLoad.hpp"
#include "pkg/geom/Ig2_Sphere_Partner_PressureGeom.hpp"
#include "pkg/law/PairLaw.hpp"

namespace roundedmesh {

PairResult resolveSpherePair(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                             TangentialSpring* spring) {
  const int bodyCount = static_cast<int>(model.bodies.size());
  const Partner& sphere = model.partners[pair.body - bodyCount];
  const Partner& other = model.partners[pair.other - bodyCount];
  const BodyState& s1 = data.state(pair.body);
  const BodyState& s2 = data.state(pair.other);
  const Real radius = std::get<Sphere>(sphere.shape).radius;
  // The sphere's frame: origin at its centre, global axes (a sphere's orientation does not change its contacts).
  const RelativeMotion motion = relativeMotion(s1, s2, Matrix3r::Identity());
  auto local = [&](const Vector3r& x) -> Vector3r { return x - s1.position; };
  PressureGeom geom;
  const GeomTest found = std::visit(
      Overloaded{[&](const Sphere& s) { return sphereSphereGeom(radius, local(s2.position), s.radius, motion, geom); },
                 [&](const Plane& p) { return spherePlaneGeom(radius, {local(p.point), p.normal}, motion, geom); },
                 [&](const Wall& w) {
                   const Plane p = wallPlane(w, s2.position, s1.position);
                   return spherePlaneGeom(radius, {local(p.point), p.normal}, motion, geom);
                 },
                 [&](const Box& b) {
                   return spherePlaneGeom(radius,
                                          boxPlane(b, local(s2.position), s2.orientation.toRotationMatrix(),
                                                   edgeRadiusFor(other, radius)),
                                          motion, geom);
                 },
                 [&](const Facet& f) {
                   const std::optional<Plane> plane =
                       facetPlane(placeFacet(f, s2.orientation.toRotationMatrix(), local(s2.position)));
                   return plane ? spherePlaneGeom(radius, *plane, motion, geom) : GeomTest{Rejection::NoOverlap};
                 }},
      other.shape);
  PairResult result;
  result.statistics.bodyPairs = 1;
  if (!found) {
    if (spring) releaseSpring(*spring, data.timeStep, result.summary);  // not touching: the spring lets go
    return result;
  }
  result.statistics.touchingPairs = 1;
  result.statistics.sphereContacts = 1;
  const PairLaw law(sphere.material, other.material, model.options.pressure, model.options.friction);
  const HertzPhys& phys = law.phys;
  const NormalLoad load = law.wholeCircleLoad(geom);
  result.summary.add(geom, load);
  TangentialLoad friction;
  dropUnusedSpring(law, spring, data.timeStep, result.summary);
  if (law.viscous()) {
    friction = coulombFriction(geom, load, phys);
    result.summary.frictionPower += -friction.force.dot(geom.slip);
  } else if (law.frictional()) {
    // One contact point: the spring at c, without twist.
    const SpringContact contact =
        springContact(geom.normal, geom.slip, motion.angular.dot(geom.normal), s1, s2, load.force,
                      phys.stiffnessRatio * hertzStiffness(load.elasticForce, geom.sphereOverlap));
    TangentialSpring fresh;
    TangentialSpring& held = spring ? *spring : fresh;
    const SpringLoad spun = tangentialSpring(contact, phys, spring ? data.timeStep : 0, held);
    friction = {spun.force, spun.sliding};
    result.summary.frictionPower += spun.dissipatedPower;
    result.summary.elasticEnergy += held.energy;
  }
  result.statistics.slidingContacts = friction.sliding;
  result.summary.sliding = friction.sliding;
  result.summary.triangleContacts = 1;  // the one contact over the whole circle
  result.summary.depth = result.summary.deepestOverlap;
  result.summary.point = s1.position + planePoint(geom, geom.effectivePoint);
  result.summary.normal = geom.normal;
  // The normal force acts along the line of centres (c lies on it) and has no moment about the sphere's centre.
  result.onBody.force = -load.force * geom.normal - friction.force;
  result.onBody.torque = planePoint(geom, geom.effectivePoint).cross(-friction.force);
  result.onOther = reaction(result.onBody, s1.position, s2.position);
  return result;
}

}  // namespace roundedmesh
