// Which triangle pairs touch (doc/physics.md, "Which triangle pairs touch"). Appendix B alone accepts pairs far
// from where two bodies really overlap: a small sphere of body 1 swallowed by a large or flat triangle's sphere of
// body 2 that reaches through or past body 2 scores an effective overlap of centimetres where the bodies overlap by
// a millimetre, or not at all; and where parts of two bodies thinner than the spheres' overlap lie across each
// other (a coarse mesh's ears and legs, prepared with sharp edges), it scores a millimetre across a gap. At a real
// contact, however shallow, the surface points on the line along n12 through c_eff, q1 on cap 1 and q2 on cap 2
// (|q1 - q2| = delta_eff), bound a segment that lies inside both bodies: from q2 the line enters body 2, from q1
// it enters body 1. So
//   a triangle pair touches only if the segment q1 q2 lies in both bodies' solids.
// Each body must hold the stretch of the segment behind its own triangle. Where that stretch is shorter than the
// distance to the triangle's nearest exit at its angle (TriangleExits.hpp), or crosses none of its exits, it does;
// this settles nearly every pair of smooth bodies. Otherwise the stretch is followed through the flat surface
// exactly. A pair deeper than `shallow` must first lie deep at its segment's middle, whatever the exits say (a
// segment along a thin sheet where two bodies overlap crosses no exit: two parallel cylinders' flat ends facing each
// other through the sheet along their sides); then it is tested against both bodies' distance fields
// (SolidDistance.hpp), at its ends and at points no farther apart than the fields' tolerance between them: within
// each body's tallest cap (points of the rounded solid lie that close to the flat one) plus the field's tolerance,
// which rejects most false deep pairs cheaply. The candidate lists use the necessary condition on one triangle of
// each pair, capReaches (CapReach.hpp).
#pragma once

#include "pkg/bound/CapReach.hpp"
#include "pkg/geom/PressureGeom.hpp"

namespace roundedmesh {

// Whether the straight path from `from`, a point of triangle s, into the solid to x (the mesh's frame) ends inside
// the mesh's rounded solid: it crosses the flat surface an even number of times on the way (each triangle but s
// whose box meets the path's, tested exactly), or an odd number and x lies within the cap of the triangle it left
// through last. Exact where the distance field is not: a sheet's point 1 mm outside a body that wraps around the
// sheet's edge (a lifter ridge in a gummy bear's hollow) is within the field's tolerance of the body, yet the path to
// it from a limb behind the sheet leaves the bear.
bool pathInsideBody(const RoundedMesh& mesh, int s, const Vector3r& from, const Vector3r& x);

// Whether that path lies in the rounded solid all the way: each stretch of it outside the flat solid lies within the
// cap of the triangle it leaves through or comes back through.
bool pathStaysInsideBody(const RoundedMesh& mesh, int s, const Vector3r& from, const Vector3r& x);

// Where the line x + u d meets the plane of triangle s: u (d not parallel to the plane; for a contact's c_eff and
// n12, the triangle faces n12, Eq. B.5).
inline Real lineToTriangle(const RoundedMesh& mesh, int s, const Vector3r& x, const Vector3r& d) {
  return mesh.rounded(s).normal.dot(mesh.vertices()[mesh.triangles()[s][0]] - x) / mesh.rounded(s).normal.dot(d);
}

// The quick test before overlapInsideBoth, for one body pair (body 2 placed in body 1's frame by `rotation`): the
// segment q1 q2 along n12, no longer than delta_eff, lies nearer no exit of triangle s of body 1 or t of body 2 at its
// angle (TriangleExits::clear), and so surely stays inside both bodies. The meshes' exits are looked up once per pair.
struct PairExits {
  PairExits(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation)
      : mesh1(mesh1), mesh2(mesh2), exits1(mesh1.exits()), exits2(mesh2.exits()), back(rotation.transpose()) {}
  bool clear(int s, int t, const PressureGeom& geom) const {
    return exits1.clear(s, mesh1.rounded(s).normal.dot(geom.normal), geom.effectiveOverlap) &&
           exits2.clear(t, -mesh2.rounded(t).normal.dot(back * geom.normal), geom.effectiveOverlap);
  }

  const RoundedMesh& mesh1;
  const RoundedMesh& mesh2;
  const TriangleExits& exits1;
  const TriangleExits& exits2;
  const Matrix3r back;  // body 1's frame into body 2's
};

// The segment test for triangle s of mesh1 and triangle t of body 2 in contact as `geom` (body 1's frame); `deep`:
// the pair is deeper than the Hertz range, and the distance fields are asked first.
bool overlapInsideBoth(const RoundedMesh& mesh1, int s, const PlacedMesh& body2, int t, const PressureGeom& geom,
                       bool deep);

}  // namespace roundedmesh
