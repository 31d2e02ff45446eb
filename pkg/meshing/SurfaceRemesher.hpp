// Remeshes (part of) a flat triangulated surface to a uniform edge length without changing its shape: CGAL's isotropic
// remeshing (Botsch and Kobbelt 2004: split, collapse, flip, tangential smoothing; 5 iterations) with every node
// kept on the input surface, and the sharp edges (dihedral angle beyond kSharpAngle) kept as constrained polylines,
// split but never flipped or smoothed away, so that corners and edges stay where they are. What Mesh.load uses to
// prepare a mesh too coarse for its curvature (BodyMesh.hpp): curvature computed from the finer mesh concentrates on
// the sharp edges at a radius of the order of the edge length, and the caps shrink with it.
// Inputs: a closed, outward-oriented surface [m], the target edge length [m] > 0, and which triangles to remesh (all
// when empty; the border of a selection is split to the length, the rest is kept). Output: the remeshed surface,
// closed and outward, checked like any input (SurfaceRepair.hpp).
#pragma once

#include <vector>

#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

constexpr Real kSharpAngle = 30;  // [degrees] between neighbouring triangles' normals

TriangleSurface remeshedSurface(const TriangleSurface& surface, Real edgeLength,
                                const std::vector<bool>& selected = {});

}  // namespace roundedmesh
