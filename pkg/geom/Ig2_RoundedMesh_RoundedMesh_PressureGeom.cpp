#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation,
                                              const std::vector<TrianglePair>& candidates, Real shallow,
                                              const RelativeMotion& motion, GeomOutput out, CurvatureModel model) {
  PressureGeom geom;
  const PlacedMesh body2{mesh2, rotation, translation};
  for (const auto& [s, t] : candidates) {
    GeomTest result = triangleSphereGeom(mesh1, s, PlacedTriangle{mesh2, t, rotation, translation}, motion, geom, model);
    if (result && geom.effectiveOverlap > shallow && !overlapInsideBoth(mesh1, s, body2, t, geom))
      result = {Rejection::ThroughBody};
    out.add(result, geom);
  }
}

}  // namespace roundedmesh
