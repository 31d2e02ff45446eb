// Closed-form integrals over S n Omega, the part of a convex polygon S inside the disc Omega of radius a centred
// at the origin, of the shapes of the Hertz pressure (Eq. 9) and of its energy density:
//   pressure        P  = integral of w dA,         w = sqrt(a^2 - r^2)                          [m^3]
//   pressureMoment  M  = integral of (x, y) w dA                                                 [m^4]
//   energy          E  = integral of w^3 dA                                                      [m^5]
// The Hertz pressure is p = (2 E* / (pi R*)) w and its energy density e = (4 E* / (3 pi R*^2)) w^3, whose
// delta-derivative at fixed r is p (doc/physics.md, "A conservative normal force: the design"); over the whole disc
// P = (2 pi / 3) a^3 and E = (2 pi / 5) a^5, Hertz's force and potential.
// How: the polygon is the signed sum of the triangles (origin, p_i, p_i+1), as in CirclePolygonArea.hpp. A
// radial f(r) integrates over such a triangle cut by the disc as the integral over its angle of
// F(min(rho, a)), F(rho) = integral of f(r) r dr from 0 to rho: a sector where the edge runs outside the disc, and
// where it runs inside, in the edge's own coordinate s (r^2 = h^2 + s^2, h the line's signed distance from the
// origin, A = a^2 - h^2) the integrals of (A - s^2)^(k/2) / (h^2 + s^2), elementary (arcsin and arctan terms).
// The first moments follow from the divergence theorem: x w = -(1/3) d(w^3)/dx, and w vanishes on the circle,
// so M = -(1/3) sum over the edges of n_e times the integral of (A - s^2)^(3/2) ds along the part inside.
// Exact to round-off (tests/cpp/DiskPolygonIntegralsTest.cpp: against the whole disc's closed forms, and against
// adaptive quadrature of random polygons to 1e-10).
// Input: corners relative to the disc's centre [m], counter-clockwise; a >= 0 [m].
#pragma once

#include "pkg/math/ConvexPolygon.hpp"

namespace roundedmesh {

struct DiskPolygonIntegrals {
  Real pressure = 0;
  Vector2r pressureMoment = Vector2r::Zero();
  Real energy = 0;
};

DiskPolygonIntegrals diskPolygonIntegrals(Real radius, const ConvexPolygon& polygon);

// Along the edge from P to Q, its part inside the disc: the integrals of w^3 ds and of lambda w^3 ds (ds the arc
// length, lambda = 0 at P and 1 at Q) [m^4]: what a straight edge of S moving outward adds to the energy integral,
// and how that splits between its two ends (the edge-force terms of the energy's gradient, ContactEnergyGradient.hpp).
struct EdgeIntegrals {
  Real energy = 0;
  Real energyMoment = 0;
};

EdgeIntegrals edgeIntegrals(Real radius, const Vector2r& P, const Vector2r& Q);

}  // namespace roundedmesh
