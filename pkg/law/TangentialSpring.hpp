// Elastic tangential contact of one body pair (doc/physics.md, "Friction"), the engine's default friction law
// (FrictionLaw::Spring). The pair's triangle contacts share one spring-dashpot in the contact plane, kept between
// steps (ContactData::springs, beside the pair's candidate list) and forgotten when the pair stops touching:
//   u      shear displacement at the pair's centre of pressure x_c: the relative tangential velocity of body 2
//          against body 1 there, integrated over the steps (Cundall-Strack), carried with the contact frame
//          (the rotation taking the last step's normal to this one's, then the bodies' mean spin about it) and
//          kept in the contact plane;
//   theta  relative rotation of the bodies about the normal n (the patch's twist);
//   force on body 2 at x_c:   F = -k_t u - c v_t,   k_t = (4 G*/E*) k_n   (Mindlin: k_t/k_n = 8 G* a / (2 E* a));
//   torque on body 2 about n: M = -k_t J theta - c J w_n,   J = sum_i w_i |r_i|^2, the normal-force-weighted
//          polar moment of the triangle contacts' points r_i about x_c in the contact plane (w_i = Fn_i / N);
//   Coulomb:  (|F| / (mu N))^2 + (M / (mu N rho))^2 <= 1, N = sum_i Fn_i, rho = sum_i w_i |r_i| (the limit
//          surface of a patch of contact points, approximated by its ellipse); beyond it both are scaled back onto
//          the ellipse and the spring is reset to the capped force (sliding).
// k_n = sum_i (3/2) F_e,i / delta_s,i is the pair's normal stiffness (each triangle contact a Hertz contact,
// dF/d(delta) = (3/2) F / delta), G* = ((2 - nu_1)/G_1 + (2 - nu_2)/G_2)^-1, G = E / (2 (1 + nu)).
// The friction of each triangle contact, for listings and pictures, is its share w_i of F plus w_i (M/J) n x r_i:
// summed, they give F at x_c and M n.
#pragma once

#include "pkg/common/Types.hpp"
#include "pkg/phys/HertzPhys.hpp"

namespace roundedmesh {

// The tangential law of every contact in a scene (rm.engine(friction=...)): the elastic spring above, or the
// paper's viscous no-slip force of Eqs. 19-21 (CoulombFriction.hpp).
enum class FrictionLaw { Spring, Viscous };

// What one pair keeps from step to step (global frame). A spring whose normal is zero has not met its contact
// yet: it starts at zero.
struct TangentialSpring {
  Vector3r displacement = Vector3r::Zero();  // u [m], in the contact plane
  Real twist = 0;                            // theta [rad]
  Vector3r normal = Vector3r::Zero();        // n of the last update; zero: none yet
  Real energy = 0;                           // (1/2) k_t |u|^2 + (1/2) k_t J theta^2 after the last update [J]

  bool active() const { return !normal.isZero(0); }
};

// One step's contact of the pair, as the spring sees it (global frame).
struct SpringContact {
  Vector3r normal;        // unit n, from body 1 toward body 2
  Vector3r slip;          // tangential velocity of body 2 relative to body 1 at x_c [m/s]
  Real spin = 0;          // (w_2 - w_1) . n [rad/s]
  Real frameSpin = 0;     // (w_1 + w_2) / 2 . n: how fast the contact frame turns about n [rad/s]
  Real normalForce = 0;   // N [N]
  Real stiffness = 0;     // k_t [N/m]
  Real polarMoment = 0;   // J [m^2]
  Real meanRadius = 0;    // rho [m]
};

struct SpringLoad {
  Vector3r force = Vector3r::Zero();  // F on body 2 at x_c [N]
  Real torque = 0;                    // M on body 2 about n [N m]
  bool sliding = false;
  Real dissipatedPower = 0;  // -(F . v_t + M w_n) - d(energy)/dt: what the bodies lose and the spring does not keep [W]
};

// The spring brought to this step (dt: the time since its last update; 0 for a contact evaluated once, which
// then has no history) and its load.
SpringLoad tangentialSpring(const SpringContact& contact, const HertzPhys& phys, Real dt, TangentialSpring& spring);

// Rotates v (perpendicular to `from`) by the smallest rotation taking the unit vector `from` to the unit vector
// `to`; zero if they are opposite.
Vector3r carriedToNormal(const Vector3r& v, const Vector3r& from, const Vector3r& to);

}  // namespace roundedmesh
