// Edge defects of a triangle set that is meant to bound a solid. On a closed, edge-manifold, consistently
// oriented surface every edge borders exactly two triangles, which run along it in opposite directions.
// Only such a surface bounds a solid whose volume and inertia mean anything.
#pragma once

#include <array>
#include <vector>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

struct EdgeDefect {
  int count = 0;                    // edges with this defect
  std::array<int, 2> first{-1, -1};  // the vertices of the first one (lowest vertex indices)
};

struct EdgeDefects {
  EdgeDefect boundary;     // borders a single triangle: the surface has a hole
  EdgeDefect nonManifold;  // borders three or more triangles
  EdgeDefect misoriented;  // borders two triangles that run along it in the same direction
};

EdgeDefects findEdgeDefects(const std::vector<Triangle>& triangles);

}  // namespace roundedmesh
