#include "pkg/shape/TriangleSurface.hpp"

namespace roundedmesh {

std::vector<Real> triangleAreas(const TriangleSurface& surface) {
  std::vector<Real> areas;
  areas.reserve(surface.triangles.size());
  for (const Triangle& t : surface.triangles) {
    const Vector3r &a = surface.vertices[t[0]], &b = surface.vertices[t[1]], &c = surface.vertices[t[2]];
    areas.push_back(0.5 * (b - a).cross(c - a).norm());
  }
  return areas;
}

}  // namespace roundedmesh
