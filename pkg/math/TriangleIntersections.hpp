// The polygon S of Appendix B for many candidates at once: for each lane k, S = P ∩ Q of two triangles in their
// contact plane (Sutherland-Hodgman: P clipped by Q's three edges, as ConvexPolygon::intersection does), and the
// point of S closest to the plane's origin c (c_eff of Eq. B.4, as ConvexPolygon::closestPoint does). Plane
// coordinates [m].
//
// The lanes run several per instruction on the widest vector unit the processor has (Google Highway, chosen at run
// time), with the reference's operations in the reference's order and no fused multiply-add: every lane's corners,
// their order and the closest point are ConvexPolygon's bit for bit (TriangleIntersectionsTest). A lane whose clip by
// Q's edge e would give more than the 4 + e corners a convex polygon can have there (possible only where rounding makes
// a nearly degenerate polygon look non-convex) is marked and left to ConvexPolygon.
#pragma once

#include "pkg/math/ConvexPolygon.hpp"

namespace roundedmesh {

struct TriangleIntersections {
  static constexpr int kCapacity = 16;  // lanes per batch: a multiple of every x86 vector unit's width
  static constexpr int kCorners = 6;    // the most corners two triangles' intersection has
  static constexpr Real kOverflow = -1; // `corners` of a lane left to ConvexPolygon

  int size = 0;  // lanes in use
  // Inputs: P's and Q's corners, counter-clockwise (as ConvexPolygon::triangle stores them).
  alignas(64) Real px[3][kCapacity], py[3][kCapacity], qx[3][kCapacity], qy[3][kCapacity];
  // Outputs: S's corners and their number (fewer than 3: S is empty, as ConvexPolygon::empty says), and the point
  // of S closest to the origin (meaningful where S is not empty).
  alignas(64) Real sx[kCorners][kCapacity], sy[kCorners][kCapacity];
  alignas(64) Real corners[kCapacity];
  alignas(64) Real closestX[kCapacity], closestY[kCapacity];

  // Lane k's inputs from two triangles as ConvexPolygon::triangle makes them; lane k's S as a ConvexPolygon.
  void set(int k, const ConvexPolygon& p, const ConvexPolygon& q);
  bool overflowed(int k) const { return corners[k] == kOverflow; }
  ConvexPolygon polygon(int k) const;
  Vector2r closestPoint(int k) const { return Vector2r(closestX[k], closestY[k]); }
};

// Fills the outputs of lanes [0, size).
void intersectTriangles(TriangleIntersections& batch);

// Whether the narrow phase's lanes (these, TrianglePlanes.hpp and PolygonContacts.hpp, which run where these do) are
// quicker than one candidate at a time on the vector unit chosen here: where it holds at least 4 doubles (AVX2,
// AVX-512) they are, by about 30 % of the settled packing's narrow phase; on units of 2 (SSE4, SSSE3) the two ways
// cost the same within a few per cent (doc/benchmarks.md, Speed III, steps 8 and 11).
bool triangleIntersectionsPay();

}  // namespace roundedmesh
