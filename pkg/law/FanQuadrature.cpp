// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once. CMake
// builds this file with -ffp-contract=off: a product and a sum fused into one rounding would differ from the
// reference in the last bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/law/FanQuadrature.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "pkg/law/FanQuadrature.hpp"
#include "pkg/math/DunavantRule.hpp"

#ifndef ROUNDEDMESH_FAN_QUADRATURE_ONCE
#define ROUNDEDMESH_FAN_QUADRATURE_ONCE

namespace roundedmesh {
namespace fan {

// The fan's corners as columns, and the rule's columns, for the vector loads.
struct FanInput {
  const Real* l1;
  const Real* l2;
  const Real* l3;
  const Real* weight;
  Real px[ConvexPolygon::kCapacity], py[ConvexPolygon::kCapacity];
  Real area[FanQuadrature::kCapacity];
  int triangles;
  Real contactRadiusSq;
};

}  // namespace fan
}  // namespace roundedmesh

#endif  // ROUNDEDMESH_FAN_QUADRATURE_ONCE

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Each lane: x = (l1 x0 + l2 xj) + l3 xj+1 (y alike), dG = (area w) sqrt(max(a^2 - (x^2 + y^2), 0)), evaluated as
// the reference's Eigen expression evaluates it. Where Max(0, v) may differ from Eigen's max (both zeros, or a NaN,
// on a processor other than x86) the shape is the same: a^2 - r^2 is never -0, and a NaN comes only from a NaN input.
void FanQuadraturePoints(const fan::FanInput& in, FanQuadrature& out) {
  const hn::CappedTag<double, FanQuadrature::kPoints> d;  // a power of two lanes, at most 16: whole vectors
  const size_t lanes = hn::Lanes(d);
  const auto zero = hn::Zero(d), radiusSq = hn::Set(d, in.contactRadiusSq);
  for (int j = 0; j < in.triangles; ++j) {
    const auto x0 = hn::Set(d, in.px[0]), x1 = hn::Set(d, in.px[j + 1]), x2 = hn::Set(d, in.px[j + 2]);
    const auto y0 = hn::Set(d, in.py[0]), y1 = hn::Set(d, in.py[j + 1]), y2 = hn::Set(d, in.py[j + 2]);
    const auto area = hn::Set(d, in.area[j]);
    for (size_t i = 0; i < FanQuadrature::kPoints; i += lanes) {
      const auto l1 = hn::LoadU(d, in.l1 + i), l2 = hn::LoadU(d, in.l2 + i), l3 = hn::LoadU(d, in.l3 + i);
      const auto x = hn::Add(hn::Add(hn::Mul(l1, x0), hn::Mul(l2, x1)), hn::Mul(l3, x2));
      const auto y = hn::Add(hn::Add(hn::Mul(l1, y0), hn::Mul(l2, y1)), hn::Mul(l3, y2));
      const auto shape = hn::Sqrt(hn::Max(zero, hn::Sub(radiusSq, hn::Add(hn::Mul(x, x), hn::Mul(y, y)))));
      const auto dG = hn::Mul(hn::Mul(area, hn::LoadU(d, in.weight + i)), shape);
      const size_t at = FanQuadrature::kPoints * j + i;
      hn::StoreU(x, d, out.x + at);
      hn::StoreU(y, d, out.y + at);
      hn::StoreU(dG, d, out.dG + at);
    }
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace roundedmesh {

HWY_EXPORT(FanQuadraturePoints);

void fanQuadrature(const ConvexPolygon& s, Real contactRadiusSq, FanQuadrature& out) {
  const QuadratureColumns& q = dunavant8Columns();
  fan::FanInput in;
  in.l1 = q.l1.data();
  in.l2 = q.l2.data();
  in.l3 = q.l3.data();
  in.weight = q.weight.data();
  in.triangles = s.size() < 3 ? 0 : s.size() - 2;
  in.contactRadiusSq = contactRadiusSq;
  for (int i = 0; i < s.size(); ++i) {
    in.px[i] = s[i].x();
    in.py[i] = s[i].y();
  }
  for (int j = 0; j < in.triangles; ++j) in.area[j] = 0.5 * cross2(s[j + 1] - s[0], s[j + 2] - s[0]);
  out.triangles = in.triangles;
  HWY_DYNAMIC_DISPATCH(FanQuadraturePoints)(in, out);
}

}  // namespace roundedmesh

#endif  // HWY_ONCE
