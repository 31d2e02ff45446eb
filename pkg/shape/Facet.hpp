// YADE's Facet: a flat triangle with corners `vertices` [m] in the facet body's frame (relative to its
// position, turned by its orientation). Both sides touch; a rounded body meets the side its centre is on.
// As a contact partner it is a finite plane (Section 2.3): radius of curvature infinite, polygon S the
// intersection of the two projected triangles.
#pragma once

#include <array>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

struct Facet {
  std::array<Vector3r, 3> vertices;
};

// The facet's corners placed by its body's position and orientation [m].
inline std::array<Vector3r, 3> facetCorners(const Facet& facet, const Vector3r& position, const Quaternionr& orientation) {
  std::array<Vector3r, 3> corners;
  for (int i = 0; i < 3; ++i) corners[i] = position + orientation * facet.vertices[i];
  return corners;
}

}  // namespace roundedmesh
