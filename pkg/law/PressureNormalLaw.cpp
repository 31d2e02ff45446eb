// The paper's normal law: the integrated pressure acts at its centre of pressure, through node forces on the
// triangle's corners (Eqs. 15-17; NodeForces.hpp).
#include "pkg/law/NormalLaws.hpp"

namespace roundedmesh {

Real pressureNormalLaw(const TriangleLoad& contact, Wrench& onBody) {
  addNodeForcesToBody(contact.corners, contact.nodeForces, contact.geom.normal, onBody);
  return contact.load.elasticEnergy;
}

}  // namespace roundedmesh
