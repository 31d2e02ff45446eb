#include "pkg/law/CoulombFriction.hpp"

#include "pkg/law/HertzPressure.hpp"
#include "pkg/math/CirclePolygonArea.hpp"

namespace roundedmesh {

TangentialLoad coulombFriction(const PressureGeom& geom, const NormalLoad& load, const HertzPhys& phys) {
  TangentialLoad out;
  const Real speed = geom.slip.norm();
  if (!phys.hasFriction() || !(speed > 0)) return out;
  const Real threshold = phys.friction * hertzPressure(geom, phys).totalForce();
  out.sliding = phys.tangentialDamping * speed > threshold;
  if (out.sliding) {
    out.force = -phys.friction * load.force / speed * geom.slip;
  } else {
    const Real a = geom.contactRadius;
    out.force = -phys.tangentialDamping * (circlePolygonArea(a, geom.polygon) / (M_PI * a * a)) * geom.slip;
  }
  return out;
}

}  // namespace roundedmesh
