// The deep-overlap term (doc/physics.md, "Deep overlaps and fast impacts", The core). Each rounded body carries a core: its inscribed
// spheres (InscribedSpheres.hpp), each shrunk by `inset` of its radius r to rho = (1 - inset) r, so that it lies
// inset r below the surface, inside the Hertz range of the radii there (a surface point an inscribed sphere touches
// has both principal radii >= r). Where a pair overlaps past that range the cores meet, and each pair of touching
// spheres pushes with Hertz's force of its own (Eq. 7 without damping), along the line through the two centres:
//     F = (4/3) E* sqrt(R) delta^3/2,   U = (8/15) E* sqrt(R) delta^5/2,
//     two core spheres:          delta = rho_i + rho_j - |c_i - c_j|,   R = rho_i rho_j / (rho_i + rho_j);
//     a core sphere on a plane:  delta = rho - h (h the centre's height over the plane on the body's side, negative
//                                behind it), R = rho; on a Box, a Facet panel's rim or a Sphere as on a sphere.
// F is a central force of the distance between two points fixed in the bodies, so it has the potential U: the core's
// energy rises along every approach of two of its spheres, and a body cannot pass through another without pushing its
// core through the other's, nor through a sheet without its centre reaching it (StopRules.hpp stops a run there).
// Input: E* [Pa]; the core sphere's centre relative to its body's position (global frame) [m]; delta [m]; R [m].
// Output: the wrench on the body (global; torque about its position), the energy [J].
#pragma once

#include <cmath>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct CoreLoad {
  Vector3r force = Vector3r::Zero();   // on the body [N]
  Vector3r torque = Vector3r::Zero();  // about the body's position [N m]
  Real energy = 0;                     // [J]
  int contacts = 0;                    // touching pairs of core spheres (or core sphere and partner)

  // A core sphere of the body at `arm` from the body's position pushed along the unit `normal` (toward the body) by an
  // overlap delta > 0 on the combined radius R.
  void add(const Vector3r& arm, const Vector3r& normal, Real delta, Real radius, Real modulus) {
    const Real stiffness = modulus * std::sqrt(radius * delta);  // E* sqrt(R delta)
    const Vector3r f = (Real(4) / 3 * stiffness * delta) * normal;
    force += f;
    torque += arm.cross(f);
    energy += Real(8) / 15 * stiffness * delta * delta;
    ++contacts;
  }
};

}  // namespace roundedmesh
