#include "pkg/geom/TriangleEdgeGeom.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pkg/geom/EllipticalContact.hpp"
#include "pkg/geom/ProjectedTriangle.hpp"
#include "pkg/math/ConvexHull.hpp"

namespace roundedmesh {
namespace {

// How deep behind a cap, as a fraction of its body's bounding radius, a rounded edge's axis may lie and still be under
// the cap: past the overlaps the stop rule lets a pair reach (0.5 r_eq, about 0.25 of a gummy bear's bounding radius)
// with room to spare; a ball swallowing a rounded ridge 0.3 r_eq deep has the axis 0.2 of its radius behind its caps.
constexpr Real kSwallowed = 0.3;

// The strip's cross-section projected on t2: rho times the range of n . t2 over the arc of outward normals n from
// normals[0] to normals[1] (the shorter way round).
std::array<Real, 2> arcRange(const std::vector<Vector3r>& normals, const Vector3r& t2) {
  const Vector3r& e0 = normals[0];
  const Vector3r e1 = (normals[1] - normals[1].dot(e0) * e0).normalized();
  const Real span = std::atan2(normals[1].dot(e1), normals[1].dot(e0));
  const Real c = e0.dot(t2), s = e1.dot(t2);
  std::array<Real, 2> range{std::min(c, normals[1].dot(t2)), std::max(c, normals[1].dot(t2))};
  const Real top = std::atan2(s, c), amplitude = std::hypot(c, s);
  for (Real angle : {top, top + M_PI, top - M_PI, top + 2 * M_PI})
    if (angle > 0 && angle < span) {
      range[0] = std::min(range[0], amplitude * std::cos(angle - top));
      range[1] = std::max(range[1], amplitude * std::cos(angle - top));
    }
  return range;
}

// The corner's patch projected on the plane, about the corner's centre: the hull of the face normals' tips and of the
// midpoints of the arcs between them, times rho (the patch's curved sides are taken at those chords).
ConvexPolygon patchOutline(const std::vector<Vector3r>& normals, Real radius, const Vector3r& t1, const Vector3r& t2) {
  std::vector<Vector2r> points;
  const int n = static_cast<int>(normals.size());
  for (int i = 0; i < n; ++i) {
    const Vector3r tip = normals[i], middle = (normals[i] + normals[(i + 1) % n]).normalized();
    for (const Vector3r& x : {tip, middle}) points.emplace_back(radius * x.dot(t1), radius * x.dot(t2));
  }
  ConvexPolygon outline;
  for (const Vector2r& x : convexHull(points)) outline.push(x);
  return outline;
}

}  // namespace

GeomTest triangleFeatureGeom(const RoundedMesh& mesh, int triangle, const RoundedFeature& feature,
                             const RelativeMotion& motion, PressureGeom& geom, CurvatureModel model) {
  const RoundedTriangle& rounded = mesh.rounded(triangle);
  const Vector3r& s = rounded.sphereCentre;
  const Real length = (feature.end - feature.start).norm();
  const bool edge = length > 0;
  const Vector3r axis = edge ? Vector3r((feature.end - feature.start) / length) : Vector3r::Zero();
  // The foot on the axis' line (the strip bounds S along it), or the corner's centre.
  const Vector3r q = feature.start + (s - feature.start).dot(axis) * axis;
  const Vector3r toAxis = q - s;
  const Real distance = toAxis.norm();
  if (!(distance > 0)) return {Rejection::NotFacing};
  const Vector3r n = toAxis / distance;
  if (!(rounded.normal.dot(n) > 0)) return {Rejection::NotFacing};
  const Real R = rounded.radius, rho = feature.radius;
  const Real overlap = R + rho - distance;
  if (!(overlap > 0)) return {Rejection::NoOverlap};
  const Real along = ((distance - rho) * (distance + rho) + R * R) / (2 * distance);
  const Vector3r c = s + along * n;
  // The contact plane must pass through the cap, within its reach (circumradius + cap height) of its circumcentre
  // along n12, and through the cylinder: a flat triangle's huge sphere puts it anywhere. And the axis may lie behind
  // the cap (a body that has swallowed the rounding) only so deep: a cap on a body's far side, facing away from an
  // edge at its front, has a sphere that reaches through the body to the edge.
  // A cap in front of the axis reaches the cylinder only if the segment comes within rho of the cap, which lies within
  // capHeight of its circumcircle: a flat triangle's sphere reaches the cylinder from centimetres away, through the
  // body, along any n it faces.
  const Vector3r nearest =
      edge ? Vector3r(feature.start + std::clamp((rounded.circumcentre - feature.start).dot(axis), Real(0), length) * axis)
           : feature.start;
  const Real behind = -(q - rounded.circumcentre).dot(rounded.normal);  // how deep the axis lies behind the cap's plane
  if (std::abs((c - rounded.circumcentre).dot(n)) > rounded.circumradius + rounded.capHeight + rho ||
      behind > rho + kSwallowed * mesh.sphereBoundRadius() ||
      (behind < 0 && (nearest - rounded.circumcentre).norm() > rho + rounded.capHeight + rounded.circumradius))
    return {Rejection::NoOverlap};
  // A cap with the axis behind it touches the cylinder only where the body has swallowed the rounding through that cap:
  // the cap is then about as near the axis as the body's nearest surface, the axis' depth D in the body
  // (SolidDistance's signed distance; negative outside, and clamped at its band, past which the axis is deep in the
  // body). Where another surface is nearer, the cap is on the far side of the part of the body the edge presses into
  // (a bear lying over a plate's rim: its back's triangles have spheres that reach the rim through the bear).
  if (behind > 0) {
    const SolidDistance& solid = mesh.solidDistance();
    const Real depth =
        -solid.signedAt(edge ? Vector3r(feature.start + std::clamp((q - feature.start).dot(axis), Real(0), length) * axis)
                             : feature.start);
    if (depth < solid.band() - solid.tolerance() && behind > depth + rho + mesh.maxCapHeight() + solid.tolerance())
      return {Rejection::ThroughBody};
  }
  // Hertz's ellipse lies within the surfaces' intersection, whose reach along the axis is sqrt(2 R delta).
  const Vector3r offset = rounded.circumcentre - c;
  const Real reach = std::sqrt(2 * R * overlap) + rounded.circumradius;
  if (offset.squaredNorm() - std::pow(offset.dot(n), 2) > reach * reach) return {Rejection::OutsideCircle};

  geom.tangent1 = edge ? axis : n.unitOrthogonal();
  geom.tangent2 = n.cross(geom.tangent1);
  projectTriangle(mesh, triangle, c, geom.tangent1, geom.tangent2, geom);
  if (edge) {
    const std::array<Real, 2> across = arcRange(feature.faceNormals, geom.tangent2);
    const Real from = (feature.start - c).dot(axis), to = (feature.end - c).dot(axis);
    geom.polygon = geom.polygon.intersection(
        ConvexPolygon::rectangle(Vector2r(0.5 * (from + to), 0.5 * rho * (across[0] + across[1])), 0.5 * (to - from),
                                 0.5 * rho * (across[1] - across[0])));
  } else {
    geom.polygon = geom.polygon.intersection(patchOutline(feature.faceNormals, rho, geom.tangent1, geom.tangent2));
  }
  if (geom.polygon.empty()) return {Rejection::EmptyPolygon};

  geom.triangle = triangle;
  geom.partnerTriangle = -1;
  geom.centre = c;
  geom.normal = n;
  geom.radius = R * rho / (R + rho);
  geom.sphereOverlap = overlap;
  geom.contactRadius = std::sqrt(overlap * geom.radius);
  geom.effectivePoint = geom.polygon.closestPoint(Vector2r::Zero());
  geom.elliptical = false;
  CapCurvature partner = exactCap(1 / rho);
  if (edge) partner.curvature = Vector2r(0, 1 / rho) * Vector2r(0, 1).transpose();  // flat along the axis (t1)
  const GeomTest ellipse = ellipticalContact(
      geom, model == CurvatureModel::Principal ? triangleCap(mesh, triangle, geom) : exactCap(1 / R), partner);
  if (!ellipse) return ellipse;
  if (!geom.elliptical) {  // a sphere's cap on a corner: the circle of Eq. 5
    const Real hSq = geom.effectivePoint.squaredNorm();
    if (!(hSq < geom.contactRadius * geom.contactRadius)) return {Rejection::BeyondContactCircle};
    geom.effectiveOverlap = overlap - R - rho + std::sqrt(std::max(R * R - hSq, Real(0))) +
                            std::sqrt(std::max(rho * rho - hSq, Real(0)));
  }
  setRelativeVelocity(geom, motion);
  return {Rejection::None};
}

Real featureReach(const RoundedMesh& mesh, Real radius) { return radius + kSwallowed * mesh.sphereBoundRadius(); }

namespace {

// Whether a box of the body's tree may hold a cap that touches the feature, or may once the feature has moved relative
// to the body so that no point of the box moves by more than `margin` [m]: a cap can touch the cylinder only if its
// box comes within rho of the axis segment (S is clipped to the segment along the axis), or has swallowed it
// (triangleFeatureGeom): the box's centre within that reach (plus the margin) and half its diagonal of the segment.
class FeatureReach {
 public:
  FeatureReach(const RoundedMesh& mesh, const RoundedFeature& feature, Real margin)
      : start_(feature.start), along_(feature.end - feature.start), lengthSq_(along_.squaredNorm()),
        capReach_(featureReach(mesh, feature.radius) + margin), nodeSlack_(1e-9 * mesh.sphereBoundRadius()) {}

