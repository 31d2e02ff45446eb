#include "pkg/meshing/Spheroid.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "pkg/meshing/ImplicitSurfaceMesher.hpp"

namespace roundedmesh {
namespace {

ImplicitSolid spheroid(Real a, Real b) {
  if (!(std::isfinite(a) && a > 0 && std::isfinite(b) && b > 0))
    throw std::invalid_argument("spheroid semi-axes must be positive and finite, got a = " + std::to_string(a) +
                                ", b = " + std::to_string(b));
  return {[a, b](const Vector3r& x) { return (x.x() * x.x() + x.y() * x.y()) / (b * b) + x.z() * x.z() / (a * a) - 1; },
          Vector3r::Zero(), 1.1 * std::max(a, b), 2 * std::min(a, b)};
}

}  // namespace

TriangleSurface spheroidSurface(Real a, Real b, int nodes) { return meshImplicitSurface(spheroid(a, b), nodes); }

Real spheroidMeanCurvature(Real a, Real b, const Vector3r& x) {
  const Real a2 = a * a, b2 = b * b;
  const Real q = (x.x() * x.x() + x.y() * x.y()) / (b2 * b2) + x.z() * x.z() / (a2 * a2);
  return (a2 + 2 * b2 - x.squaredNorm()) / (2 * a2 * b2 * b2 * std::pow(q, 1.5));
}

namespace {

// The point of the spheroid under each triangle's centroid.
std::vector<Vector3r> surfacePoints(Real a, Real b, const TriangleSurface& surface) {
  const ImplicitSolid solid = spheroid(a, b);
  std::vector<Vector3r> points;
  points.reserve(surface.triangles.size());
  for (const Triangle& t : surface.triangles)
    points.push_back(
        projectOnSurface(solid, (surface.vertices[t[0]] + surface.vertices[t[1]] + surface.vertices[t[2]]) / 3));
  return points;
}

}  // namespace

std::vector<Real> spheroidTriangleCurvatures(Real a, Real b, const TriangleSurface& surface) {
  std::vector<Real> curvatures;
  for (const Vector3r& x : surfacePoints(a, b, surface)) curvatures.push_back(spheroidMeanCurvature(a, b, x));
  return curvatures;
}

std::vector<PrincipalCurvature> spheroidTrianglePrincipalCurvatures(Real a, Real b, const TriangleSurface& surface) {
  const Vector3r hessian(2 / (b * b), 2 / (b * b), 2 / (a * a));
  const std::vector<Vector3r> points = surfacePoints(a, b, surface);
  std::vector<PrincipalCurvature> out;
  for (int t = 0; t < static_cast<int>(points.size()); ++t)
    out.push_back(implicitPrincipalCurvature(hessian.cwiseProduct(points[t]), Matrix3r(hessian.asDiagonal()),
                                             triangleNormal(surface, t)));
  return out;
}

}  // namespace roundedmesh
