// The convex hull of points in a plane (Andrew's monotone chain): its corners counter-clockwise, a corner on a
// straight stretch dropped (one whose turn, the cross product of its two edges, is below `straight` [m^2]).
#pragma once

#include <vector>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

std::vector<Vector2r> convexHull(std::vector<Vector2r> points, Real straight = 0);

}  // namespace roundedmesh
