// The three corners of a rounded mesh's triangle t, in its body frame [m].
#pragma once

#include <array>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

inline std::array<Vector3r, 3> triangleCorners(const RoundedMesh& mesh, int t) {
  const Triangle& c = mesh.triangles()[t];
  return {mesh.vertices()[c[0]], mesh.vertices()[c[1]], mesh.vertices()[c[2]]};
}

}  // namespace roundedmesh
