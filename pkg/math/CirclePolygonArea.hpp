// Exact area of the intersection of a disc (centre at the origin, radius a) with a counter-clockwise
// polygon: A(S n Omega) of Eqs. 14 and 20. Closed form, summing the signed area of the disc cut by the
// triangle (origin, p_i, p_i+1) over the polygon's edges: circular sectors where an edge runs outside the
// disc, straight triangles where it runs inside.
// Input: corners relative to the disc's centre [m]. Output: area [m^2].
#pragma once

#include "pkg/math/ConvexPolygon.hpp"

namespace roundedmesh {

Real circlePolygonArea(Real radius, const ConvexPolygon& polygon);

}  // namespace roundedmesh
