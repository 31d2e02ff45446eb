#include "pkg/law/NodeForces.hpp"

#include <algorithm>
#include <cmath>

namespace roundedmesh {

std::array<Real, 3> nodeForces(const std::array<Vector2r, 3>& nodes, const NormalLoad& load) {
  // Eq. 15 holds for a load of either sign (the energy law's damping pulls while the sides part); a zero load has no
  // centre of pressure.
  if (load.force == 0 || !std::isfinite(load.force)) return {0, 0, 0};
  const Vector2r centre = centreOfPressure(load);
  std::array<Real, 3> lambda;
  for (int i = 0; i < 3; ++i)
    lambda[i] = cross2(nodes[(i + 1) % 3] - centre, nodes[(i + 2) % 3] - centre);
  const Real twiceArea = lambda[0] + lambda[1] + lambda[2];
  // An edge-on triangle has no area to carry pressure; only round-off reaches here, and any split will do.
  if (twiceArea == 0) return {load.force / 3, load.force / 3, load.force / 3};
  // The centre of pressure lies in S, inside the projected triangle; clamping only removes round-off.
  Real sum = 0;
  for (Real& l : lambda) sum += (l = std::max(l / twiceArea, Real(0)));
  return {load.force * lambda[0] / sum, load.force * lambda[1] / sum, load.force * lambda[2] / sum};
}

void addNodeForcesToBody(const std::array<Vector3r, 3>& corners, const std::array<Real, 3>& forces,
                         const Vector3r& normal, Wrench& body1) {
  for (int i = 0; i < 3; ++i) {
    const Vector3r force = -forces[i] * normal;
    body1.force += force;
    body1.torque += corners[i].cross(force);
  }
}

}  // namespace roundedmesh
