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

// A deep list's shell about one triangle of body 2: its cap box moved into body 1's frame and grown by the list's
// reach (outer) and by the Hertz range's (inner).
struct Shell {
  Real outerMin[3], outerMax[3], innerMin[3], innerMax[3];
};

// Body 1's columns are padded to a multiple of this: whole vectors of doubles on every x86 target (at most 8 lanes);
// ShellFirstPass refuses a target whose lanes do not divide it.
constexpr size_t kPadding = 16;

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

// How a pass reads one body's triangle columns into its lanes: the triangles at `index` (any pairs), consecutive
// triangles from `first`, or one triangle in every lane. Each reads the same numbers, so the tests decide alike.
struct ByIndex {
  VI index;
  HWY_INLINE V operator()(const std::vector<Real>& column) const { return hn::GatherIndex(D(), column.data(), index); }
};
struct Consecutive {
  size_t first;
  HWY_INLINE V operator()(const std::vector<Real>& column) const { return hn::LoadU(D(), column.data() + first); }
};
struct Broadcast {
  int64_t triangle;
  HWY_INLINE V operator()(const std::vector<Real>& column) const { return hn::Set(D(), column[triangle]); }
};

template <class Read>
HWY_INLINE void Read3(const Read& read, const std::vector<Real> (&column)[3], V out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = read(column[k]);
}

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

