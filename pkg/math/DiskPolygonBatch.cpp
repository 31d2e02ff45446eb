// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once. CMake
// builds this file with -ffp-contract=off: a product and a sum fused into one rounding would differ from the scalar
// reference (DiskPolygonIntegrals.cpp) in the last bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/math/DiskPolygonBatch.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"
#include "hwy/contrib/math/math-inl.h"

#include <algorithm>
#include <stdexcept>

#include "pkg/math/DiskPolygonBatch.hpp"

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// atan2(y, x) for y >= 0, in [0, pi]: Highway's arctangent of the ratio in [0, 1], then the octant.
template <class D, class V>
HWY_INLINE V angleOf(D d, V y, V x) {
  const V zero = hn::Zero(d), ax = hn::Abs(x);
  const V small = hn::Min(y, ax), large = hn::Max(y, ax);
  const V ratio = hn::IfThenElse(hn::Eq(large, zero), zero, hn::Div(small, large));
  V angle = hn::Atan(d, ratio);
  angle = hn::IfThenElse(hn::Gt(y, ax), hn::Sub(hn::Set(d, M_PI / 2), angle), angle);
  return hn::IfThenElse(hn::Lt(x, zero), hn::Sub(hn::Set(d, M_PI), angle), angle);
}

// Each lane follows edgeInDisc and triangleShare (DiskPolygonIntegrals.cpp) and edgeIntegrals, operation by operation;
// std::max(x, 0) is x < 0 ? 0 : x, and a lane's branches are both computed and one kept.
void DiskPolygonLanes(DiskPolygonBatch& b) {
  const hn::CappedTag<double, DiskPolygonBatch::kLanes> d;
  using V = hn::Vec<decltype(d)>;
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), three = hn::Set(d, 3.0);
  const V five = hn::Set(d, 5.0), eight = hn::Set(d, 8.0);
  auto atLeastZero = [&](V x) { return hn::IfThenElse(hn::Lt(x, zero), zero, x); };
  auto signOf = [&](V x) {
    return hn::IfThenElse(hn::Gt(x, zero), one, hn::IfThenElse(hn::Lt(x, zero), hn::Neg(one), zero));
  };
  for (size_t at = 0; at < static_cast<size_t>(b.edges); at += lanes) {
    const V px = hn::Load(d, b.px + at), py = hn::Load(d, b.py + at);
    const V qx = hn::Load(d, b.qx + at), qy = hn::Load(d, b.qy + at), a = hn::Load(d, b.radius + at);
    // edgeInDisc
    const V dx = hn::Sub(qx, px), dy = hn::Sub(qy, py);
    const V length = hn::Sqrt(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)));
    const V b1 = hn::Add(hn::Mul(px, dx), hn::Mul(py, dy));
    const V c = hn::Sub(hn::Add(hn::Mul(px, px), hn::Mul(py, py)), hn::Mul(a, a));
    const V lengthSq = hn::Mul(length, length);
    const V discriminant = hn::Sub(hn::Mul(b1, b1), hn::Mul(lengthSq, c));
    const V root = hn::Sqrt(atLeastZero(discriminant));
    const V tIn = hn::Max(hn::Div(hn::Sub(hn::Neg(b1), root), lengthSq), zero);
    const V tOut = hn::Min(hn::Div(hn::Add(hn::Neg(b1), root), lengthSq), one);
    const V ux = hn::Div(dx, length), uy = hn::Div(dy, length);
    hn::Store(ux, d, b.unitX + at);
    hn::Store(uy, d, b.unitY + at);
    const V h = hn::Sub(hn::Mul(px, uy), hn::Mul(py, ux));
    const V A = hn::Sub(hn::Mul(a, a), hn::Mul(h, h));
    const auto inside = hn::And(hn::And(hn::Gt(length, zero), hn::Gt(discriminant, zero)),
                                hn::And(hn::Lt(tIn, tOut), hn::Gt(A, zero)));
    const V halfChord = hn::Sqrt(atLeastZero(A));
    auto w = [&](V s) { return hn::Sqrt(atLeastZero(hn::Mul(hn::Sub(halfChord, s), hn::Add(halfChord, s)))); };
    const V sP = hn::Add(hn::Mul(px, ux), hn::Mul(py, uy)), sQ = hn::Add(hn::Mul(qx, ux), hn::Mul(qy, uy));
    const auto enters = hn::Gt(tIn, zero), leaves = hn::Lt(tOut, one);
    const V s0 = hn::IfThenElse(enters, hn::Neg(halfChord), sP), s1 = hn::IfThenElse(leaves, halfChord, sQ);
    const V w0 = hn::IfThenZeroElse(enters, w(s0)), w1 = hn::IfThenZeroElse(leaves, w(s1));
    const V crossW = hn::Sub(hn::Mul(w0, s1), hn::Mul(s0, w1));
    const V arc = angleOf(d, hn::Abs(crossW), hn::Add(hn::Mul(w0, w1), hn::Mul(s0, s1)));
    auto p3Polynomial = [&](V s, V ws) {
      return hn::Mul(hn::Mul(hn::Div(s, eight), hn::Sub(hn::Mul(five, A), hn::Mul(hn::Mul(two, s), s))), ws);
    };
    const V edgeEnergy = hn::Add(hn::Sub(p3Polynomial(s1, w1), p3Polynomial(s0, w0)),
                                 hn::Mul(hn::Div(hn::Mul(hn::Mul(three, A), A), eight), arc));
    // triangleShare
    const V aa = hn::Mul(a, a), aaa = hn::Mul(aa, a);
    const V a3 = hn::Div(aaa, three), a5 = hn::Div(hn::Mul(hn::Mul(hn::Mul(a3, a), a), three), five);
    const V crossPQ = hn::Sub(hn::Mul(px, qy), hn::Mul(py, qx));
    const V dotPQ = hn::Add(hn::Mul(px, qx), hn::Mul(py, qy));
    const V sign = signOf(h), absH = hn::Abs(h), hh = hn::Mul(h, h);
    // Outside: the sector's angle, atan2(cross, dot) = sgn(cross) atan2(|cross|, dot); inside: from s.
    const V angleSize = angleOf(d, hn::IfThenElse(inside, hn::Mul(absH, length), hn::Abs(crossPQ)),
                                hn::IfThenElse(inside, hn::Add(hh, hn::Mul(sP, sQ)), dotPQ));
    const V coneAngle = angleOf(d, hn::Mul(hn::Mul(a, absH), hn::Abs(crossW)),
                                hn::Add(hn::Mul(hn::Mul(hh, w0), w1), hn::Mul(hn::Mul(aa, s0), s1)));
    const V cone1 = hn::Sub(hn::Sub(hn::Mul(hn::Mul(aaa, sign), coneAngle),
                                    hn::Mul(hn::Mul(h, hn::Add(aa, hn::Div(A, two))), arc)),
                            hn::Div(hn::Mul(h, hn::Sub(hn::Mul(s1, w1), hn::Mul(s0, w0))), two));
    const V insidePressure = hn::Sub(hn::Mul(hn::Mul(a3, sign), angleSize), hn::Div(cone1, three));
    const V insideEnergy = hn::Sub(hn::Mul(hn::Mul(a5, sign), angleSize),
                                   hn::Div(hn::Sub(hn::Mul(aa, cone1), hn::Mul(h, edgeEnergy)), five));
    const V outsideAngle = hn::IfThenElseZero(hn::Gt(length, zero), hn::CopySign(angleSize, crossPQ));
    hn::Store(hn::IfThenElse(inside, insidePressure, hn::Mul(a3, outsideAngle)), d, b.pressure + at);
    hn::Store(hn::IfThenElse(inside, insideEnergy, hn::Mul(a5, outsideAngle)), d, b.energy + at);
    const V third = hn::Div(edgeEnergy, three);
    hn::Store(hn::IfThenElseZero(inside, hn::Mul(hn::Neg(uy), third)), d, b.momentX + at);
    hn::Store(hn::IfThenElseZero(inside, hn::Mul(ux, third)), d, b.momentY + at);
    // edgeIntegrals
    auto fifth = [](V x) { return hn::Mul(hn::Mul(hn::Mul(hn::Mul(x, x), x), x), x); };
    const V sMoment = hn::Div(hn::Sub(fifth(w0), fifth(w1)), five);
    const V edgeMoment = hn::Div(hn::Sub(sMoment, hn::Mul(sP, edgeEnergy)), length);
    hn::Store(hn::IfThenElseZero(inside, edgeEnergy), d, b.edgeEnergy + at);
    hn::Store(hn::IfThenElseZero(inside, edgeMoment), d, b.edgeEnergyMoment + at);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace roundedmesh {

HWY_EXPORT(DiskPolygonLanes);

void DiskPolygonBatch::add(Real a, const ConvexPolygon& polygon) {
  if (polygons == kPolygons) throw std::logic_error("DiskPolygonBatch: more than kPolygons polygons");
  firstEdge[polygons] = edges;
  if (!polygon.empty() && a > 0) {
    for (int i = 0; i < polygon.size(); ++i) {
      const Vector2r &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
      px[edges] = p.x();
      py[edges] = p.y();
      qx[edges] = q.x();
      qy[edges] = q.y();
      radius[edges] = a;
      ++edges;
    }
  }
  firstEdge[++polygons] = edges;
}

DiskPolygonIntegrals DiskPolygonBatch::integrals(int k) const {
  DiskPolygonIntegrals sum;
  for (int e = firstEdge[k]; e < firstEdge[k + 1]; ++e) {
    sum.pressure += pressure[e];
    sum.pressureMoment += Vector2r(momentX[e], momentY[e]);
    sum.energy += energy[e];
  }
  sum.pressure = std::max(sum.pressure, Real(0));
  sum.energy = std::max(sum.energy, Real(0));
  return sum;
}

void integrateDiskPolygons(DiskPolygonBatch& batch) {
  if (batch.edges == 0) return;
  // The vector loop runs over whole vectors of at most kLanes: the lanes past the last edge compute on copies of the
  // first.
  constexpr int lanes = DiskPolygonBatch::kLanes;
  const int padded = (batch.edges + lanes - 1) / lanes * lanes;
  for (Real* column : {batch.px, batch.py, batch.qx, batch.qy, batch.radius})
    for (int e = batch.edges; e < padded; ++e) column[e] = column[0];
  HWY_DYNAMIC_DISPATCH(DiskPolygonLanes)(batch);
}

}  // namespace roundedmesh

#endif  // HWY_ONCE
