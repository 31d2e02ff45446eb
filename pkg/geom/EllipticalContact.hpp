// The contact ellipse of one triangle contact when the surfaces are curved differently in different directions
// (engine option curvature='principal'; doc/physics.md, "Principal curvatures: the contact ellipse").
// The contact plane (normal n12, axes t1, t2, origin c) and the sphere overlap delta_s come from the encompassing
// spheres, and only a pair the paper's circular contact accepts (S meets its circle) gets an ellipse
// (TriangleSphereGeom.hpp, TrianglePlaneGeom.hpp): the quadrics' second-order overlap is meaningful only near the
// caps, and far pairs of flat triangles, whose spheres overlap deeply, would otherwise take huge ellipses. Each surface's cap
// is then the quadric with the triangle's principal curvatures (PrincipalCurvature.hpp) through the top of its
// sphere's cap over the circumcentre, written as that sphere plus a correction, in plane coordinates about c:
//   K_i      the shape operator in the plane, convex toward the partner positive: k1 e1 e1' + k2 e2 e2', e1 the
//            direction d1 of k1 projected on the plane and normalised, e2 perpendicular to it in the plane
//   D_i    = I / R_i - K_i          (R_i the sphere's radius; zero for a sphere, a plane, or k1 = k2 = 1/R_i)
//   dh_i   = h(H_i) - h(1/R_i)    the cap's top over the sphere's at the circumcentre, h(H) the height of a cap of
//            curvature H over the circumcircle (radius rho_i), negative for H < 0
//   beta_i   the circumcentre in the plane
//   o(x)   = delta_s + dh_1 + dh_2 - x' K x / 2 + x' L + C,   K = K_1 + K_2,   L = -(D_1 beta_1 + D_2 beta_2),
//            C = (beta_1' D_1 beta_1 + beta_2' D_2 beta_2) / 2
// the surfaces' overlap over the plane to second order. Its maximum delta = o(x*) at x* = K^-1 L, and the
// eigenvalues lambdaA <= lambdaB of K, give Hertz's ellipse (EllipticalHertz.hpp) centred at x*. Concave caps
// (H_i < 0) lie below their triangle: the contact follows the smooth surface, not the facets bridging a groove.
// For a sphere every correction vanishes and the contact is the circle of Eq. 5 exactly.
// The ellipse is stored as the map y = T (x - x*) onto the circle of radius sqrt(a b) (det T = 1: areas are kept),
// over which the law integrates the circular pressure (PressureGeom::toCircle). A pair whose larger relative
// curvature lambdaB is below half the circular model's 1/R_1 + 1/R_2 (flat on flat, concave on concave: nothing
// Hertzian to resolve) keeps the circle: geom is left as the caller made it. Rejects the pair if
// delta <= 0, or if S misses the ellipse.
#pragma once

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

// One surface's cap seen from the contact plane.
struct CapCurvature {
  Matrix2r curvature = Matrix2r::Zero();   // K_i [1/m]
  Matrix2r correction = Matrix2r::Zero();  // D_i [1/m]
  Vector2r base = Vector2r::Zero();        // beta_i [m]
  Real sphereCurvature = 0;                // 1/R_i of its sphere in the circular model (0: a plane) [1/m]
  Real heightShift = 0;                    // dh_i [m]
};

// A rounded triangle whose mesh lies in body 1's frame after x -> rotation * x + translation.
CapCurvature triangleCap(const RoundedMesh& mesh, int triangle, const PressureGeom& geom,
                         const Matrix3r& rotation = Matrix3r::Identity(),
                         const Vector3r& translation = Vector3r::Zero());
// An analytic sphere of curvature 1/R, or a plane (0): exact in the sphere model, no correction.
CapCurvature exactCap(Real curvature);

// Fills geom's ellipse, overlap and effective point from its plane, polygon S and sphere overlap, or leaves it
// circular (geom.elliptical false).
GeomTest ellipticalContact(PressureGeom& geom, const CapCurvature& cap1, const CapCurvature& cap2);

}  // namespace roundedmesh
