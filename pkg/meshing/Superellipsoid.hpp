// Superellipsoid (Barr 1981) |x/a|^p + |y/b|^p + |z/c|^p = 1: semi-axes a, b, c [m] along x, y, z and one exponent
// p >= 2 (2: an ellipsoid; 3-8: a pill or rounded box whose faces flatten and edges tighten as p grows), as an
// implicit solid for the mesher (ImplicitSurfaceMesher.hpp) and the curvature generators (ImplicitCurvature.hpp).
// Its volume is 8 a b c Gamma(1 + 1/p)^3 / Gamma(1 + 3/p). At the centre of a face (p > 2) both principal
// curvatures vanish: Hertz holds nowhere near it, which the speed-against-error study leaves out as a crease.
#pragma once

#include "pkg/meshing/ImplicitSurfaceMesher.hpp"

namespace roundedmesh {

struct Superellipsoid {
  Real a, b, c;   // semi-axes [m] > 0
  Real exponent;  // p >= 2
};

// f = |x/a|^p + |y/b|^p + |z/c|^p - 1. Throws std::invalid_argument naming the bad parameter.
ImplicitSolid implicitSolid(const Superellipsoid& shape);

Real superellipsoidVolume(const Superellipsoid& shape);

}  // namespace roundedmesh
