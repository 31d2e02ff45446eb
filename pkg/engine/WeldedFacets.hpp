// The model's Facets welded into surfaces (FacetSurface.hpp) as they stand now: each Facet partner gets its weld,
// its panel's outline in the facet body's frame, so that the weld moves with the facets (a turning drum). Facets that
// share edges are taken to move together, as YADE's facetBox, facetCylinder and imported meshes do.
#pragma once

#include <vector>

#include "pkg/engine/BodyState.hpp"
#include "pkg/engine/ContactModel.hpp"

namespace roundedmesh {

// partnerStates: in the order of model.partners. Facets welded before are welded afresh.
void weldFacetPartners(ContactModel& model, const std::vector<BodyState>& partnerStates);

}  // namespace roundedmesh
