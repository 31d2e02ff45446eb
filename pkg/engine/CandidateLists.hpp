// The candidate triangle pairs of two rounded bodies, kept between steps (doc/physics.md, "Lists kept between
// steps"). Within the Hertz range a list holds contacts 1.5 times as deep as the pair's deepest one at its last
// evaluation, plus two skins: contacts deepen continuously, so the list grows with them (a new list holds
// `shallow` [m], the deepest contact meant to be Hertzian). A pair past it holds every contact it can have, `full`
// [m] deep (deepestPossible): the deep-contact criterion can accept a pair much deeper than the others at once (a
// segment through both bodies at a slant), which a list grown from the deepest one would miss. A list is rebuilt
// when it was never built, when body 2 may have moved by more than the skin since, when the deepest contact comes
// within a skin of the depth it holds or passes the Hertz range, or when it holds more than twice the depth needed
// (a pair that has come apart). The new skin follows the pair's motion per step (ListSkins); the near list it is
// taken from is searched again only when it no longer covers the new one.
#pragma once

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

// The deepest effective overlap [m] a triangle pair of these bodies can have and pass the deep-contact criterion
// (DeepContactCriterion.hpp): its surface points q1, q2 both lie within each body's solid, up to the criterion's
// tolerance, so |q1 - q2| is at most the diameter of the ball that holds the smaller one.
Real deepestPossible(const RoundedMesh& a, const RoundedMesh& b);

// Brings `list` up to date for body 2's pose in body 1's frame (x1 = matrix * x2 + translation, `rotation` the same
// as a quaternion); `radius`: the pair's smaller volume-equivalent radius [m], the unit of `skins`. Rebuilds and the
// near pairs they scan are counted in `statistics`, and with `timed` the near searches' CPU time.
void updateCandidates(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Quaternionr& rotation,
                      const Matrix3r& matrix, const Vector3r& translation, const ListSkins& skins, Real radius,
                      Real shallow, Real full, CandidateList& list, ContactStatistics& statistics, bool timed);

// Brings a rounded body's candidate triangles against a Facet partner up to date (FacetList), the facet placed in the
// body's frame by x_body = toBody x_facet + facetOrigin, `radius` the body's volume-equivalent radius [m], the unit of
// `skins`. They are made again when they were never made, when the facet's shape or its edge radius changed, when a
// point of the body's tree may have moved by more than their skin relative to the facet, or its centre far enough to
// be on the facet's other side (facetSide); the skin follows the pair's motion per step, as a pair of bodies' does.
// Rebuilds are counted in `statistics` (candidateRebuilds).
void updateFacetCandidates(const RoundedMesh& mesh, const Facet& facet, const Matrix3r& toBody,
                           const Vector3r& facetOrigin, const BodyState& body, const BodyState& facetState,
                           Real edgeRadius, const ListSkins& skins, Real radius, FacetList& list,
                           ContactStatistics& statistics);

}  // namespace roundedmesh
