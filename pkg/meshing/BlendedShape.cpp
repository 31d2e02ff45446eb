#include "pkg/meshing/BlendedShape.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "pkg/shape/MassProperties.hpp"

namespace roundedmesh {
namespace {

Real signedDistance(const ShapePrimitive& p, const Vector3r& x) {
  const Vector3r axis = p.b - p.a;
  const Real length2 = axis.squaredNorm();
  const Real along = length2 > 0 ? std::clamp((x - p.a).dot(axis) / length2, Real(0), Real(1)) : Real(0);
  return (x - (p.a + along * axis)).norm() - p.radius;
}

Real smoothMinimum(Real a, Real b, Real k) {
  if (k <= 0) return std::min(a, b);
  const Real h = std::max(k - std::abs(a - b), Real(0)) / k;
  return std::min(a, b) - h * h * k / 4;
}

}  // namespace

Real blendedDistance(const BlendedShape& shape, const Vector3r& x) {
  Real f = signedDistance(shape.primitives.front(), x);
  for (std::size_t i = 1; i < shape.primitives.size(); ++i)
    f = smoothMinimum(f, signedDistance(shape.primitives[i], x), shape.blend);
  return f;
}

ImplicitSolid implicitSolid(const BlendedShape& shape) {
  if (shape.primitives.empty()) throw std::invalid_argument("shape: no primitives");
  if (!(std::isfinite(shape.blend) && shape.blend >= 0))
    throw std::invalid_argument("shape: blend_k must be finite and >= 0, got " + std::to_string(shape.blend));
  const Vector3r inside = shape.primitives.front().a;
  Real reach = 0, thinnest = INFINITY;
  for (const ShapePrimitive& p : shape.primitives) {
    if (!(std::isfinite(p.radius) && p.radius > 0) || !p.a.allFinite() || !p.b.allFinite())
      throw std::invalid_argument("shape: every primitive needs finite points and a positive radius");
    reach = std::max({reach, (p.a - inside).norm() + p.radius, (p.b - inside).norm() + p.radius});
    thinnest = std::min(thinnest, 2 * p.radius);
  }
  return {[shape](const Vector3r& x) { return blendedDistance(shape, x); }, inside,
          1.1 * (reach + shape.blend / 4), thinnest};
}

TriangleSurface blendedShapeSurface(const BlendedShape& shape, int nodes, Real volume, Real* scale) {
  if (!(std::isfinite(volume) && volume > 0))
    throw std::invalid_argument("volume must be positive and finite, got " + std::to_string(volume));
  TriangleSurface surface = meshImplicitSurface(implicitSolid(shape), nodes);
  const Real factor = std::cbrt(volume / massProperties(surface.vertices, surface.triangles).volume);
  for (Vector3r& v : surface.vertices) v *= factor;
  if (scale) *scale = factor;
  return surface;
}

}  // namespace roundedmesh
