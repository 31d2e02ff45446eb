#include "pkg/geom/Ig2_Sphere_Partner_PressureGeom.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"
#include "pkg/math/Segment.hpp"

namespace roundedmesh {
namespace {

// The geometry once n12, c (on the line from s1 along n12), delta and R* are known.
GeomTest wholeCircle(const Vector3r& normal, const Vector3r& centre, Real overlap, Real radius,
                     const RelativeMotion& motion, PressureGeom& geom) {
  if (!(overlap > 0)) return {Rejection::NoOverlap};
  geom.triangle = -1;
  geom.partnerTriangle = -1;
  geom.normal = normal;
  geom.tangent1 = normal.unitOrthogonal();
  geom.tangent2 = normal.cross(geom.tangent1);
  geom.centre = centre;
  geom.radius = radius;
  geom.sphereOverlap = overlap;
  geom.effectiveOverlap = overlap;
  geom.contactRadius = std::sqrt(overlap * radius);
  // Twice the circle's radius, so that no corner of the square touches the circle: the area of S n Omega is
  // the whole circle's without a tangent edge for CirclePolygonArea to round.
  geom.polygon = ConvexPolygon::rectangle(Vector2r::Zero(), 2 * geom.contactRadius, 2 * geom.contactRadius);
  geom.effectivePoint = Vector2r::Zero();
  setRelativeVelocity(geom, motion);
  return {Rejection::None};
}

}  // namespace

GeomTest sphereSphereGeom(Real radius, const Vector3r& centre2, Real radius2, const RelativeMotion& motion,
                          PressureGeom& geom) {
  const Real d = centre2.norm();
  if (!(d > 0)) return {Rejection::NoOverlap};  // concentric: no direction to push along
  const Vector3r n = centre2 / d;
  const Real x = (d * d + radius * radius - radius2 * radius2) / (2 * d);
  return wholeCircle(n, x * n, radius + radius2 - d, radius * radius2 / (radius + radius2), motion, geom);
}

GeomTest spherePlaneGeom(Real radius, const Plane& plane, const RelativeMotion& motion, PressureGeom& geom) {
  const Real height = -plane.normal.dot(plane.point);  // of the sphere's centre above the plane
  return wholeCircle(-plane.normal, -height * plane.normal, radius - height, radius, motion, geom);
}

Plane boxPlane(const Box& box, const Vector3r& centre, const Matrix3r& orientation, Real edgeRadius) {
  const Vector3r local = orientation.transpose() * -centre;  // the sphere's centre in the box's frame
  const Vector3r& h = box.halfExtents;
  const Real rho = std::min(edgeRadius, h.minCoeff());
  // The rounded box is the box shrunk by rho, grown by a ball of rho: its point nearest a centre outside the shrunk
  // box lies rho beyond the shrunk box's nearest point.
  const Vector3r nearest = local.cwiseMax(-(h.array() - rho).matrix()).cwiseMin((h.array() - rho).matrix());
  if (nearest != local) {
    const Vector3r out = (local - nearest).normalized();
    const Vector3r point = centre + orientation * (nearest + rho * out);
    return {point, orientation * out};
  }
  // Sunk into the box: pushed out through the face it is least deep behind.
  int axis;
  (h - local.cwiseAbs()).minCoeff(&axis);
  const Real side = local[axis] >= 0 ? 1 : -1;
  const Vector3r normal = side * orientation.col(axis);
  return {centre + orientation * (local + (side * h[axis] - local[axis]) * Vector3r::Unit(axis)), normal};
}

std::optional<Plane> facetPlane(const PlacedFacet& facet) {
  // The facet in its own plane coordinates (origin at corner 0), the sphere's centre projected on it.
  const std::array<Vector3r, 3>& corners = facet.corners;
  if (!hasArea(corners)) return std::nullopt;
  const Vector3r u = (corners[1] - corners[0]).normalized();
  Vector3r normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  const Vector3r v = normal.cross(u);
  auto inPlane = [&](const Vector3r& x) { return Vector2r((x - corners[0]).dot(u), (x - corners[0]).dot(v)); };
  const std::array<Vector2r, 3> own{Vector2r::Zero(), inPlane(corners[1]), inPlane(corners[2])};
  const Vector2r centre = inPlane(Vector3r::Zero());
  Vector2r p;
  if (facet.weld) {  // the outline, counter-clockwise about the normal: the centre, or its nearest edge's point
    p = centre;
    Real nearest = std::numeric_limits<Real>::infinity();
    const int n = static_cast<int>(facet.outline.size());
    for (int i = 0; i < n; ++i) {
      const Vector2r a = inPlane(facet.outline[i]), b = inPlane(facet.outline[(i + 1) % n]);
      if (cross2(b - a, centre - a) >= 0) continue;
      const Vector2r x = closestOnSegment(centre, a, b);
      if ((x - centre).squaredNorm() < nearest) {
        nearest = (x - centre).squaredNorm();
        p = x;
      }
    }
    if (facet.weld->panelSize > 1 && !facetOwns(own, *facet.weld, p)) return std::nullopt;
  } else {
    p = ConvexPolygon::triangle(own[0], own[1], own[2]).closestPoint(centre);
  }
  if (normal.dot(-corners[0]) < 0) normal = -normal;  // both sides touch: the one the sphere is on
  const Vector3r point = corners[0] + p.x() * u + p.y() * v;
  // Normal to the line from the sphere's centre, or the facet's own normal if the centre lies on the facet.
  const Real distance = point.norm();
  return Plane{point, distance > 0 ? Vector3r(-point / distance) : normal};
}

}  // namespace roundedmesh
