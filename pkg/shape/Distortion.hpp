// Mesh distortion D = std(triangle area) / mean(triangle area) (Eq. 26): 0 for a perfectly even mesh,
// about 0.7 for the heavily distorted spheres of Fig. 4. Population standard deviation.
#pragma once

#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

Real distortion(const TriangleSurface& surface);

}  // namespace roundedmesh
