// Ig2 functor: the triangles of a rounded body against an analytic sphere (a YADE Sphere), S being the
// projected triangle (Section 2.3). Only triangles whose cap boxes meet the sphere's box are tested. A triangle
// contact deeper than `shallow` [m] counts only where the sphere really reaches into the body there, as the
// deep-contact criterion asks of two bodies: the sphere's deepest point on the line along n12 through c_eff lies in
// the body's rounded solid (the path to it from the triangle stays inside, pathInsideBody). Past the Hertz range a
// flat triangle's large sphere otherwise swallows a small sphere that only grazes the body (a 10 mm sphere beside a
// gummy bear in the drum of scripts/examples/example_drum.py: 11.6 mm 'deep' where it came within 0.7 mm of the mesh).
// Inputs in body 1's frame: the sphere's centre, and its motion relative to body 1.
#pragma once

#include <limits>
#include <vector>

#include "pkg/geom/TriangleSphereGeom.hpp"
#include "pkg/shape/Sphere.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Sphere_PressureGeom(const RoundedMesh& mesh, const Sphere& sphere, const Vector3r& centre,
                                         const RelativeMotion& motion, GeomOutput out, CurvatureModel model = CurvatureModel::Mean,
                                         Real shallow = std::numeric_limits<Real>::infinity());

}  // namespace roundedmesh
