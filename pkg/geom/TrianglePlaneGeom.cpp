#include "pkg/geom/TrianglePlaneGeom.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pkg/geom/DeepContactCriterion.hpp"
#include "pkg/geom/EllipticalContact.hpp"

namespace roundedmesh {
namespace {

// The polygon clipped to the outline moved by `offset`, each edge moved inward by its inset: by the edges it crosses
// only, so that a panel's outline of many corners leaves a small polygon small.
ConvexPolygon clippedToOutline(const ConvexPolygon& polygon, const FaceOutline& outline, const Vector2r& offset) {
  ConvexPolygon buffers[2];
  int spare = 0;
  const ConvexPolygon* current = &polygon;
  const int n = static_cast<int>(outline.corners.size());
  for (int i = 0; i < n && !current->empty(); ++i) {
    Vector2r a = outline.corners[i] + offset, b = outline.corners[(i + 1) % n] + offset;
    if (!outline.inset.empty() && outline.inset[i] > 0) {
      const Vector2r along = (b - a).normalized(), inward(-along.y(), along.x());
      a += outline.inset[i] * inward;
      b += outline.inset[i] * inward;
    }
    bool crosses = false;
    for (int k = 0; k < current->size() && !crosses; ++k) crosses = cross2(b - a, (*current)[k] - a) < 0;
    if (!crosses) continue;
    current->clipInto(a, b, buffers[spare]);
    current = &buffers[spare];
    spare = 1 - spare;
  }
  return *current;
}

}  // namespace

GeomTest trianglePlaneGeom(const RoundedMesh& mesh, int triangle, const ContactFace& face,
                           const RelativeMotion& motion, PressureGeom& geom, CurvatureModel model) {
  const RoundedTriangle& rounded = mesh.rounded(triangle);
  if (!(rounded.normal.dot(face.normal) > 0)) return {Rejection::NotFacing};

  const Real R = rounded.radius;
  const Real distance = face.normal.dot(face.origin - rounded.sphereCentre);
  const Real overlap = R - distance;
  if (!(overlap > 0)) return {Rejection::NoOverlap};
  const Real a = std::sqrt(overlap * R);

  const Vector3r c = rounded.sphereCentre + distance * face.normal;
  // The projected triangle lies in the projected circumcircle: if that misses the contact circle, so does S.
  const Vector3r offset = rounded.circumcentre - c;
  const Real inPlaneSq = offset.squaredNorm() - std::pow(offset.dot(face.normal), 2);
  if (inPlaneSq > std::pow(a + rounded.circumradius, 2)) return {Rejection::OutsideCircle};

  auto toPlane = [&](const Vector3r& x) { return Vector2r((x - c).dot(face.tangent1), (x - c).dot(face.tangent2)); };
  const Triangle& corners = mesh.triangles()[triangle];
  for (int i = 0; i < 3; ++i) geom.nodes[i] = toPlane(mesh.vertices()[corners[i]]);
  geom.polygon = ConvexPolygon::triangle(geom.nodes[0], geom.nodes[1], geom.nodes[2]);
  if (face.faceOutline) geom.polygon = clippedToOutline(geom.polygon, *face.faceOutline, toPlane(face.origin));
  if (geom.polygon.empty()) return {Rejection::EmptyPolygon};

  geom.effectivePoint = geom.polygon.closestPoint(Vector2r::Zero());
  const Real hSq = geom.effectivePoint.squaredNorm();
  if (!(hSq < a * a)) return {Rejection::BeyondContactCircle};

  geom.triangle = triangle;
  geom.partnerTriangle = -1;
  geom.centre = c;
  geom.normal = face.normal;
  geom.tangent1 = face.tangent1;
  geom.tangent2 = face.tangent2;
  geom.radius = R;
  geom.sphereOverlap = overlap;
  geom.contactRadius = a;
  geom.effectiveOverlap = overlap - R + std::sqrt(R * R - hSq);
  geom.elliptical = false;
  if (model == CurvatureModel::Principal) {
    const GeomTest ellipse = ellipticalContact(geom, triangleCap(mesh, triangle, geom), exactCap(0));
    if (!ellipse) return ellipse;
  }
  setRelativeVelocity(geom, motion);
  return {Rejection::None};
}

namespace {

// How far p, inside a convex outline, lies from its nearest open edge, with the edge's slack (infinity if none is
// open).
Real distanceToOpenEdge(const FaceOutline& outline, const Vector2r& p) {
  Real nearest = std::numeric_limits<Real>::infinity();
  const int n = static_cast<int>(outline.corners.size());
  for (int i = 0; i < n; ++i) {
    if (!outline.open.empty() && !outline.open[i]) continue;
    const Vector2r a = outline.corners[i], b = outline.corners[(i + 1) % n];
    const Real along = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), Real(0), Real(1));
    nearest = std::min(nearest, (p - (a + along * (b - a))).norm() + (outline.slack.empty() ? 0 : outline.slack[i]));
  }
  return nearest;
}

}  // namespace

void faceGeometry(const RoundedMesh& mesh, const ContactFace& face, const RelativeMotion& motion, GeomOutput out,
                  CurvatureModel model) {
  // A cap that reaches the plane has part of its box on the partner's side.
  auto reachesPlane = [&](const AlignedBox3r& box) {
    return face.normal.dot(face.origin - box.center()) < 0.5 * face.normal.cwiseAbs().dot(box.sizes());
  };
  // A cap whose projection meets the outline lies in the prism over it, as deep on either side as the body is wide.
  AlignedBox3r prism(Vector3r::Constant(-std::numeric_limits<Real>::infinity()),
                     Vector3r::Constant(std::numeric_limits<Real>::infinity()));
  if (face.faceOutline) {
    prism.setEmpty();
    const Real reach = 2 * mesh.sphereBoundRadius();
    for (const Vector2r& x : face.faceOutline->corners) {
      const Vector3r corner = face.origin + x.x() * face.tangent1 + x.y() * face.tangent2;
      prism.extend(corner + reach * face.normal).extend(corner - reach * face.normal);
    }
  }
  PressureGeom geom;
  mesh.tree().query([&](const AlignedBox3r& box) { return reachesPlane(box) && box.intersects(prism); }, [&](int t) {
    GeomTest result = trianglePlaneGeom(mesh, t, face, motion, geom, model);
    if (result && face.owns && !face.owns(faceCoordinates(face, planePoint(geom, geom.effectivePoint)))) return;
    if (result && face.sheet) {
      // The line along n12 through c_eff meets triangle t (c_eff is in its projection S) `behind` the sheet, or in
      // front of it, where only the cap's bulge crosses the sheet and c_eff lies between the triangle and the cap.
      const Vector3r onSheet = planePoint(geom, geom.effectivePoint);
      const Real toEdge = distanceToOpenEdge(*face.faceOutline, faceCoordinates(face, onSheet));
      // Only a body that reaches an open edge from c_eff can have come round it.
      const bool edgeInReach = toEdge < 2 * mesh.sphereBoundRadius();
      const Real behind = edgeInReach ? lineToTriangle(mesh, t, onSheet, face.normal) : 0;
      if ((behind > 0 && !pathInsideBody(mesh, t, onSheet + behind * face.normal, onSheet)) ||
          !(geom.effectiveOverlap <= toEdge))
        result = {Rejection::ThroughBody};
    }
    out.add(result, geom);
  });
}

}  // namespace roundedmesh
