// Ig2 functor: the triangles of a rounded body against a YADE Box, a rigid cuboid whose edges and corners are rounded
// by a radius rho (Section 2.3; doc/physics.md, "What each partner's surface is"): six faces, finite planes trimmed
// rho short of the edges; twelve edges, strips of cylinders of radius rho about the edges of the box shrunk by rho;
// eight corners, patches of spheres of radius rho about its corners (TriangleEdgeGeom.hpp). The body meets the faces
// whose outer side holds its centre: one face above it, two beyond an edge, three beyond a corner; a body whose centre
// has sunk into the box, the face it is least deep behind (as YADE's Ig2_Box_Sphere_ScGeom does for a sphere); and
// the edges and corners of those faces. Each face is a plane whose S is the projected triangle clipped to the face's
// trimmed rectangle (faceGeometry), so a body whose contact lies inside a face gets what a Wall in the face's plane
// gives, whatever the box's thickness. rho is at most the box's smallest half-size.
// Inputs in body 1's frame: the box's centre and orientation, and its motion relative to body 1.
#pragma once

#include <vector>

#include "pkg/geom/TrianglePlaneGeom.hpp"
#include "pkg/shape/Box.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Box_PressureGeom(const RoundedMesh& mesh, const Box& box, const Vector3r& centre,
                                      const Matrix3r& orientation, Real edgeRadius, const RelativeMotion& motion,
                                      GeomOutput out, CurvatureModel model = CurvatureModel::Mean);

}  // namespace roundedmesh
