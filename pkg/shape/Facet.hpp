// YADE's Facet: a flat triangle with corners `vertices` [m] in the facet body's frame (relative to its
// position, turned by its orientation). Both sides touch; a rounded body meets the side its centre is on.
// As a contact partner it is a finite plane (Section 2.3): radius of curvature infinite, polygon S the
// intersection of the two projected triangles. Facets welded into a surface (FacetSurface.hpp) carry their weld:
// the panel of coplanar facets they belong to, and what lies beyond each edge.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <vector>

#include "pkg/common/Types.hpp"
#include "pkg/shape/FacetSurface.hpp"

namespace roundedmesh {

struct Facet {
  std::array<Vector3r, 3> vertices;
  std::shared_ptr<const FacetWeld> weld;  // outline in the facet body's frame; none: a facet alone
};

// The facet's corners placed by its body's position and orientation [m].
inline std::array<Vector3r, 3> facetCorners(const Facet& facet, const Vector3r& position, const Quaternionr& orientation) {
  std::array<Vector3r, 3> corners;
  for (int i = 0; i < 3; ++i) corners[i] = position + orientation * facet.vertices[i];
  return corners;
}

// Whether the corners span a plane: a facet whose corners are collinear (to a billionth of its size), as CAD exports
// leave some, has no normal and touches nothing.
inline bool hasArea(const std::array<Vector3r, 3>& corners) {
  const Real size = std::max({(corners[1] - corners[0]).norm(), (corners[2] - corners[1]).norm(),
                              (corners[0] - corners[2]).norm()});
  return (corners[1] - corners[0]).cross(corners[2] - corners[0]).norm() > 1e-9 * size * size;
}

// A facet moved into another frame (x' = rotation x + translation, x in the facet body's frame): its corners and,
// welded, its panel's outline, with the weld's flags.
struct PlacedFacet {
  std::array<Vector3r, 3> corners;
  std::vector<Vector3r> outline, outlineBeyond;  // empty for a facet alone
  std::array<Vector3r, 3> beyond;
  const FacetWeld* weld = nullptr;
};

inline PlacedFacet placeFacet(const Facet& facet, const Matrix3r& rotation, const Vector3r& translation) {
  PlacedFacet placed;
  auto place = [&](const Vector3r& x) -> Vector3r { return rotation * x + translation; };
  for (int i = 0; i < 3; ++i) placed.corners[i] = place(facet.vertices[i]);
  if (facet.weld) {
    placed.weld = facet.weld.get();
    placed.outline.reserve(facet.weld->outline.size());
    placed.outlineBeyond.reserve(facet.weld->outlineBeyond.size());
    for (const Vector3r& x : facet.weld->outline) placed.outline.push_back(place(x));
    for (const Vector3r& x : facet.weld->outlineBeyond) placed.outlineBeyond.push_back(place(x));
    for (int i = 0; i < 3; ++i) placed.beyond[i] = place(facet.weld->beyond[i]);
  }
  return placed;
}

}  // namespace roundedmesh
