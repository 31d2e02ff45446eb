// Bound: the candidate triangle pairs taken from a near list (TrianglePairCandidates.hpp) several pairs per
// instruction. A first pass reads the near pairs' triangles from both meshes' columns (TriangleColumns.hpp) in
// batches as wide as the processor's vector unit (Google Highway, the widest of SSE2 ... AVX-512 the processor has,
// chosen at run time) and rejects, with no branch per pair, those that fail filter 1 (boxes), 2 (balls),
// 3 (sphere overlap), 4 (facing) or the first test of 5 (the projected circumcircles against the contact circle),
// each by a margin far above the rounding of either pass (see the .cpp); the pairs left go through the reference's
// own test (touchablePair). So the list is the reference's, pair for pair and in the same order, whatever the
// vector unit, and the margin only lets a few more pairs through to the exact test.
#pragma once

#include <vector>

#include "pkg/bound/TrianglePairCandidates.hpp"

namespace roundedmesh {

// touchableTrianglePairs, batched: the same arguments, the same `pairs`.
void touchableTrianglePairsBatched(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                                   const Vector3r& translation, Real skin, Real depth,
                                   const std::vector<TrianglePair>& near, std::vector<TrianglePair>& pairs);

// The name of the instruction set the batches run on here (e.g. "AVX2", "AVX3" for AVX-512), for benchmarks.
const char* batchedTarget();

}  // namespace roundedmesh
