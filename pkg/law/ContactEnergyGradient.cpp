#include "pkg/law/ContactEnergyGradient.hpp"

#include <algorithm>

#include "pkg/law/FacingRamp.hpp"

namespace roundedmesh {
namespace {

// The edges of S, each moved outward, as the energy's gradient: an edge on the line of a triangle's edge A B (its
// own, or the partner triangle's) adds its share to dU/du of A and B, by the distance along A B; any other edge is
// the partner face's outline (a Facet's or a Box face's), whose corners only the sum of their gradients needs.
struct EdgeGradients {
  std::array<Vector2r, 3> own = {Vector2r::Zero(), Vector2r::Zero(), Vector2r::Zero()};
  std::array<Vector2r, 3> partner = {Vector2r::Zero(), Vector2r::Zero(), Vector2r::Zero()};
  Vector2r outline = Vector2r::Zero();
};

// A triangle's edge lines A B, to find the one an edge of S lies on: off the line by at most the tolerance is
// |d x (x - A)| <= tolerance |d|, d = B - A, squared.
struct EdgeLines {
  std::array<Vector2r, 3> from, along;
  std::array<Real, 3> lengthSq, reach;

  EdgeLines(const std::array<Vector2r, 3>& triangle, Real tolerance) {
    for (int e = 0; e < 3; ++e) {
      from[e] = triangle[e];
      along[e] = triangle[(e + 1) % 3] - triangle[e];
      lengthSq[e] = along[e].squaredNorm();
      reach[e] = tolerance * tolerance * lengthSq[e];
    }
  }
  bool onLine(int e, const Vector2r& x) const {
    const Real off = cross2(along[e], x - from[e]);
    return off * off <= reach[e];
  }
};

// Adds the edge P Q of S (outward normal m, its integrals `edge`) to the corners of the triangle if it lies on one of
// its edges A B: lambda along P Q is l = lP + lambda (lQ - lP) along A B, so the integral of l w^3 ds, B's share, is
// lP energy + (lQ - lP) energyMoment, and A's share the rest.
bool onTriangleEdge(const EdgeLines& lines, const Vector2r& P, const Vector2r& Q, const Vector2r& m,
                    const EdgeIntegrals& edge, Real k, std::array<Vector2r, 3>& g) {
  for (int e = 0; e < 3; ++e) {
    if (!(lines.lengthSq[e] > 0) || !lines.onLine(e, P) || !lines.onLine(e, Q)) continue;
    const Vector2r &A = lines.from[e], &d = lines.along[e];
    const Real lP = (P - A).dot(d) / lines.lengthSq[e], lQ = (Q - A).dot(d) / lines.lengthSq[e];
    const Real toB = lP * edge.energy + (lQ - lP) * edge.energyMoment;
    g[e] += k * (edge.energy - toB) * m;
    g[(e + 1) % 3] += k * toB * m;
    return true;
  }
  return false;
}

EdgeGradients edgeGradients(const PressureGeom& geom, bool partnerTriangle, Real k, const DiskPolygonBatch& edges,
                            int polygon) {
  const ConvexPolygon& S = geom.polygon;
  // S's corners on a triangle's edge line come from clipping: off it by round-off of the corners' size.
  Real size = geom.contactRadius;
  for (const Vector2r& u : geom.nodes) size = std::max(size, u.cwiseAbs().maxCoeff());
  const Real tolerance = 1e-9 * size;
  const EdgeLines own(geom.nodes, tolerance);
  const EdgeLines partner(partnerTriangle ? geom.partnerNodes : geom.nodes, tolerance);
  EdgeGradients g;
  for (int i = 0; i < S.size(); ++i) {
    const EdgeIntegrals edge = edges.edge(polygon, i);
    if (edge.energy == 0) continue;  // outside the disc (or a point): no energy to move
    const Vector2r &P = S[i], &Q = S[(i + 1) % S.size()];
    const Vector2r unit = edges.direction(polygon, i);
    const Vector2r m(unit.y(), -unit.x());  // outward: S is counter-clockwise
    if (onTriangleEdge(own, P, Q, m, edge, k, g.own)) continue;
    if (partnerTriangle && onTriangleEdge(partner, P, Q, m, edge, k, g.partner)) continue;
    g.outline += k * edge.energy * m;
  }
  return g;
}

// -grad U, U itself, as if every triangle faced fully.
EnergyForces fullyFacing(const PressureGeom& geom, Real elasticForce, Real energyAmplitude,
                         const std::array<Vector3r, 3>& corners1, const Vector3r& sphere1, const EnergyPartner& partner,
                         const DiskPolygonBatch& edges, int polygon) {
  const Vector3r& n = geom.normal;
  auto inSpace = [&](const Vector2r& u) -> Vector3r { return u.x() * geom.tangent1 + u.y() * geom.tangent2; };
  const bool triangle = partner.kind == EnergyPartner::Triangle;
  const EdgeGradients g = edgeGradients(geom, triangle, energyAmplitude, edges, polygon);
  EnergyForces out;
  out.energy = energyAmplitude * edges.integrals(polygon).energy;
  if (partner.kind == EnergyPartner::Plane) {
    // The outline's corners are the partner's: moving s1 in the plane moves c, and so every projected corner, its
    // own and the outline's alike.
    Vector3r atSphere = elasticForce * n - inSpace(g.outline);
    for (int j = 0; j < 3; ++j) {
      const Vector3r gj = inSpace(g.own[j]);
      atSphere -= gj;
      out.onBody2[out.count++] = {corners1[j], gj};
    }
    out.onBody2[out.count++] = {sphere1, atSphere};
    return out;
  }
  const Vector3r s12 = partner.sphereCentre - sphere1;
  const Real distance = s12.norm();
  Vector3r turning = Vector3r::Zero();  // sum_j eta_j g_j
  for (int j = 0; j < 3; ++j) turning += (corners1[j] - sphere1).dot(n) * inSpace(g.own[j]);
  if (triangle) {
    for (int j = 0; j < 3; ++j) {
      const Vector3r gj = inSpace(g.partner[j]);
      turning += (partner.corners[j] - sphere1).dot(n) * gj;
      out.onBody2[out.count++] = {partner.corners[j], -gj};
    }
  }
  out.onBody2[out.count++] = {partner.sphereCentre, elasticForce * n + turning / distance};
  return out;
}

// w U in place of U (FacingRamp.hpp): the forces scaled by w, and -U grad w added. Body 2 moved by t and turned by
// omega changes n12 by (1 - n12 n12^T) t / |s2 - s1| and n2 (or a plane's n12) by omega x n2.
void turnedAside(const Vector3r& n, const Vector3r& normal1, const Vector3r& sphere1, const EnergyPartner& partner,
                 EnergyForces& out) {
  const Real facing1 = normal1.dot(n), facing2 = -partner.normal.dot(n);
  const FacingRamp own = facingRamp(facing1);
  const FacingRamp other = partner.kind == EnergyPartner::Triangle ? facingRamp(facing2) : FacingRamp{1, 0};
  const Real w = own.value * other.value;
  if (w == 1) return;  // both at 1: their slopes are 0
  const Real U = out.energy;
  out.energy *= w;
  for (int k = 0; k < out.count; ++k) out.onBody2[k].force *= w;
  if (partner.kind == EnergyPartner::Plane) {
    // d(n1 . n12) = omega . (n12 x n1)
    out.coupleOnBody2 = -U * own.slope * n.cross(normal1);
    return;
  }
  // d(n1 . n12) = (n1 - (n1 . n12) n12) . t / |s2 - s1|;  d(-n2 . n12) = -(n2 + (-n2 . n12) n12) . t / |s2 - s1|
  // - omega . (n2 x n12). The force at s2 is the last of onBody2.
  Vector3r atSphere = -own.slope * other.value * (normal1 - facing1 * n);
  if (partner.kind == EnergyPartner::Triangle) {
    atSphere += own.value * other.slope * (partner.normal + facing2 * n);
    out.coupleOnBody2 = U * own.value * other.slope * partner.normal.cross(n);
  }
  out.onBody2[out.count - 1].force += U / (partner.sphereCentre - sphere1).norm() * atSphere;
}

}  // namespace

EnergyForces contactEnergyGradient(const PressureGeom& geom, Real elasticForce, Real energyAmplitude,
                                   const std::array<Vector3r, 3>& corners1, const Vector3r& sphere1,
                                   const Vector3r& normal1, const EnergyPartner& partner, const DiskPolygonBatch& edges,
                                   int polygon) {
  EnergyForces out = fullyFacing(geom, elasticForce, energyAmplitude, corners1, sphere1, partner, edges, polygon);
  turnedAside(geom.normal, normal1, sphere1, partner, out);
  return out;
}

}  // namespace roundedmesh
