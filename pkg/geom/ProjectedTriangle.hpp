// A triangle of body 1 seen on a contact plane (Section 2.3, Fig. 2): the plane through c with in-plane axes t1, t2;
// plane coordinates are taken about c. What every Ig2 of a rounded triangle starts S from.
#pragma once

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

inline Vector2r planeCoordinates(const Vector3r& x, const Vector3r& c, const Vector3r& t1, const Vector3r& t2) {
  return Vector2r((x - c).dot(t1), (x - c).dot(t2));
}

// Triangle `triangle` of `mesh` projected on the plane: its corners, in mesh order -> geom.nodes, and their triangle,
// S before any clipping -> geom.polygon.
inline void projectTriangle(const RoundedMesh& mesh, int triangle, const Vector3r& c, const Vector3r& t1,
                            const Vector3r& t2, PressureGeom& geom) {
  const Triangle& corners = mesh.triangles()[triangle];
  for (int i = 0; i < 3; ++i) geom.nodes[i] = planeCoordinates(mesh.vertices()[corners[i]], c, t1, t2);
  geom.polygon = ConvexPolygon::triangle(geom.nodes[0], geom.nodes[1], geom.nodes[2]);
}

}  // namespace roundedmesh
