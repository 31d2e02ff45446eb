// A small convex polygon in a plane, counter-clockwise, stored inline (no allocation): the projected
// triangles and their intersection polygon S of Section 2.3 / Appendix B. Clipping a triangle by a
// rectangle gives at most 7 corners, by a triangle at most 6, and S (at most 6) by a rectangle at most 10.
#pragma once

#include <array>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

class ConvexPolygon {
 public:
  static constexpr int kCapacity = 10;

  ConvexPolygon() = default;
  // A triangle in either orientation; stored counter-clockwise.
  static ConvexPolygon triangle(const Vector2r& a, const Vector2r& b, const Vector2r& c);
  // The axis-aligned rectangle [-hx, hx] x [-hy, hy] around centre.
  static ConvexPolygon rectangle(const Vector2r& centre, Real hx, Real hy);

  int size() const { return size_; }
  bool empty() const { return size_ < 3; }
  const Vector2r& operator[](int i) const { return corners_[i]; }
  void push(const Vector2r& p) {
    if (size_ == kCapacity) overflow();
    corners_[size_++] = p;
  }

  Real area() const;
  // True if p lies inside or on the boundary.
  bool contains(const Vector2r& p) const;
  // The point of the polygon (interior included) closest to p.
  Vector2r closestPoint(const Vector2r& p) const;
  // Keeps the part on the left of the directed line from a to b (Sutherland-Hodgman step).
  ConvexPolygon clippedBy(const Vector2r& a, const Vector2r& b) const;
  // The same into `out` (not this polygon), without a copy.
  void clipInto(const Vector2r& a, const Vector2r& b, ConvexPolygon& out) const;
  // Intersection with another convex polygon.
  ConvexPolygon intersection(const ConvexPolygon& clip) const;
  // Intersection with the square [-h, h]^2 about the origin, clipped only by the square's edges that have a corner
  // beyond them: the same corners as intersection(rectangle(0, h, h)), since clipping by another returns them
  // unchanged, for fewer clips where most of a polygon lies inside.
  ConvexPolygon clippedToSquare(Real h) const;
  ConvexPolygon translated(const Vector2r& offset) const;

 private:
  [[noreturn]] static void overflow();

  std::array<Vector2r, kCapacity> corners_;
  int size_ = 0;
};

}  // namespace roundedmesh
