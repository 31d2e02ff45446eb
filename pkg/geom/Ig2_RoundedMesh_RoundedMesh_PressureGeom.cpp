#include "pkg/geom/Ig2_RoundedMesh_RoundedMesh_PressureGeom.hpp"

#include <algorithm>

#include "pkg/geom/PolygonContacts.hpp"
#include "pkg/geom/TrianglePlanes.hpp"
#include "pkg/math/TriangleIntersections.hpp"

namespace roundedmesh {

void Ig2_RoundedMesh_RoundedMesh_PressureGeom(const RoundedMesh& mesh1, const RoundedMesh& mesh2,
                                              const Matrix3r& rotation, const Vector3r& translation,
                                              const std::vector<TrianglePair>& candidates, Real shallow,
                                              const RelativeMotion& motion, GeomOutput out, CurvatureModel model,
                                              PolygonLanes lanes) {
  const PlacedMesh body2{mesh2, rotation, translation};
  const PairExits exits(mesh1, mesh2, rotation);
  auto placed = [&](int t) { return PlacedTriangle{mesh2, t, rotation, translation}; };
  // The segment q1 q2 is no longer than delta_eff: nearer no exit of either triangle for nearly every pair of smooth
  // bodies (`surelyInside`); the others are tested in full.
  auto add = [&](int s, int t, GeomTest result, const PressureGeom& geom, bool surelyInside) {
    if (result && !surelyInside && !overlapInsideBoth(mesh1, s, body2, t, geom, geom.effectiveOverlap > shallow))
      result = {Rejection::ThroughBody};
    out.add(result, geom);
  };
  auto clear = [&](int s, int t, GeomTest result, const PressureGeom& geom) {
    return result && exits.clear(s, t, geom);
  };

  if (lanes == PolygonLanes::Never || (lanes == PolygonLanes::WherePaying && !triangleIntersectionsPay())) {
    PressureGeom geom;
    for (const auto& [s, t] : candidates) {
      const GeomTest result = triangleSphereGeom(mesh1, s, placed(t), motion, geom, model);
      add(s, t, result, geom, clear(s, t, result, geom));
    }
    return;
  }
  // Up to a batch of candidates at a time, in lanes: the tests before S and the contact planes, S, and for the
  // paper's circles the rest; then each contact's exits one at a time.
  constexpr int kBatch = TrianglePlanes::kCapacity;
  TrianglePlanes planes;
  TriangleIntersections clips;
  PolygonContacts contacts;
  PressureGeom geom;
  const int total = static_cast<int>(candidates.size());
  for (int first = 0; first < total; first += kBatch) {
    planes.size = std::min(kBatch, total - first);
    for (int k = 0; k < planes.size; ++k) {
      planes.s[k] = candidates[first + k][0];
      planes.t[k] = candidates[first + k][1];
    }
    trianglePlanes(mesh1, mesh2, rotation, translation, planes, clips);
    intersectTriangles(clips);
    if (model == CurvatureModel::Mean) polygonContacts(mesh1, mesh2, rotation, planes, clips, motion, contacts);
    for (int k = 0; k < planes.size; ++k) {
      const auto& [s, t] = candidates[first + k];
      GeomTest result = planes.result(k);
      if (!result) {
        out.add(result, geom);
        continue;
      }
      planes.get(k, geom);
      if (clips.overflowed(k)) {
        geom.polygon = ConvexPolygon::triangle(geom.nodes[0], geom.nodes[1], geom.nodes[2]);  // P'
        clipByPartner(geom);
      } else if (model == CurvatureModel::Mean) {
        result = contacts.result(k);
        if (result) contacts.get(k, clips, s, t, geom);
        add(s, t, result, geom, contacts.surelyInside(k));
        continue;
      } else {
        geom.polygon = clips.polygon(k);
        if (!geom.polygon.empty()) geom.effectivePoint = clips.closestPoint(k);
      }
      result = triangleContactOnPolygon(mesh1, s, placed(t), motion, geom, model);
      add(s, t, result, geom, clear(s, t, result, geom));
    }
  }
}

}  // namespace roundedmesh
