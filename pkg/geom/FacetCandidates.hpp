// The body's triangles that Ig2_RoundedMesh_Facet_PressureGeom may test against a facet, for the body on `side` of it:
// its face's (faceCandidates) and each edge rounding's (featureCandidates, in the order of the facet's edges), found
// for the facet and body where they were when these were made, with a margin: they hold every triangle the Ig2 tests
// while the body stays on that side and no point of the body's tree moves by more than the margin relative to the
// facet. Made by facetCandidates (Ig2_RoundedMesh_Facet_PressureGeom.hpp); kept per pair from step to step
// (CandidateList::facet), as the triangle pairs of two bodies are.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

namespace roundedmesh {

struct FacetCandidates {
  int side = 0;
  std::vector<int> face;
  std::array<std::vector<int>, 3> strips;

  // Then the Ig2 finds nothing.
  bool empty() const {
    return face.empty() && std::all_of(strips.begin(), strips.end(), [](const auto& s) { return s.empty(); });
  }
};

}  // namespace roundedmesh
