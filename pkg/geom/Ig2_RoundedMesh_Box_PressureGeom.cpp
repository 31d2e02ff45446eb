#include "pkg/geom/Ig2_RoundedMesh_Box_PressureGeom.hpp"

#include <algorithm>
#include <array>

#include "pkg/geom/TriangleEdgeGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Box_PressureGeom(const RoundedMesh& mesh, const Box& box, const Vector3r& centre,
                                      const Matrix3r& orientation, Real edgeRadius, const RelativeMotion& motion,
                                      GeomOutput out, CurvatureModel model) {
  const Real rho = std::min(edgeRadius, box.halfExtents.minCoeff());
  const Vector3r inner = box.halfExtents.array() - rho;  // the half-sizes of the box shrunk by rho
  // The body's centre (body 1's origin) in the box's axes, and how far it lies outside face f = 2 * axis +
  // (outward normal along -axis ? 1 : 0).
  const Vector3r bodyCentre = -orientation.transpose() * centre;
  auto height = [&](int f) { return (f % 2 ? -bodyCentre[f / 2] : bodyCentre[f / 2]) - box.halfExtents[f / 2]; };
  auto sign = [](int f) { return f % 2 ? Real(-1) : Real(1); };
  int leastDeep = 0;
  for (int f = 1; f < 6; ++f)
    if (height(f) > height(leastDeep)) leastDeep = f;
  std::array<bool, 6> met{};
  for (int f = 0; f < 6; ++f) met[f] = height(f) > 0 || f == leastDeep;
  for (int f = 0; f < 6; ++f) {
    if (!met[f]) continue;
    const int axis = f / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    // The face's plane takes the in-plane axes a Plane with its normal takes, so that a contact inside the face is
    // computed as a Wall's, to round-off.
    ContactFace face;
    face.origin = centre + sign(f) * box.halfExtents[axis] * orientation.col(axis);
    face.normal = -sign(f) * orientation.col(axis);
    face.tangent1 = face.normal.unitOrthogonal();
    face.tangent2 = face.normal.cross(face.tangent1);
    std::array<Vector2r, 4> corners;
    const std::array<Vector2r, 4> signs = {Vector2r(1, 1), Vector2r(-1, 1), Vector2r(-1, -1), Vector2r(1, -1)};
    for (int i = 0; i < 4; ++i) {
      const Vector3r x = signs[i].x() * inner[u] * orientation.col(u) + signs[i].y() * inner[v] * orientation.col(v);
      corners[i] = Vector2r(x.dot(face.tangent1), x.dot(face.tangent2));
    }
    // Counter-clockwise about n12.
    const Vector2r e1 = corners[1] - corners[0], e2 = corners[2] - corners[0];
    if (e1.x() * e2.y() - e1.y() * e2.x() < 0) std::swap(corners[1], corners[3]);
    const FaceOutline outline({corners.begin(), corners.end()});
    face.faceOutline = &outline;
    faceGeometry(mesh, face, motion, out, model);
  }
  if (!(rho > 0)) return;
  // A point of the shrunk box in body 1's frame, and a face's outward normal there.
  auto at = [&](const Vector3r& boxPoint) -> Vector3r { return centre + orientation * boxPoint; };
  auto outward = [&](int f) -> Vector3r { return sign(f) * orientation.col(f / 2); };
  for (int axis = 0; axis < 3; ++axis) {  // the edges along `axis`, between faces fu and fv
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int fu : {2 * u, 2 * u + 1})
      for (int fv : {2 * v, 2 * v + 1}) {
        if (!met[fu] && !met[fv]) continue;
        Vector3r x = Vector3r::Zero();
        x[u] = sign(fu) * inner[u];
        x[v] = sign(fv) * inner[v];
        Vector3r start = x, end = x;
        start[axis] = -inner[axis];
        end[axis] = inner[axis];
        if (start == end) continue;  // a box as thin as rho along the edge: its corners cover it
        featureGeometry(mesh, RoundedFeature{at(start), at(end), rho, {outward(fu), outward(fv)}}, motion, out, model);
      }
  }
  for (int fx : {0, 1})
    for (int fy : {2, 3})
      for (int fz : {4, 5}) {
        if (!met[fx] && !met[fy] && !met[fz]) continue;
        const Vector3r x(sign(fx) * inner.x(), sign(fy) * inner.y(), sign(fz) * inner.z());
        featureGeometry(mesh, RoundedFeature{at(x), at(x), rho, {outward(fx), outward(fy), outward(fz)}}, motion, out,
                        model);
      }
}

}  // namespace roundedmesh
