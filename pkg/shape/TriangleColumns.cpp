#include "pkg/shape/TriangleColumns.hpp"

#include <algorithm>

#include "pkg/shape/RoundedMesh.hpp"
#include "pkg/shape/TriangleCorners.hpp"

namespace roundedmesh {

TriangleColumns triangleColumns(const RoundedMesh& mesh) {
  TriangleColumns c;
  const int n = mesh.triangleCount();
  for (int k = 0; k < 3; ++k)
    for (std::vector<Real>* column : {&c.boxMin[k], &c.boxMax[k], &c.circumcentre[k], &c.sphereCentre[k], &c.normal[k]})
      column->resize(n);
  for (auto& coordinates : c.corner)
    for (std::vector<Real>& column : coordinates) column.resize(n);
  c.circumradius.resize(n);
  c.radius.resize(n);
  c.sphereCentreDistance.resize(n);
  for (int t = 0; t < n; ++t) {
    const RoundedTriangle& r = mesh.rounded(t);
    const AlignedBox3r& box = mesh.tree().triangleBox(t);
    const std::array<Vector3r, 3> corners = triangleCorners(mesh, t);
    for (int k = 0; k < 3; ++k) {
      c.boxMin[k][t] = box.min()[k];
      c.boxMax[k][t] = box.max()[k];
      c.circumcentre[k][t] = r.circumcentre[k];
      c.sphereCentre[k][t] = r.sphereCentre[k];
      c.normal[k][t] = r.normal[k];
      for (int i = 0; i < 3; ++i) c.corner[i][k][t] = corners[i][k];
    }
    c.circumradius[t] = r.circumradius;
    c.radius[t] = r.radius;
    c.largestRadius = std::max(c.largestRadius, r.radius);
    c.sphereCentreDistance[t] = r.sphereCentre.norm();
  }
  return c;
}

}  // namespace roundedmesh
