#include "pkg/engine/WeldedFacets.hpp"

#include <memory>

namespace roundedmesh {

void weldFacetPartners(ContactModel& model, const std::vector<BodyState>& partnerStates) {
  std::vector<Facet*> facets;
  std::vector<const BodyState*> states;
  std::vector<std::array<Vector3r, 3>> corners;
  for (size_t p = 0; p < model.partners.size(); ++p)
    if (Facet* facet = std::get_if<Facet>(&model.partners[p].shape)) {
      facets.push_back(facet);
      states.push_back(&partnerStates[p]);
      corners.push_back(facetCorners(*facet, partnerStates[p].position, partnerStates[p].orientation));
    }
  const std::vector<FacetWeld> welds = weldFacets(corners, weldTolerance(corners));
  for (size_t f = 0; f < facets.size(); ++f) {
    auto weld = std::make_shared<FacetWeld>(welds[f]);
    const Quaternionr toFacet = states[f]->orientation.conjugate();
    for (Vector3r& x : weld->outline) x = toFacet * (x - states[f]->position);
    for (Vector3r& x : weld->outlineBeyond) x = toFacet * (x - states[f]->position);
    for (Vector3r& x : weld->beyond) x = toFacet * (x - states[f]->position);
    facets[f]->weld = std::move(weld);
  }
}

}  // namespace roundedmesh
