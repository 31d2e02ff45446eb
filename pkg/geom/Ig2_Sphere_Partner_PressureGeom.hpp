// Ig2 functor of a sphere body (rm.add_sphere: an analytic sphere whose every contact the engine computes)
// against another sphere or a flat partner, in the sphere's frame (origin at its centre, global axes). The
// contact is one PressureGeom standing for the whole contact circle: the limit of the rounded-triangle
// geometry (TriangleSphereGeom.hpp) for a body that is one sphere, every part of the circle in S.
//   sphere-sphere: delta = R1 + R2 - d,  n12 = (s2 - s1) / d,  R* = R1 R2 / (R1 + R2)   (Eqs. 3, 10)
//                  c on the radical plane, x = (d^2 + R1^2 - R2^2) / (2 d) from s1, as for a rounded triangle
//   sphere-plane:  delta = R1 - dist(s1, plane),  n12 = -plane normal,  R* = R1,  c the foot of s1
//   Wall: its plane on the sphere's side; Box, Facet: the plane through their point closest to s1, normal to
//   the line from s1 (a face, edge or corner contact alike), the face least deep if s1 has sunk into a box.
// Then a = sqrt(delta R*) (Eq. 5), S a square around the whole circle (A(S n Omega) = pi a^2), c_eff = c,
// delta_eff = delta. Rejects (NoOverlap) when delta <= 0.
#pragma once

#include <array>
#include <optional>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/shape/Box.hpp"
#include "pkg/shape/Facet.hpp"
#include "pkg/shape/Plane.hpp"

namespace roundedmesh {

GeomTest sphereSphereGeom(Real radius, const Vector3r& centre2, Real radius2, const RelativeMotion& motion,
                          PressureGeom& geom);

// plane: in the sphere's frame, normal toward the sphere.
GeomTest spherePlaneGeom(Real radius, const Plane& plane, const RelativeMotion& motion, PressureGeom& geom);

// The plane a Box (centre, orientation: box frame -> sphere frame; its edges and corners rounded by edgeRadius [m],
// at most its smallest half-size) or a Facet (placed in the sphere's frame) presents to a sphere centred at the
// origin: through the partner's point nearest the centre. A welded Facet presents its panel's (FacetSurface.hpp),
// and nothing (nullopt) when that point belongs to another member.
Plane boxPlane(const Box& box, const Vector3r& centre, const Matrix3r& orientation, Real edgeRadius);
std::optional<Plane> facetPlane(const PlacedFacet& facet);

}  // namespace roundedmesh
