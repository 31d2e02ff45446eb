// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once. CMake
// builds this file with -ffp-contract=off: a product and a sum fused into one rounding would differ from
// ConvexPolygon's in the last bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/math/TriangleIntersections.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "pkg/math/TriangleIntersections.hpp"

#include <algorithm>

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each lane follows ConvexPolygon::clipInto, intersection and closestPoint step by step. A polygon's corners are
// columns of vectors; a lane's count is a vector of doubles (small whole numbers, exact). Where clipInto pushes a
// corner to the next free slot, here every slot the lane's count can point at takes the corner under a mask.
void IntersectTriangleLanes(TriangleIntersections& b) {
  const hn::CappedTag<double, TriangleIntersections::kCapacity> d;
  using V = hn::Vec<decltype(d)>;
  using M = hn::Mask<decltype(d)>;
  constexpr int kMost = TriangleIntersections::kCorners;
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), three = hn::Set(d, 3.0);
  for (size_t lane = 0; lane < static_cast<size_t>(b.size); lane += lanes) {
    V x[kMost], y[kMost];
    for (int i = 0; i < kMost; ++i) x[i] = y[i] = zero;
    for (int i = 0; i < 3; ++i) {
      x[i] = hn::Load(d, b.px[i] + lane);
      y[i] = hn::Load(d, b.py[i] + lane);
    }
    V count = three;
    M overflow = hn::FirstN(d, 0);
    // P clipped by Q's edge e keeps what lies left of the directed line from Q's corner e to corner e + 1. Before
    // clip e a polygon has at most 3 + e corners, after it 4 + e.
    for (int e = 0; e < 3; ++e) {
      const int before = 3 + e, after = before + 1;
      const V ax = hn::Load(d, b.qx[e] + lane), ay = hn::Load(d, b.qy[e] + lane);
      const V dx = hn::Sub(hn::Load(d, b.qx[(e + 1) % 3] + lane), ax);
      const V dy = hn::Sub(hn::Load(d, b.qy[(e + 1) % 3] + lane), ay);
      const M active = hn::Ge(count, three);  // intersection stops at an empty polygon
      V side[kMost];                          // cross2(direction, corner - a)
      for (int i = 0; i < before; ++i)
        side[i] = hn::Sub(hn::Mul(dx, hn::Sub(y[i], ay)), hn::Mul(dy, hn::Sub(x[i], ax)));
      V outX[kMost], outY[kMost];
      for (int j = 0; j < after; ++j) outX[j] = outY[j] = zero;
      V filled = zero;
      // The lane's next free slot takes (px, py) where `push`; filled can be at most `highest` before it.
      auto pushInto = [&](M push, V px, V py, int highest) {
        for (int j = 0; j <= highest && j < after; ++j) {
          const M here = hn::And(push, hn::Eq(filled, hn::Set(d, j)));
          outX[j] = hn::IfThenElse(here, px, outX[j]);
          outY[j] = hn::IfThenElse(here, py, outY[j]);
        }
        filled = hn::Add(filled, hn::IfThenElseZero(push, one));
      };
      for (int i = 0; i < before; ++i) {
        const M present = hn::Lt(hn::Set(d, i), count);
        // The edge from corner i to the next one, which is corner 0 after the lane's last corner.
        V qx = x[0], qy = y[0], sq = side[0];
        if (i + 1 < before) {
          const M last = hn::Eq(hn::Set(d, i + 1), count);
          qx = hn::IfThenElse(last, x[0], x[i + 1]);
          qy = hn::IfThenElse(last, y[0], y[i + 1]);
          sq = hn::IfThenElse(last, side[0], side[i + 1]);
        }
        const V sp = side[i];
        pushInto(hn::And(present, hn::Ge(sp, zero)), x[i], y[i], 2 * i);
        const M crosses = hn::Or(hn::And(hn::Gt(sp, zero), hn::Lt(sq, zero)),
                                 hn::And(hn::Lt(sp, zero), hn::Gt(sq, zero)));
        const V t = hn::Div(sp, hn::Sub(sp, sq));
        pushInto(hn::And(present, crosses), hn::Add(x[i], hn::Mul(t, hn::Sub(qx, x[i]))),
                 hn::Add(y[i], hn::Mul(t, hn::Sub(qy, y[i]))), 2 * i + 1);
      }
      for (int j = 0; j < after; ++j) {
        x[j] = hn::IfThenElse(active, outX[j], x[j]);
        y[j] = hn::IfThenElse(active, outY[j], y[j]);
      }
      overflow = hn::Or(overflow, hn::And(active, hn::Gt(filled, hn::Set(d, after))));
      count = hn::IfThenElse(active, hn::Min(filled, hn::Set(d, after)), count);
    }

    // The closest point to the origin p = 0: on an edge that p lies outside of (cross2(edge, p - a) < 0), the
    // clamped foot of p, the nearest such.
    V bestX = zero, bestY = zero, bestDistanceSq = hn::Inf(d);
    for (int i = 0; i < kMost; ++i) {
      const M present = hn::Lt(hn::Set(d, i), count);
      V nx = x[0], ny = y[0];
      if (i + 1 < kMost) {
        const M last = hn::Eq(hn::Set(d, i + 1), count);
        nx = hn::IfThenElse(last, x[0], x[i + 1]);
        ny = hn::IfThenElse(last, y[0], y[i + 1]);
      }
      const V ex = hn::Sub(nx, x[i]), ey = hn::Sub(ny, y[i]);
      const V toPx = hn::Sub(zero, x[i]), toPy = hn::Sub(zero, y[i]);
      const M outside = hn::And(present, hn::Lt(hn::Sub(hn::Mul(ex, toPy), hn::Mul(ey, toPx)), zero));
      const V lengthSq = hn::Add(hn::Mul(ex, ex), hn::Mul(ey, ey));
      const V along = hn::Div(hn::Add(hn::Mul(toPx, ex), hn::Mul(toPy, ey)), lengthSq);
      // std::clamp(along, 0, 1): along < 0 ? 0 : (1 < along ? 1 : along), NaN kept as clamp keeps it.
      const V clamped = hn::IfThenElse(hn::Lt(along, zero), zero, hn::IfThenElse(hn::Lt(one, along), one, along));
      const V t = hn::IfThenElse(hn::Gt(lengthSq, zero), clamped, zero);
      const V footX = hn::Add(x[i], hn::Mul(t, ex)), footY = hn::Add(y[i], hn::Mul(t, ey));
      const V offX = hn::Sub(zero, footX), offY = hn::Sub(zero, footY);
      const V distanceSq = hn::Add(hn::Mul(offX, offX), hn::Mul(offY, offY));
      const M nearer = hn::And(outside, hn::Lt(distanceSq, bestDistanceSq));
      bestX = hn::IfThenElse(nearer, footX, bestX);
      bestY = hn::IfThenElse(nearer, footY, bestY);
      bestDistanceSq = hn::IfThenElse(nearer, distanceSq, bestDistanceSq);
    }

    for (int i = 0; i < kMost; ++i) {
      hn::Store(x[i], d, b.sx[i] + lane);
      hn::Store(y[i], d, b.sy[i] + lane);
    }
    hn::Store(hn::IfThenElse(overflow, hn::Set(d, TriangleIntersections::kOverflow), count), d, b.corners + lane);
    hn::Store(bestX, d, b.closestX + lane);
    hn::Store(bestY, d, b.closestY + lane);
  }
}

