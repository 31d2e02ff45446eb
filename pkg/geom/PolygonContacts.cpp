// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once. CMake
// builds this file with -ffp-contract=off: a product and a sum fused into one rounding would differ from
// triangleContactOnPolygon's in the last bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/geom/PolygonContacts.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"
#include "pkg/math/Vector3Lanes.hpp"

#include "pkg/geom/PolygonContacts.hpp"
#include "pkg/shape/TriangleExits.hpp"

#ifndef ROUNDEDMESH_POLYGON_CONTACTS_ONCE
#define ROUNDEDMESH_POLYGON_CONTACTS_ONCE

namespace roundedmesh {
namespace polygons {

struct Batch {
  const TriangleColumns* mesh1;
  const TriangleColumns* mesh2;
  const Real* clearances1;  // TriangleExits::clearances
  const Real* clearances2;
  const TrianglePlanes* planes;
  const TriangleIntersections* clips;
  Real back[3][3];  // body 1's frame into body 2's: rotation's transpose
  Real linear[3], angular[3];
};

}  // namespace polygons
}  // namespace roundedmesh

#endif  // ROUNDEDMESH_POLYGON_CONTACTS_ONCE

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

namespace {

using D = hn::CappedTag<double, PolygonContacts::kCapacity>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

// RelativeMotion::at: linear + angular x x.
HWY_INLINE void VelocityAt(const V linear[3], const V angular[3], const V x[3], V out[3]) {
  Cross3(angular, x, out);
  for (int i = 0; i < 3; ++i) out[i] = hn::Add(linear[i], out[i]);
}
// std::max(x, 0): x unless x < 0, a NaN kept.
HWY_INLINE V AtLeastZero(V x) { return hn::IfThenElse(hn::Lt(x, hn::Zero(D())), hn::Zero(D()), x); }
HWY_INLINE void Load3(const Real (&column)[3][PolygonContacts::kCapacity], size_t lane, V out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = hn::Load(D(), column[i] + lane);
}
// TriangleExits::clear(t, cosine, length): length below triangle t's clearance at the level of cosine, the number
// of levels' cosines above it (they fall with the level; a NaN is level 0, as TriangleExits::level has it).
template <class VI>
HWY_INLINE hn::Mask<D> Clear(const Real* clearances, VI t, V cosine, V length) {
  const D d;
  const hn::RebindToSigned<D> di;
  V level = hn::Zero(d);
  for (int k = 0; k < TriangleExits::kLevels - 1; ++k)
    level = hn::Add(level, hn::IfThenElseZero(hn::Lt(cosine, hn::Set(d, TriangleExits::kLevelCosines[k])), hn::Set(d, 1.0)));
  const VI at = hn::Add(hn::Mul(t, hn::Set(di, TriangleExits::kLevels)), hn::ConvertTo(di, level));
  return hn::Lt(length, hn::GatherIndex(d, clearances, at));
}

}  // namespace

