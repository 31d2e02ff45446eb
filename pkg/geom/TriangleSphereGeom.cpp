#include "pkg/geom/TriangleSphereGeom.hpp"

#include <algorithm>
#include <cmath>

namespace roundedmesh {
namespace {

// The in-plane distance from c of a circle's centre x (the projected circumcircle holds the projected
// triangle): if it exceeds a + rho, the triangle's projection misses the contact circle.
bool missesContactCircle(const Vector3r& x, Real rho, const Vector3r& c, const Vector3r& n, Real a) {
  const Vector3r offset = x - c;
  const Real inPlaneSq = offset.squaredNorm() - std::pow(offset.dot(n), 2);
  return inPlaneSq > std::pow(a + rho, 2);
}

}  // namespace

ContactSphere contactSphere(const RoundedMesh& mesh2, int t, const Matrix3r& rotation, const Vector3r& translation) {
  const RoundedTriangle& rounded = mesh2.rounded(t);
  ContactSphere sphere;
  sphere.centre = rotation * rounded.sphereCentre + translation;
  sphere.radius = rounded.radius;
  sphere.triangle = t;
  sphere.normal = rotation * rounded.normal;
  const Triangle& corners = mesh2.triangles()[t];
  for (int i = 0; i < 3; ++i) sphere.corners[i] = rotation * mesh2.vertices()[corners[i]] + translation;
  return sphere;
}

bool triangleSphereGeom(const RoundedMesh& mesh, int triangle, const ContactSphere& sphere,
                        const RelativeMotion& motion, PressureGeom& geom) {
  const RoundedTriangle& rounded = mesh.rounded(triangle);
  const Vector3r d = sphere.centre - rounded.sphereCentre;
  const bool isTriangle = sphere.triangle >= 0;
  if (!(rounded.normal.dot(d) > 0) || (isTriangle && !(sphere.normal.dot(d) < 0))) return false;

  const Real R1 = rounded.radius, R2 = sphere.radius;
  const Real distance = d.norm();
  const Real overlap = R1 + R2 - distance;
  if (!(overlap > 0)) return false;
  const Vector3r n = d / distance;
  const Real R = R1 * R2 / (R1 + R2);
  const Real a = std::sqrt(overlap * R);
  // (d - R2)(d + R2) rather than d^2 - R2^2: no cancellation when R2 is huge (a nearly flat triangle).
  const Vector3r c = rounded.sphereCentre + ((distance - R2) * (distance + R2) + R1 * R1) / (2 * distance) * n;
  if (missesContactCircle(rounded.circumcentre, rounded.circumradius, c, n, a)) return false;

  geom.tangent1 = n.unitOrthogonal();
  geom.tangent2 = n.cross(geom.tangent1);
  auto toPlane = [&](const Vector3r& x) { return Vector2r((x - c).dot(geom.tangent1), (x - c).dot(geom.tangent2)); };
  const Triangle& corners = mesh.triangles()[triangle];
  for (int i = 0; i < 3; ++i) geom.nodes[i] = toPlane(mesh.vertices()[corners[i]]);
  geom.polygon = ConvexPolygon::triangle(geom.nodes[0], geom.nodes[1], geom.nodes[2]);
  if (isTriangle) {
    for (int i = 0; i < 3; ++i) geom.partnerNodes[i] = toPlane(sphere.corners[i]);
    geom.polygon = geom.polygon.intersection(
        ConvexPolygon::triangle(geom.partnerNodes[0], geom.partnerNodes[1], geom.partnerNodes[2]));
  }
  if (geom.polygon.empty()) return false;

  geom.effectivePoint = geom.polygon.closestPoint(Vector2r::Zero());
  const Real hSq = geom.effectivePoint.squaredNorm();
  if (!(hSq < a * a)) return false;

  geom.triangle = triangle;
  geom.partnerTriangle = sphere.triangle;
  geom.centre = c;
  geom.normal = n;
  geom.radius = R;
  geom.sphereOverlap = overlap;
  geom.contactRadius = a;
  geom.effectiveOverlap = overlap - R1 - R2 + std::sqrt(std::max(R1 * R1 - hSq, Real(0))) +
                          std::sqrt(std::max(R2 * R2 - hSq, Real(0)));
  setRelativeVelocity(geom, motion);
  return true;
}

}  // namespace roundedmesh
