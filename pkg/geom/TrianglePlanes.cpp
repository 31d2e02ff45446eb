// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once. CMake
// builds this file with -ffp-contract=off: a product and a sum fused into one rounding would differ from
// trianglePlane's in the last bit.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/geom/TrianglePlanes.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"
#include "pkg/math/Vector3Lanes.hpp"

#include "pkg/geom/TrianglePlanes.hpp"

#ifndef ROUNDEDMESH_TRIANGLE_PLANES_ONCE
#define ROUNDEDMESH_TRIANGLE_PLANES_ONCE

namespace roundedmesh {
namespace planes {

// A batch's pose of body 2 and the two meshes' columns.
struct Pose {
  const TriangleColumns* mesh1;
  const TriangleColumns* mesh2;
  Real rotation[3][3];
  Real translation[3];
};

}  // namespace planes
}  // namespace roundedmesh

#endif  // ROUNDEDMESH_TRIANGLE_PLANES_ONCE

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::CappedTag<double, TrianglePlanes::kCapacity>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;
using VI = hn::Vec<hn::RebindToSigned<D>>;

namespace {

// rotation x + translation (Vector3Lanes.hpp: Eigen's order).
HWY_INLINE void Place(const V (&rotation)[3][3], const V translation[3], const V x[3], V out[3]) {
  Rotate3(rotation, x, out);
  for (int i = 0; i < 3; ++i) out[i] = hn::Add(out[i], translation[i]);
}
// planeCoordinates: ((x - c) . t1, (x - c) . t2).
HWY_INLINE void Project(const V x[3], const V c[3], const V t1[3], const V t2[3], V& u, V& v) {
  const V offset[3] = {hn::Sub(x[0], c[0]), hn::Sub(x[1], c[1]), hn::Sub(x[2], c[2])};
  u = Dot3(offset, t1);
  v = Dot3(offset, t2);
}
// ConvexPolygon::triangle(a, b, c): a, then b and c if cross2(b - a, c - a) >= 0, else c and b.
HWY_INLINE void Triangle(const V x[3], const V y[3], Real (&outX)[3][TrianglePlanes::kCapacity],
              Real (&outY)[3][TrianglePlanes::kCapacity], size_t lane) {
  const D d;
  const V bx = hn::Sub(x[1], x[0]), by = hn::Sub(y[1], y[0]), cx = hn::Sub(x[2], x[0]), cy = hn::Sub(y[2], y[0]);
  const M turning = hn::Ge(hn::Sub(hn::Mul(bx, cy), hn::Mul(by, cx)), hn::Zero(d));
  hn::Store(x[0], d, outX[0] + lane);
  hn::Store(y[0], d, outY[0] + lane);
  hn::Store(hn::IfThenElse(turning, x[1], x[2]), d, outX[1] + lane);
  hn::Store(hn::IfThenElse(turning, y[1], y[2]), d, outY[1] + lane);
  hn::Store(hn::IfThenElse(turning, x[2], x[1]), d, outX[2] + lane);
  hn::Store(hn::IfThenElse(turning, y[2], y[1]), d, outY[2] + lane);
}

}  // namespace

