// A rounded tetrahedral grain: the smooth maximum of the four face planes of a regular tetrahedron,
//   f(x) = s ln sum_i exp(n_i . x / s) - h,
// n_i the outward unit face normals, h [m] the distance of the faces from the centre (the inradius of the sharp
// tetrahedron, which it approaches as s -> 0) and s [m] the rounding length. f is convex, so the solid {f < 0} is
// strictly convex with curvature everywhere positive: nearly flat faces (at a face's centre both principal
// curvatures are w (4/3) / (s (w_1 - w)), w_1 = e^(t/s) / Z and w = e^(-t/(3s)) / Z the weights of the face's own
// plane and of the other three at the face's centre t n_1, Z their sum), rounded edges and tight corners: a grain
// shape not made of spheres. It lies inside the sharp tetrahedron (circumradius 3 h).
#pragma once

#include <array>

#include "pkg/meshing/ImplicitSurfaceMesher.hpp"

namespace roundedmesh {

struct RoundedTetrahedron {
  Real inradius;  // h [m] > 0
  Real rounding;  // s [m], 0 < s < h / ln 3 (beyond, the corners round off entirely)
};

// The outward unit normals of the faces: (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1), over sqrt 3.
std::array<Vector3r, 4> tetrahedronFaceNormals();

// Throws std::invalid_argument naming the bad parameter.
ImplicitSolid implicitSolid(const RoundedTetrahedron& shape);

}  // namespace roundedmesh
