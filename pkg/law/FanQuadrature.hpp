// Law2's quadrature points (Eq. 11) for a whole polygon at once: S is split into the fan of triangles
// (s_0, s_j, s_j+1), and at Dunavant's 16 points of each (DunavantRule.hpp) this computes the point (x, y) [m] in
// the contact plane and dG = area_j * w_i * sqrt(max(a^2 - x^2 - y^2, 0)) [m^3], the pressure's shape times the
// point's share of the area. The Hertz pressure at a point is its amplitude times that shape (HertzPressure.hpp).
//
// The points run several per instruction, on the widest vector unit the processor has (Google Highway, chosen at
// run time), with the same operations in the same order as one point at a time (no fused multiply-add): every
// lane is bitwise the reference's, whatever the vector unit (FanQuadratureTest).
#pragma once

#include "pkg/math/ConvexPolygon.hpp"

namespace roundedmesh {

struct FanQuadrature {
  static constexpr int kPoints = 16;
  static constexpr int kCapacity = ConvexPolygon::kCapacity - 2;  // triangles of the fan
  int triangles = 0;
  // Triangle j's points are [16 j, 16 j + 16).
  alignas(64) Real x[kCapacity * kPoints];
  alignas(64) Real y[kCapacity * kPoints];
  alignas(64) Real dG[kCapacity * kPoints];
};

// `contactRadiusSq`: a^2 [m^2]; `s`: the polygon in the contact plane's coordinates around c [m].
void fanQuadrature(const ConvexPolygon& s, Real contactRadiusSq, FanQuadrature& out);

}  // namespace roundedmesh