// Filters 1-5 of touchablePair (TrianglePairCandidates.cpp, canTouch) for the pairs (s, t), s read by `s` from mesh 1's
// columns and t by `t` from mesh 2's, in the reference's formulas, as many as kFilters says (filters 2-4:
// passesFilters2to4's).
template <Filters kFilters, class Read1, class Read2>
HWY_INLINE Verdict TestPairs(const batched::NearScan& q, const ScanConstants& k, const Read1& s, const Read2& t) {
  constexpr bool kWhole = kFilters == Filters::Whole;
  const D d;
  const V zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0), half = hn::Set(d, 0.5);
  const V margin = k.margin;
  Verdict filters1to4{hn::FirstN(d, 0), hn::FirstN(d, hn::Lanes(d))};
  if constexpr (kFilters != Filters::TwoToFour) {
    // Filter 1: triangle t's cap box moved into body 1's frame, grown by the reach, against s's.
    V min2[3], max2[3], min1[3], max1[3], centre2[3], size2[3], centre[3], extent[3];
    Read3(t, q.mesh2->boxMin, min2);
    Read3(t, q.mesh2->boxMax, max2);
    Read3(s, q.mesh1->boxMin, min1);
    Read3(s, q.mesh1->boxMax, max1);
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
  Read3(s, q.mesh1->circumcentre, pc);
  Read3(t, q.mesh2->circumcentre, qc0);
  Rotate3(k.R, qc0, qc);
  for (int i = 0; i < 3; ++i) {
    qc[i] = qc[i] + k.T[i];
    offset[i] = qc[i] - pc[i];
  }
  const V pRho = s(q.mesh1->circumradius);
  const V qRho = t(q.mesh2->circumradius);
  const V balls = pRho + qRho + k.reach;
  filters1to4.fails = hn::Or(filters1to4.fails, hn::Gt(Dot3(offset, offset), (balls + margin) * (balls + margin)));
  filters1to4.passes = hn::And(filters1to4.passes, hn::Lt(Dot3(offset, offset), (balls - margin) * (balls - margin)));
  // Filters 3 and 4: the encompassing spheres' overlap and facing, within the motion.
  V ps[3], qs0[3], sphereOffset[3], pn[3], qn0[3], qn[3], psFromOrigin2[3];
  Read3(s, q.mesh1->sphereCentre, ps);
  Read3(t, q.mesh2->sphereCentre, qs0);
  Rotate3(k.R, qs0, sphereOffset);
  for (int i = 0; i < 3; ++i) {
    sphereOffset[i] = sphereOffset[i] + k.T[i] - ps[i];
    psFromOrigin2[i] = ps[i] - k.T[i];
  }
  const V distance = hn::Sqrt(Dot3(sphereOffset, sphereOffset));
  const V pR = s(q.mesh1->radius);
  const V qR = t(q.mesh2->radius);
  const V qsFromOrigin = t(q.mesh2->sphereCentreDistance);
  const V moved = k.skin * hn::Max(one, qsFromOrigin * k.inverseBound2);
  const V apart = k.skin * hn::Max(one, hn::Min(qsFromOrigin, hn::Sqrt(Dot3(psFromOrigin2, psFromOrigin2))) * k.inverseBound2);
  const V overlap = pR + qR - distance;
  filters1to4.check(zero, overlap + apart, margin);
  Read3(s, q.mesh1->normal, pn);
  Read3(t, q.mesh2->normal, qn0);
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
    Read3(s, q.mesh1->corner[corner], xp);
    Read3(t, q.mesh2->corner[corner], xq0);
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
    const Verdict verdict =
        TestPairs<Filters::FirstPass>(q, k, ByIndex{hn::LoadU(di, q.s + i)}, ByIndex{hn::LoadU(di, q.t + i)});
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
    const Verdict verdict =
        TestPairs<kFilters>(q, k, ByIndex{hn::GatherIndex(di, q.s, which)}, ByIndex{hn::GatherIndex(di, q.t, which)});
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

// A deep list's shell (appendTouchableShellPairsBatched), the scan's mesh 1 being the columns of body 1's triangles in it, in
// order and padded with NaN: the positions of those whose cap boxes meet the shell's outer box and not its inner one,
// as AlignedBox3r::intersects decides (comparisons only, a NaN meeting nothing), and that the first pass does not reject
// against body 2's triangle `two`, written to `kept` (room for the padded columns). Returns how many.
size_t ShellFirstPass(const batched::NearScan& q, size_t padded, int64_t two, const batched::Shell& shell,
                      int64_t* kept) {
  const D d;
  const DI di;
  const size_t lanes = hn::Lanes(d);
  HWY_ASSERT(batched::kPadding % lanes == 0);  // whole vectors within the padded columns
  const ScanConstants k(q);
  size_t count = 0;
  for (size_t i = 0; i < padded; i += lanes) {
    M outer = hn::FirstN(d, lanes), inner = hn::FirstN(d, lanes);
    for (int axis = 0; axis < 3; ++axis) {
      const V min = hn::LoadU(d, q.mesh1->boxMin[axis].data() + i), max = hn::LoadU(d, q.mesh1->boxMax[axis].data() + i);
      outer = hn::And(outer, hn::And(hn::Le(min, hn::Set(d, shell.outerMax[axis])),
                                     hn::Le(hn::Set(d, shell.outerMin[axis]), max)));
      inner = hn::And(inner, hn::And(hn::Le(min, hn::Set(d, shell.innerMax[axis])),
                                     hn::Le(hn::Set(d, shell.innerMin[axis]), max)));
    }
    const M inShell = hn::AndNot(inner, outer);
    if (hn::AllFalse(d, inShell)) continue;
    const Verdict verdict = TestPairs<Filters::FirstPass>(q, k, Consecutive{i}, Broadcast{two});
    const M keep = hn::AndNot(verdict.fails, inShell);
    count += hn::CompressStore(hn::Iota(di, static_cast<int64_t>(i)), hn::RebindMask(di, keep), di, kept + count);
  }
  return count;
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
#include <limits>

namespace roundedmesh {

HWY_EXPORT(KeptNearPairs);
HWY_EXPORT(ShellFirstPass);
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

// The second pass over the scan's pairs at positions `kept` (those the first left), and the reference's own test for
// the pairs it cannot decide: appends the pairs that pass to `pairs`, in order. Returns how many the reference decided.
size_t appendTouchable(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                       const Vector3r& translation, Real skin, Real depth, const batched::NearScan& scan,
                       const int64_t* kept, size_t count, std::vector<TrianglePair>& pairs) {
  thread_local std::vector<int64_t> decision;
  decision.resize(count);
  HWY_DYNAMIC_DISPATCH(DecidedNearPairs)(scan, kept, count, decision.data());
  const Matrix3r absRotation = rotation.cwiseAbs();
  size_t undecided = 0;
  for (size_t k = 0; k < count; ++k) {
    const TrianglePair st{static_cast<int>(scan.s[kept[k]]), static_cast<int>(scan.t[kept[k]])};
    if (decision[k] == -1) ++undecided;
    if (decision[k] == 1 ||
        (decision[k] == -1 && touchablePair(mesh1, st[0], mesh2, st[1], rotation, absRotation, translation, skin, depth)))
      pairs.push_back(st);
  }
  return undecided;
}

// The columns of the triangles `which` of `all`, in that order, padded with NaN to a multiple of kPadding.
void selectColumns(const TriangleColumns& all, const std::vector<int>& which, TriangleColumns& selected) {
  const size_t padded = (which.size() + batched::kPadding - 1) / batched::kPadding * batched::kPadding;
  auto select = [&](const std::vector<Real>& from, std::vector<Real>& to) {
    to.assign(padded, std::numeric_limits<Real>::quiet_NaN());
    for (size_t i = 0; i < which.size(); ++i) to[i] = from[which[i]];
  };
  for (int k = 0; k < 3; ++k) {
    select(all.boxMin[k], selected.boxMin[k]);
    select(all.boxMax[k], selected.boxMax[k]);
    select(all.circumcentre[k], selected.circumcentre[k]);
    select(all.sphereCentre[k], selected.sphereCentre[k]);
    select(all.normal[k], selected.normal[k]);
    for (int corner = 0; corner < 3; ++corner) select(all.corner[corner][k], selected.corner[corner][k]);
  }
  select(all.circumradius, selected.circumradius);
  select(all.radius, selected.radius);
  select(all.sphereCentreDistance, selected.sphereCentreDistance);
  selected.largestRadius = all.largestRadius;
}

}  // namespace

size_t touchableTrianglePairsBatched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                   const Vector3r& translation, Real skin, Real depth,
                                   const std::vector<TrianglePair>& near, std::vector<TrianglePair>& pairs) {
  pairs.clear();
  thread_local std::vector<int64_t> s, t, kept;
  splitPairs(near, s, t);
  kept.resize(near.size());
  const batched::NearScan scan = scanOf(mesh1, mesh2, rotation, translation, skin, depth + skin, s, t);
  const size_t keptCount = HWY_DYNAMIC_DISPATCH(KeptNearPairs)(scan, kept.data());
  return appendTouchable(mesh1, mesh2, rotation, translation, skin, depth, scan, kept.data(), keptCount, pairs);
}

size_t appendTouchableShellPairsBatched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                        const Vector3r& translation, Real skin, Real depth, Real inner,
                                        const std::vector<int>& reaching1, const std::vector<int>& reaching2,
                                        std::vector<TrianglePair>& pairs) {
  // The pairs the first pass leaves, a chunk at a time through the second, so that the scratch each thread keeps stays
  // small (two of YADE's GTS horses of 9,514 triangles have tens of millions of pairs in their shells).
  constexpr size_t kChunk = size_t(1) << 16;
  thread_local TriangleColumns selected;
  thread_local std::vector<int64_t> s, t, positions, every;
  selectColumns(mesh1.columns(), reaching1, selected);
  const size_t padded = selected.radius.size();
  s.clear();
  t.clear();
  size_t undecided = 0;
  auto secondPass = [&]() {
    every.resize(s.size());
    for (size_t k = 0; k < s.size(); ++k) every[k] = static_cast<int64_t>(k);
    const batched::NearScan scan = scanOf(mesh1, mesh2, rotation, translation, skin, depth + skin, s, t);
    undecided += appendTouchable(mesh1, mesh2, rotation, translation, skin, depth, scan, every.data(), s.size(), pairs);
    s.clear();
    t.clear();
  };
  batched::NearScan firstPass = scanOf(mesh1, mesh2, rotation, translation, skin, depth + skin, s, t);
  firstPass.mesh1 = &selected;  // the margin stays the whole mesh's
  firstPass.s = firstPass.t = nullptr;  // its pairs are the shell's, not listed
  firstPass.count = 0;
  positions.resize(padded);
  for (const int two : reaching2) {
    const AlignedBox3r& box2 = mesh2.tree().triangleBox(two);
    const AlignedBox3r outer = transformedBox(box2, rotation, translation, depth + skin);
    const AlignedBox3r within = transformedBox(box2, rotation, translation, inner);
    batched::Shell shell;
    for (int axis = 0; axis < 3; ++axis) {
      shell.outerMin[axis] = outer.min()[axis];
      shell.outerMax[axis] = outer.max()[axis];
      shell.innerMin[axis] = within.min()[axis];
      shell.innerMax[axis] = within.max()[axis];
    }
    const size_t count = HWY_DYNAMIC_DISPATCH(ShellFirstPass)(firstPass, padded, two, shell, positions.data());
    for (size_t k = 0; k < count; ++k) {
      s.push_back(reaching1[positions[k]]);
      t.push_back(two);
    }
    if (s.size() >= kChunk) secondPass();
  }
  secondPass();
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
