// Ig2 functor: the triangles of a rounded body whose cap boxes meet the box, against its six finite faces.
// A triangle meets
// the faces whose outer side holds its encompassing sphere's centre (at most three); if the centre has
// sunk into the box, the face it is least deep behind. Each such face is a plane with the projected
// triangle clipped to the face's rectangle (Section 2.3, "finite plane").
// Inputs in body 1's frame: the box's centre and orientation, and its motion relative to body 1.
#pragma once

#include <vector>

#include "pkg/geom/TrianglePlaneGeom.hpp"
#include "pkg/shape/Box.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Box_PressureGeom(const RoundedMesh& mesh, const Box& box, const Vector3r& centre,
                                      const Matrix3r& orientation, const RelativeMotion& motion,
                                      GeomOutput out, CurvatureModel model = CurvatureModel::Mean);

}  // namespace roundedmesh
