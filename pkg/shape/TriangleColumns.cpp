#include "pkg/shape/TriangleColumns.hpp"

#include <algorithm>

#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

TriangleColumns triangleColumns(const RoundedMesh& mesh) {
  TriangleColumns c;
  const int n = mesh.triangleCount();
  for (int k = 0; k < 3; ++k)
    for (std::vector<Real>* column : {&c.boxMin[k], &c.boxMax[k], &c.circumcentre[k], &c.sphereCentre[k], &c.normal[k]})
      column->resize(n);
  c.circumradius.resize(n);
  c.radius.resize(n);
  c.sphereCentreDistance.resize(n);
  for (int t = 0; t < n; ++t) {
    const RoundedTriangle& r = mesh.rounded(t);
    const AlignedBox3r& box = mesh.tree().triangleBox(t);
    for (int k = 0; k < 3; ++k) {
      c.boxMin[k][t] = box.min()[k];
      c.boxMax[k][t] = box.max()[k];
      c.circumcentre[k][t] = r.circumcentre[k];
      c.sphereCentre[k][t] = r.sphereCentre[k];
      c.normal[k][t] = r.normal[k];
    }
    c.circumradius[t] = r.circumradius;
    c.radius[t] = r.radius;
    c.largestRadius = std::max(c.largestRadius, r.radius);
    c.sphereCentreDistance[t] = r.sphereCentre.norm();
  }
  return c;
}

}  // namespace roundedmesh
