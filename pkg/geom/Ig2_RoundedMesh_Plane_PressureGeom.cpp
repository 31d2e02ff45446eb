#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Plane_PressureGeom(const RoundedMesh& mesh, const Plane& plane, const RelativeMotion& motion,
                                        std::vector<PressureGeom>& geoms) {
  ContactFace face;
  face.origin = plane.point;
  face.normal = -plane.normal;
  face.tangent1 = face.normal.unitOrthogonal();
  face.tangent2 = face.normal.cross(face.tangent1);
  PressureGeom geom;
  for (int t = 0; t < mesh.triangleCount(); ++t)
    if (trianglePlaneGeom(mesh, t, face, motion, geom)) geoms.push_back(geom);
}

}  // namespace roundedmesh
