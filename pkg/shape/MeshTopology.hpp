// Checks that triangles form a closed, edge-manifold, consistently oriented surface: every directed edge
// (a, b) of a triangle appears in exactly one triangle, and its reverse (b, a) in exactly one other. Only
// such a surface bounds a solid whose volume and inertia mean anything.
// Throws std::invalid_argument naming the first offending edge and its triangles.
#pragma once

#include <vector>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

void requireClosedOrientedSurface(const std::vector<Triangle>& triangles);

}  // namespace roundedmesh
