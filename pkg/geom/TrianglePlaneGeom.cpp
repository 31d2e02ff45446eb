#include "pkg/geom/TrianglePlaneGeom.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "pkg/geom/DeepContactCriterion.hpp"
#include "pkg/geom/EllipticalContact.hpp"
#include "pkg/geom/ProjectedTriangle.hpp"
#include "pkg/math/Segment.hpp"

namespace roundedmesh {

FaceOutline::FaceOutline(std::vector<Vector2r> corners_, std::vector<bool> open_, std::vector<Real> inset_,
                         std::vector<Real> slack_)
    : corners(std::move(corners_)), open(std::move(open_)), inset(std::move(inset_)), slack(std::move(slack_)) {
  const int n = static_cast<int>(corners.size());
  lines.reserve(n);
  for (int i = 0; i < n; ++i) {
    const Vector2r along = (corners[(i + 1) % n] - corners[i]).normalized(), inward(-along.y(), along.x());
    const Vector2r shift = (inset.empty() ? 0 : inset[i]) * inward;
    lines.push_back({corners[i] + shift, corners[(i + 1) % n] + shift, inward, inward.dot(corners[i] + shift)});
  }
}

namespace {

// The polygon, within the circle of `radius` about `centre`, clipped to the outline moved by `offset`: by the edges
// that circle crosses only, so that a panel's outline of many corners costs a dot product per corner.
ConvexPolygon clippedToOutline(const ConvexPolygon& polygon, const Vector2r& centre, Real radius,
                               const FaceOutline& outline, const Vector2r& offset) {
  ConvexPolygon buffers[2];
  int spare = 0;
  const ConvexPolygon* current = &polygon;
  for (const FaceOutline::Line& line : outline.lines) {
    if (current->empty()) break;
    if (line.inward.dot(centre - offset) - line.offset >= radius) continue;
    current->clipInto(line.from + offset, line.to + offset, buffers[spare]);
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

  auto toPlane = [&](const Vector3r& x) { return planeCoordinates(x, c, face.tangent1, face.tangent2); };
  projectTriangle(mesh, triangle, c, face.tangent1, face.tangent2, geom);
  if (face.faceOutline)
    geom.polygon = clippedToOutline(geom.polygon, toPlane(rounded.circumcentre), rounded.circumradius,
                                    *face.faceOutline, toPlane(face.origin));
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
    const Real slack = outline.slack.empty() ? 0 : outline.slack[i];
    nearest = std::min(nearest, (p - closestOnSegment(p, a, b)).norm() + slack);
  }
  return nearest;
}

}  // namespace

FaceReach::FaceReach(const RoundedMesh& mesh, const ContactFace& face, Real margin)
    : normal_(face.normal), origin_(face.origin), margin_(margin), nodeSlack_(1e-9 * mesh.sphereBoundRadius()) {
  // A cap that reaches the plane has part of its box on the partner's side. Behind a sheet with an open edge, a cap
  // deeper than the outline is wide (plus the edges' slack) is farther behind it than from any open edge, and the
  // sheet rule would reject it: it is not tested.
  if (face.sheet && face.faceOutline) {
    const FaceOutline& outline = *face.faceOutline;
    if (outline.open.empty() || std::find(outline.open.begin(), outline.open.end(), true) != outline.open.end()) {
      Real width = 0, slack = 0;
      for (const Vector2r& x : outline.corners)
        for (const Vector2r& y : outline.corners) width = std::max(width, (x - y).norm());
      for (Real s : outline.slack) slack = std::max(slack, s);
      deepest_ = width + slack;
    }
  }
  // A cap whose projection meets the outline (or the part of it whose contacts the face keeps) lies in the prism over
  // it, as deep on either side as the body is wide: a box (a node's, or a triangle's) that holds such a cap meets that
  // prism's AABB, and reaches inside each edge's line, its farthest corner along the line's inward normal (in the
  // plane) on the inner side. A contact's c_eff lies in S, the projection of a point of its triangle, and a panel's
  // member keeps it up to 1e-9 of its size outside its own triangle (facetOwns): the lines are moved out by 1e-6 of the
  // region's size for that and for round-off.
  const FaceOutline* region = face.owned ? face.owned : face.faceOutline;
  if (!region) return;
  const Real reach = 2 * mesh.sphereBoundRadius();
  prism_.setEmpty();
  Eigen::AlignedBox<Real, 2> extent;
  for (const Vector2r& x : region->corners) {
    const Vector3r corner = face.origin + x.x() * face.tangent1 + x.y() * face.tangent2;
    prism_.extend(corner + reach * face.normal).extend(corner - reach * face.normal);
    extent.extend(x);
  }
  // The extent's diagonal depends on the in-plane axes, which turn with the face: a margin's test takes the most it can
  // be, sqrt(2) times the region's diameter.
  Real lineMargin = 1e-6 * extent.sizes().norm();
  if (margin > 0) {
    Real diameter = 0;
    for (const Vector2r& x : region->corners)
      for (const Vector2r& y : region->corners) diameter = std::max(diameter, (x - y).norm());
    lineMargin = 1e-6 * std::sqrt(Real(2)) * diameter;
  }
  // A region of more edges is bounded by its first kRegionSides.
  for (int i = 0; i < static_cast<int>(region->lines.size()) && sideCount_ < kRegionSides; ++i) {
    const FaceOutline::Line& line = region->lines[i];
    const Vector3r inward = line.inward.x() * face.tangent1 + line.inward.y() * face.tangent2;
    sides_[sideCount_++] = {inward, inward.cwiseAbs(), line.offset + inward.dot(face.origin) - lineMargin - margin};
  }
}

void faceCandidates(const RoundedMesh& mesh, const ContactFace& face, Real margin, std::vector<int>& triangles) {
  triangles.clear();
  mesh.tree().visitReachable(FaceReach(mesh, face, margin), [&](int t) { triangles.push_back(t); });
}

void faceGeometry(const RoundedMesh& mesh, const ContactFace& face, const RelativeMotion& motion, GeomOutput out,
                  CurvatureModel model, const std::vector<int>* candidates) {
  const FaceReach reachable(mesh, face, 0);
  PressureGeom geom;
  auto test = [&](int t) {
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
  };
  mesh.tree().visitReachable(reachable, test, candidates);
}

}  // namespace roundedmesh
