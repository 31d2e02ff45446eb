// Icosphere (Section 3.1): the regular icosahedron, each triangle split into four k times, new nodes
// projected on the sphere. 10 * 4^k + 2 nodes (12, 42, 162, 642, 2562 for k = 0..4), 20 * 4^k triangles,
// counter-clockwise seen from outside.
// Inputs: radius [m] > 0, subdivisions k in [0, 8].
#pragma once

#include <cstdint>

#include "pkg/shape/RoundedMesh.hpp"
#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

TriangleSurface icosphereSurface(Real radius, int subdivisions);

// The icosphere with every triangle's radius of curvature set to the sphere's.
RoundedMesh icosphere(Real radius, int subdivisions);

// The distorted icospheres of Fig. 4a: nodes walk at random along the sphere, one at a time, in steps of at
// most a tenth of the mean edge, each step refused if it would fold a triangle over or shrink it below 1e-4
// of the mean area, until the distortion D of Eq. 26 reaches `targetDistortion` (within one step's change,
// about 1e-3). Reproducible for a given seed. Throws std::invalid_argument outside [D of the regular
// icosphere, 1.5].
TriangleSurface distortedIcosphereSurface(Real radius, int subdivisions, Real targetDistortion, std::uint32_t seed);

}  // namespace roundedmesh
