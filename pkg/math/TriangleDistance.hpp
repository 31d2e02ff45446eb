// The least distance between two triangles abc and def in space [m] (Ericson, Real-Time Collision Detection, 5.1.9
// and 5.1.5): triangles that do not cross are closest at a corner of one against the other or between two edges, so
// the least of the six corner-triangle and nine edge-edge distances; 0 for triangles that share a corner. Triangles
// that cross each other (not two of one closed mesh) get the distance of their edges, which is then an upper bound.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "pkg/math/ClosestPoint.hpp"

namespace roundedmesh {

// The least distance between the segments pq and rs [m].
inline Real segmentDistance(const Vector3r& p, const Vector3r& q, const Vector3r& r, const Vector3r& s) {
  const Vector3r d1 = q - p, d2 = s - r, w = p - r;
  const Real a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(w);
  Real along1 = 0, along2 = 0;
  if (a == 0 && e == 0) return w.norm();
  if (a == 0) {
    along2 = std::clamp(f / e, Real(0), Real(1));
  } else {
    const Real c = d1.dot(w);
    if (e == 0) {
      along1 = std::clamp(-c / a, Real(0), Real(1));
    } else {
      const Real b = d1.dot(d2), denominator = a * e - b * b;
      // Parallel segments (denominator 0): any point of pq serves; take p.
      along1 = denominator > 0 ? std::clamp((b * f - c * e) / denominator, Real(0), Real(1)) : Real(0);
      along2 = (b * along1 + f) / e;
      if (along2 < 0) {
        along2 = 0;
        along1 = std::clamp(-c / a, Real(0), Real(1));
      } else if (along2 > 1) {
        along2 = 1;
        along1 = std::clamp((b - c) / a, Real(0), Real(1));
      }
    }
  }
  return ((p + along1 * d1) - (r + along2 * d2)).norm();
}

inline Real triangleDistance(const std::array<Vector3r, 3>& first, const std::array<Vector3r, 3>& second) {
  Real least = kInfinity;
  for (int i = 0; i < 3; ++i) {
    least = std::min(least, (first[i] - closestOnTriangle(first[i], second[0], second[1], second[2])).norm());
    least = std::min(least, (second[i] - closestOnTriangle(second[i], first[0], first[1], first[2])).norm());
    for (int j = 0; j < 3; ++j)
      least = std::min(least, segmentDistance(first[i], first[(i + 1) % 3], second[j], second[(j + 1) % 3]));
  }
  return least;
}

}  // namespace roundedmesh
