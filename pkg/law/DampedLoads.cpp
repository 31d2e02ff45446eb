// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once. CMake
// builds this file with -ffp-contract=off: a product and a sum fused into one rounding would differ from dampedLoad's
// and nodeForces' in the last bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/law/DampedLoads.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "pkg/law/DampedLoads.hpp"

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::CappedTag<double, DampedLoads::kCapacity>;
using V = hn::Vec<D>;

HWY_INLINE V atLeastZero(V x) { return hn::IfThenElse(hn::Lt(x, hn::Zero(D())), hn::Zero(D()), x); }

// nodeForces of the load (force, moment) on the triangle (x, y), step by step, into out[i][lane...]: none for a zero
// or non-finite load, a third each on an edge-on triangle. Inlined: called, it was the lanes' function's tail call,
// which then returned without clearing the vector registers' upper halves (vzeroupper), and the energy law's load,
// scalar code after the lanes, took 1.65-2.07 times as long.
HWY_INLINE void storeNodeForces(V force, V momentX, V momentY, const V (&x)[3], const V (&y)[3],
                                Real (*out)[DampedLoads::kCapacity], size_t lane) {
  const D d;
  const V zero = hn::Zero(d);
  const auto unloaded = hn::Or(hn::Eq(force, zero), hn::Not(hn::Lt(hn::Abs(force), hn::Inf(d))));
  const V px = hn::Div(hn::Neg(momentY), force), py = hn::Div(momentX, force);
  V lambda[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const V ax = hn::Sub(x[j], px), ay = hn::Sub(y[j], py), bx = hn::Sub(x[k], px), by = hn::Sub(y[k], py);
    lambda[i] = hn::Sub(hn::Mul(ax, by), hn::Mul(ay, bx));
  }
  const V twiceArea = hn::Add(hn::Add(lambda[0], lambda[1]), lambda[2]);
  V sum = zero;
  for (V& l : lambda) sum = hn::Add(sum, l = atLeastZero(hn::Div(l, twiceArea)));
  const V third = hn::Div(force, hn::Set(d, 3.0));
  const auto edgeOn = hn::Eq(twiceArea, zero);
  for (int i = 0; i < 3; ++i) {
    const V split = hn::IfThenElse(edgeOn, third, hn::Div(hn::Mul(force, lambda[i]), sum));
    hn::Store(hn::IfThenElseZero(hn::Not(unloaded), split), d, out[i] + lane);
  }
}

// Each lane follows dampedLoad (centreOfPressure, overlapRateAt, dampingFactor) and then nodeForces on the damped
// load, step by step; std::max(x, 0) is x < 0 ? 0 : x.
void DampedLoadLanes(DampedLoads& b) {
  const D d;
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), damping = hn::Set(d, b.damping);
  for (size_t lane = 0; lane < static_cast<size_t>(b.size); lane += lanes) {
    const V force = hn::Load(d, b.force + lane);
    const V momentX = hn::Load(d, b.momentX + lane), momentY = hn::Load(d, b.momentY + lane);
    const V rateAtC = hn::Load(d, b.overlapRate + lane);
    const V centreX = hn::Div(hn::Neg(momentY), force), centreY = hn::Div(momentX, force);
    const V slopeDotCentre = hn::Add(hn::Mul(hn::Load(d, b.slopeX + lane), centreX),
                                     hn::Mul(hn::Load(d, b.slopeY + lane), centreY));
    const V rate = hn::IfThenElse(hn::Gt(force, zero), hn::Add(rateAtC, slopeDotCentre), rateAtC);
    const V factor =
        atLeastZero(hn::Add(one, hn::Div(hn::Mul(damping, rate), hn::Load(d, b.overlap + lane))));
    const V dampedForce = hn::Mul(force, factor);
    const V dampedX = hn::Mul(momentX, factor), dampedY = hn::Mul(momentY, factor);
    hn::Store(dampedForce, d, b.dampedForce + lane);
    hn::Store(dampedX, d, b.dampedMomentX + lane);
    hn::Store(dampedY, d, b.dampedMomentY + lane);
    hn::Store(rate, d, b.rateAtCentre + lane);

    // Eq. 15 on the damped load, and where asked on its damping part (the damped load less the elastic one).
    V x[3], y[3];
    for (int i = 0; i < 3; ++i) {
      x[i] = hn::Load(d, b.nodeX[i] + lane);
      y[i] = hn::Load(d, b.nodeY[i] + lane);
    }
    storeNodeForces(dampedForce, dampedX, dampedY, x, y, b.nodeForce, lane);
    if (b.withDamping)
      storeNodeForces(hn::Sub(dampedForce, force), hn::Sub(dampedX, momentX), hn::Sub(dampedY, momentY), x, y,
                      b.dampingNodeForce, lane);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace roundedmesh {

HWY_EXPORT(DampedLoadLanes);

void DampedLoads::set(int k, const NormalLoad& elastic, const PressureGeom& geom) {
  force[k] = elastic.force;
  momentX[k] = elastic.moment.x();
  momentY[k] = elastic.moment.y();
  regime[k] = elastic.regime;
  elasticEnergy[k] = elastic.elasticEnergy;
  overlapRate[k] = geom.overlapRate;
  slopeX[k] = geom.overlapRateSlope.x();
  slopeY[k] = geom.overlapRateSlope.y();
  overlap[k] = geom.sphereOverlap;
  for (int i = 0; i < 3; ++i) {
    nodeX[i][k] = geom.nodes[i].x();
    nodeY[i][k] = geom.nodes[i].y();
  }
}

NormalLoad DampedLoads::load(int k) const {
  NormalLoad load{dampedForce[k], Vector2r(dampedMomentX[k], dampedMomentY[k]), regime[k]};
  load.elasticForce = force[k];
  load.elasticMoment = Vector2r(momentX[k], momentY[k]);
  load.overlapRate = rateAtCentre[k];
  load.elasticEnergy = elasticEnergy[k];
  return load;
}

void dampLoads(DampedLoads& batch) {
  // The vector loop runs over whole vectors: the lanes past `size` compute on copies of lane 0.
  auto padColumn = [&batch](Real* column) {
    for (int k = batch.size; k < DampedLoads::kCapacity; ++k) column[k] = column[0];
  };
  for (Real* column : {batch.force, batch.momentX, batch.momentY, batch.overlapRate, batch.slopeX, batch.slopeY,
                       batch.overlap})
    padColumn(column);
  for (int i = 0; i < 3; ++i) {
    padColumn(batch.nodeX[i]);
    padColumn(batch.nodeY[i]);
  }
  HWY_DYNAMIC_DISPATCH(DampedLoadLanes)(batch);
}

}  // namespace roundedmesh

#endif  // HWY_ONCE
