#include "pkg/geom/DeepContactCriterion.hpp"

#include <algorithm>
#include <cmath>

namespace roundedmesh {
namespace {

bool inBody2(const PlacedMesh& body2, const Vector3r& x, Real slack = 0) {
  return insideRoundedSolid(body2.mesh, body2.rotation.transpose() * (x - body2.translation), slack);
}

}  // namespace

bool insideRoundedSolid(const RoundedMesh& mesh, const Vector3r& x, Real slack) {
  const SolidDistance& solid = mesh.solidDistance();
  return solid.at(x) <= mesh.maxCapHeight() + solid.tolerance() + slack;
}

bool overlapInsideBoth(const RoundedMesh& mesh1, int s, const PlacedMesh& body2, int t, const PressureGeom& geom) {
  const RoundedTriangle& p = mesh1.rounded(s);
  const RoundedTriangle& q = body2.mesh.rounded(t);
  const Vector3r sphere2 = body2.rotation * q.sphereCentre + body2.translation;
  // The line along n12 through c_eff, offset from the line of centres by `lateral`.
  const Vector3r lateral = planePoint(geom, geom.effectivePoint) - geom.centre;
  const Real hSq = lateral.squaredNorm();
  const Vector3r q1 = p.sphereCentre + lateral + std::sqrt(std::max(p.radius * p.radius - hSq, Real(0))) * geom.normal;
  const Vector3r q2 = sphere2 + lateral - std::sqrt(std::max(q.radius * q.radius - hSq, Real(0))) * geom.normal;
  const Vector3r middle = 0.5 * (q1 + q2);
  return inBody2(body2, q1) && inBody2(body2, middle) && insideRoundedSolid(mesh1, q2) && insideRoundedSolid(mesh1, middle);
}

bool capReaches(const RoundedMesh& mesh1, int s, const PlacedMesh& body2, Real slack) {
  const RoundedTriangle& cap = mesh1.rounded(s);
  return inBody2(body2, cap.circumcentre, cap.circumradius + slack);
}

}  // namespace roundedmesh
