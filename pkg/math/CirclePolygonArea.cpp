#include "pkg/math/CirclePolygonArea.hpp"

#include <algorithm>
#include <cmath>

namespace roundedmesh {
namespace {

Real angleBetween(const Vector2r& u, const Vector2r& v) { return std::atan2(cross2(u, v), u.dot(v)); }

// Signed area of the disc of radius r at the origin intersected with the triangle (origin, p, q).
// Sectors are taken only where the segment runs outside the disc, between points on the circle or
// outside it: an angle between two vectors near the origin (a corner at the disc's centre, up to
// round-off) would be arbitrary.
Real discTriangleArea(const Vector2r& p, const Vector2r& q, Real r) {
  const Vector2r d = q - p;
  const Real a = d.squaredNorm();
  if (a == 0) return 0;
  // Points p + t d on the circle: a t^2 + 2 b t + c = 0.
  const Real b = p.dot(d);
  const Real c = p.squaredNorm() - r * r;
  const Real discriminant = b * b - a * c;
  const Real s = discriminant > 0 ? std::sqrt(discriminant) : 0;
  const Real tIn = std::max((-b - s) / a, Real(0));
  const Real tOut = std::min((-b + s) / a, Real(1));
  if (discriminant <= 0 || tIn >= tOut) return 0.5 * r * r * angleBetween(p, q);  // the segment stays outside

  Real area = 0;
  Vector2r enter = p, leave = q;
  if (tIn > 0) {
    enter = p + tIn * d;
    area += 0.5 * r * r * angleBetween(p, enter);
  }
  if (tOut < 1) {
    leave = p + tOut * d;
    area += 0.5 * r * r * angleBetween(leave, q);
  }
  return area + 0.5 * cross2(enter, leave);
}

}  // namespace

Real circlePolygonArea(Real radius, const ConvexPolygon& polygon) {
  if (polygon.empty() || radius <= 0) return 0;
  Real area = 0;
  for (int i = 0; i < polygon.size(); ++i)
    area += discTriangleArea(polygon[i], polygon[(i + 1) % polygon.size()], radius);
  return std::max(area, Real(0));
}

}  // namespace roundedmesh
