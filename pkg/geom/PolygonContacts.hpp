// The rest of Appendix B once S is known (triangleContactOnPolygon, TriangleSphereGeom.hpp, for the paper's circular
// contacts) for the candidates of a batch whose contact planes and polygons S are in lanes (TrianglePlanes.hpp,
// TriangleIntersections.hpp): for each lane,
//   S empty                          -> Rejection::EmptyPolygon
//   h = |c_eff - c| >= a             -> Rejection::BeyondContactCircle
//   delta_eff (Eq. B.4)              delta_s - R1 - R2 + sqrt(R1^2 - h^2) + sqrt(R2^2 - h^2) [m]
//   the sides' approach rate at c, its slope over the plane, and the slip at c_eff (setRelativeVelocity) [m/s, 1/s]
//   from the relative motion of body 2 in body 1's frame;
//   whether the segment q1 q2 along n12, no longer than delta_eff, surely stays inside both bodies: nearer no exit of
//   either triangle at its angle (TriangleExits::clear); the others need the exits' full test (overlapInsideBoth).
//
// As the other batched kernels: Google Highway lanes with triangleContactOnPolygon's operations in its order and no
// fused multiply-add, every lane its result bit for bit (PolygonContactsTest, and in place RecordedSceneTest).
#pragma once

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/geom/TrianglePlanes.hpp"
#include "pkg/math/TriangleIntersections.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

struct PolygonContacts {
  static constexpr int kCapacity = TrianglePlanes::kCapacity;

  // Where a lane passed the planes' tests and S did not overflow: the test that rejected it (a Rejection's value),
  // else Rejection::None and the fields below.
  alignas(64) Real rejection[kCapacity];
  alignas(64) Real effectiveOverlap[kCapacity], overlapRate[kCapacity], slopeX[kCapacity], slopeY[kCapacity];
  alignas(64) Real slip[3][kCapacity];
  alignas(64) Real clear[kCapacity];  // 1 where the segment surely stays inside both bodies, else 0

  GeomTest result(int k) const { return {static_cast<Rejection>(static_cast<int>(rejection[k]))}; }
  bool surelyInside(int k) const { return clear[k] != 0; }
  // Lane k's contact into geom, whose plane (TrianglePlanes::get) is set: S, c_eff and the fields above, a circle's
  // ellipse fields, and the two triangles.
  void get(int k, const TriangleIntersections& clips, int triangle, int partnerTriangle, PressureGeom& geom) const;
};

// Fills the lanes [0, planes.size) of `contacts` from `planes` and `clips` as trianglePlanes and intersectTriangles left
// them (the lanes past planes.size included); body 2 placed in body 1's frame by `rotation` (x1 = rotation x2 + t).
void polygonContacts(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                     const TrianglePlanes& planes, const TriangleIntersections& clips, const RelativeMotion& motion,
                     PolygonContacts& contacts);

}  // namespace roundedmesh
