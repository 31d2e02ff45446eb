#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

#include <algorithm>
#include <array>

#include "pkg/math/TriangleIntersections.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation,
                                              const std::vector<TrianglePair>& candidates, Real shallow,
                                              const RelativeMotion& motion, GeomOutput out, CurvatureModel model) {
  constexpr int kBatch = TriangleIntersections::kCapacity;
  const PlacedMesh body2{mesh2, rotation, translation};
  std::array<PressureGeom, kBatch> geoms;
  std::array<GeomTest, kBatch> results;
  std::array<int, kBatch> laneOf;  // the batch's lane of each candidate that reached S
  TriangleIntersections batch;
  const int total = static_cast<int>(candidates.size());
  for (int first = 0; first < total; first += kBatch) {
    const int count = std::min(kBatch, total - first);
    batch.size = 0;
    for (int k = 0; k < count; ++k) {
      const auto& [s, t] = candidates[first + k];
      results[k] = trianglePlane(mesh1, s, PlacedTriangle{mesh2, t, rotation, translation}, geoms[k]);
      if (!results[k]) continue;
      laneOf[k] = batch.size;
      batch.set(batch.size++, geoms[k].polygon, partnerPolygon(geoms[k]));
    }
    intersectTriangles(batch);
    for (int k = 0; k < count; ++k) {
      const auto& [s, t] = candidates[first + k];
      PressureGeom& geom = geoms[k];
      GeomTest result = results[k];
      if (result) {
        const PlacedTriangle partner{mesh2, t, rotation, translation};
        const int lane = laneOf[k];
        if (batch.overflowed(lane)) {
          geom.polygon = geom.polygon.intersection(partnerPolygon(geom));
          if (!geom.polygon.empty()) geom.effectivePoint = geom.polygon.closestPoint(Vector2r::Zero());
        } else {
          geom.polygon = batch.polygon(lane);
          geom.effectivePoint = batch.closestPoint(lane);
        }
        result = triangleContactOnPolygon(mesh1, s, partner, motion, geom, model);
      }
      if (result && geom.effectiveOverlap > shallow && !overlapInsideBoth(mesh1, s, body2, t, geom))
        result = {Rejection::ThroughBody};
      out.add(result, geom);
    }
  }
}

}  // namespace roundedmesh
