// The distance from a closed triangulated surface's solid, on a grid in the body frame: 0 inside the solid,
// the distance to the surface outside, up to `band` (farther points read as band or more); and the signed distance,
// negative inside, down to -band. Between grid nodes the value is interpolated trilinearly; since the exact
// distance is 1-Lipschitz, the interpolated value differs from it by at most tolerance() = sqrt(3) * spacing. The contact criterion for deep triangle pairs
// (doc/physics.md, "Which triangle pairs touch") asks how far a triangle's cap lies from the other body's solid.
// Inputs: the surface's vertices [m] and triangles (closed, outward), the grid spacing [m] and band [m].
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

class SolidDistance {
 public:
  SolidDistance(const std::vector<Vector3r>& vertices, const std::vector<std::array<int, 3>>& triangles,
                Real spacing, Real band);

  // The interpolated distance at x (body frame) [m]: 0 inside.
  Real at(const Vector3r& x) const { return interpolated(x, true); }
  // The interpolated signed distance at x [m]: negative inside, the depth below the surface (to -band).
  Real signedAt(const Vector3r& x) const { return interpolated(x, false); }
  Real tolerance() const { return std::sqrt(Real(3)) * spacing_; }
  Real band() const { return band_; }

 private:
  Real node(int i, int j, int k) const { return values_[(static_cast<size_t>(k) * ny_ + j) * nx_ + i]; }
  Real interpolated(const Vector3r& x, bool outsideOnly) const;

  Vector3r origin_;  // the grid's first node
  Real spacing_, band_;
  int nx_, ny_, nz_;
  std::vector<float> values_;
};

}  // namespace roundedmesh
