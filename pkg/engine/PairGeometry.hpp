// Stage 3 of a contact step, geometry, for one pair (Ig2, in the body's frame): its triangle contacts. For two
// rounded bodies through their candidate list (CandidateLists.hpp), evaluated again with a deeper list while the
// deepest contact outgrows it; for a partner, the Ig2 of its kind (Plane, Wall, Box, Facet, Sphere).
#pragma once

#include <vector>

#include "pkg/engine/ContactData.hpp"

namespace roundedmesh {

// Velocity of body 2's material relative to body 1's, in body 1's frame (R_BW: global -> body 1's axes), about
// body 1's position.
RelativeMotion relativeMotion(const BodyState& s1, const BodyState& s2, const Matrix3r& R_BW);

// The pair's triangle contacts -> geoms (body 1's frame), the funnel's counts -> statistics. `candidates`: the pair's
// list kept between steps, brought up to date here; without it, the candidate triangle pairs are found afresh, for
// contacts up to kDeepestOverlap of the smaller body deep.
void pairGeometry(const ContactModel& model, const ContactData& data, const BodyPair& pair,
                  std::vector<PressureGeom>& geoms, ContactStatistics& statistics, CandidateList* candidates = nullptr);

}  // namespace roundedmesh
