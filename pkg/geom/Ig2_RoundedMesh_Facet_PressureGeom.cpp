#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"

#include <algorithm>
#include <optional>

#include "pkg/geom/TriangleEdgeGeom.hpp"
#include "pkg/math/Segment.hpp"

namespace roundedmesh {
namespace {

// An edge is rounded only while 1 + cos(theta) > kFoldedBack, theta the angle between its faces' outward normals: its
// axis then lies at most rho sqrt(2 / kFoldedBack) from the edge.
constexpr Real kFoldedBack = 1e-3;

// Whether the queries of faceGeometry and featureGeometry can test any of the body's triangles: the root of its tree
// must pass the first test of one of them. The face's query tests the boxes that reach its plane from the body's side
// (n12 pointing from the body into the facet) and reach inside each edge line of its region, which lies in the
// facet's own triangle (a panel's member keeps only the contacts over it; a facet alone, or alone in its panel, clips
// S to its outline, the triangle moved in), with a margin of 1e-6 of the region's size (here of the triangle's
// perimeter, which is larger). A strip's query tests the boxes within featureReach of its axis, which lies at most
// rho sqrt(2 / kFoldedBack) from the edge: the root passes where a box it holds may (kNestedBallFactor). Most facets
// whose bounds a body's bound meets lie beside it or beyond its reach.
bool treeMayReach(const RoundedMesh& mesh, const PlacedFacet& facet, const Vector3r& n12, Real edgeRadius) {
  const AlignedBox3r& root = mesh.tree().nodes().front().box;
  const Vector3r centre = root.center(), half = 0.5 * root.sizes();
  const std::array<Vector3r, 3>& corners = facet.corners;
  const Real stripReach =
      featureReach(mesh, edgeRadius) + std::sqrt(2 / kFoldedBack) * edgeRadius + kNestedBallFactor * half.norm();
  Real perimeter = 0;
  for (int e = 0; e < 3; ++e) {
    const Vector3r &a = corners[e], &b = corners[(e + 1) % 3];
    if (facet.weld && facet.weld->ownsStrip[e] && (centre - closestOnSegment(centre, a, b)).norm() <= stripReach)
      return true;
    perimeter += (b - a).norm();
  }
  if (!(n12.dot(centre - corners[0]) > -n12.cwiseAbs().dot(half))) return false;  // all in front of the plane
  for (int e = 0; e < 3; ++e) {
    const Vector3r &a = corners[e], &b = corners[(e + 1) % 3], &opposite = corners[(e + 2) % 3];
    Vector3r inward = n12.cross(b - a).normalized();
    if (inward.dot(opposite - a) < 0) inward = -inward;
    if (inward.dot(centre - a) + inward.cwiseAbs().dot(half) < -1e-6 * perimeter) return false;
  }
  return true;
}

// The facet's unit normal, (c1 - c0) x (c2 - c0) normalised: its side 0.
Vector3r unitNormal(const std::array<Vector3r, 3>& c) { return (c[1] - c[0]).cross(c[2] - c[0]).normalized(); }

// The side of the surface the body's centre (the origin) is on, seen from this facet: the side of its plane, unless
// the centre lies behind the plane past an edge that is convex from the other side, and in front of the facets beyond
// that edge: then it is outside a ridge (above a lifter's apex, past its plane's reach), on the other side. With
// `clearance`, how far the centre lies from the nearest plane whose side it decides by.
int surfaceSide(const PlacedFacet& facet, const Vector3r& normal, Real* clearance) {
  const Vector3r& origin = facet.corners[0];
  const int planeSide = normal.dot(origin) > 0 ? 1 : 0;
  const int other = 1 - planeSide;
  if (clearance) *clearance = std::abs(normal.dot(origin));
  const Vector3r centroid = (facet.corners[0] + facet.corners[1] + facet.corners[2]) / 3;
  const int n = static_cast<int>(facet.outline.size());
  int side = planeSide;
  for (int k = 0; k < n && (clearance || side == planeSide); ++k) {
    const FacetWeld& weld = *facet.weld;
    if (weld.outlineClosed[k][other] || !weld.outlineClosed[k][planeSide] || !facet.outlineBeyond[k].allFinite())
      continue;
    const Vector3r &a = facet.outline[k], &b = facet.outline[(k + 1) % n];
    Vector3r beyondNormal = (b - a).cross(facet.outlineBeyond[k] - a);
    if (beyondNormal.dot(centroid - a) > 0) beyondNormal = -beyondNormal;
    const Vector3r pastEdge = normal.cross(b - a);  // in the plane, across the edge
    const Real past = pastEdge.dot(-a) * pastEdge.dot(centroid - a);
    if (past < 0 && beyondNormal.dot(-a) > 0) side = other;
    if (clearance)
      *clearance = std::min({*clearance, std::abs(pastEdge.dot(a)) / pastEdge.norm(),
                             std::abs(beyondNormal.dot(a)) / beyondNormal.norm()});
  }
  return side;
}

}  // namespace

int facetSide(const PlacedFacet& facet, Real* clearance) {
  const Vector3r normal = unitNormal(facet.corners);
  if (facet.weld) return surfaceSide(facet, normal, clearance);
  if (clearance) *clearance = std::abs(normal.dot(facet.corners[0]));
  return normal.dot(facet.corners[0]) > 0 ? 1 : 0;
}

bool facetOwns(const std::array<Vector2r, 3>& corners, const FacetWeld& weld, const Vector2r& p) {
  Real size = 0;
  for (int i = 0; i < 3; ++i) size = std::max(size, (corners[(i + 1) % 3] - corners[i]).norm());
  const Real on = 1e-9 * size;
  for (int i = 0; i < 3; ++i)
    if ((p - corners[i]).norm() <= on) return weld.ownsCorner[i];
  for (int i = 0; i < 3; ++i)
    if ((p - closestOnSegment(p, corners[i], corners[(i + 1) % 3])).norm() <= on) return weld.ownsEdge[i];
  const Real orientation = cross2(corners[1] - corners[0], corners[2] - corners[0]);
  for (int i = 0; i < 3; ++i)
    if (!(cross2(corners[(i + 1) % 3] - corners[i], p - corners[i]) * orientation > 0)) return false;
  return true;
}

namespace {

// n12 of a facet seen from `side`: from the body into the facet.
Vector3r towardFacet(const PlacedFacet& facet, int side) {
  const Vector3r normal = unitNormal(facet.corners);
  return side == 1 ? normal : Vector3r(-normal);
}

// What a body on `side` of the facet can touch: the face (its plane within the panel's outline, moved in from the
// rounded edges, keeping the contacts over the facet itself) and the roundings of the edges the facet owns that are
// convex from that side. It points into itself: neither copied nor moved.
class FacetSurfaces {
 public:
  FacetSurfaces(const PlacedFacet& facet, int side, Real edgeRadius);
  FacetSurfaces(const FacetSurfaces&) = delete;
  FacetSurfaces& operator=(const FacetSurfaces&) = delete;

