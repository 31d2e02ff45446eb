// Compiled once per instruction set by Highway's foreach_target; the code outside HWY_NAMESPACE only once.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "pkg/bound/BatchedCandidates.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep
#include "hwy/highway.h"
#include "pkg/math/Vector3Lanes.hpp"

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
  Real resolution;   // a distance between the spheres' centres shorter than this [m] leaves filter 5 to the
                     // reference (the rounding could decide it)
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

using D = hn::ScalableTag<double>;
using DI = hn::RebindToSigned<D>;
using V = hn::Vec<D>;
using VI = hn::Vec<DI>;
using M = hn::Mask<D>;

// The scan's constants, one per lane.
struct ScanConstants {
  V skin, reach, turn, inverseBound2, margin, resolution;
  V R[3][3], absR[3][3], T[3];
  explicit ScanConstants(const batched::NearScan& q) {
    const D d;
    skin = hn::Set(d, q.skin);
    reach = hn::Set(d, q.reach);
    turn = hn::Set(d, q.turn);
    inverseBound2 = hn::Set(d, 1 / q.bound2);
    margin = hn::Set(d, q.margin);
    resolution = hn::Set(d, q.resolution);
    for (int i = 0; i < 3; ++i) {
      T[i] = hn::Set(d, q.translation[i]);
      for (int j = 0; j < 3; ++j) {
        R[i][j] = hn::Set(d, q.rotation[i][j]);
        absR[i][j] = hn::Set(d, q.absRotation[i][j]);
      }
    }
  }
};

// The outcome of a test `lhs <= rhs` known whatever the rounding: each side may differ from the reference's by up to
// `tolerance`. A lane that is neither (within the tolerance, or NaN) is left to the reference.
struct Verdict {
  M fails, passes;
  void check(V lhs, V rhs, V tolerance) {
    fails = hn::Or(fails, hn::Gt(lhs, rhs + tolerance));
    passes = hn::And(passes, hn::Lt(lhs, rhs - tolerance));
  }
};

// The square of the distance from the origin to a plane triangle (0 inside), and whether it is too thin for its
// inside test to be sure of its sign (distanceFromOrigin in TrianglePairCandidates.cpp, the reference).
V SquaredDistanceFromOrigin(const V x[3], const V y[3], M& thin) {
  const V orientation = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  M outside = hn::FirstN(D(), 0);
  V best = hn::Set(D(), INFINITY), edgesSq = hn::Zero(D());
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const V ex = x[j] - x[i], ey = y[j] - y[i];
    outside = hn::Or(outside, hn::Lt((ey * x[i] - ex * y[i]) * orientation, hn::Zero(D())));
    const V lengthSq = ex * ex + ey * ey;
    edgesSq = edgesSq + lengthSq;
    const V along = hn::Min(hn::Max(hn::Neg(x[i] * ex + y[i] * ey) / lengthSq, hn::Zero(D())), hn::Set(D(), 1.0));
    const V px = x[i] + along * ex, py = y[i] + along * ey;
    best = hn::Min(best, px * px + py * py);
  }
  thin = hn::Or(thin, hn::Le(hn::Abs(orientation), hn::Set(D(), 1e-6) * edgesSq));
  return hn::IfThenElseZero(outside, best);
}

// The largest gap between two plane triangles' extents along their edges' normals (separation in the reference).
V Separation(const V ax[3], const V ay[3], const V bx[3], const V by[3]) {
  V gap = hn::Zero(D());
  for (const auto& [x, y] : {std::pair<const V*, const V*>(ax, ay), std::pair<const V*, const V*>(bx, by)})
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const V ex = x[j] - x[i], ey = y[j] - y[i];
      const V length = hn::Sqrt(ex * ex + ey * ey);
      const V nx = hn::Neg(ey) / length, ny = ex / length;
      V minA = ax[0] * nx + ay[0] * ny, maxA = minA, minB = bx[0] * nx + by[0] * ny, maxB = minB;
      for (int k = 1; k < 3; ++k) {
        const V a = ax[k] * nx + ay[k] * ny, b = bx[k] * nx + by[k] * ny;
        minA = hn::Min(minA, a);
        maxA = hn::Max(maxA, a);
        minB = hn::Min(minB, b);
        maxB = hn::Max(maxB, b);
      }
      gap = hn::Max(gap, hn::Max(minB - maxA, minA - maxB));
    }
  return gap;
}