  bool operator()(const AlignedBox3r& box) const { return within(box, 0.5 * box.sizes().norm()); }

  // A node of the tree passes where any box it holds may (kNestedBallFactor), with a billionth of the body's size for
  // round-off.
  bool node(const AlignedBox3r& box) const {
    return within(box, kNestedBallFactor * 0.5 * box.sizes().norm() + nodeSlack_);
  }

 private:
  bool within(const AlignedBox3r& box, Real radius) const {
    const Vector3r centre = box.center();
    const Real t = lengthSq_ > 0 ? std::clamp((centre - start_).dot(along_) / lengthSq_, Real(0), Real(1)) : 0;
    const Real reach = capReach_ + radius;
    return (centre - start_ - t * along_).squaredNorm() <= reach * reach;
  }

  Vector3r start_, along_;
  Real lengthSq_, capReach_, nodeSlack_;
};

}  // namespace

void featureCandidates(const RoundedMesh& mesh, const RoundedFeature& feature, Real margin,
                       std::vector<int>& triangles) {
  triangles.clear();
  mesh.tree().visitReachable(FeatureReach(mesh, feature, margin), [&](int t) { triangles.push_back(t); });
}

void featureGeometry(const RoundedMesh& mesh, const RoundedFeature& feature, const RelativeMotion& motion,
                     GeomOutput out, CurvatureModel model, const std::vector<int>* candidates) {
  PressureGeom geom;
  mesh.tree().visitReachable(
      FeatureReach(mesh, feature, 0),
      [&](int t) { out.add(triangleFeatureGeom(mesh, t, feature, motion, geom, model), geom); }, candidates);
}

}  // namespace roundedmesh
