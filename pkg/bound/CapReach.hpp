// Whether a point lies in a rounded body's solid, as far as its distance field (SolidDistance.hpp) can tell: within
// the tallest cap of the flat solid, plus the field's tolerance (a point of the rounded solid lies that close to the
// flat one). capReaches is the necessary condition on one triangle that the candidate lists (TrianglePairCandidates.hpp)
// use, and the deep-contact criterion (DeepContactCriterion.hpp) refines: cap s, whose points lie within rho_s of
// its circumcentre, comes within that tolerance of body 2's solid, up to `slack` [m] of motion to come.
#pragma once

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

// Body 2 in body 1's frame: x1 = rotation * x2 + translation.
struct PlacedMesh {
  const RoundedMesh& mesh;
  const Matrix3r& rotation;
  const Vector3r& translation;
};

// x in the mesh's frame, up to `slack` [m] more.
inline bool insideRoundedSolid(const RoundedMesh& mesh, const Vector3r& x, Real slack = 0) {
  const SolidDistance& solid = mesh.solidDistance();
  return solid.at(x) <= mesh.maxCapHeight() + solid.tolerance() + slack;
}

// x in body 1's frame.
inline bool insidePlaced(const PlacedMesh& body2, const Vector3r& x, Real slack = 0) {
  return insideRoundedSolid(body2.mesh, body2.rotation.transpose() * (x - body2.translation), slack);
}

// Triangle s of mesh1 (body 1's frame) against body 2.
inline bool capReaches(const RoundedMesh& mesh1, int s, const PlacedMesh& body2, Real slack) {
  const RoundedTriangle& cap = mesh1.rounded(s);
  return insidePlaced(body2, cap.circumcentre, cap.circumradius + slack);
}

}  // namespace roundedmesh
