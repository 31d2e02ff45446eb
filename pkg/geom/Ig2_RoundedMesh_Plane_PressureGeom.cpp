#include "pkg/geom/Ig2_RoundedMesh_Plane_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Plane_PressureGeom(const RoundedMesh& mesh, const Plane& plane, const RelativeMotion& motion,
                                        GeomOutput out, CurvatureModel model) {
  ContactFace face;
  face.origin = plane.point;
  face.normal = -plane.normal;
  face.tangent1 = face.normal.unitOrthogonal();
  face.tangent2 = face.normal.cross(face.tangent1);
  faceGeometry(mesh, face, motion, out, model);
}

}  // namespace roundedmesh
