#include "pkg/shape/TriangleSurface.hpp"

#include <algorithm>

namespace roundedmesh {

Real triangleArea(const TriangleSurface& s, int t) {
  const Triangle& corners = s.triangles[t];
  const Vector3r &a = s.vertices[corners[0]], &b = s.vertices[corners[1]], &c = s.vertices[corners[2]];
  return 0.5 * (b - a).cross(c - a).norm();
}

Vector3r triangleNormal(const TriangleSurface& s, int t) {
  const Triangle& corners = s.triangles[t];
  const Vector3r &a = s.vertices[corners[0]], &b = s.vertices[corners[1]], &c = s.vertices[corners[2]];
  return (b - a).cross(c - a).normalized();
}

std::vector<Real> triangleAreas(const TriangleSurface& surface) {
  std::vector<Real> areas(surface.triangles.size());
  for (std::size_t t = 0; t < areas.size(); ++t) areas[t] = triangleArea(surface, static_cast<int>(t));
  return areas;
}

Vector3r circumcentre(const Vector3r& a, const Vector3r& b, const Vector3r& c) {
  const Vector3r ab = b - a, ac = c - a;
  const Vector3r n = ab.cross(ac);
  return a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2 * n.squaredNorm());
}

bool hasZeroArea(const Vector3r& a, const Vector3r& b, const Vector3r& c) {
  const Real longestEdgeSq = std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  return !((b - a).cross(c - a).norm() > 1e-12 * longestEdgeSq);
}

Eigen::AlignedBox<Real, 3> boundingBox(const std::vector<Vector3r>& points) {
  Eigen::AlignedBox<Real, 3> box;
  for (const Vector3r& p : points) box.extend(p);
  return box;
}

}  // namespace roundedmesh
