// Where a segment crosses a triangle (Moller and Trumbore 1997, "Fast, minimum storage ray-triangle intersection").
#pragma once

#include "pkg/common/Types.hpp"

namespace roundedmesh {

// Where the segment from `from` to `to` crosses triangle abc (Moller-Trumbore), as a parameter in (0, 1]; -1 if it
// does not (a segment in the triangle's plane does not pass through it).
inline Real crossing(const Vector3r& from, const Vector3r& to, const Vector3r& a, const Vector3r& b, const Vector3r& c) {
  const Vector3r d = to - from, e1 = b - a, e2 = c - a;
  const Vector3r h = d.cross(e2);
  const Real det = e1.dot(h);
  if (det == 0) return -1;
  const Real inverse = 1 / det;
  const Vector3r s = from - a;
  const Real u = inverse * s.dot(h);
  if (u < 0 || u > 1) return -1;
  const Vector3r q = s.cross(e1);
  const Real v = inverse * d.dot(q);
  if (v < 0 || u + v > 1) return -1;
  const Real t = inverse * e2.dot(q);
  return t > 0 && t <= 1 ? t : -1;
}

// A segment that starts on triangle abc of a mesh, often at a corner or an edge of it (c_eff is often a corner of
// S), is started within abc instead, as far from the corner as round-off could blur (1e-6 of the way to its
// centroid), so that it starts on abc alone and then runs parallel: the shift to apply to both its ends.
inline Vector3r startWithin(const Vector3r& a, const Vector3r& b, const Vector3r& c, const Vector3r& from) {
  return 1e-6 * ((a + b + c) / 3 - from);
}

}  // namespace roundedmesh
