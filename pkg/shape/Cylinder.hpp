// Closed cylinder of radius R and length L along z, centred on the origin, with flat caps (scene S5's
// crossed and parallel cylinders), meshed with about the requested number of nodes: rings of nodes
// staggered by half a step along the hull, concentric rings on the caps, spaced so that triangles are
// close to equilateral. Lengths in m.
// cylinderTriangleCurvatures gives the smooth shape's mean curvature per triangle: 1/(2R) on the hull
// (principal curvatures 1/R and 0), 0 on the caps.
#pragma once

#include <vector>

#include "pkg/shape/PrincipalCurvature.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

TriangleSurface cylinderSurface(Real radius, Real length, int nodes);

std::vector<Real> cylinderTriangleCurvatures(Real radius, const TriangleSurface& surface);

// Principal curvatures per triangle: 1/R around the hull (direction z x n) and 0 along the axis; 0 on the caps.
std::vector<PrincipalCurvature> cylinderTrianglePrincipalCurvatures(Real radius, const TriangleSurface& surface);

}  // namespace roundedmesh