// Which filters a pass applies: 2-4 (a near search's, canTouch without `full`: the trees' search has applied 1); the
// cheap first pass of a scan, 1-4 and filter 5's first test, the projected circumcircles, for the tests' failures
// only; or all of 1-5 and both sides of every test.
enum class Filters { TwoToFour, FirstPass, Whole };

// Filters 1-5 of touchablePair (TrianglePairCandidates.cpp, canTouch) for the pairs (s, t), in the reference's
// formulas, as many as kFilters says (filters 2-4: passesFilters2to4's).
template <Filters kFilters>
HWY_INLINE Verdict TestPairs(const batched::NearScan& q, const ScanConstants& k, VI s, VI t) {
  constexpr bool kWhole = kFilters == Filters::Whole;
  const D d;
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), half = hn::Set(d, 0.5);
  const V margin = k.margin;
  Verdict filters1to4{hn::FirstN(d, 0), hn::FirstN(d, hn::Lanes(d))};
  if constexpr (kFilters != Filters::TwoToFour) {
    // Filter 1: triangle t's cap box moved into body 1's frame, grown by the reach, against s's.
    V min2[3], max2[3], min1[3], max1[3], centre2[3], size2[3], centre[3], extent[3];
    Gather3(D(), q.mesh2->boxMin, t, min2);
    Gather3(D(), q.mesh2->boxMax, t, max2);
    Gather3(D(), q.mesh1->boxMin, s, min1);
    Gather3(D(), q.mesh1->boxMax, s, max1);
    for (int i = 0; i < 3; ++i) {
      centre2[i] = half * (min2[i] + max2[i]);
      size2[i] = half * (max2[i] - min2[i]);
    }
    Rotate3(k.R, centre2, centre);
    Rotate3(k.absR, size2, extent);
    for (int i = 0; i < 3; ++i) {
      centre[i] = centre[i] + k.T[i];
      extent[i] = extent[i] + k.reach;
      filters1to4.check(min1[i], centre[i] + extent[i], margin);
      filters1to4.check(centre[i] - extent[i], max1[i], margin);
    }
  }
  // Filter 2: the circumscribed balls.
  V pc[3], qc0[3], qc[3], offset[3];
  Gather3(D(), q.mesh1->circumcentre, s, pc);
  Gather3(D(), q.mesh2->circumcentre, t, qc0);
  Rotate3(k.R, qc0, qc);
  for (int i = 0; i < 3; ++i) {
    qc[i] = qc[i] + k.T[i];
    offset[i] = qc[i] - pc[i];
  }
  const V pRho = hn::GatherIndex(d, q.mesh1->circumradius.data(), s);
  const V qRho = hn::GatherIndex(d, q.mesh2->circumradius.data(), t);
  const V balls = pRho + qRho + k.reach;
  filters1to4.fails = hn::Or(filters1to4.fails, hn::Gt(Dot3(offset, offset), (balls + margin) * (balls + margin)));
  filters1to4.passes = hn::And(filters1to4.passes, hn::Lt(Dot3(offset, offset), (balls - margin) * (balls - margin)));
  // Filters 3 and 4: the encompassing spheres' overlap and facing, within the motion.
  V ps[3], qs0[3], sphereOffset[3], pn[3], qn0[3], qn[3], psFromOrigin2[3];
  Gather3(D(), q.mesh1->sphereCentre, s, ps);
  Gather3(D(), q.mesh2->sphereCentre, t, qs0);
  Rotate3(k.R, qs0, sphereOffset);
  for (int i = 0; i < 3; ++i) {
    sphereOffset[i] = sphereOffset[i] + k.T[i] - ps[i];
    psFromOrigin2[i] = ps[i] - k.T[i];
  }
  const V distance = hn::Sqrt(Dot3(sphereOffset, sphereOffset));
  const V pR = hn::GatherIndex(d, q.mesh1->radius.data(), s);
  const V qR = hn::GatherIndex(d, q.mesh2->radius.data(), t);
  const V qsFromOrigin = hn::GatherIndex(d, q.mesh2->sphereCentreDistance.data(), t);
  const V moved = k.skin * hn::Max(one, qsFromOrigin * k.inverseBound2);
  const V apart = k.skin * hn::Max(one, hn::Min(qsFromOrigin, hn::Sqrt(Dot3(psFromOrigin2, psFromOrigin2))) * k.inverseBound2);
  const V overlap = pR + qR - distance;
  filters1to4.check(zero, overlap + apart, margin);
  Gather3(D(), q.mesh1->normal, s, pn);
  Gather3(D(), q.mesh2->normal, t, qn0);
  Rotate3(k.R, qn0, qn);
  filters1to4.check(zero, Dot3(pn, sphereOffset) + moved, margin);
  filters1to4.check(Dot3(qn, sphereOffset), moved + k.turn * (distance + moved), margin);
  if constexpr (kFilters == Filters::TwoToFour) return filters1to4;
  // Filter 5 (the contact circle, whose centre c and radius a_max can move with the motion) holds for pairs whose
  // centres stay apart within it; it is decided here only where they stay clearly apart (resolution): the circle's
  // slack grows without bound as they meet.
  V n[3], c[3];
  for (int i = 0; i < 3; ++i) n[i] = sphereOffset[i] / distance;
  const V x = ((distance - qR) * (distance + qR) + pR * pR) / (two * distance);
  for (int i = 0; i < 3; ++i) c[i] = ps[i] + x * n[i];
  const V tilt = hn::Min(two, two * moved / distance);
  const V reduced = pR * qR / (pR + qR);
  const V aMaxAbove = hn::Sqrt(hn::Max(overlap + apart + margin, zero) * reduced);
  const V nearest = distance - apart;
  const V stretch = half + hn::Abs(qR - pR) * (qR + pR) / (two * nearest * nearest);
  const V shift = stretch * apart + hn::Abs(x) * tilt;
  const M fifthApplies = hn::Gt(nearest, k.resolution);
  auto tolerance = [&](V scale) { return margin + hn::Set(d, 1e-9) * hn::Abs(scale); };
  // Its first test: each projected circumcircle within reach of the contact circle.
  Verdict fifth{hn::FirstN(d, 0), hn::FirstN(d, hn::Lanes(d))};
  V aMaxBelow = aMaxAbove;
  if constexpr (kWhole) aMaxBelow = hn::Sqrt(hn::Max(overlap + apart - margin, zero) * reduced);
  for (const auto& [circleCentre, radius] : {std::pair<const V*, V>(pc, pRho), std::pair<const V*, V>(qc, qRho)}) {
    V fromC[3];
    for (int i = 0; i < 3; ++i) fromC[i] = circleCentre[i] - c[i];
    const V squared = Dot3(fromC, fromC), along = Dot3(fromC, n);
    const V lateralSq = squared - along * along;
    const V rest = radius + shift + (hn::Sqrt(squared) + radius) * tilt + k.skin;
    const V above = aMaxAbove + rest + tolerance(rest);
    fifth.fails = hn::Or(fifth.fails, hn::Gt(lateralSq, above * above));
    if constexpr (kWhole) {
      const V below = aMaxBelow + rest - tolerance(rest);
      fifth.passes = hn::And(fifth.passes, hn::And(hn::Gt(below, zero), hn::Lt(lateralSq, below * below)));
    }
  }
  if constexpr (!kWhole) return Verdict{hn::Or(filters1to4.fails, hn::And(fifthApplies, fifth.fails)), filters1to4.passes};
  // Its second test: the triangles projected on the contact plane now, each within a_max of c and overlapping, by
  // the slack the motion allows. Any axes of the plane will do: the tests measure distances in it.
  const M zLargest = hn::Gt(n[2] * n[2], n[0] * n[0] + n[1] * n[1]);
  V u[3];
  u[0] = hn::IfThenZeroElse(zLargest, hn::Neg(n[1]));
  u[1] = hn::IfThenElse(zLargest, hn::Neg(n[2]), n[0]);
  u[2] = hn::IfThenElseZero(zLargest, n[1]);
  const V uLength = hn::Sqrt(Dot3(u, u));
  for (V& ui : u) ui = ui / uLength;
  V v[3];
  Cross3(n, u, v);
  V px[3], py[3], qx[3], qy[3], farSq = zero;
  for (int corner = 0; corner < 3; ++corner) {
    V xp[3], xq0[3], xq[3];
    Gather3(D(), q.mesh1->corner[corner], s, xp);
    Gather3(D(), q.mesh2->corner[corner], t, xq0);
    Rotate3(k.R, xq0, xq);
    for (int i = 0; i < 3; ++i) {
      xp[i] = xp[i] - c[i];
      xq[i] = xq[i] + k.T[i] - c[i];
    }
    farSq = hn::Max(farSq, hn::Max(Dot3(xp, xp), Dot3(xq, xq)));
    px[corner] = Dot3(xp, u);
    py[corner] = Dot3(xp, v);
    qx[corner] = Dot3(xq, u);
    qy[corner] = Dot3(xq, v);
  }
  const V far = hn::Sqrt(farSq);
  const V slack = shift + far * tilt + k.skin;
  M thin = hn::FirstN(d, 0);
  const V farther = hn::Sqrt(hn::Max(SquaredDistanceFromOrigin(px, py, thin), SquaredDistanceFromOrigin(qx, qy, thin)));
  // A projected edge shorter than 1e-6 of the corners' distance from c gives an axis whose direction the rounding
  // could decide.
  const V shortest = hn::Set(d, 1e-6) * far;
  for (const auto& [x, y] : {std::pair<const V*, const V*>(px, py), std::pair<const V*, const V*>(qx, qy)})
    for (int i = 0; i < 3; ++i) {
      const V ex = x[(i + 1) % 3] - x[i], ey = y[(i + 1) % 3] - y[i];
      thin = hn::Or(thin, hn::Lt(ex * ex + ey * ey, shortest * shortest));
    }
  Verdict projected{hn::FirstN(d, 0), hn::FirstN(d, hn::Lanes(d))};
  projected.fails = hn::Gt(farther, aMaxAbove + slack + tolerance(slack));
  projected.passes = hn::Lt(farther, aMaxBelow + slack - tolerance(slack));
  projected.check(Separation(px, py, qx, qy), two * slack, tolerance(slack));
  projected.fails = hn::AndNot(thin, projected.fails);
  projected.passes = hn::AndNot(thin, projected.passes);
  const M fifthSkipped = hn::Lt(nearest, hn::Neg(margin));
  const M fifthFails = hn::And(fifthApplies, hn::Or(fifth.fails, projected.fails));
  const M fifthPasses = hn::Or(fifthSkipped, hn::And(fifthApplies, hn::And(fifth.passes, projected.passes)));
  return Verdict{hn::Or(filters1to4.fails, fifthFails), hn::And(filters1to4.passes, fifthPasses)};
}

