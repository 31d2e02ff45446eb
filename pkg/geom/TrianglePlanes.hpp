// The tests before S and the contact plane of Appendix B (trianglePlane, TriangleSphereGeom.hpp) for many candidates
// of one body pair at once: for each lane k, triangle s_k of body 1 against triangle t_k of body 2, placed in body 1's
// frame by x1 = rotation x2 + translation (lengths [m]):
//   facing (Eq. B.5)   n1 . (s2 - s1) > 0 and n2 . (s1 - s2) > 0
//   overlap (Eq. 10)   delta_s = R1 + R2 - |s2 - s1| > 0, n12 = (s2 - s1) / |s2 - s1|
//   contact circle     R* = R1 R2 / (R1 + R2) (Eq. 3), a = sqrt(delta_s R*) (Eq. 5), c on the radical plane; P's
//                      circumcircle, projected, must come within a of c
//   the plane          t1 = n12's unit orthogonal (Eigen's unitOrthogonal), t2 = n12 x t1; both triangles' corners in
//                      plane coordinates about c
// and P' and Q' as the input of S's lanes (TriangleIntersections.hpp), in ConvexPolygon::triangle's order.
//
// The lanes read the triangles from the meshes' columns (TriangleColumns.hpp) and run several per instruction on the
// widest vector unit the processor has (Google Highway, chosen at run time), with trianglePlane's operations in its
// order (Eigen's, for its sums and products of small vectors) and no fused multiply-add: every lane is trianglePlane's
// bit for bit (TrianglePlanesTest, and in place RecordedSceneTest).
#pragma once

#include <cstdint>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/math/TriangleIntersections.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

struct TrianglePlanes {
  static constexpr int kCapacity = TriangleIntersections::kCapacity;

  int size = 0;  // lanes in use
  // Inputs: each lane's triangle of body 1 and of body 2.
  alignas(64) int64_t s[kCapacity], t[kCapacity];
  // Outputs: the test that rejected the lane (a Rejection's value; Rejection::None where the lane passes); where it
  // passes, the plane and the projected corners of both triangles in mesh order (PressureGeom's fields).
  alignas(64) Real rejection[kCapacity];
  alignas(64) Real centre[3][kCapacity], normal[3][kCapacity], tangent1[3][kCapacity], tangent2[3][kCapacity];
  alignas(64) Real radius[kCapacity], sphereOverlap[kCapacity], contactRadius[kCapacity];
  alignas(64) Real nodeX[3][kCapacity], nodeY[3][kCapacity], partnerX[3][kCapacity], partnerY[3][kCapacity];

  GeomTest result(int k) const { return {static_cast<Rejection>(static_cast<int>(rejection[k]))}; }
  // Lane k's plane into geom, as trianglePlane fills it but for geom.polygon: P' is in the lanes of `clips`.
  void get(int k, PressureGeom& geom) const;
};

// Fills the outputs of lanes [0, planes.size), and of `clips` the inputs of the same lanes (P' and Q', meaningful
// where the lane passes) and its size.
void trianglePlanes(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                    const Vector3r& translation, TrianglePlanes& planes, TriangleIntersections& clips);

}  // namespace roundedmesh
