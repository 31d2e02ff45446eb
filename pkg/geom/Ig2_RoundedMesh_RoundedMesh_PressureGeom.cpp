#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

#include <algorithm>
#include <array>

#include "pkg/math/TriangleIntersections.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation,
                                              const std::vector<TrianglePair>& candidates, Real shallow,
                                              const RelativeMotion& motion, GeomOutput out, CurvatureModel model,
                                              PolygonLanes lanes) {
  const PlacedMesh body2{mesh2, rotation, translation};
  const TriangleExits &exits1 = mesh1.exits(), &exits2 = mesh2.exits();
  const Matrix3r back = rotation.transpose();
  auto placed = [&](int t) { return PlacedTriangle{mesh2, t, rotation, translation}; };
  auto add = [&](int s, int t, GeomTest result, const PressureGeom& geom) {
    // The segment q1 q2 is no longer than delta_eff: nearer no exit of either triangle for nearly every pair of
    // smooth bodies; the others are tested in full.
    if (result &&
        !(exits1.clear(s, mesh1.rounded(s).normal.dot(geom.normal), geom.effectiveOverlap) &&
          exits2.clear(t, -mesh2.rounded(t).normal.dot(back * geom.normal), geom.effectiveOverlap)) &&
        !overlapInsideBoth(mesh1, s, body2, t, geom, geom.effectiveOverlap > shallow))
      result = {Rejection::ThroughBody};
    out.add(result, geom);
  };

  if (lanes == PolygonLanes::Never || (lanes == PolygonLanes::WherePaying && !triangleIntersectionsPay())) {
    PressureGeom geom;
    for (const auto& [s, t] : candidates) add(s, t, triangleSphereGeom(mesh1, s, placed(t), motion, geom, model), geom);
    return;
  }
  // S of up to kBatch candidates clipped together: each candidate's tests before S, then S in lanes, then the rest.
  constexpr int kBatch = TriangleIntersections::kCapacity;
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
      results[k] = trianglePlane(mesh1, s, placed(t), geoms[k]);
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
        const int lane = laneOf[k];
        if (batch.overflowed(lane)) {
          clipByPartner(geom);
        } else {
          geom.polygon = batch.polygon(lane);
          if (!geom.polygon.empty()) geom.effectivePoint = batch.closestPoint(lane);
        }
        result = triangleContactOnPolygon(mesh1, s, placed(t), motion, geom, model);
      }
      add(s, t, result, geom);
    }
  }
}

}  // namespace roundedmesh
