// A bare triangulated surface: vertices [m] and triangles (corner indices, counter-clockwise seen from
// outside). The geometry every mesh source produces (files, arrays, generators) before a radius of
// curvature is attached to each triangle (RoundedMesh).
#pragma once

#include <vector>

#include "pkg/common/Types.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

struct TriangleSurface {
  std::vector<Vector3r> vertices;
  std::vector<Triangle> triangles;
};

// Triangle areas [m^2].
std::vector<Real> triangleAreas(const TriangleSurface& surface);

}  // namespace roundedmesh
