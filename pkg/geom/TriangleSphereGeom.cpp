#include "pkg/geom/TriangleSphereGeom.hpp"

#include <algorithm>
#include <cmath>

#include "pkg/geom/EllipticalContact.hpp"
#include "pkg/geom/ProjectedTriangle.hpp"

namespace roundedmesh {
namespace {

// The in-plane distance from c of a circle's centre x (the projected circumcircle holds the projected
// triangle): if it exceeds a + rho, the triangle's projection misses the contact circle.
bool missesContactCircle(const Vector3r& x, Real rho, const Vector3r& c, const Vector3r& n, Real a) {
  const Vector3r offset = x - c;
  const Real height = offset.dot(n), reach = a + rho;
  return offset.squaredNorm() - height * height > reach * reach;
}

// The partner as a ContactSphere already in body 1's frame.
struct GivenSphere {
  const ContactSphere& sphere;
  const Vector3r& centre() const { return sphere.centre; }
  Real radius() const { return sphere.radius; }
  int triangle() const { return sphere.triangle; }
  Vector3r normal() const { return sphere.normal; }
  const Vector3r& corner(int i) const { return sphere.corners[i]; }
  CapCurvature cap(const PressureGeom& geom) const {
    return sphere.mesh ? triangleCap(*sphere.mesh, sphere.triangle, geom, sphere.rotation, sphere.translation)
                       : exactCap(1 / sphere.radius);
  }
};

// The partner as a triangle of body 2's mesh, each piece moved into body 1's frame when asked for.
struct MovedTriangle {
  explicit MovedTriangle(const PlacedTriangle& p) : placed(p), rounded(p.mesh.rounded(p.triangle)) {}
  Vector3r centre() const { return placed.rotation * rounded.sphereCentre + placed.translation; }
  Real radius() const { return rounded.radius; }
  int triangle() const { return placed.triangle; }
  Vector3r normal() const { return placed.rotation * rounded.normal; }
  Vector3r corner(int i) const {
    return placed.rotation * placed.mesh.vertices()[placed.mesh.triangles()[placed.triangle][i]] + placed.translation;
  }
  CapCurvature cap(const PressureGeom& geom) const {
    return triangleCap(placed.mesh, placed.triangle, geom, placed.rotation, placed.translation);
  }

