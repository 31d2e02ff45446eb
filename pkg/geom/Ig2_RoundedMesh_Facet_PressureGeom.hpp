// Ig2 functor: the triangles of a rounded body against a YADE Facet, a finite plane (Section 2.3): the
// contact plane is the facet's, on the side of the body's centre, and S is the projected triangle clipped
// to the facet (trianglePlaneGeom). Only triangles whose cap boxes meet the facet's box are tested.
// Inputs in body 1's frame: the facet's corners, the deepest overlap to look for [m] (a triangle sunk through
// the facet by d has its box up to d from the facet's), and the facet's motion relative to body 1.
#pragma once

#include <array>
#include <vector>

#include "pkg/geom/TrianglePlaneGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Facet_PressureGeom(const RoundedMesh& mesh, const std::array<Vector3r, 3>& corners, Real margin,
                                        const RelativeMotion& motion, GeomOutput out);

}  // namespace roundedmesh
