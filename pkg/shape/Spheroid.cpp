#include "pkg/shape/Spheroid.hpp"

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

std::vector<Real> spheroidTriangleCurvatures(Real a, Real b, const TriangleSurface& surface) {
  const ImplicitSolid solid = spheroid(a, b);
  std::vector<Real> curvatures;
  curvatures.reserve(surface.triangles.size());
  for (const Triangle& t : surface.triangles) {
    const Vector3r centroid = (surface.vertices[t[0]] + surface.vertices[t[1]] + surface.vertices[t[2]]) / 3;
    curvatures.push_back(spheroidMeanCurvature(a, b, projectOnSurface(solid, centroid)));
  }
  return curvatures;
}

}  // namespace roundedmesh