// Each lane follows contactOnPolygon (TriangleSphereGeom.cpp) and setRelativeVelocity (PressureGeom.hpp) step by step.
void PolygonContactLanes(const polygons::Batch& batch, PolygonContacts& out) {
  const D d;
  const hn::RebindToSigned<D> di;
  const V zero = hn::Zero(d), three = hn::Set(d, 3.0);
  V linear[3], angular[3], back[3][3];
  for (int i = 0; i < 3; ++i) {
    linear[i] = hn::Set(d, batch.linear[i]);
    angular[i] = hn::Set(d, batch.angular[i]);
    for (int j = 0; j < 3; ++j) back[i][j] = hn::Set(d, batch.back[i][j]);
  }
  const TrianglePlanes& planes = *batch.planes;
  const TriangleIntersections& clips = *batch.clips;
  for (size_t lane = 0; lane < static_cast<size_t>(planes.size); lane += hn::Lanes(d)) {
    const V ex = hn::Load(d, clips.closestX + lane), ey = hn::Load(d, clips.closestY + lane);
    const V hSq = hn::Add(hn::Mul(ex, ex), hn::Mul(ey, ey));
    const V a = hn::Load(d, planes.contactRadius + lane);
    V rejection = hn::IfThenElseZero(hn::Not(hn::Lt(hSq, hn::Mul(a, a))), hn::Set(d, double(Rejection::BeyondContactCircle)));
    rejection = hn::IfThenElse(hn::Lt(hn::Load(d, clips.corners + lane), three), hn::Set(d, double(Rejection::EmptyPolygon)), rejection);
    rejection = hn::IfThenElse(hn::Eq(hn::Load(d, planes.rejection + lane), zero), rejection, hn::Load(d, planes.rejection + lane));
    hn::Store(rejection, d, out.rejection + lane);

    const auto s = hn::Load(di, planes.s + lane), t = hn::Load(di, planes.t + lane);
    const V R1 = hn::GatherIndex(d, batch.mesh1->radius.data(), s);
    const V R2 = hn::GatherIndex(d, batch.mesh2->radius.data(), t);
    const V reach1 = hn::Sqrt(AtLeastZero(hn::Sub(hn::Mul(R1, R1), hSq)));
    const V reach2 = hn::Sqrt(AtLeastZero(hn::Sub(hn::Mul(R2, R2), hSq)));
    const V overlap = hn::Load(d, planes.sphereOverlap + lane);
    const V effectiveOverlap = hn::Add(hn::Add(hn::Sub(hn::Sub(overlap, R1), R2), reach1), reach2);
    hn::Store(effectiveOverlap, d, out.effectiveOverlap + lane);

    V c[3], n[3], t1[3], t2[3], v[3];
    Load3(planes.centre, lane, c);
    Load3(planes.normal, lane, n);
    // The exits' quick test: the angle of n12 to each triangle's inward normal, body 2's in its own frame.
    V normal[3], turned[3];
    Gather3(d, batch.mesh1->normal, s, normal);
    const M clear1 = Clear(batch.clearances1, s, Dot3(normal, n), effectiveOverlap);
    Gather3(d, batch.mesh2->normal, t, normal);
    Rotate3(back, n, turned);
    const M clear2 = Clear(batch.clearances2, t, hn::Neg(Dot3(normal, turned)), effectiveOverlap);
    hn::Store(hn::IfThenElseZero(hn::And(clear1, clear2), hn::Set(d, 1.0)), d, out.clear + lane);
    Load3(planes.tangent1, lane, t1);
    Load3(planes.tangent2, lane, t2);
    VelocityAt(linear, angular, c, v);
    hn::Store(hn::Neg(Dot3(n, v)), d, out.overlapRate + lane);
    Cross3(angular, t1, v);
    hn::Store(hn::Neg(Dot3(n, v)), d, out.slopeX + lane);
    Cross3(angular, t2, v);
    hn::Store(hn::Neg(Dot3(n, v)), d, out.slopeY + lane);
    V point[3];
    for (int i = 0; i < 3; ++i) point[i] = hn::Add(hn::Add(c[i], hn::Mul(ex, t1[i])), hn::Mul(ey, t2[i]));
    VelocityAt(linear, angular, point, v);
    const V along = Dot3(v, n);
    for (int i = 0; i < 3; ++i) hn::Store(hn::Sub(v[i], hn::Mul(along, n[i])), d, out.slip[i] + lane);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace roundedmesh {

HWY_EXPORT(PolygonContactLanes);

void polygonContacts(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                     const TrianglePlanes& planes, const TriangleIntersections& clips, const RelativeMotion& motion,
                     PolygonContacts& contacts) {
  polygons::Batch batch{&mesh1.columns(), &mesh2.columns(), mesh1.exits().clearances(), mesh2.exits().clearances(),
                        &planes, &clips, {}, {}, {}};
  for (int i = 0; i < 3; ++i) {
    batch.linear[i] = motion.linear[i];
    batch.angular[i] = motion.angular[i];
    for (int j = 0; j < 3; ++j) batch.back[i][j] = rotation(j, i);
  }
  HWY_DYNAMIC_DISPATCH(PolygonContactLanes)(batch, contacts);
}

void PolygonContacts::get(int k, const TriangleIntersections& clips, int triangle, int partnerTriangle,
                          PressureGeom& geom) const {
  geom.polygon = clips.polygon(k);
  geom.effectivePoint = clips.closestPoint(k);
  geom.triangle = triangle;
  geom.partnerTriangle = partnerTriangle;
  geom.effectiveOverlap = effectiveOverlap[k];
  geom.elliptical = false;
  geom.ellipseCentre = Vector2r::Zero();
  geom.toCircle = Matrix2r::Identity();
  geom.overlapRate = overlapRate[k];
  geom.overlapRateSlope = Vector2r(slopeX[k], slopeY[k]);
  geom.slip = Vector3r(slip[0][k], slip[1][k], slip[2][k]);
}

}  // namespace roundedmesh

#endif  // HWY_ONCE
