#include "pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.hpp"

#include <array>
#include <limits>

namespace roundedmesh {

void Ig2_RoundedMesh_Box_PressureGeom(const RoundedMesh& mesh, const Box& box, const Vector3r& centre,
                                      const Matrix3r& orientation, const RelativeMotion& motion,
                                      GeomOutput out, CurvatureModel model) {
  // Face f = 2 * axis + (outward normal along -axis ? 1 : 0); t1 x t2 = n12 = -outward normal.
  std::array<ContactFace, 6> faces;
  std::array<ConvexPolygon, 6> outlines;
  for (int axis = 0; axis < 3; ++axis) {
    const int j = (axis + 1) % 3, k = (axis + 2) % 3;
    for (int negative = 0; negative < 2; ++negative) {
      const int f = 2 * axis + negative;
      const Real sign = negative ? -1 : 1;
      const int u = negative ? j : k, v = negative ? k : j;
      ContactFace& face = faces[f];
      face.origin = centre + sign * box.halfExtents[axis] * orientation.col(axis);
      face.normal = -sign * orientation.col(axis);
      face.tangent1 = orientation.col(u);
      face.tangent2 = orientation.col(v);
      outlines[f] = ConvexPolygon::rectangle(Vector2r::Zero(), box.halfExtents[u], box.halfExtents[v]);
      face.faceOutline = &outlines[f];
    }
  }

  const AlignedBox3r boxInBodyFrame = transformedBox(AlignedBox3r(-box.halfExtents, box.halfExtents), orientation, centre);
  PressureGeom geom;
  mesh.tree().query([&](const AlignedBox3r& b) { return b.intersects(boxInBodyFrame); }, [&](int t) {
    const Vector3r local = orientation.transpose() * (mesh.rounded(t).sphereCentre - centre);
    int nearestFace = 0;
    Real nearestHeight = -std::numeric_limits<Real>::infinity();
    bool outside = false;
    for (int f = 0; f < 6; ++f) {
      const int axis = f / 2;
      const Real height = (f % 2 ? -local[axis] : local[axis]) - box.halfExtents[axis];
      if (height > 0) {
        outside = true;
        out.add(trianglePlaneGeom(mesh, t, faces[f], motion, geom, model), geom);
      } else if (height > nearestHeight) {
        nearestHeight = height;
        nearestFace = f;
      }
    }
    if (!outside) out.add(trianglePlaneGeom(mesh, t, faces[nearestFace], motion, geom, model), geom);
  });
}

}  // namespace roundedmesh
