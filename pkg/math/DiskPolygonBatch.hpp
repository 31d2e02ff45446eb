// The closed forms of DiskPolygonIntegrals.hpp for many polygons at once (a pair's triangle contacts, 16 at a time),
// edge by edge in vector lanes: each edge P Q of a polygon S against its disc of radius a gives
//   its triangle (origin, P, Q)'s signed share of P = integral of w dA, M = integral of (x, y) w dA and
//   E = integral of w^3 dA over S n Omega (w = sqrt(a^2 - r^2)), whose sums over S's edges are S's integrals;
//   the edge's own integrals of w^3 ds and lambda w^3 ds along its part inside the disc (edgeIntegrals).
// As the other batched kernels: Google Highway lanes with the scalar reference's operations in its order and no fused
// multiply-add, so that each edge's share equals the reference's but for its arctangents: three per edge, Highway's
// polynomial (3 ulp; fused multiply-adds where the instruction set has them, so its last bits depend on it) where
// the reference calls the C library's atan2 (DiskPolygonBatchTest, every instruction set: 1e-14 of the disc's
// values). The sums add the shares in S's order, as diskPolygonIntegrals does.
#pragma once

#include <array>

#include "pkg/math/ConvexPolygon.hpp"
#include "pkg/math/DiskPolygonIntegrals.hpp"

namespace roundedmesh {

struct DiskPolygonBatch {
  static constexpr int kPolygons = 16;
  static constexpr int kEdges = kPolygons * ConvexPolygon::kCapacity;
  static constexpr int kLanes = 8;  // at most, per vector: every x86 vector unit's doubles
  static_assert(kEdges % kLanes == 0);

  int polygons = 0;                              // polygons added since clear()
  int edges = 0;                                 // their edges
  std::array<int, kPolygons + 1> firstEdge{};    // polygon k's edges are [firstEdge[k], firstEdge[k + 1])
  // Inputs per edge: its ends [m] and its disc's radius a [m].
  alignas(64) Real px[kEdges], py[kEdges], qx[kEdges], qy[kEdges], radius[kEdges];
  // Outputs per edge: its triangle's shares of P [m^3], M [m^4] and E [m^5], its edge integrals [m^4], and its
  // direction (Q - P) / |Q - P| (NaN where P = Q, where Eigen's normalized() gives zero).
  alignas(64) Real pressure[kEdges], momentX[kEdges], momentY[kEdges], energy[kEdges];
  alignas(64) Real edgeEnergy[kEdges], edgeEnergyMoment[kEdges];
  alignas(64) Real unitX[kEdges], unitY[kEdges];

  void clear() { polygons = edges = 0; }
  // Adds S (counter-clockwise, about its disc's centre) and its disc's radius as the next polygon: no edges for an
  // empty S or a radius that is not positive, as diskPolygonIntegrals returns zero for them.
  void add(Real a, const ConvexPolygon& polygon);
  // Polygon k's integrals, as diskPolygonIntegrals(a, S) returns them.
  DiskPolygonIntegrals integrals(int k) const;
  // Edge i of polygon k (from corner i to i + 1), as edgeIntegrals(a, S[i], S[i + 1]) returns it (zero where the
  // polygon added no edges), and its direction, (S[i + 1] - S[i]).normalized() bit for bit where S[i + 1] != S[i]
  // (zero where the polygon added no edges).
  EdgeIntegrals edge(int k, int i) const {
    const int e = firstEdge[k] + i;
    if (e >= firstEdge[k + 1]) return {};
    return {edgeEnergy[e], edgeEnergyMoment[e]};
  }
  Vector2r direction(int k, int i) const {
    const int e = firstEdge[k] + i;
    if (e >= firstEdge[k + 1]) return Vector2r::Zero();
    return {unitX[e], unitY[e]};
  }
};

// Fills the outputs of every edge added; the lanes past the last edge compute on copies of the first.
void integrateDiskPolygons(DiskPolygonBatch& batch);

}  // namespace roundedmesh