  const PlacedTriangle placed;
  const RoundedTriangle& rounded;
};

// The tests before S, and the contact plane: fills geom's plane, radius, sphereOverlap, contactRadius, nodes, and
// polygon with P'; for a triangle partner also partnerNodes (Q's corners).
template <class Partner>
GeomTest contactPlane(const RoundedMesh& mesh, int triangle, const Partner& partner, PressureGeom& geom) {
  const RoundedTriangle& rounded = mesh.rounded(triangle);
  const Vector3r d = partner.centre() - rounded.sphereCentre;
  const bool isTriangle = partner.triangle() >= 0;
  if (!(rounded.normal.dot(d) > 0) || (isTriangle && !(partner.normal().dot(d) < 0))) return {Rejection::NotFacing};

  const Real R1 = rounded.radius, R2 = partner.radius();
  const Real distance = d.norm();
  const Real overlap = R1 + R2 - distance;
  if (!(overlap > 0)) return {Rejection::NoOverlap};
  const Vector3r n = d / distance;
  const Real R = R1 * R2 / (R1 + R2);
  const Real a = std::sqrt(overlap * R);
  // (d - R2)(d + R2) rather than d^2 - R2^2: no cancellation when R2 is huge (a nearly flat triangle).
  const Vector3r c = rounded.sphereCentre + ((distance - R2) * (distance + R2) + R1 * R1) / (2 * distance) * n;
  if (missesContactCircle(rounded.circumcentre, rounded.circumradius, c, n, a)) return {Rejection::OutsideCircle};

  geom.centre = c;
  geom.normal = n;
  geom.radius = R;
  geom.sphereOverlap = overlap;
  geom.contactRadius = a;
  geom.tangent1 = n.unitOrthogonal();
  geom.tangent2 = n.cross(geom.tangent1);
  projectTriangle(mesh, triangle, c, geom.tangent1, geom.tangent2, geom);
  if (isTriangle)
    for (int i = 0; i < 3; ++i)
      geom.partnerNodes[i] = planeCoordinates(partner.corner(i), c, geom.tangent1, geom.tangent2);
  return {Rejection::None};
}

// With S in geom.polygon and its point closest to c in geom.effectivePoint: the contact circle's test and the rest.
template <class Partner>
GeomTest contactOnPolygon(const RoundedMesh& mesh, int triangle, const Partner& partner, const RelativeMotion& motion,
                          PressureGeom& geom, CurvatureModel model) {
  if (geom.polygon.empty()) return {Rejection::EmptyPolygon};
  const Real hSq = geom.effectivePoint.squaredNorm();
  const Real a = geom.contactRadius;
  if (!(hSq < a * a)) return {Rejection::BeyondContactCircle};

  const Real R1 = mesh.rounded(triangle).radius, R2 = partner.radius();
  geom.triangle = triangle;
  geom.partnerTriangle = partner.triangle();
  geom.effectiveOverlap = geom.sphereOverlap - R1 - R2 + std::sqrt(std::max(R1 * R1 - hSq, Real(0))) +
                          std::sqrt(std::max(R2 * R2 - hSq, Real(0)));
  // A circular contact's ellipse fields are the identity's, not what an earlier candidate left in geom.
  geom.elliptical = false;
  geom.ellipseCentre = Vector2r::Zero();
  geom.toCircle = Matrix2r::Identity();
  if (model == CurvatureModel::Principal) {
    const GeomTest ellipse = ellipticalContact(geom, triangleCap(mesh, triangle, geom), partner.cap(geom));
    if (!ellipse) return ellipse;
  }
  setRelativeVelocity(geom, motion);
  return {Rejection::None};
}

template <class Partner>
GeomTest sphereGeom(const RoundedMesh& mesh, int triangle, const Partner& partner, const RelativeMotion& motion,
                    PressureGeom& geom, CurvatureModel model) {
  const GeomTest plane = contactPlane(mesh, triangle, partner, geom);
  if (!plane) return plane;
  if (partner.triangle() >= 0)
    clipByPartner(geom);
  else if (!geom.polygon.empty())
    geom.effectivePoint = geom.polygon.closestPoint(Vector2r::Zero());
  return contactOnPolygon(mesh, triangle, partner, motion, geom, model);
}

}  // namespace

ContactSphere contactSphere(const RoundedMesh& mesh2, int t, const Matrix3r& rotation, const Vector3r& translation) {
  const MovedTriangle moved(PlacedTriangle{mesh2, t, rotation, translation});
  ContactSphere sphere;
  sphere.centre = moved.centre();
  sphere.radius = moved.radius();
  sphere.triangle = t;
  sphere.normal = moved.normal();
  for (int i = 0; i < 3; ++i) sphere.corners[i] = moved.corner(i);
  sphere.mesh = &mesh2;
  sphere.rotation = rotation;
  sphere.translation = translation;
  return sphere;
}

GeomTest triangleSphereGeom(const RoundedMesh& mesh, int triangle, const ContactSphere& sphere,
                            const RelativeMotion& motion, PressureGeom& geom, CurvatureModel model) {
  return sphereGeom(mesh, triangle, GivenSphere{sphere}, motion, geom, model);
}

GeomTest triangleSphereGeom(const RoundedMesh& mesh, int triangle, const PlacedTriangle& partner,
                            const RelativeMotion& motion, PressureGeom& geom, CurvatureModel model) {
  return sphereGeom(mesh, triangle, MovedTriangle(partner), motion, geom, model);
}

void clipByPartner(PressureGeom& geom) {
  geom.polygon = geom.polygon.intersection(partnerPolygon(geom));
  if (!geom.polygon.empty()) geom.effectivePoint = geom.polygon.closestPoint(Vector2r::Zero());
}

GeomTest trianglePlane(const RoundedMesh& mesh, int triangle, const PlacedTriangle& partner, PressureGeom& geom) {
  return contactPlane(mesh, triangle, MovedTriangle(partner), geom);
}

GeomTest triangleContactOnPolygon(const RoundedMesh& mesh, int triangle, const PlacedTriangle& partner,
                                  const RelativeMotion& motion, PressureGeom& geom, CurvatureModel model) {
  return contactOnPolygon(mesh, triangle, MovedTriangle(partner), motion, geom, model);
}

}  // namespace roundedmesh