// The first pass: writes the indices (into the scan's pairs) of those not rejected to `kept` (room for all); returns
// how many. A compressed store may write a whole vector, lanes [keptCount, keptCount + lanes), which stays within the
// first i + lanes <= count entries since keptCount <= i.
size_t KeptNearPairs(const batched::NearScan& q, int64_t* kept) {
  const D d;
  const DI di;
  const size_t lanes = hn::Lanes(d);
  const ScanConstants k(q);
  size_t keptCount = 0;
  size_t i = 0;
  for (; i + lanes <= q.count; i += lanes) {
    const Verdict verdict = TestPairs<Filters::FirstPass>(q, k, hn::LoadU(di, q.s + i), hn::LoadU(di, q.t + i));
    const auto index = hn::Iota(di, static_cast<int64_t>(i));
    keptCount += hn::CompressStore(index, hn::RebindMask(di, hn::Not(verdict.fails)), di, kept + keptCount);
  }
  for (; i < q.count; ++i) kept[keptCount++] = static_cast<int64_t>(i);  // the tail: to the second pass
  return keptCount;
}

// Over the scan's pairs at positions `kept`: `decision` per pair, 1 if it passes kFilters, 0 if it fails one, -1 if the
// rounding could tell either way (for the reference's own test: touchablePair, or passesFilters2to4 for filters 2-4).
template <Filters kFilters>
void Decided(const batched::NearScan& q, const int64_t* kept, size_t count, int64_t* decision) {
  const D d;
  const DI di;
  const size_t lanes = hn::Lanes(d);
  const ScanConstants k(q);
  HWY_ALIGN int64_t tail[HWY_MAX_BYTES / sizeof(int64_t)], tailDecision[HWY_MAX_BYTES / sizeof(int64_t)];
  for (size_t i = 0; i < count; i += lanes) {
    const size_t n = std::min(lanes, count - i);
    const int64_t* index = kept + i;
    if (n < lanes) {  // the tail, padded with its last pair
      for (size_t j = 0; j < lanes; ++j) tail[j] = kept[i + std::min(j, n - 1)];
      index = tail;
    }
    const VI which = hn::LoadU(di, index);
    const Verdict verdict = TestPairs<kFilters>(q, k, hn::GatherIndex(di, q.s, which), hn::GatherIndex(di, q.t, which));
    const VI outcome = hn::IfThenElse(hn::RebindMask(di, verdict.passes), hn::Set(di, 1),
                                      hn::IfThenElse(hn::RebindMask(di, verdict.fails), hn::Zero(di), hn::Set(di, -1)));
    if (n == lanes) {
      hn::StoreU(outcome, di, decision + i);
    } else {
      hn::StoreU(outcome, di, tailDecision);
      std::copy(tailDecision, tailDecision + n, decision + i);
    }
  }
}