bool LanesPay() { return hn::Lanes(hn::ScalableTag<double>()) >= 4; }

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace roundedmesh {

HWY_EXPORT(IntersectTriangleLanes);
HWY_EXPORT(LanesPay);

bool triangleIntersectionsPay() { return HWY_DYNAMIC_DISPATCH(LanesPay)(); }

void TriangleIntersections::set(int k, const ConvexPolygon& p, const ConvexPolygon& q) {
  for (int i = 0; i < 3; ++i) {
    px[i][k] = p[i].x();
    py[i][k] = p[i].y();
    qx[i][k] = q[i].x();
    qy[i][k] = q[i].y();
  }
}

ConvexPolygon TriangleIntersections::polygon(int k) const {
  ConvexPolygon s;
  for (int i = 0; i < static_cast<int>(corners[k]); ++i) s.push(Vector2r(sx[i][k], sy[i][k]));
  return s;
}

void intersectTriangles(TriangleIntersections& batch) {
  // The vector loop runs over whole vectors, of at most kCapacity lanes: the lanes past `size` hold copies of lane 0,
  // so that every lane computes on numbers the batch was given.
  for (int k = batch.size; k < TriangleIntersections::kCapacity; ++k)
    for (int i = 0; i < 3; ++i) {
      batch.px[i][k] = batch.px[i][0];
      batch.py[i][k] = batch.py[i][0];
      batch.qx[i][k] = batch.qx[i][0];
      batch.qy[i][k] = batch.qy[i][0];
    }
  HWY_DYNAMIC_DISPATCH(IntersectTriangleLanes)(batch);
}

}  // namespace roundedmesh

#endif  // HWY_ONCE
