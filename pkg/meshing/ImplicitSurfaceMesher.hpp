// Triangulates the surface f(x) = 0 of a smooth solid {f < 0} with about a requested number of nodes and
// near-equilateral triangles, every node on the surface:
//   1. marching tetrahedra on a cubic grid sample the surface finer than needed (closed and manifold);
//   2. CGAL's isotropic remeshing brings it to a uniform target edge length L, projecting every moved or
//      new node onto f = 0 (Newton steps along the gradient);
//   3. L is corrected from the node count, N ~ area / (sqrt(3)/2 L^2), until the count is within 2 % (at
//      most 8 tries; the closest is kept, in practice within 2 %).
// The result is deterministic (CGAL's own surface mesher is not: its output depends on memory addresses).
// Inputs: f (negative inside, with a gradient that does not vanish near the surface), a point inside,
// a radius around it that holds the solid [m], its thinnest part [m], the number of nodes wanted (12 to
// 50,000). The sampling grid has at most 256 nodes along each axis; a solid thinner than 1/30 of its
// bounding radius, or too many nodes for that grid, raise std::invalid_argument.
// Output: a closed, outward-oriented surface.
#pragma once

#include <functional>

#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

struct ImplicitSolid {
  std::function<Real(const Vector3r&)> f;  // < 0 inside, > 0 outside
  Vector3r inside;                         // f(inside) < 0
  Real boundingRadius;                     // the solid lies within this distance of inside [m]
  Real thickness;                          // of its thinnest part [m]: the first sampling grid resolves it
};

TriangleSurface meshImplicitSurface(const ImplicitSolid& solid, int nodes);

// The point of f = 0 nearest to x along f's gradient (Newton iterations), used to put nodes on the surface.
Vector3r projectOnSurface(const ImplicitSolid& solid, Vector3r x);

}  // namespace roundedmesh
