// Bound: the candidate triangle pairs of two rounded bodies, Verlet lists kept between steps. A list holds
// every triangle pair (s of mesh 1, t of mesh 2) that can be in contact, with an effective overlap of at most
// `depth`, while every point of mesh 2 moves by at most `skin` from the pose it was built at
// (x1 = rotation * x2 + translation). Why each filter is safe:
//   A contact has its surface points q1 on cap s and q2 on cap t (Appendix B: the line along n12 through
//   c_eff crosses both triangles, and leaves each sphere through its cap) with |q1 - q2| = delta_eff.
//   Caps lie in their cap boxes (TriangleTree) and in the balls of radius rho about the circumcentres, so:
//   (1) boxes:   the cap boxes come within depth + skin of each other (TriangleTree::queryPairs);
//   (2) balls:   |cc_s - cc_t| <= rho_s + rho_t + depth + skin;
//   (3) overlap: R_s + R_t - |s_s - s_t| > -m, where m bounds how far the centres' distance can change: a motion
//                that moves mesh 2's bound (radius r2 about its origin) by at most skin turns it by at most
//                skin / r2, which moves sphere centre t, at distance |s_t| from that origin, by at most
//                m_t = skin * max(1, |s_t| / r2) in body 1's frame, and centre s by at most skin * max(1, l_s / r2)
//                in body 2's (l_s its distance from body 2's origin); the distance changes by neither more, so m is
//                the smaller (a flat or concave triangle's centre, 100 r_eq behind it by default, moves far on the
//                slightest turn);
//   (4) facing (Eq. B.5) within the same motions: n_s . d > -m_t and n_t . d < m_t + (skin / r2)(|d| + m_t),
//                d = s_t - s_s;
//   (5) circle:  S = P' n Q' meets the contact circle, so both projected triangles come within a of c and
//                overlap; tested on the plane of now, with a grown to its largest within the motion and every
//                distance given the slack by which the motion can move c, tilt n and move the corners.
// Two levels, as a Verlet list with an outer shell: nearTrianglePairs searches the triangle trees with
// filters 1-4 (the trees filter 1, filters 2-4 follow in lanes; all five for a deep pair's pairs past the Hertz range)
// for a large skin, rarely;
// touchableTrianglePairs takes from such a list, with no search, the pairs that pass all five filters for a small
// skin. A pose within the small skin of the inner list's, whose pose is within (large - small) of the outer list's,
// is within the large skin of the outer list's.
#pragma once

#include <array>
#include <vector>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

using TrianglePair = std::array<int, 2>;

// Pairs whose cap boxes are more than `shallow` + skin apart can only be contacts deeper than `shallow`: they
// are kept only if both caps reach the other body within the motion (capReaches of DeepContactCriterion.hpp,
// slack 2 skin: the interpolated distance changes by at most sqrt(3) times the motion), and they are found among
// the triangles whose caps reach, not by searching the trees. In a list deeper than twice `shallow` (a pair past
// the Hertz range) these pairs must also pass filter 5 for this skin, which the other pairs of a near list are spared:
// they are most of such a list, and few of them can touch.
void nearTrianglePairs(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                       const Vector3r& translation, Real skin, Real depth, Real shallow,
                       std::vector<TrianglePair>& pairs);

// From `near` (a list for a larger skin and depth, built at a pose within (its skin - skin) of this one), one pair at
// a time: the reference of touchableTrianglePairsBatched (BatchedCandidates.hpp), which the engine uses.
void touchableTrianglePairs(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                            const Vector3r& translation, Real skin, Real depth, const std::vector<TrianglePair>& near,
                            std::vector<TrianglePair>& pairs);

// Whether triangle s of mesh 1 and t of mesh 2 pass filters 2-4 for this skin and `reach` (depth + skin): the test
// of one pair of nearTrianglePairs after the trees' search (filter 1), the reference of
// keepPassingFilters2to4Batched (BatchedCandidates.hpp), which the search uses.
bool passesFilters2to4(const RoundedMesh& mesh1, int s, const RoundedMesh& mesh2, int t, const Matrix3r& rotation,
                       const Vector3r& translation, Real skin, Real reach);

// Whether triangle s of mesh 1 and t of mesh 2 pass filters 1-5 for this skin and depth: the test of one pair of
// touchableTrianglePairs (`absRotation`: |rotation|, formed once per list).
bool touchablePair(const RoundedMesh& mesh1, int s, const RoundedMesh& mesh2, int t, const Matrix3r& rotation,
                   const Matrix3r& absRotation, const Vector3r& translation, Real skin, Real depth);

}  // namespace roundedmesh
