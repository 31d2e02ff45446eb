// The normal laws: how one triangle contact's normal load (Law2) acts on the bodies, chosen by
// rm.engine(normal=...) (EngineOptions.hpp). Each law is one function in a file of its own, registered once in
// NormalLaws.cpp under the name users write:
//   'pressure' (PressureNormalLaw.cpp): the paper's, the integrated pressure at its centre of pressure, as node
//              forces on the triangle's corners (Eqs. 15-17);
//   'energy'   (EnergyNormalLaw.cpp): the exact gradient of the contact's elastic energy (ContactEnergyGradient.hpp),
//              its damping as the paper's.
// Adding a law: a value of NormalLaw (Law2_...IntegratedPressure.hpp), a file with its function, and its line in the
// registry.
#pragma once

#include <array>
#include <vector>

#include "pkg/law/ContactEnergyGradient.hpp"
#include "pkg/law/NodeForces.hpp"
#include "pkg/math/DiskPolygonBatch.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

// One triangle contact as a normal law sees it, in body 1's frame (origin at its position).
struct TriangleLoad {
  const PressureGeom& geom;
  const NormalLoad& load;
  const std::array<Vector3r, 3>& corners;  // body 1's triangle [m]
  const std::array<Real, 3>& nodeForces;   // Eq. 15 of the whole load [N]
  const std::array<Real, 3>& dampingNodeForces;  // Eq. 15 of its damping part, only for a law that needsDamping [N]
  const Vector3r& sphereCentre;            // of body 1's triangle [m]
  const Vector3r& triangleNormal;          // n1, body 1's triangle's outward unit normal
  const EnergyPartner& partner;            // body 2's side, filled only for a law that needsPartner
  const HertzPhys& phys;
  // Where the load was integrated in closed form (integratesExactly): its polygon is `exactIndex` of `exact`, S itself
  // for a circular contact (the energy law's, which always integrates so), T(S) for an ellipse.
  const DiskPolygonBatch* exact = nullptr;
  int exactIndex = 0;
};

// Adds the contact's force on body 1 to its wrench (torque about body 1's origin); returns the elastic energy the
// contact stores under this law [J], whose gradient its elastic force is where the law is conservative.
using NormalLawFunction = Real (*)(const TriangleLoad& contact, Wrench& onBody);

struct NormalLawEntry {
  const char* name;  // as users write it: rm.engine(normal=name)
  NormalLaw law;
  NormalLawFunction apply;
  bool needsPartner;  // whether the law reads TriangleLoad::partner (the engine builds it only then)
  bool needsDamping;  // whether it reads TriangleLoad::dampingNodeForces (the engine computes them only then)
};

// Every normal law, in the order of NormalLaw's values.
const std::vector<NormalLawEntry>& normalLaws();
const NormalLawEntry& normalLaw(NormalLaw law);

Real pressureNormalLaw(const TriangleLoad& contact, Wrench& onBody);
Real energyNormalLaw(const TriangleLoad& contact, Wrench& onBody);

}  // namespace roundedmesh