// Each lane follows contactPlane (TriangleSphereGeom.cpp) step by step, with every test's branch as a mask: a lane a
// test rejects computes on, and only its rejection is kept.
void TrianglePlaneLanes(const planes::Pose& pose, TrianglePlanes& out, TriangleIntersections& clips) {
  const D d;
  const hn::RebindToSigned<D> di;
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
  const V precision = hn::Set(d, 1e-12);  // Eigen's dummy_precision, unitOrthogonal's test
  V rotation[3][3], translation[3];
  for (int i = 0; i < 3; ++i) {
    translation[i] = hn::Set(d, pose.translation[i]);
    for (int j = 0; j < 3; ++j) rotation[i][j] = hn::Set(d, pose.rotation[i][j]);
  }
  const TriangleColumns &p = *pose.mesh1, &q = *pose.mesh2;
  for (size_t lane = 0; lane < static_cast<size_t>(out.size); lane += hn::Lanes(d)) {
    const VI s = hn::Load(di, out.s + lane), t = hn::Load(di, out.t + lane);
    V s1[3], n1[3], s2[3], n2[3], x[3];
    Gather3(d, p.sphereCentre, s, s1);
    Gather3(d, p.normal, s, n1);
    Gather3(d, q.sphereCentre, t, x);
    Place(rotation, translation, x, s2);
    Gather3(d, q.normal, t, x);
    Rotate3(rotation, x, n2);
    const V between[3] = {hn::Sub(s2[0], s1[0]), hn::Sub(s2[1], s1[1]), hn::Sub(s2[2], s1[2])};
    const M notFacing =
        hn::Or(hn::Not(hn::Gt(Dot3(n1, between), zero)), hn::Not(hn::Lt(Dot3(n2, between), zero)));

    const V R1 = hn::GatherIndex(d, p.radius.data(), s), R2 = hn::GatherIndex(d, q.radius.data(), t);
    const V distance = hn::Sqrt(Dot3(between, between));
    const V overlap = hn::Sub(hn::Add(R1, R2), distance);
    const M noOverlap = hn::Not(hn::Gt(overlap, zero));
    const V n[3] = {hn::Div(between[0], distance), hn::Div(between[1], distance), hn::Div(between[2], distance)};
    const V R = hn::Div(hn::Mul(R1, R2), hn::Add(R1, R2));
    const V a = hn::Sqrt(hn::Mul(overlap, R));
    const V along = hn::Div(hn::Add(hn::Mul(hn::Sub(distance, R2), hn::Add(distance, R2)), hn::Mul(R1, R1)),
                            hn::Mul(two, distance));
    V c[3];
    for (int i = 0; i < 3; ++i) c[i] = hn::Add(s1[i], hn::Mul(along, n[i]));
    V offset[3];
    Gather3(d, p.circumcentre, s, x);
    for (int i = 0; i < 3; ++i) offset[i] = hn::Sub(x[i], c[i]);
    const V height = Dot3(offset, n);
    const V reach = hn::Add(a, hn::GatherIndex(d, p.circumradius.data(), s));
    const M outside = hn::Gt(hn::Sub(Dot3(offset, offset), hn::Mul(height, height)), hn::Mul(reach, reach));
    V rejection = hn::IfThenElse(outside, hn::Set(d, double(Rejection::OutsideCircle)), zero);
    rejection = hn::IfThenElse(noOverlap, hn::Set(d, double(Rejection::NoOverlap)), rejection);
    rejection = hn::IfThenElse(notFacing, hn::Set(d, double(Rejection::NotFacing)), rejection);
    hn::Store(rejection, d, out.rejection + lane);

    // unitOrthogonal: (-n_y, n_x, 0) / |(n_x, n_y)| unless both are much smaller than n_z, else (0, -n_z, n_y) / |(n_y, n_z)|.
    const V zScale = hn::Mul(hn::Abs(n[2]), precision);
    const M offAxis = hn::Or(hn::Not(hn::Le(hn::Abs(n[0]), zScale)), hn::Not(hn::Le(hn::Abs(n[1]), zScale)));
    const V inverseXY = hn::Div(one, hn::Sqrt(hn::Add(hn::Mul(n[0], n[0]), hn::Mul(n[1], n[1]))));
    const V inverseYZ = hn::Div(one, hn::Sqrt(hn::Add(hn::Mul(n[1], n[1]), hn::Mul(n[2], n[2]))));
    const V t1[3] = {hn::IfThenElse(offAxis, hn::Mul(hn::Neg(n[1]), inverseXY), zero),
                     hn::IfThenElse(offAxis, hn::Mul(n[0], inverseXY), hn::Mul(hn::Neg(n[2]), inverseYZ)),
                     hn::IfThenElseZero(hn::Not(offAxis), hn::Mul(n[1], inverseYZ))};
    V t2[3];
    Cross3(n, t1, t2);
    for (int i = 0; i < 3; ++i) {
      hn::Store(c[i], d, out.centre[i] + lane);
      hn::Store(n[i], d, out.normal[i] + lane);
      hn::Store(t1[i], d, out.tangent1[i] + lane);
      hn::Store(t2[i], d, out.tangent2[i] + lane);
    }
    hn::Store(R, d, out.radius + lane);
    hn::Store(overlap, d, out.sphereOverlap + lane);
    hn::Store(a, d, out.contactRadius + lane);

    V px[3], py[3], qx[3], qy[3];
    for (int i = 0; i < 3; ++i) {
      Gather3(d, p.corner[i], s, x);
      Project(x, c, t1, t2, px[i], py[i]);
      V placed[3];
      Gather3(d, q.corner[i], t, x);
      Place(rotation, translation, x, placed);
      Project(placed, c, t1, t2, qx[i], qy[i]);
      hn::Store(px[i], d, out.nodeX[i] + lane);
      hn::Store(py[i], d, out.nodeY[i] + lane);
      hn::Store(qx[i], d, out.partnerX[i] + lane);
      hn::Store(qy[i], d, out.partnerY[i] + lane);
    }
    Triangle(px, py, clips.px, clips.py, lane);
    Triangle(qx, qy, clips.qx, clips.qy, lane);
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

namespace roundedmesh {

HWY_EXPORT(TrianglePlaneLanes);

void trianglePlanes(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                    const Vector3r& translation, TrianglePlanes& planes, TriangleIntersections& clips) {
  planes::Pose pose{&mesh1.columns(), &mesh2.columns(), {}, {}};
  for (int i = 0; i < 3; ++i) {
    pose.translation[i] = translation[i];
    for (int j = 0; j < 3; ++j) pose.rotation[i][j] = rotation(i, j);
  }
  // The last vector's lanes past the batch gather from triangle 0.
  for (int k = planes.size; k < TrianglePlanes::kCapacity; ++k) planes.s[k] = planes.t[k] = 0;
  clips.size = planes.size;
  HWY_DYNAMIC_DISPATCH(TrianglePlaneLanes)(pose, planes, clips);
}

void TrianglePlanes::get(int k, PressureGeom& geom) const {
  for (int i = 0; i < 3; ++i) {
    geom.centre[i] = centre[i][k];
    geom.normal[i] = normal[i][k];
    geom.tangent1[i] = tangent1[i][k];
    geom.tangent2[i] = tangent2[i][k];
    geom.nodes[i] = Vector2r(nodeX[i][k], nodeY[i][k]);
    geom.partnerNodes[i] = Vector2r(partnerX[i][k], partnerY[i][k]);
  }
  geom.radius = radius[k];
  geom.sphereOverlap = sphereOverlap[k];
  geom.contactRadius = contactRadius[k];
}

}  // namespace roundedmesh

#endif  // HWY_ONCE
