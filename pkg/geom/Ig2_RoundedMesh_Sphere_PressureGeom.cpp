#include "pkg/geom/Ig2_RoundedMesh_Sphere_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Sphere_PressureGeom(const RoundedMesh& mesh, const Sphere& sphere, const Vector3r& centre,
                                         const RelativeMotion& motion, GeomOutput out, CurvatureModel model) {
  ContactSphere partner;
  partner.centre = centre;
  partner.radius = sphere.radius;
  const AlignedBox3r box(centre.array() - sphere.radius, centre.array() + sphere.radius);
  PressureGeom geom;
  mesh.tree().query([&](const AlignedBox3r& b) { return b.intersects(box); }, [&](int t) {
    out.add(triangleSphereGeom(mesh, t, partner, motion, geom, model), geom);
  });
}

}  // namespace roundedmesh
