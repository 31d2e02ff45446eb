// Ig2 functor: the triangles of a rounded body against a YADE Facet, a finite plane (Section 2.3): the
// contact plane is the facet's, on the side of the body's centre, and S is the projected triangle clipped
// to the facet (trianglePlaneGeom). Only triangles whose cap boxes meet the box of the facet's prism on its far
// side are tested: a contact's surface point on the cap lies beyond the facet's plane, over the facet (c_eff is in
// S), and no farther from the plane than the body's bound radius (the body's centre is on the near side), so the
// prism reaches as deep as the body does. (It used to reach 0.1 r_eq, and a body pressed deeper into a facet lost its
// contacts: doc/physics.md, "Deep overlaps and fast impacts".)
// Inputs in body 1's frame: the facet's corners, and the facet's motion relative to body 1.
#pragma once

#include <array>
#include <vector>

#include "pkg/geom/TrianglePlaneGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Facet_PressureGeom(const RoundedMesh& mesh, const std::array<Vector3r, 3>& corners,
                                        const RelativeMotion& motion, GeomOutput out, CurvatureModel model = CurvatureModel::Mean);

}  // namespace roundedmesh
