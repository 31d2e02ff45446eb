#include "pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.hpp"

#include <array>

namespace roundedmesh {

void Ig2_RoundedMesh_Box_PressureGeom(const RoundedMesh& mesh, const Box& box, const Vector3r& centre,
                                      const Matrix3r& orientation, const RelativeMotion& motion,
                                      GeomOutput out, CurvatureModel model) {
  // The body's centre (body 1's origin) in the box's axes, and how far it lies outside face f = 2 * axis +
  // (outward normal along -axis ? 1 : 0).
  const Vector3r bodyCentre = -orientation.transpose() * centre;
  auto height = [&](int f) { return (f % 2 ? -bodyCentre[f / 2] : bodyCentre[f / 2]) - box.halfExtents[f / 2]; };
  int leastDeep = 0;
  for (int f = 1; f < 6; ++f)
    if (height(f) > height(leastDeep)) leastDeep = f;
  for (int f = 0; f < 6; ++f) {
    if (!(height(f) > 0) && f != leastDeep) continue;
    const int axis = f / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    const Real sign = f % 2 ? -1 : 1;
    // The face's plane takes the in-plane axes a Plane with its normal takes, so that a contact inside the face is
    // computed as a Wall's, to round-off.
    ContactFace face;
    face.origin = centre + sign * box.halfExtents[axis] * orientation.col(axis);
    face.normal = -sign * orientation.col(axis);
    face.tangent1 = face.normal.unitOrthogonal();
    face.tangent2 = face.normal.cross(face.tangent1);
    std::array<Vector2r, 4> corners;
    const std::array<Vector2r, 4> signs = {Vector2r(1, 1), Vector2r(-1, 1), Vector2r(-1, -1), Vector2r(1, -1)};
    for (int i = 0; i < 4; ++i) {
      const Vector3r x = signs[i].x() * box.halfExtents[u] * orientation.col(u) +
                         signs[i].y() * box.halfExtents[v] * orientation.col(v);
      corners[i] = Vector2r(x.dot(face.tangent1), x.dot(face.tangent2));
    }
    // Counter-clockwise about n12.
    const Vector2r e1 = corners[1] - corners[0], e2 = corners[2] - corners[0];
    if (e1.x() * e2.y() - e1.y() * e2.x() < 0) std::swap(corners[1], corners[3]);
    const FaceOutline outline{{corners.begin(), corners.end()}, {}};
    face.faceOutline = &outline;
    faceGeometry(mesh, face, motion, out, model);
  }
}

}  // namespace roundedmesh
