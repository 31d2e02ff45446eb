// Bound: the candidate triangle pairs taken from a near list (TrianglePairCandidates.hpp) several pairs per
// instruction, in batches as wide as the processor's vector unit (Google Highway, the widest of SSE2 ... AVX-512 the
// processor has, chosen at run time), reading both meshes' columns (TriangleColumns.hpp). A first pass rejects, with
// no branch per pair, those that fail filter 1 (boxes), 2 (balls), 3 (sphere overlap), 4 (facing) or the first test
// of 5 (the projected circumcircles against the contact circle); a second takes the pairs left through all five
// filters, the projected triangles of 5 too. Each decides a pair only where its margin, far above the rounding of
// either computation (see the .cpp), shows the reference's outcome; the few pairs within it go through the
// reference's own test (touchablePair). So the list is the reference's, pair for pair and in the same order,
// whatever the vector unit. The near search's filters 2-4 of the pairs the trees give run the same way, their reference
// passesFilters2to4.
#pragma once

#include <cstddef>
#include <vector>

#include "pkg/bound/TrianglePairCandidates.hpp"

namespace roundedmesh {

// touchableTrianglePairs, batched: the same arguments, the same `pairs`. Returns how many pairs the reference's own
// test decided.
size_t touchableTrianglePairsBatched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                   const Vector3r& translation, Real skin, Real depth,
                                   const std::vector<TrianglePair>& near, std::vector<TrianglePair>& pairs);

// The pairs of a list as deep as the bodies beyond the trees' search at the Hertz range (nearTrianglePairs), batched:
// every s of `reaching1` and t of `reaching2` (the triangles whose caps reach into the other body) whose cap boxes meet
// within depth + skin and not within `inner` [m] (AlignedBox3r::intersects of s's box and t's moved into body 1's frame
// by transformedBox), that touchablePair keeps, appended to `pairs` in the order t, then s, each as listed. Returns how
// many pairs the reference's own test decided.
size_t appendTouchableShellPairsBatched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                        const Vector3r& translation, Real skin, Real depth, Real inner,
                                        const std::vector<int>& reaching1, const std::vector<int>& reaching2,
                                        std::vector<TrianglePair>& pairs);

// The near search's filters 2-4 (passesFilters2to4) on `pairs`, batched: keeps those that pass, in their order.
// `reach`: depth + skin [m]. Returns how many pairs the reference's own test decided.
size_t keepPassingFilters2to4Batched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                     const Vector3r& translation, Real skin, Real reach,
                                     std::vector<TrianglePair>& pairs);

// The name of the instruction set the batches run on here (e.g. "AVX2", "AVX3" for AVX-512), for benchmarks.
const char* batchedTarget();

}  // namespace roundedmesh
