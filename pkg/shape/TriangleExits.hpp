// Part of a RoundedMesh: where a straight line that enters the flat solid through one of its triangles can leave it
// again, near where it entered (doc/physics.md, "Which triangle pairs touch"). A line entering through triangle i
// at an angle theta to its inward normal runs below the plane of i, and leaves the solid only through a triangle j
// that it crosses outward: j reaches below the plane of i, and its outward normal n_j has a positive component
// along the line, so n_i and n_j are more than 90 deg - theta apart. Such a j is an exit of i at that angle; the
// line cannot reach it before it has run the distance between the two triangles. For each triangle, its exits
// within `reach` [m], nearest first, each with the least of the angles theta (15, 30, ..., 90 deg) at which it
// counts. A segment that enters through i and crosses none of the exits it can reach stays inside: so a triangle
// pair's overlap is tested exactly against a few triangles instead of followed through the whole mesh.
#pragma once

#include <array>
#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

class RoundedMesh;

class TriangleExits {
 public:
  static constexpr int kLevels = 6;
  // cos of 15, 30, 45, 60, 75 and 90 deg: a line at theta counts exits from the first level with cos >= cos(theta).
  static constexpr std::array<Real, kLevels> kLevelCosines{0.96592582628906831, 0.86602540378443865,
                                                           0.70710678118654757, 0.5, 0.25881904510252074, 0};
  // Their sines: j is an exit at a level if cos(n_i, n_j) < sin(theta) = cos(90 deg - theta).
  static constexpr std::array<Real, kLevels> kLevelSines{0.25881904510252074, 0.5, 0.70710678118654757,
                                                         0.86602540378443865, 0.96592582628906831, 1};

  TriangleExits() = default;
  TriangleExits(const RoundedMesh& mesh, Real reach);

  Real reach() const { return reach_; }
  // The level of a line entering at cos(theta) = cosine with the inward normal (cosine > 0: a line that enters).
  static int level(Real cosine) {
    int k = 0;
    while (k < kLevels - 1 && cosine < kLevelCosines[k]) ++k;
    return k;
  }
  // How far such a line surely stays inside: the distance to the nearest exit of triangle t at that level, or
  // reach() if none is nearer [m].
  Real clearance(int t, Real cosine) const { return nearest_[t][level(cosine)]; }
  // The same for every triangle and level: triangle t's at level k is clearances()[kLevels t + k] [m].
  const Real* clearances() const { return nearest_.empty() ? nullptr : nearest_.front().data(); }
  // Whether such a line surely stays inside for `length` [m]: no exit at its angle is nearer.
  bool clear(int t, Real cosine, Real length) const { return length < clearance(t, cosine); }
  // Whether the segment from `entry`, a point of triangle t, to `end` (below the plane of t) surely stays in the
  // flat solid: it is no longer than reach() and crosses none of t's exits at its angle. False: it leaves, or is
  // too long to tell.
  bool keepsInside(const RoundedMesh& mesh, int t, const Vector3r& entry, const Vector3r& end) const;

 private:
  struct Exit {
    Real distance;
    int triangle;
    int level;
  };
  Real reach_ = 0;
  std::vector<std::array<Real, kLevels>> nearest_;  // contiguous: clearances()
  static_assert(sizeof(std::array<Real, kLevels>) == kLevels * sizeof(Real));
  std::vector<int> first_;  // triangle t's exits are exits_[first_[t]], ..., exits_[first_[t + 1] - 1]
  std::vector<Exit> exits_;
};

}  // namespace roundedmesh
