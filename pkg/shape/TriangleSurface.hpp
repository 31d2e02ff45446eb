// A bare triangulated surface: vertices [m] and triangles (corner indices, counter-clockwise seen from
// outside). The geometry every mesh source produces (files, arrays, generators) before a radius of
// curvature is attached to each triangle (RoundedMesh).
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "pkg/common/Types.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

struct TriangleSurface {
  std::vector<Vector3r> vertices;
  std::vector<Triangle> triangles;
};

// Area of triangle t [m^2], and of every triangle.
Real triangleArea(const TriangleSurface& surface, int t);
std::vector<Real> triangleAreas(const TriangleSurface& surface);
// Outward unit normal of triangle t (corners counter-clockwise seen from outside).
Vector3r triangleNormal(const TriangleSurface& surface, int t);

// Centre of the circle through a, b, c, in their plane [m].
Vector3r circumcentre(const Vector3r& a, const Vector3r& b, const Vector3r& c);

// Whether the triangle a, b, c has no area worth the name: twice its area at most 1e-12 of its longest edge
// squared. Relative, so that it holds at any scale; round-off of any sensible triangle is far above it.
bool hasZeroArea(const Vector3r& a, const Vector3r& b, const Vector3r& c);

Eigen::AlignedBox<Real, 3> boundingBox(const std::vector<Vector3r>& points);

}  // namespace roundedmesh
