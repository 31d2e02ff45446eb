// Law2's damping and Eq. 15 for many triangle contacts at once (a pair's contacts, in lanes): for each lane, from
// the contact's elastic load Fe, Me (elasticLoad, Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp),
//   c_p = (-Me_y, Me_x) / Fe                                 the centre of pressure, about c [m]
//   ddelta/dt = ddelta/dt(c) + slope . c_p                   the approach rate there (at c unless Fe > 0) [m/s]
//   f = max(1 + A (ddelta/dt) / delta_s, 0)                  Eq. 7's damping factor (HertzPressure.hpp)
//   Fn = f Fe, Mn = f Me                                     the damped load [N, N m]
//   f_i = Fn lambda_i / sum(lambda), lambda_i >= 0           the node forces of Eq. 15 (NodeForces.hpp) [N]
// with lambda_i the barycentric weights of the damped load's centre of pressure on the triangle's projected corners;
// where asked, the same for the damping part alone, Fn - Fe and Mn - Me (the energy law's, whose elastic force is the
// energy's gradient instead).
//
// As the narrow phase's batched kernels: Google Highway lanes with dampedLoad's and nodeForces' operations in their
// order and no fused multiply-add, every lane their result bit for bit (DampedLoadsTest). Unlike S's lanes these pay
// on every vector unit: a contact's divisions form one chain, which lanes run side by side.
#pragma once

#include <array>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/law/Law2_PressureGeom_HertzPhys_IntegratedPressure.hpp"

namespace roundedmesh {

struct DampedLoads {
  static constexpr int kCapacity = 16;  // lanes per batch: a multiple of every x86 vector unit's width

  int size = 0;              // lanes in use
  Real damping = 0;          // A of the pair's HertzPhys [s]
  bool withDamping = false;  // whether to give the node forces of the damping part too (the energy law's)
  // Inputs: the elastic load, and the contact's approach rate at c with its slope, sphere overlap and nodes.
  alignas(64) Real force[kCapacity], momentX[kCapacity], momentY[kCapacity];
  Regime regime[kCapacity];
  Real elasticEnergy[kCapacity];
  alignas(64) Real overlapRate[kCapacity], slopeX[kCapacity], slopeY[kCapacity], overlap[kCapacity];
  alignas(64) Real nodeX[3][kCapacity], nodeY[3][kCapacity];
  // Outputs: the damped load, the approach rate at its centre of pressure, and the node forces.
  alignas(64) Real dampedForce[kCapacity], dampedMomentX[kCapacity], dampedMomentY[kCapacity];
  alignas(64) Real rateAtCentre[kCapacity];
  alignas(64) Real nodeForce[3][kCapacity];
  alignas(64) Real dampingNodeForce[3][kCapacity];  // Eq. 15 of the damped load less the elastic one

  void set(int k, const NormalLoad& elastic, const PressureGeom& geom);
  // Lane k's load as dampedLoad makes it from the elastic load set there, and its node forces.
  NormalLoad load(int k) const;
  std::array<Real, 3> nodeForces(int k) const { return {nodeForce[0][k], nodeForce[1][k], nodeForce[2][k]}; }
  std::array<Real, 3> dampingNodeForces(int k) const {
    return {dampingNodeForce[0][k], dampingNodeForce[1][k], dampingNodeForce[2][k]};
  }
};

// Fills the outputs of lanes [0, size); the inputs of the lanes past `size` become copies of lane 0's.
void dampLoads(DampedLoads& batch);

}  // namespace roundedmesh