// The second pass of a scan, over the first's `kept` pairs: every filter.
void DecidedNearPairs(const batched::NearScan& q, const int64_t* kept, size_t count, int64_t* decision) {
  Decided<Filters::Whole>(q, kept, count, decision);
}

// A near search's filters 2-4, over the pairs at positions `kept`.
void DecidedFilters2to4(const batched::NearScan& q, const int64_t* kept, size_t count, int64_t* decision) {
  Decided<Filters::TwoToFour>(q, kept, count, decision);
}

const char* TargetName() { return hwy::TargetName(HWY_TARGET); }

}  // namespace HWY_NAMESPACE
}  // namespace roundedmesh
HWY_AFTER_NAMESPACE();

#if HWY_ONCE

#include <algorithm>

namespace roundedmesh {

HWY_EXPORT(KeptNearPairs);
HWY_EXPORT(DecidedNearPairs);
HWY_EXPORT(DecidedFilters2to4);
HWY_EXPORT(TargetName);

// The margin: every quantity the passes compare is a sum of products of lengths no larger than the bodies' bounds,
// their offset and the triangles' radii, L, or such a length times a factor they share with the reference; each
// rounds it by a few ulps of L (1e-16 L), and the margin, 1e-9 L (plus 1e-9 of the factor's term in filter 5), is ten
// million times that. Where the reference takes a square root of a difference that may be near 0 (a_max), the
// passes take it of the difference plus or minus the margin, so that it bounds the reference's from above or below.
// Two things the rounding could decide are left to the reference: filter 5 where the spheres' centres come within
// 1e-6 L of each other (its slack grows as 1 / distance^2 there) and a projected triangle with an edge shorter than
// 1e-6 of the corners' distance from c, or whose doubled area is below 1e-6 of its edges squared (the direction of
// that edge, or the side of the origin, could be the rounding's).
namespace {

// A scan of the pairs (s[k], t[k]) for this pose, skin and reach (depth + skin).
batched::NearScan scanOf(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                         const Vector3r& translation, Real skin, Real reach, const std::vector<int64_t>& s,
                         const std::vector<int64_t>& t) {
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
  scan.reach = reach;
  scan.bound2 = mesh2.sphereBoundRadius();
  scan.turn = skin / scan.bound2;
  const Real scale = mesh1.sphereBoundRadius() + mesh2.sphereBoundRadius() + translation.norm() +
                     mesh1.columns().largestRadius + mesh2.columns().largestRadius + scan.reach;
  scan.margin = 1e-9 * scale;
  scan.resolution = 1e-6 * scale;
  scan.s = s.data();
  scan.t = t.data();
  scan.count = s.size();
  return scan;
}

// The pairs' two index columns.
void splitPairs(const std::vector<TrianglePair>& pairs, std::vector<int64_t>& s, std::vector<int64_t>& t) {
  s.resize(pairs.size());
  t.resize(pairs.size());
  for (size_t k = 0; k < pairs.size(); ++k) {
    s[k] = pairs[k][0];
    t[k] = pairs[k][1];
  }
}

}  // namespace

size_t touchableTrianglePairsBatched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                   const Vector3r& translation, Real skin, Real depth,
                                   const std::vector<TrianglePair>& near, std::vector<TrianglePair>& pairs) {
  pairs.clear();
  thread_local std::vector<int64_t> s, t, kept, decision;
  splitPairs(near, s, t);
  kept.resize(near.size());
  decision.resize(near.size());
  const batched::NearScan scan = scanOf(mesh1, mesh2, rotation, translation, skin, depth + skin, s, t);
  const size_t keptCount = HWY_DYNAMIC_DISPATCH(KeptNearPairs)(scan, kept.data());
  HWY_DYNAMIC_DISPATCH(DecidedNearPairs)(scan, kept.data(), keptCount, decision.data());
  const Matrix3r absRotation = rotation.cwiseAbs();
  size_t undecided = 0;
  for (size_t k = 0; k < keptCount; ++k) {
    const TrianglePair& st = near[kept[k]];
    if (decision[k] == -1) ++undecided;
    if (decision[k] == 1 ||
        (decision[k] == -1 && touchablePair(mesh1, st[0], mesh2, st[1], rotation, absRotation, translation, skin, depth)))
      pairs.push_back(st);
  }
  return undecided;
}

