// Part of a RoundedMesh: where a straight line that enters the flat solid through one of its triangles can leave it
// again, near where it entered (doc/physics.md, "Which triangle pairs touch"). A line entering through triangle i
// at an angle theta to its inward normal runs below the plane of i, and leaves the solid only through a triangle j
// that it crosses outward: j reaches below the plane of i, and its outward normal n_j has a positive component
// along the line, so that n_i and n_j are more than 90 deg - theta apart:
//   n_i . n_j < sin(theta).
// Such a j is an exit of i at that angle; the line cannot reach it before it has run the distance between the two
// triangles. For each triangle: the triangles below its plane within `reach` [m], nearest first, with n_i . n_j. A
// segment that enters through i and crosses none of the exits it can reach stays inside: so a triangle pair's
// overlap is tested exactly against a few triangles instead of followed through the whole mesh.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

class RoundedMesh;

class TriangleExits {
 public:
  TriangleExits() = default;
  TriangleExits(const RoundedMesh& mesh, Real reach);

  Real reach() const { return reach_; }
  // Whether a line entering through triangle t at cos(theta) = cosine with its inward normal (0 < cosine <= 1)
  // surely stays inside for `length` [m]: no exit at that angle is nearer.
  bool clear(int t, Real cosine, Real length) const {
    const Real sine = std::sqrt(std::max(1 - cosine * cosine, Real(0)));
    for (int k = first_[t]; k < first_[t + 1] && exits_[k].distance < length; ++k)
      if (exits_[k].cosine < sine) return false;
    return length <= reach_;
  }
  // Whether the segment from `entry`, a point of triangle t, to `end` (below the plane of t) surely stays in the
  // flat solid: it is no longer than reach() and crosses none of t's exits at its angle. False: it leaves, or is
  // too long to tell.
  bool keepsInside(const RoundedMesh& mesh, int t, const Vector3r& entry, const Vector3r& end) const;

 private:
  struct Exit {
    Real distance;  // between the two triangles [m]
    Real cosine;    // n_i . n_j
    int triangle;
  };
  Real reach_ = 0;
  std::vector<int> first_;  // triangle t's candidates are exits_[first_[t]], ..., exits_[first_[t + 1] - 1]
  std::vector<Exit> exits_;
};

}  // namespace roundedmesh
