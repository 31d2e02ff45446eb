// The reference shapes of shapes.json (pear, gummy bear): the solid {f < 0} with
//   f(x) = smin_k(d_1(x), ..., d_n(x)) applied left to right,
//   smin_k(a, b) = min(a, b) - h^2 k / 4,  h = max(k - |a - b|, 0) / k   (polynomial smooth minimum),
// where d_i is the exact signed distance to a sphere or a capsule (a segment swept by a ball). Shape units.
#pragma once

#include <vector>

#include "pkg/meshing/ImplicitSurfaceMesher.hpp"

namespace roundedmesh {

struct ShapePrimitive {
  Vector3r a;   // a sphere's centre, or one end of a capsule's segment
  Vector3r b;   // the capsule's other end; equal to a for a sphere
  Real radius;  // > 0
};

struct BlendedShape {
  Real blend;  // k >= 0; 0 is the plain union
  std::vector<ShapePrimitive> primitives;
};

Real blendedDistance(const BlendedShape& shape, const Vector3r& x);

// The shape as an implicit solid for the mesher: inside = the first primitive's point, bounding radius
// covering every primitive plus the blend's reach k/4 beyond their union.
// Throws std::invalid_argument for no primitives, a negative blend or a non-positive radius.
ImplicitSolid implicitSolid(const BlendedShape& shape);

// The shape meshed with about `nodes` nodes (ImplicitSurfaceMesher.hpp) and scaled uniformly so that the
// mesh encloses `volume` [m^3], which makes the body's mass exact; the scale factor [m per shape unit] is
// returned in `scale` if given.
TriangleSurface blendedShapeSurface(const BlendedShape& shape, int nodes, Real volume, Real* scale = nullptr);

}  // namespace roundedmesh
