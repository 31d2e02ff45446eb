// The energy law (doc/physics.md, "The energy law"): the elastic force is the exact gradient of the contact's
// energy (ContactEnergyGradient.hpp), so that it does no work round a closed path; the damping, the rest of the
// pressure, acts as the paper's (node forces, Eq. 15), pushing while the sides approach and pulling while they part,
// as Eq. 7's term does until the whole pressure reaches zero. A partner's rounded edge or corner meets a triangle in
// Hertz's ellipse (TriangleEdgeGeom.hpp), whatever the curvature model, whose pressure is not the circle's energy's
// gradient: there the paper's force acts.
#include <cassert>

#include "pkg/law/HertzPressure.hpp"
#include "pkg/law/NormalLaws.hpp"

namespace roundedmesh {

Real energyNormalLaw(const TriangleLoad& contact, Wrench& onBody) {
  const PressureGeom& geom = contact.geom;
  if (geom.elliptical) return pressureNormalLaw(contact, onBody);
  // The engine integrates this law's loads in closed form, over S itself for a circle.
  assert(contact.exact != nullptr);
  const NormalLoad& load = contact.load;
  addNodeForcesToBody(contact.corners, contact.dampingNodeForces, geom.normal, onBody);
  const EnergyForces elastic = contactEnergyGradient(
      geom, load.elasticForce, hertzEnergyAmplitude(contact.phys, geom.radius), contact.corners, contact.sphereCentre,
      contact.triangleNormal, contact.partner, *contact.exact, contact.exactIndex);
  for (int k = 0; k < elastic.count; ++k) {
    onBody.force -= elastic.onBody2[k].force;
    onBody.torque -= elastic.onBody2[k].point.cross(elastic.onBody2[k].force);
  }
  onBody.torque -= elastic.coupleOnBody2;
  return elastic.energy;
}

}  // namespace roundedmesh
