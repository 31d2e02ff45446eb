#include "pkg/geom/Ig2_RoundedMesh_Sphere_PressureGeom.hpp"

#include <cmath>

#include "pkg/geom/DeepContactCriterion.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_Sphere_PressureGeom(const RoundedMesh& mesh, const Sphere& sphere, const Vector3r& centre,
                                         const RelativeMotion& motion, GeomOutput out, CurvatureModel model,
                                         Real shallow) {
  ContactSphere partner;
  partner.centre = centre;
  partner.radius = sphere.radius;
  const AlignedBox3r box(centre.array() - sphere.radius, centre.array() + sphere.radius);
  PressureGeom geom;
  mesh.tree().query([&](const AlignedBox3r& b) { return b.intersects(box); }, [&](int t) {
    GeomTest result = triangleSphereGeom(mesh, t, partner, motion, geom, model);
    if (result && geom.effectiveOverlap > shallow) {
      const Vector3r onPlane = planePoint(geom, geom.effectivePoint);
      // The line along n12 through c_eff, `lateral` off the line of centres: it must meet the sphere at all (a flat
      // triangle's circle a = sqrt(delta_s R*) reaches past the sphere's radius once delta_s does), and the sphere's
      // point on it nearest the body must lie in the body.
      const Vector3r lateral = onPlane - geom.centre;
      const Real across = sphere.radius * sphere.radius - lateral.squaredNorm();
      const Vector3r deepest = centre + lateral - std::sqrt(std::max(across, Real(0))) * geom.normal;
      // From where that line meets triangle t (c_eff is in its projection S).
      const Vector3r onTriangle = onPlane + lineToTriangle(mesh, t, onPlane, geom.normal) * geom.normal;
      if (!(across > 0) || !pathInsideBody(mesh, t, onTriangle, deepest))
        result = {Rejection::ThroughBody};
    }
    out.add(result, geom);
  });
}

}  // namespace roundedmesh
