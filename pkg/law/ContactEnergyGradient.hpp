// The elastic force of one triangle contact as the exact gradient of its energy (doc/physics.md, "The energy law"):
//   U = integral over S n Omega of e dA,   e = (4 E* / (3 pi R*^2)) (a^2 - r^2)^(3/2),   a^2 = R* delta_s,
// a function of the two bodies' relative pose through the spheres' centres s1, s2 (delta_s, the plane's normal n12
// and centre c) and the corners of the triangles projected on the plane (the polygon S = P' n Q'). Its gradient:
//   - dU/d(delta_s) = the integral of the elastic pressure, F_el (Law2's elasticForce): a central force along n12;
//   - dU/du_j, u_j a projected corner: each edge of P' or Q' on the boundary of S moves outward, adding
//     e ds along its part inside Omega, shared between its two corners by the distance along it:
//     g_j = k m_e integral of (1 - l) w^3 ds (m_e the edge's outward normal, k = 4 E* / (3 pi R*^2));
//   - the plane turns with n12 = (s2 - s1) / |s2 - s1|, which moves every projected corner: a force at s2 of
//     sum_j eta_j g_j / |s2 - s1|, eta_j = (X_j - s1) . n12 the corner's height above s1.
// Each edge of S lies on an edge of P' or Q' (found by its line), or on the outline of a Box's face or a Facet, whose
// corners are the partner's: their gradients h_k enter only through their sum.
// So, as forces on body 2 at points (body 1's frame), against a rounded triangle or a sphere: F_el n12 + that sum at s2,
// and -g_j at each of body 2's corners; against a plane, a Box's face or a Facet (c the foot of s1, which carries every
// projected corner with it): F_el n12 - sum_j g_j - sum_k h_k at s1 and +g_j at each of body 1's corners. Body 1
// receives the opposite forces at the same points. Only the circular contact (curvature 'mean').
// Where a triangle is turned nearly side-on to n12 the energy is w U (FacingRamp.hpp, the facing test of Eq. B.5 made
// continuous) and its gradient w grad U + U grad w, where w's factors f(n1 . n12) and f(-n2 . n12) turn with the
// bodies: n12 with s2 - s1 (a force at s2), n2 with body 2 (a couple), and against a plane n1 against the face's
// normal (a couple).
#pragma once

#include <array>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/math/DiskPolygonBatch.hpp"

namespace roundedmesh {

// Body 2 as the energy sees it: a rounded triangle (its sphere's centre and corners), a sphere, or a plane.
struct EnergyPartner {
  enum Kind { Triangle, Sphere, Plane } kind;
  Vector3r sphereCentre = Vector3r::Zero();  // s2 (not for a plane)
  std::array<Vector3r, 3> corners;           // a triangle's, in the order of geom.partnerNodes
  Vector3r normal = Vector3r::Zero();        // a triangle's outward unit normal n2
};

struct PointForce {
  Vector3r point = Vector3r::Zero();
  Vector3r force = Vector3r::Zero();
};

struct EnergyForces {
  std::array<PointForce, 4> onBody2;
  int count = 0;
  Vector3r coupleOnBody2 = Vector3r::Zero();  // [N m]
  Real energy = 0;                            // w U, the energy these forces are minus the gradient of [J]
};

// corners1: body 1's triangle corners in the order of geom.nodes, sphere1: its sphere's centre s1 [m], normal1 its
// outward unit normal n1, body 1's frame. elasticForce [N], energyAmplitude k [Pa/m^2]; U and S's edges' integrals
// along their parts inside Omega: those of polygon `polygon` of `edges` (DiskPolygonBatch.hpp, where the elastic force
// was integrated).
EnergyForces contactEnergyGradient(const PressureGeom& geom, Real elasticForce, Real energyAmplitude,
                                   const std::array<Vector3r, 3>& corners1, const Vector3r& sphere1,
                                   const Vector3r& normal1, const EnergyPartner& partner, const DiskPolygonBatch& edges,
                                   int polygon);

}  // namespace roundedmesh
