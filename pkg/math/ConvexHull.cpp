#include "pkg/math/ConvexHull.hpp"

#include <algorithm>

namespace roundedmesh {

std::vector<Vector2r> convexHull(std::vector<Vector2r> points, Real straight) {
  std::sort(points.begin(), points.end(),
            [](const Vector2r& a, const Vector2r& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  std::vector<Vector2r> hull(2 * points.size());
  auto turnsLeft = [&](const Vector2r& a, const Vector2r& b, const Vector2r& c) { return cross2(b - a, c - a) > straight; };
  int k = 0;
  for (size_t i = 0; i < points.size(); ++i) {  // lower hull
    while (k >= 2 && !turnsLeft(hull[k - 2], hull[k - 1], points[i])) --k;
    hull[k++] = points[i];
  }
  for (int i = static_cast<int>(points.size()) - 2, lower = k + 1; i >= 0; --i) {  // upper hull
    while (k >= lower && !turnsLeft(hull[k - 2], hull[k - 1], points[i])) --k;
    hull[k++] = points[i];
  }
  hull.resize(std::max(k - 1, 0));
  return hull;
}

}  // namespace roundedmesh
