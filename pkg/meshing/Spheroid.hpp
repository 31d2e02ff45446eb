// Spheroid x^2/b^2 + y^2/b^2 + z^2/a^2 = 1: semi-axis a along z, b across (scene S5), meshed with about
// the requested number of nodes (ImplicitSurfaceMesher.hpp), and its exact mean curvature, for
// prescribing the smooth shape's curvature instead of computing it from the mesh. Lengths in m.
#pragma once

#include <vector>

#include "pkg/shape/PrincipalCurvature.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

TriangleSurface spheroidSurface(Real a, Real b, int nodes);

// Mean curvature of the spheroid at its surface point x [1/m], from the ellipsoid formula
//   H = (a^2 + 2 b^2 - |x|^2) / (2 a^2 b^4 q^(3/2)),  q = (x^2 + y^2)/b^4 + z^2/a^4.
Real spheroidMeanCurvature(Real a, Real b, const Vector3r& x);

// Per triangle: H where Newton steps along the gradient of f from the triangle's centroid meet the spheroid
// (close to the nearest point; the centroid lies within a cap height of the surface).
std::vector<Real> spheroidTriangleCurvatures(Real a, Real b, const TriangleSurface& surface);

// Per triangle, at the same surface point: both principal curvatures and directions of the shape operator
// P Hess(f) P / |grad f| of f = (x^2 + y^2)/b^2 + z^2/a^2 - 1 (P: projection on the tangent plane), in the
// triangle's plane.
std::vector<PrincipalCurvature> spheroidTrianglePrincipalCurvatures(Real a, Real b, const TriangleSurface& surface);

}  // namespace roundedmesh
