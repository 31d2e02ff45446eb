// Ig2 functor: the triangles of a rounded body against a YADE Box, a rigid cuboid whose six faces are finite
// planes (Section 2.3). The body meets the faces whose outer side holds its centre: one face above it, two beyond an
// edge, three beyond a corner; a body whose centre has sunk into the box, the face it is least deep behind (as YADE's
// Ig2_Box_Sphere_ScGeom does for a sphere). Each such face is a plane whose S is the projected triangle clipped to
// the face's rectangle (faceGeometry), so a body whose contact lies inside a face gets what a Wall in the face's
// plane gives, whatever the box's thickness; at an edge or a corner, the contacts of each face over its own
// rectangle.
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
