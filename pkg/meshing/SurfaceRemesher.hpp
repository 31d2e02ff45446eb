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

// The whole surface remeshed to about `nodes` nodes (4 to 200,000): the edge length L from the area A, nodes ~
// 2 A / (sqrt(3) L^2) for near-equilateral triangles, corrected by the count each try gives (at most 4 tries; the
// closest is kept: within 10 % from 300 nodes on for smooth shapes, measured 0-7 %; coarser targets and sharp
// edges, kept as they are, leave more nodes than asked). A try whose collapses leave a degenerate triangle is
// skipped; std::invalid_argument if all are. What roundedmesh.cheapest_model uses to bring a user's mesh to the
// node count a force error needs.
TriangleSurface remeshedToNodes(const TriangleSurface& surface, int nodes);

}  // namespace roundedmesh
