#include "pkg/shape/TriangleExits.hpp"

#include <algorithm>

#include "pkg/math/SegmentCrossing.hpp"
#include "pkg/math/TriangleDistance.hpp"
#include "pkg/shape/RoundedMesh.hpp"
#include "pkg/shape/TriangleCorners.hpp"

namespace roundedmesh {

TriangleExits::TriangleExits(const RoundedMesh& mesh, Real reach)
    : reach_(reach), nearest_(mesh.triangleCount()), first_(mesh.triangleCount() + 1, 0) {
  // Each triangle's bounding ball about its centroid, so that far triangles are passed over unmeasured.
  std::vector<Vector3r> centroid(mesh.triangleCount());
  std::vector<Real> ball(mesh.triangleCount());
  for (int t = 0; t < mesh.triangleCount(); ++t) {
    const auto p = triangleCorners(mesh, t);
    centroid[t] = (p[0] + p[1] + p[2]) / 3;
    ball[t] = std::max({(p[0] - centroid[t]).norm(), (p[1] - centroid[t]).norm(), (p[2] - centroid[t]).norm()});
  }
  std::vector<Exit> found;
  for (int i = 0; i < mesh.triangleCount(); ++i) {
    const auto own = triangleCorners(mesh, i);
    const Vector3r& normal = mesh.rounded(i).normal;
    const Real plane = normal.dot(own[0]);
    const AlignedBox3r box(own[0].cwiseMin(own[1]).cwiseMin(own[2]).array() - reach,
                           own[0].cwiseMax(own[1]).cwiseMax(own[2]).array() + reach);
    found.clear();
    mesh.tree().query([&](const AlignedBox3r& node) { return node.intersects(box); }, [&](int j) {
      if (j == i || (centroid[j] - centroid[i]).norm() - ball[i] - ball[j] > reach) return;
      const auto other = triangleCorners(mesh, j);
      if (!(std::min({normal.dot(other[0]), normal.dot(other[1]), normal.dot(other[2])}) < plane)) return;
      // The first level whose 90 deg - theta j is turned past: cos(angle) < sin(theta) = cos(90 deg - theta).
      const Real cosine = normal.dot(mesh.rounded(j).normal);
      int level = 0;
      while (level < kLevels && !(cosine < kLevelSines[level])) ++level;
      if (level == kLevels) return;
      const Real distance = triangleDistance(own, other);
      if (distance <= reach) found.push_back({distance, j, level});
    });
    std::sort(found.begin(), found.end(), [](const Exit& a, const Exit& b) { return a.distance < b.distance; });
    nearest_[i].fill(reach);
    for (const Exit& e : found)
      for (int level = e.level; level < kLevels; ++level) nearest_[i][level] = std::min(nearest_[i][level], e.distance);
    exits_.insert(exits_.end(), found.begin(), found.end());
    first_[i + 1] = static_cast<int>(exits_.size());
  }
}

bool TriangleExits::keepsInside(const RoundedMesh& mesh, int t, const Vector3r& entry, const Vector3r& end) const {
  const Vector3r direction = end - entry;
  const Real length = direction.norm();
  if (!(length <= reach_)) return false;
  const int at = level(-mesh.rounded(t).normal.dot(direction) / length);
  const auto own = triangleCorners(mesh, t);
  const Vector3r shift = startWithin(own[0], own[1], own[2], entry);
  for (int k = first_[t]; k < first_[t + 1] && exits_[k].distance < length; ++k) {
    if (exits_[k].level > at) continue;
    const auto exit = triangleCorners(mesh, exits_[k].triangle);
    if (crossing(entry + shift, end + shift, exit[0], exit[1], exit[2]) >= 0) return false;
  }
  return true;
}

}  // namespace roundedmesh
