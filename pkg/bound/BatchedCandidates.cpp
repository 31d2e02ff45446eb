// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/bound/BatchedCandidates.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"

#include "pkg/bound/BatchedCandidates.hpp"

#ifndef ROUNDEDMESH_BATCHED_CANDIDATES_ONCE
#define ROUNDEDMESH_BATCHED_CANDIDATES_ONCE

#include <cstdint>

namespace roundedmesh {
namespace batched {

// One scan: body 2's pose in body 1's frame, the list's skin and reach, and the near pairs as two index columns.
struct NearScan {
  const TriangleColumns* mesh1;
  const TriangleColumns* mesh2;
  Real rotation[3][3], absRotation[3][3], translation[3];
  Real skin, reach;  // reach = depth + skin [m]
  Real turn;         // the largest rotation within the skin, skin / (mesh 2's bound radius) [rad]
  Real bound2;       // mesh 2's bound radius [m]
  Real margin;       // [m]
  const int64_t* s;
  const int64_t* t;
  size_t count;
};

}  // namespace batched
}  // namespace roundedmesh

#endif  // ROUNDEDMESH_BATCHED_CANDIDATES_ONCE

HWY_BEFORE_NAMESPACE();
namespace roundedmesh {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Writes the indices (into the scan's pairs) of those not rejected to `kept` (room for all); returns how many. A
// compressed store may write a whole vector, lanes [keptCount, keptCount + lanes), which stays within the first
// i + lanes <= count entries since keptCount <= i.
size_t KeptNearPairs(const batched::NearScan& q, int64_t* kept) {
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  using V = hn::Vec<decltype(d)>;
  const size_t lanes = hn::Lanes(d);
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), half = hn::Set(d, 0.5);
  const V skin = hn::Set(d, q.skin), reach = hn::Set(d, q.reach), turn = hn::Set(d, q.turn);
  const V inverseBound2 = hn::Set(d, 1 / q.bound2), margin = hn::Set(d, q.margin);
  V R[3][3], absR[3][3], T[3];
  for (int i = 0; i < 3; ++i) {
    T[i] = hn::Set(d, q.translation[i]);
    for (int j = 0; j < 3; ++j) {
      R[i][j] = hn::Set(d, q.rotation[i][j]);
      absR[i][j] = hn::Set(d, q.absRotation[i][j]);
    }
  }
  auto gather3 = [&](const std::vector<Real>(&column)[3], hn::Vec<decltype(di)> index, V out[3]) {
    for (int k = 0; k < 3; ++k) out[k] = hn::GatherIndex(d, column[k].data(), index);
  };
  auto rotate = [&](const V (&M)[3][3], const V x[3], V out[3]) {
    for (int i = 0; i < 3; ++i) out[i] = M[i][0] * x[0] + M[i][1] * x[1] + M[i][2] * x[2];
  };
  auto dot = [](const V a[3], const V b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  size_t keptCount = 0;
  size_t i = 0;
  for (; i + lanes <= q.count; i += lanes) {
    const auto s = hn::LoadU(di, q.s + i), t = hn::LoadU(di, q.t + i);
    // Filter 1: triangle t's cap box moved into body 1's frame, grown by the reach, against s's.
    V min2[3], max2[3], min1[3], max1[3], centre2[3], size2[3], centre[3], extent[3];
    gather3(q.mesh2->boxMin, t, min2);
    gather3(q.mesh2->boxMax, t, max2);
    gather3(q.mesh1->boxMin, s, min1);
    gather3(q.mesh1->boxMax, s, max1);
    for (int k = 0; k < 3; ++k) {
      centre2[k] = half * (min2[k] + max2[k]);
      size2[k] = half * (max2[k] - min2[k]);
    }
    rotate(R, centre2, centre);
    rotate(absR, size2, extent);
    auto rejected = hn::FirstN(d, 0);  // none yet
    for (int k = 0; k < 3; ++k) {
      centre[k] = centre[k] + T[k];
      extent[k] = extent[k] + reach + margin;
      rejected = hn::Or(rejected, hn::Or(hn::Gt(min1[k], centre[k] + extent[k]), hn::Gt(centre[k] - extent[k], max1[k])));
    }
    // Filter 2: the circumscribed balls.
    V pc[3], qc0[3], qc[3];
    gather3(q.mesh1->circumcentre, s, pc);
    gather3(q.mesh2->circumcentre, t, qc0);
    rotate(R, qc0, qc);
    V offset[3];
    for (int k = 0; k < 3; ++k) {
      qc[k] = qc[k] + T[k];
      offset[k] = qc[k] - pc[k];
    }
    const V pRho = hn::GatherIndex(d, q.mesh1->circumradius.data(), s);
    const V qRho = hn::GatherIndex(d, q.mesh2->circumradius.data(), t);
    const V balls = pRho + qRho + reach + margin;
    rejected = hn::Or(rejected, hn::Gt(dot(offset, offset), balls * balls));
    // Filters 3 and 4: the encompassing spheres' overlap and facing, within the motion.
    V ps[3], qs0[3], sphereOffset[3], pn[3], qn0[3], qn[3];
    gather3(q.mesh1->sphereCentre, s, ps);
    gather3(q.mesh2->sphereCentre, t, qs0);
    rotate(R, qs0, sphereOffset);
    for (int k = 0; k < 3; ++k) sphereOffset[k] = sphereOffset[k] + T[k] - ps[k];
    const V distance = hn::Sqrt(dot(sphereOffset, sphereOffset));
    const V pR = hn::GatherIndex(d, q.mesh1->radius.data(), s);
    const V qR = hn::GatherIndex(d, q.mesh2->radius.data(), t);
    const V qsFromOrigin = hn::GatherIndex(d, q.mesh2->sphereCentreDistance.data(), t);
    const V moved = skin * hn::Max(one, qsFromOrigin * inverseBound2);
    V psFromOrigin2[3];
    for (int k = 0; k < 3; ++k) psFromOrigin2[k] = ps[k] - T[k];
    const V apart = skin * hn::Max(one, hn::Min(qsFromOrigin, hn::Sqrt(dot(psFromOrigin2, psFromOrigin2))) * inverseBound2);
    const V overlap = pR + qR - distance;
    rejected = hn::Or(rejected, hn::Le(overlap + apart + margin, zero));
    gather3(q.mesh1->normal, s, pn);
    gather3(q.mesh2->normal, t, qn0);
    rotate(R, qn0, qn);
    rejected = hn::Or(rejected, hn::Le(dot(pn, sphereOffset) + moved + margin, zero));
    rejected = hn::Or(rejected, hn::Ge(dot(qn, sphereOffset), moved + turn * (distance + moved) + margin));
    // Filter 5, its first test: each projected circumcircle within reach of the contact circle, whose centre c and
    // radius a_max can move with the motion (TrianglePairCandidates.cpp, canTouch), for pairs whose centres stay
    // apart within it (the others go to the reference's test). A pair at distance 0 gives NaN here, which rejects
    // nothing.
    V n[3], c[3];
    for (int k = 0; k < 3; ++k) n[k] = sphereOffset[k] / distance;
    const V x = ((distance - qR) * (distance + qR) + pR * pR) / (two * distance);
    for (int k = 0; k < 3; ++k) c[k] = ps[k] + x * n[k];
    const V tilt = hn::Min(two, two * moved / distance);
    const V aMax = hn::Sqrt(hn::Max(overlap + apart + margin, zero) * pR * qR / (pR + qR));
    const V nearest = distance - apart;
    const V stretch = half + hn::Abs(qR - pR) * (qR + pR) / (two * nearest * nearest);
    const V shift = stretch * apart + hn::Abs(x) * tilt;
    auto outOfReach = [&](const V centre[3], V radius) {
      V fromC[3];
      for (int k = 0; k < 3; ++k) fromC[k] = centre[k] - c[k];
      const V squared = dot(fromC, fromC), along = dot(fromC, n);
      const V reachable = aMax + radius + shift + (hn::Sqrt(squared) + radius) * tilt + skin + margin;
      return hn::Gt(squared - along * along, reachable * reachable);
    };
    rejected = hn::Or(rejected, hn::And(hn::Gt(nearest, margin), hn::Or(outOfReach(pc, pRho), outOfReach(qc, qRho))));
    const auto index = hn::Iota(di, static_cast<int64_t>(i));
    keptCount += hn::CompressStore(index, hn::RebindMask(di, hn::Not(rejected)), di, kept + keptCount);
  }
  for (; i < q.count; ++i) kept[keptCount++] = static_cast<int64_t>(i);  // the tail: to the exact test
  return keptCount;
}

const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

#include <algorithm>

namespace roundedmesh {

HWY_EXPORT(KeptNearPairs);
HWY_EXPORT(TargetName);

// The margin: every quantity the first pass compares is a sum of products of lengths no larger than the bodies'
// bounds, their offset and the triangles' radii, L; each pass rounds it by a few ulps of L (1e-16 L), and the
// margin, 1e-9 L, is ten million times that. Where the reference takes a square root of a difference that may be
// near 0 (a_max), the first pass takes it of the difference plus the margin, so that it is never smaller.
void touchableTrianglePairsBatched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                   const Vector3r& translation, Real skin, Real depth,
                                   const std::vector<TrianglePair>& near, std::vector<TrianglePair>& pairs) {
  pairs.clear();
  thread_local std::vector<int64_t> s, t, kept;
  const size_t count = near.size();
  s.resize(count);
  t.resize(count);
  kept.resize(count);
  for (size_t k = 0; k < count; ++k) {
    s[k] = near[k][0];
    t[k] = near[k][1];
  }
  batched::NearScan scan;
  scan.mesh1 = &mesh1.columns();
  scan.mesh2 = &mesh2.columns();
  const Matrix3r absRotation = rotation.cwiseAbs();
  for (int i = 0; i < 3; ++i) {
    scan.translation[i] = translation[i];
    for (int j = 0; j < 3; ++j) {
      scan.rotation[i][j] = rotation(i, j);
      scan.absRotation[i][j] = absRotation(i, j);
    }
  }
  scan.skin = skin;
  scan.reach = depth + skin;
  scan.bound2 = mesh2.sphereBoundRadius();
  scan.turn = skin / scan.bound2;
  scan.margin = 1e-9 * (mesh1.sphereBoundRadius() + mesh2.sphereBoundRadius() + translation.norm() +
                        mesh1.columns().largestRadius + mesh2.columns().largestRadius + scan.reach);
  scan.s = s.data();
  scan.t = t.data();
  scan.count = count;
  const size_t keptCount = HWY_DYNAMIC_DISPATCH(KeptNearPairs)(scan, kept.data());
  for (size_t k = 0; k < keptCount; ++k) {
    const TrianglePair& st = near[kept[k]];
    if (touchablePair(mesh1, st[0], mesh2, st[1], rotation, absRotation, translation, skin, depth)) pairs.push_back(st);
  }
}

const char* batchedTarget() { return HWY_DYNAMIC_DISPATCH(TargetName)(); }

}  // namespace roundedmesh

#endif  // HWY_ONCE