  const ContactFace& face() const { return face_; }
  const std::optional<RoundedFeature>& strip(int edge) const { return strips_[edge]; }

 private:
  ContactFace face_;
  std::optional<FaceOutline> outline_, ownOutline_;
  std::array<Vector2r, 3> own_;
  std::array<std::optional<RoundedFeature>, 3> strips_;
};

FacetSurfaces::FacetSurfaces(const PlacedFacet& facet, int side, Real edgeRadius) {
  const std::array<Vector3r, 3>& corners = facet.corners;
  face_.origin = corners[0];
  face_.normal = towardFacet(facet, side);
  face_.tangent1 = face_.normal.unitOrthogonal();
  face_.tangent2 = face_.normal.cross(face_.tangent1);
  face_.sheet = true;
  const FacetWeld* weld = facet.weld;
  if (!weld) {
    const ConvexPolygon triangle = ConvexPolygon::triangle(
        faceCoordinates(face_, corners[0]), faceCoordinates(face_, corners[1]), faceCoordinates(face_, corners[2]));
    outline_.emplace(std::vector<Vector2r>{triangle[0], triangle[1], triangle[2]});
    face_.faceOutline = &*outline_;
    return;
  }
  // The rounding of the edge from a to b, convex from the body's side, toward the facets beyond it (a corner of theirs
  // off the edge; NaN for a free edge): the outward normals of both faces, or none where the edge is not convex (or
  // folds back on itself). A free edge turns as a 90-degree edge would, its second face the plane across the sheet's
  // rim: a lip of radius rho curving behind the sheet, within its outline.
  const Vector3r outward = -face_.normal;
  const Vector3r inside = (corners[0] + corners[1] + corners[2]) / 3;
  auto rounding = [&](const Vector3r& a, const Vector3r& b, const Vector3r& beyond) -> std::optional<RoundedFeature> {
    if (!(edgeRadius > 0)) return std::nullopt;
    Vector3r other = (beyond.allFinite() ? (b - a).cross(beyond - a) : (b - a).cross(outward)).normalized();
    if (other.dot(inside - a) > 0) other = -other;
    const Real cosine = outward.dot(other);
    if (!(1 + cosine > kFoldedBack)) return std::nullopt;
    const Vector3r axisOffset = edgeRadius * (outward + other) / (1 + cosine);
    return RoundedFeature{a - axisOffset, b - axisOffset, edgeRadius, {outward, other}};
  };
  const int n = static_cast<int>(facet.outline.size());
  std::vector<Vector2r> outlineCorners;
  std::vector<bool> open;
  std::vector<Real> inset, slack;
  outlineCorners.reserve(n);
  open.reserve(n);
  inset.reserve(n);
  slack.reserve(n);
  for (int k = 0; k < n; ++k) {
    outlineCorners.push_back(faceCoordinates(face_, facet.outline[k]));
    open.push_back(!weld->outlineClosed[k][side]);
    const std::optional<RoundedFeature> strip =
        open.back() ? rounding(facet.outline[k], facet.outline[(k + 1) % n], facet.outlineBeyond[k]) : std::nullopt;
    // The face stops where the strip's cylinder touches it: rho tan(theta / 2) short of the edge.
    inset.push_back(strip ? edgeRadius * strip->faceNormals[0].cross(strip->faceNormals[1]).norm() /
                                (1 + strip->faceNormals[0].dot(strip->faceNormals[1]))
                          : 0);
    // A cap comes round a rounded edge only past the rounding's axis.
    slack.push_back(strip ? (strip->start - facet.outline[k]).norm() : 0);
  }
  // The outline turns counter-clockwise about the normal, so clockwise about n12 on side 0.
  if (side == 0) {
    std::reverse(outlineCorners.begin(), outlineCorners.end());
    auto reverseEdges = [](auto& edges) {  // edge i ran from corner i to i + 1
      std::reverse(edges.begin(), edges.end());
      std::rotate(edges.begin(), edges.begin() + 1, edges.end());
    };
    reverseEdges(open);
    reverseEdges(inset);
    reverseEdges(slack);
  }
  outline_.emplace(std::move(outlineCorners), std::move(open), std::move(inset), std::move(slack));
  face_.faceOutline = &*outline_;
  // A panel's member keeps the contacts whose c_eff it holds, and tests only the caps over itself.
  own_ = {faceCoordinates(face_, corners[0]), faceCoordinates(face_, corners[1]), faceCoordinates(face_, corners[2])};
  if (weld->panelSize > 1) {
    const ConvexPolygon ownTriangle = ConvexPolygon::triangle(own_[0], own_[1], own_[2]);  // counter-clockwise
    ownOutline_.emplace(std::vector<Vector2r>{ownTriangle[0], ownTriangle[1], ownTriangle[2]});
    face_.owns = [this, weld](const Vector2r& p) { return facetOwns(own_, *weld, p); };
    face_.owned = &*ownOutline_;
  }
  for (int e = 0; e < 3; ++e)
    if (weld->ownsStrip[e] && !weld->edgeClosed[e][side])
      strips_[e] = rounding(corners[e], corners[(e + 1) % 3], facet.beyond[e]);
}

}  // namespace

void facetCandidates(const RoundedMesh& mesh, const PlacedFacet& facet, int side, Real edgeRadius, Real margin,
                     FacetCandidates& candidates) {
  candidates.side = side;
  candidates.face.clear();
  for (std::vector<int>& strip : candidates.strips) strip.clear();
  if (!hasArea(facet.corners)) return;
  const FacetSurfaces surfaces(facet, side, edgeRadius);
  faceCandidates(mesh, surfaces.face(), margin, candidates.face);
  for (int e = 0; e < 3; ++e)
    if (surfaces.strip(e)) featureCandidates(mesh, *surfaces.strip(e), margin, candidates.strips[e]);
}

void Ig2_RoundedMesh_Facet_PressureGeom(const RoundedMesh& mesh, const PlacedFacet& facet, Real edgeRadius,
                                        const RelativeMotion& motion, GeomOutput out, CurvatureModel model,
                                        const FacetCandidates* candidates) {
  if (!hasArea(facet.corners)) return;  // a sliver with collinear corners: no plane, nothing to push with
  if (candidates && candidates->empty()) return;
  // n12 points from the body (its centre is body 1's origin) into the facet.
  const int side = candidates ? candidates->side : facetSide(facet);
  if (!treeMayReach(mesh, facet, towardFacet(facet, side), edgeRadius)) return;
  const FacetSurfaces surfaces(facet, side, edgeRadius);
  faceGeometry(mesh, surfaces.face(), motion, out, model, candidates ? &candidates->face : nullptr);
  for (int e = 0; e < 3; ++e)
    if (surfaces.strip(e))
      featureGeometry(mesh, *surfaces.strip(e), motion, out, model, candidates ? &candidates->strips[e] : nullptr);
}

}  // namespace roundedmesh
