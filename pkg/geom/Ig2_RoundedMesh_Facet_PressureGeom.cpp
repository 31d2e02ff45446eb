#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Facet_PressureGeom(const RoundedMesh& mesh, const std::array<Vector3r, 3>& corners,
                                        const RelativeMotion& motion, GeomOutput out, CurvatureModel model) {
  const Vector3r normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  ContactFace face;
  face.origin = corners[0];
  // n12 points from the body (its centre is body 1's origin) into the facet.
  face.normal = normal.dot(corners[0]) > 0 ? normal : Vector3r(-normal);
  face.tangent1 = face.normal.unitOrthogonal();
  face.tangent2 = face.normal.cross(face.tangent1);
  face.sheet = true;
  const ConvexPolygon outline = ConvexPolygon::triangle(faceCoordinates(face, corners[0]), faceCoordinates(face, corners[1]),
                                                        faceCoordinates(face, corners[2]));
  face.faceOutline = &outline;
  faceGeometry(mesh, face, motion, out, model);
}

}  // namespace roundedmesh
