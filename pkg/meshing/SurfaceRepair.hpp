// Turns polygons as read from a file or given as arrays into a surface that can bound a rigid body, or
// says exactly what is wrong and where.
// Repaired silently, because the repair cannot change the shape: exact duplicate vertices are welded (STL
// stores every triangle's corners separately), vertices no polygon uses are dropped, polygons with more
// than three corners are triangulated (CGAL), neighbouring triangles of opposite orientation on a closed,
// edge-manifold surface are turned to agree (CGAL's orient_polygon_soup) and each part outward, and a surface that
// is entirely inside-out is reversed.
// Rejected, with std::invalid_argument naming the defect, how often it occurs and where it first occurs
// (face number and vertex index in the input, coordinates): non-finite coordinates, corner indices out of
// range, faces with fewer than three distinct corners, degenerate (zero-area) triangles, boundary edges (not
// closed), edges bordering more than two triangles (not edge-manifold), neighbouring triangles of opposite
// orientation that cannot be turned to agree without splitting a vertex (a non-orientable or pinched surface),
// separate parts of opposite orientation, and a surface that encloses no volume.
#pragma once

#include <cstddef>
#include <vector>

#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

struct PolygonSoup {
  std::vector<Vector3r> points;                    // [m]
  std::vector<std::vector<std::size_t>> polygons;  // corner indices into points
};

// Repairs that change the shape, each only when asked for.
struct RepairOptions {
  // Close every hole that is flat and seen whole from the centroid of its corners with a fan from that centroid (an
  // open end cut flat, as in YADE's examples/rod-penetration/rod-tiny.stl); any other hole is refused, named.
  bool fillFlatHoles = false;
};

TriangleSurface repairedSurface(const PolygonSoup& soup, const RepairOptions& options = {});

// The checks of repairedSurface on a surface that must already be valid, consistently oriented and outward: throws
// the same errors, repairs nothing. Vertex indices in messages are the surface's own.
void requireValidSurface(const TriangleSurface& surface);

}  // namespace roundedmesh
