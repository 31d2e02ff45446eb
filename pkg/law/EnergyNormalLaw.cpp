// The energy law (doc/physics.md, "The energy law"): the elastic force is the exact gradient of the contact's
// energy (ContactEnergyGradient.hpp), so that it does no work round a closed path; the damping, the rest of the
// pressure, acts as the paper's (node forces, Eq. 15), pushing while the sides approach and pulling while they part,
// as Eq. 7's term does until the whole pressure reaches zero.
#include <cassert>

#include "pkg/law/HertzPressure.hpp"
#include "pkg/law/NormalLaws.hpp"

namespace roundedmesh {

void energyNormalLaw(const TriangleLoad& contact, Wrench& onBody) {
  const PressureGeom& geom = contact.geom;
  // The engine integrates this law's loads in closed form, over S itself: EngineOptions allows it circles only.
  assert(contact.exact != nullptr && !geom.elliptical);
  const NormalLoad& load = contact.load;
  addNodeForcesToBody(contact.corners, contact.dampingNodeForces, geom.normal, onBody);
  const EnergyForces elastic =
      contactEnergyGradient(geom, load.elasticForce, hertzEnergyAmplitude(contact.phys, geom.radius), contact.corners,
                            contact.sphereCentre, contact.partner, *contact.exact, contact.exactIndex);
  for (int k = 0; k < elastic.count; ++k) {
    onBody.force -= elastic.onBody2[k].force;
    onBody.torque -= elastic.onBody2[k].point.cross(elastic.onBody2[k].force);
  }
}

}  // namespace roundedmesh
