// Mass properties of the solid bounded by a closed, outward-oriented triangle mesh, at unit density:
// volume [m^3], centre of mass [m] and inertia tensor about it [m^5; times density gives kg m^2].
// Exact for the polyhedron: each triangle spans a tetrahedron with the origin, whose signed volume and
// second moments are summed (divergence theorem).
#pragma once

#include <cmath>
#include <vector>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

struct MassProperties {
  Real volume;
  Vector3r centroid;
  Matrix3r inertia;  // about the centroid, unit density
};

MassProperties massProperties(const std::vector<Vector3r>& vertices, const std::vector<Triangle>& triangles);

// Radius of the sphere of the same volume [m].
inline Real equivalentRadius(Real volume) { return std::cbrt(3 * volume / (4 * M_PI)); }

// Principal axes of an inertia tensor: orientation maps principal-frame vectors to the input frame, and
// moments are the matching principal moments. A tensor that is already diagonal (off-diagonal part below
// 1e-9 of the trace: an axis-aligned spheroid, a sphere, a mesh already in its principal frame) keeps
// the identity and its axis order, so such meshes are neither rotated nor have their axes permuted.
struct PrincipalAxes {
  Quaternionr orientation;
  Vector3r moments;
};

PrincipalAxes principalAxes(const Matrix3r& inertia);

}  // namespace roundedmesh
