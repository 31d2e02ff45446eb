#include "pkg/law/ContactEnergyGradient.hpp"

#include <algorithm>

#include "pkg/math/DiskPolygonIntegrals.hpp"

namespace roundedmesh {
namespace {

// dU/du_j of the corners of triangle `own` (plane coordinates about c), its edges clipped to the triangle `other`
// (if any: S = own n other) and to the disc of radius a.
std::array<Vector2r, 3> cornerGradients(const std::array<Vector2r, 3>& own, const std::array<Vector2r, 3>* other,
                                        Real a, Real k) {
  std::array<Vector2r, 3> g = {Vector2r::Zero(), Vector2r::Zero(), Vector2r::Zero()};
  for (int e = 0; e < 3; ++e) {
    const Vector2r &A = own[e], &B = own[(e + 1) % 3], &C = own[(e + 2) % 3];
    const Vector2r d = B - A;
    Vector2r outward = Vector2r(d.y(), -d.x()).normalized();
    if (outward.dot(C - A) > 0) outward = -outward;
    Real l0 = 0, l1 = 1;
    if (other) {
      // The part of the edge inside the other triangle: (A + l d - q) . inward >= 0 for each of its edges.
      for (int i = 0; i < 3 && l1 > l0; ++i) {
        const Vector2r &q = (*other)[i], &r = (*other)[(i + 1) % 3], &opposite = (*other)[(i + 2) % 3];
        Vector2r inward(r.y() - q.y(), q.x() - r.x());
        if (inward.dot(opposite - q) < 0) inward = -inward;
        const Real at = (A - q).dot(inward), rate = d.dot(inward);
        if (rate > 0) l0 = std::max(l0, -at / rate);
        else if (rate < 0) l1 = std::min(l1, -at / rate);
        else if (at < 0) l1 = l0;
      }
    }
    if (!(l1 > l0)) continue;
    const SegmentIntegrals edge = segmentIntegrals(a, A, B, l0, l1);
    g[e] += k * (edge.energy - edge.energyMoment) * outward;
    g[(e + 1) % 3] += k * edge.energyMoment * outward;
  }
  return g;
}

}  // namespace

EnergyForces contactEnergyGradient(const PressureGeom& geom, Real elasticForce, Real energyAmplitude,
                                   const std::array<Vector3r, 3>& corners1, const Vector3r& sphere1,
                                   const EnergyPartner& partner) {
  const Vector3r& n = geom.normal;
  auto inSpace = [&](const Vector2r& u) -> Vector3r { return u.x() * geom.tangent1 + u.y() * geom.tangent2; };
  const bool triangle = partner.kind == EnergyPartner::Triangle;
  const std::array<Vector2r, 3> g1 = cornerGradients(geom.nodes, triangle ? &geom.partnerNodes : nullptr,
                                                     geom.contactRadius, energyAmplitude);
  EnergyForces out;
  if (partner.kind == EnergyPartner::Plane) {
    Vector3r atSphere = elasticForce * n;
    for (int j = 0; j < 3; ++j) {
      const Vector3r g = inSpace(g1[j]);
      atSphere -= g;
      out.onBody2[out.count++] = {corners1[j], g};
    }
    out.onBody2[out.count++] = {sphere1, atSphere};
    return out;
  }
  const Vector3r s12 = partner.sphereCentre - sphere1;
  const Real distance = s12.norm();
  Vector3r turning = Vector3r::Zero();  // sum_j eta_j g_j
  for (int j = 0; j < 3; ++j) turning += (corners1[j] - sphere1).dot(n) * inSpace(g1[j]);
  if (triangle) {
    const std::array<Vector2r, 3> g2 =
        cornerGradients(geom.partnerNodes, &geom.nodes, geom.contactRadius, energyAmplitude);
    for (int j = 0; j < 3; ++j) {
      const Vector3r g = inSpace(g2[j]);
      turning += (partner.corners[j] - sphere1).dot(n) * g;
      out.onBody2[out.count++] = {partner.corners[j], -g};
    }
  }
  out.onBody2[out.count++] = {partner.sphereCentre, elasticForce * n + turning / distance};
  return out;
}

}  // namespace roundedmesh
