#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation,
                                              const std::vector<TrianglePair>& candidates, Real shallow,
                                              const RelativeMotion& motion, GeomOutput out, CurvatureModel model) {
  PressureGeom geom;
  const PlacedMesh body2{mesh2, rotation, translation};
  const TriangleExits &exits1 = mesh1.exits(), &exits2 = mesh2.exits();
  const Matrix3r back = rotation.transpose();
  for (const auto& [s, t] : candidates) {
    GeomTest result = triangleSphereGeom(mesh1, s, PlacedTriangle{mesh2, t, rotation, translation}, motion, geom, model);
    // The segment q1 q2 is no longer than delta_eff: nearer no exit of either triangle for nearly every pair of
    // smooth bodies; the others are tested in full.
    if (result &&
        !(exits1.clear(s, mesh1.rounded(s).normal.dot(geom.normal), geom.effectiveOverlap) &&
          exits2.clear(t, -mesh2.rounded(t).normal.dot(back * geom.normal), geom.effectiveOverlap)) &&
        !overlapInsideBoth(mesh1, s, body2, t, geom, geom.effectiveOverlap > shallow))
      result = {Rejection::ThroughBody};
    out.add(result, geom);
  }
}

}  // namespace roundedmesh
