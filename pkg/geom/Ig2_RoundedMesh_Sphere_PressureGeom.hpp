// Ig2 functor: the triangles of a rounded body against an analytic sphere (a YADE Sphere), S being the
// projected triangle (Section 2.3). Only triangles whose cap boxes meet the sphere's box are tested.
// Inputs in body 1's frame: the sphere's centre, and its motion relative to body 1.
#pragma once

#include <vector>

#include "pkg/geom/TriangleSphereGeom.hpp"
#include "pkg/shape/Sphere.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Sphere_PressureGeom(const RoundedMesh& mesh, const Sphere& sphere, const Vector3r& centre,
                                         const RelativeMotion& motion, GeomOutput out, CurvatureModel model = CurvatureModel::Mean);

}  // namespace roundedmesh
