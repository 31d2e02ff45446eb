#include "pkg/geom/EllipticalContact.hpp"

#include <cmath>

#include "pkg/geom/EllipticalHertz.hpp"

namespace roundedmesh {
namespace {

// The height over its chord circle of radius rho of a sphere's cap of curvature H (negative: below the chord):
// R - sqrt(R^2 - rho^2) for R = 1/H, written so that it holds for any sign of H and never divides by zero; for a
// triangle wider than 1/H (rho |H| > 1) it continues as rho^2 H.
Real capHeight(Real H, Real rho) {
  return rho * rho * H / (1 + std::sqrt(std::max(1 - rho * rho * H * H, Real(0))));
}

}  // namespace

CapCurvature triangleCap(const RoundedMesh& mesh, int triangle, const PressureGeom& geom, const Matrix3r& rotation,
                         const Vector3r& translation) {
  const RoundedTriangle& r = mesh.rounded(triangle);
  const PrincipalCurvature& k = mesh.principal(triangle);
  // d1 projected on the plane, and its perpendicular there: the curvatures are kept exactly, so that a
  // flat direction stays flat and an isotropic triangle isotropic however the triangle is tilted.
  const Vector3r d1 = rotation * k.d1;
  const Vector2r u = Vector2r(d1.dot(geom.tangent1), d1.dot(geom.tangent2)).normalized();
  CapCurvature cap;
  cap.curvature = k.k2 * Matrix2r::Identity() + (k.k1 - k.k2) * u * u.transpose();
  cap.correction = Matrix2r::Identity() / r.radius - cap.curvature;
  const Vector3r offset = rotation * r.circumcentre + translation - geom.centre;
  cap.base = Vector2r(offset.dot(geom.tangent1), offset.dot(geom.tangent2));
  cap.sphereCurvature = 1 / r.radius;
  cap.heightShift = capHeight(k.mean(), r.circumradius) - r.capHeight;
  return cap;
}

CapCurvature exactCap(Real curvature) {
  CapCurvature cap;
  cap.curvature = curvature * Matrix2r::Identity();
  cap.sphereCurvature = curvature;
  return cap;
}

GeomTest ellipticalContact(PressureGeom& geom, const CapCurvature& cap1, const CapCurvature& cap2) {
  const Matrix2r K = cap1.curvature + cap2.curvature;
  const Vector2r L = -(cap1.correction * cap1.base + cap2.correction * cap2.base);
  const Real C = 0.5 * (cap1.base.dot(cap1.correction * cap1.base) + cap2.base.dot(cap2.correction * cap2.base));
  // Eigenvalues of the symmetric K: mean -+ radius; v along lambdaB, u = v turned by -90 degrees along lambdaA.
  const Real mean = 0.5 * (K(0, 0) + K(1, 1));
  const Real radius = std::sqrt(0.25 * (K(0, 0) - K(1, 1)) * (K(0, 0) - K(1, 1)) + K(0, 1) * K(0, 1));
  const Real lambdaA = mean - radius, lambdaB = mean + radius;
  if (!(lambdaB > 0.5 * (cap1.sphereCurvature + cap2.sphereCurvature))) return {Rejection::None};
  // An eigenvector of [[p, q], [q, r]] for lambdaB is (lambdaB - r, q) and (q, lambdaB - p): the first is the longer
  // for p >= r. None for a circle: any axes do.
  const Real q = 0.5 * (K(0, 1) + K(1, 0));
  const Vector2r along = K(0, 0) >= K(1, 1) ? Vector2r(lambdaB - K(1, 1), q) : Vector2r(q, lambdaB - K(0, 0));
  const Real length = along.norm();
  const Vector2r v = length > 0 ? Vector2r(along / length) : Vector2r(Vector2r::UnitX()), u(v.y(), -v.x());
  // Along a flat direction (line contact) the overlap has no maximum: x* stays with the triangles along it.
  const bool line = !(lambdaA * kLineContactRatio > lambdaB);
  const Vector2r centre =
      (line ? 0.5 * (cap1.base + cap2.base).dot(u) : L.dot(u) / lambdaA) * u + L.dot(v) / lambdaB * v;
  const Real overlap = geom.sphereOverlap + cap1.heightShift + cap2.heightShift + C + centre.dot(L - 0.5 * (K * centre));
  if (!(overlap > 0)) return {Rejection::NoOverlap};

  const HertzEllipse ellipse = hertzEllipse(lambdaA, lambdaB, overlap);
  const Real rho = std::sqrt(ellipse.a * ellipse.b);
  geom.elliptical = true;
  geom.ellipseCentre = centre;
  // The stretch along u and v, without a turn: the identity for a circle.
  geom.toCircle = rho / ellipse.a * u * u.transpose() + rho / ellipse.b * v * v.transpose();
  geom.sphereOverlap = overlap;
  geom.contactRadius = rho;
  geom.radius = 2 * rho / (M_PI * ellipse.peakPerModulus);  // (2 E*/pi) / radius = p0 / rho, as in Eq. 9

  const Vector2r nearest = circlePolygon(geom).closestPoint(Vector2r::Zero());
  if (!(nearest.squaredNorm() < rho * rho)) return {Rejection::BeyondContactCircle};
  geom.effectivePoint = centre + geom.toCircle.inverse() * nearest;
  const Vector2r fromCentre = geom.effectivePoint - centre;
  geom.effectiveOverlap = overlap - 0.5 * fromCentre.dot(K * fromCentre);
  return {Rejection::None};
}

}  // namespace roundedmesh
