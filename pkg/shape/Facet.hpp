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

}  // namespace roundedmesh
