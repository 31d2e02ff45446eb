// Ig2 functor: the triangles of two rounded bodies against each other (Appendix B). Candidate pairs come
// from the two meshes' hierarchies traversed under the relative pose (TriangleTree::queryPairs); each
// candidate goes through triangleSphereGeom with body 2's triangle moved into body 1's frame.
// Inputs: body 2's pose in body 1's frame (x1 = rotation * x2 + translation), the deepest overlap to look for
// [m] (the pair search's margin), and body 2's motion relative to body 1. Appends one PressureGeom per triangle pair in contact, in traversal order (fixed for a pose).
#pragma once

#include <vector>

#include "pkg/geom/TriangleSphereGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation, Real margin,
                                              const RelativeMotion& motion, std::vector<PressureGeom>& geoms);

}  // namespace roundedmesh
