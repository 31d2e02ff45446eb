// Ig2 functor: the triangles of a rounded body against an infinite plane (a Plane, or a YADE Wall): one
// PressureGeom per triangle whose contact circle meets its projection (trianglePlaneGeom), among the triangles
// whose cap boxes reach the plane (faceGeometry).
// Inputs in body 1's frame: the plane, and the motion of the plane relative to body 1.
#pragma once

#include <vector>

#include "pkg/geom/TrianglePlaneGeom.hpp"
#include "pkg/shape/Plane.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Plane_PressureGeom(const RoundedMesh& mesh, const Plane& plane, const RelativeMotion& motion,
                                        GeomOutput out, CurvatureModel model = CurvatureModel::Mean);

}  // namespace roundedmesh
