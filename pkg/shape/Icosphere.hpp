// Icosphere (Section 3.1): the regular icosahedron, each triangle split into four k times, new nodes
// projected on the sphere. 10 * 4^k + 2 nodes (12, 42, 162, 642, 2562 for k = 0..4), 20 * 4^k triangles,
// counter-clockwise seen from outside.
// Inputs: radius [m] > 0, subdivisions k in [0, 8]. Every triangle's radius of curvature is the sphere's.
#pragma once

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

RoundedMesh icosphere(Real radius, int subdivisions);

}  // namespace roundedmesh
