// Both principal curvatures of a surface under each triangle, and their directions: what the elliptical
// contact (doc/physics.md, "Principal curvatures and the contact ellipse") needs beyond the mean curvature of
// Eq. 1, which the paper's circular contact uses alone (its Section 4: "only one average radius of curvature").
//
// From a mesh: the per-face shape operator of Rusinkiewicz (Estimating curvatures and their derivatives on
// triangle meshes, 3DPVT 2004): on each triangle, the 2x2 second fundamental form II that best maps its three
// edges e_i to the change of the vertex normals along them, II e_i = n(end) - n(start), in least squares.
// Vertex normals are Max's weighted normals (J. Graphics Tools 4 (1999)), exact for a sphere's vertices. It is
// chosen because it is defined per triangle, as the contact model needs, needs only the triangle and its three
// vertex normals, and reproduces a sphere's and a cylinder's curvatures exactly when the vertex normals are exact;
// on irregular meshes it is first-order accurate (tests/cpp/PrincipalCurvatureTest.cpp measures it).
// Prescribed: from a smooth shape's shape operator at the triangle (spheroids, cylinders, spheres).
//
// Sign: positive where the surface is convex (a sphere of radius R has 1/R twice), negative where concave.
// Outputs per triangle: k1 >= k2 [1/m] and the unit direction d1 of k1, in the triangle's plane; the direction of
// k2 is n x d1 with n the triangle's outward normal.
#pragma once

#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct TriangleSurface;

struct PrincipalCurvature {
  Real k1 = 0, k2 = 0;             // [1/m], k1 >= k2
  Vector3r d1 = Vector3r::UnitX();  // direction of k1, unit, tangent to the triangle

  Real mean() const { return (k1 + k2) / 2; }
  static PrincipalCurvature isotropic(Real k, const Vector3r& normal) { return {k, k, normal.unitOrthogonal()}; }
};

// Rusinkiewicz's per-face estimate on a closed, outward-oriented surface.
std::vector<PrincipalCurvature> principalCurvatures(const TriangleSurface& surface);

// The principal curvatures of a symmetric shape operator [1/m] in its tangent plane (unit normal `normal`), with
// the direction of k1 turned into the plane of a triangle (unit normal triangleNormal) by the smallest rotation
// between the normals: the values are the surface's own, and an isotropic operator stays isotropic.
PrincipalCurvature principalCurvature(const Matrix3r& shapeOperator, const Vector3r& normal,
                                      const Vector3r& triangleNormal);

// The principal curvatures of an implicit surface f = 0 at a point, from grad f and Hess f there: the shape operator
// P Hess(f) P / |grad f| (P: projection on the tangent plane; R. Goldman, Comput. Aided Geom. Des. 22 (2005)
// 632-658) through principalCurvature above, divided by `scale` when f's lengths are scale times smaller than the
// mesh's (shape units against metres).
PrincipalCurvature implicitPrincipalCurvature(const Vector3r& gradient, const Matrix3r& hessian,
                                              const Vector3r& triangleNormal, Real scale = 1);

// Max's vertex normals: the sum over the incident triangles of (e1 x e2) / (|e1|^2 |e2|^2), normalised.
std::vector<Vector3r> vertexNormals(const TriangleSurface& surface);

}  // namespace roundedmesh
