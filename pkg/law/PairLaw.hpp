// The contact law of one pair, as law/ owns it and engine/ applies it in its frames (PairLoad.cpp, SpherePair.cpp):
//   Ip2: the pair's HertzPhys from the two materials (HertzPhys.hpp);
//   Law2: each triangle contact's normal load, the Hertz pressure integrated over S n Omega (Eqs. 9-14);
//   the normal law that makes that load a force on the bodies (NormalLaws.hpp: 'pressure', Eq. 15, or 'energy');
//   the friction law (FrictionLaw: the pair's tangential spring, or the paper's viscous law), whose spring scales
//   the Hertz stiffness (HertzPressure.hpp).
// Everything here follows from the materials and the engine's options; nothing depends on frames or poses.
#pragma once

#include "pkg/law/HertzPressure.hpp"
#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"
#include "pkg/law/NormalLaws.hpp"
#include "pkg/law/TangentialSpring.hpp"
#include "pkg/material/HertzMaterial.hpp"

namespace roundedmesh {

struct PairLaw {
  HertzPhys phys;
  PressureOptions pressure;
  const NormalLawEntry* normal;
  FrictionLaw friction;

  PairLaw(const HertzMaterial& first, const HertzMaterial& second, const PressureOptions& options,
          FrictionLaw frictionLaw)
      : phys(Ip2_HertzMaterial_HertzMaterial_HertzPhys(first, second)),
        pressure(options),
        normal(&normalLaw(options.normal)),
        friction(frictionLaw) {}

  // Law2's elastic load of one triangle contact, which the engine damps with the pair's others (DampedLoads.hpp).
  NormalLoad elasticLoad(const PressureGeom& geom) const { return roundedmesh::elasticLoad(geom, phys, pressure); }
  // Whether that load is integrated in closed form, and then the same load from the closed forms' integrals over
  // circlePolygon(geom), which the engine takes in lanes (DiskPolygonBatch.hpp).
  bool integratesExactly() const { return roundedmesh::integratesExactly(pressure); }
  NormalLoad exactLoad(const DiskPolygonIntegrals& integrals, const PressureGeom& geom) const {
    return roundedmesh::exactLoad(integrals, geom, phys);
  }
  // The load of a contact that is one whole circle (two spheres, a sphere on a flat partner): Eq. 7 itself.
  NormalLoad wholeCircleLoad(const PressureGeom& geom) const {
    PressureOptions whole = pressure;
    whole.regime = RegimeChoice::Direct;
    return Law2_PressureGeom_HertzPhys_IntegratedPressure(geom, phys, whole);
  }
  // Whether the pair has friction at all (a positive coefficient), and whether it is the viscous law's.
  bool frictional() const { return phys.friction > 0; }
  bool viscous() const { return friction == FrictionLaw::Viscous; }
};

}  // namespace roundedmesh
