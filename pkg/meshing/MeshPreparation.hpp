// Prepares a flat mesh whose curvature is computed from it (Eq. 1) so that its rounded body stays within a tolerance
// of it (CapTolerance.hpp): where some cap rises higher than maxCapHeight (a mesh too coarse for its curvature: sharp
// edges, slivers, a coarse scan), the surface is remeshed finer there (SurfaceRemesher.hpp: same shape, sharp edges
// kept): each pass remeshes the triangles beyond the tolerance and their neighbours, to their median edge length times
// sqrt(maxCapHeight / tallest cap) (between 0.3 and 0.8), until every cap is within it, for at most kMaxRemeshPasses
// passes and kMaxRemeshTriangles triangles. A mesh already within the tolerance is returned as it is. Whatever is
// still beyond after the last pass is for boundCapHeights.
// Inputs: a closed, outward surface [m], the radius flat and concave triangles use (maxRadius) [m], maxCapHeight [m].
#pragma once

#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

constexpr int kMaxRemeshPasses = 8;
constexpr int kMaxRemeshTriangles = 100000;

struct PreparedSurface {
  TriangleSurface surface;
  int remeshPasses = 0;  // 0: the input as it is
  Real edgeLength = 0;   // target edge length of the last pass [m], the finest
};

PreparedSurface surfaceWithinTolerance(const TriangleSurface& surface, Real maxRadius, Real maxCapHeight);

}  // namespace roundedmesh