size_t keepPassingFilters2to4Batched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                     const Vector3r& translation, Real skin, Real reach,
                                     std::vector<TrianglePair>& pairs) {
  thread_local std::vector<int64_t> s, t, every, decision;
  splitPairs(pairs, s, t);
  every.resize(pairs.size());
  for (size_t k = 0; k < pairs.size(); ++k) every[k] = static_cast<int64_t>(k);
  decision.resize(pairs.size());
  const batched::NearScan scan = scanOf(mesh1, mesh2, rotation, translation, skin, reach, s, t);
  HWY_DYNAMIC_DISPATCH(DecidedFilters2to4)(scan, every.data(), pairs.size(), decision.data());
  size_t undecided = 0, kept = 0;
  for (size_t k = 0; k < pairs.size(); ++k) {
    const TrianglePair st = pairs[k];
    if (decision[k] == -1) ++undecided;
    if (decision[k] == 1 ||
        (decision[k] == -1 && passesFilters2to4(mesh1, st[0], mesh2, st[1], rotation, translation, skin, reach)))
      pairs[kept++] = st;
  }
  pairs.resize(kept);
  return undecided;
}

const char* batchedTarget() { return HWY_DYNAMIC_DISPATCH(TargetName)(); }

}  // namespace roundedmesh

#endif  // HWY_ONCE
