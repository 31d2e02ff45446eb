#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation, Real margin,
                                              const RelativeMotion& motion, std::vector<PressureGeom>& geoms) {
  PressureGeom geom;
  TriangleTree::queryPairs(mesh1.tree(), mesh2.tree(), rotation, translation, margin, [&](int s, int t) {
    // Eq. B.5 first: it needs only the two normals and sphere centres.
    const RoundedTriangle& p = mesh1.rounded(s);
    const RoundedTriangle& q = mesh2.rounded(t);
    const Vector3r d = rotation * q.sphereCentre + translation - p.sphereCentre;
    if (!(p.normal.dot(d) > 0 && (rotation * q.normal).dot(d) < 0)) return;
    if (triangleSphereGeom(mesh1, s, contactSphere(mesh2, t, rotation, translation), motion, geom))
      geoms.push_back(geom);
  });
}

}  // namespace roundedmesh
