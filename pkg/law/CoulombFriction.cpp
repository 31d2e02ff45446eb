#include "pkg/law/CoulombFriction.hpp"

#include "pkg/law/HertzPressure.hpp"
#include "pkg/math/CirclePolygonArea.hpp"

namespace roundedmesh {

Real circleFraction(const PressureGeom& geom) {
  const Real a = geom.contactRadius;
  return circlePolygonArea(a, circlePolygon(geom)) / (M_PI * a * a);
}

TangentialLoad coulombFriction(const PressureGeom& geom, const NormalLoad& load, const HertzPhys& phys, Real share) {
  TangentialLoad out;
  const Real speed = geom.slip.norm();
  if (!(phys.friction > 0) || !(speed > 0)) return out;
  const Real threshold = phys.friction * hertzPressure(geom, phys).totalForce();
  out.sliding = phys.tangentialDamping * speed > threshold;
  if (out.sliding) {
    out.force = -phys.friction * load.force / speed * geom.slip;
  } else {
    out.force = -phys.tangentialDamping * (share < 0 ? circleFraction(geom) : share) * geom.slip;
  }
  return out;
}

}  // namespace roundedmesh
