// The facing test of Eq. B.5 made continuous in energy, for the energy law (doc/physics.md, "The energy law"). The
// test drops a triangle contact the moment its triangle turns side-on to the line of the spheres' centres
// (n . n12 = 0), and S n Omega may still hold energy then: a jump of the energy, which the work round a closed path
// picks up. The energy law stores w U instead of U, w = f(n1 . n12) f(-n2 . n12), one factor per triangle (a Sphere,
// or a plane's face, has none), where
//   f(x) = 0 for x <= 0,   3 t^2 - 2 t^3 with t = x / kFacingRamp for 0 < x < kFacingRamp,   1 from kFacingRamp on:
// continuous with its slope, so that the force, w U's gradient, stays continuous too. kFacingRamp = 0.1, a triangle
// more than 84 degrees from facing: no triangle of a smooth pair in the Hertz range is so far turned.
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

constexpr Real kFacingRamp = 0.1;

struct FacingRamp {
  Real value;  // f(x)
  Real slope;  // df/dx
};

inline FacingRamp facingRamp(Real cosine) {
  if (!(cosine > 0)) return {0, 0};
  if (cosine >= kFacingRamp) return {1, 0};
  const Real t = cosine / kFacingRamp;
  return {t * t * (3 - 2 * t), 6 * t * (1 - t) / kFacingRamp};
}

}  // namespace roundedmesh
