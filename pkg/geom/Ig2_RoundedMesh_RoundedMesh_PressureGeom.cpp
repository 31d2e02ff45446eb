#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation,
                                              const std::vector<TrianglePair>& candidates,
                                              const RelativeMotion& motion, GeomOutput out) {
  PressureGeom geom;
  for (const auto& [s, t] : candidates)
    out.add(triangleSphereGeom(mesh1, s, PlacedTriangle{mesh2, t, rotation, translation}, motion, geom), geom);
}

}  // namespace roundedmesh
