#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Plane_PressureGeom(const RoundedMesh& mesh, const Plane& plane, const RelativeMotion& motion,
                                        GeomOutput out, CurvatureModel model) {
  ContactFace face;
  face.origin = plane.point;
  face.normal = -plane.normal;
  face.tangent1 = face.normal.unitOrthogonal();
  face.tangent2 = face.normal.cross(face.tangent1);
  // A cap that reaches the plane has part of its box on the solid side.
  auto reachesPlane = [&](const AlignedBox3r& box) {
    return plane.normal.dot(box.center() - plane.point) < 0.5 * plane.normal.cwiseAbs().dot(box.sizes());
  };
  PressureGeom geom;
  mesh.tree().query(reachesPlane, [&](int t) {
    out.add(trianglePlaneGeom(mesh, t, face, motion, geom, model), geom);
  });
}

}  // namespace roundedmesh
