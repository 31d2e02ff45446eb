#include "pkg/geom/Ig2_RoundedMesh_Facet_PressureGeom.hpp"

#include <algorithm>

namespace roundedmesh {
namespace {

// Distance from p to the segment from a to b.
Real segmentDistance(const Vector2r& p, const Vector2r& a, const Vector2r& b) {
  const Real along = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), Real(0), Real(1));
  return (p - (a + along * (b - a))).norm();
}

}  // namespace

bool facetOwns(const std::array<Vector2r, 3>& corners, const FacetWeld& weld, const Vector2r& p) {
  Real size = 0;
  for (int i = 0; i < 3; ++i) size = std::max(size, (corners[(i + 1) % 3] - corners[i]).norm());
  const Real on = 1e-9 * size;
  for (int i = 0; i < 3; ++i)
    if ((p - corners[i]).norm() <= on) return weld.ownsCorner[i];
  for (int i = 0; i < 3; ++i)
    if (segmentDistance(p, corners[i], corners[(i + 1) % 3]) <= on) return weld.ownsEdge[i];
  const Real orientation = cross2(corners[1] - corners[0], corners[2] - corners[0]);
  for (int i = 0; i < 3; ++i)
    if (!(cross2(corners[(i + 1) % 3] - corners[i], p - corners[i]) * orientation > 0)) return false;
  return true;
}

void Ig2_RoundedMesh_Facet_PressureGeom(const RoundedMesh& mesh, const PlacedFacet& facet, const RelativeMotion& motion,
                                        GeomOutput out, CurvatureModel model) {
  const std::array<Vector3r, 3>& corners = facet.corners;
  const Vector3r normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalized();
  // The body's side (FacetWeld's side 0: that of the normal of the corners' order); n12 points from the body (its
  // centre is body 1's origin) into the facet.
  const int side = normal.dot(corners[0]) > 0 ? 1 : 0;
  ContactFace face;
  face.origin = corners[0];
  face.normal = side == 1 ? normal : Vector3r(-normal);
  face.tangent1 = face.normal.unitOrthogonal();
  face.tangent2 = face.normal.cross(face.tangent1);
  face.sheet = true;
  FaceOutline outline;
  const FacetWeld* weld = facet.weld;
  if (weld) {
    for (const Vector3r& x : facet.outline) outline.corners.push_back(faceCoordinates(face, x));
    for (const SidePair& closed : weld->outlineClosed) outline.open.push_back(!closed[side]);
    // The outline turns counter-clockwise about the normal, so clockwise about n12 on side 0.
    if (side == 0) {
      std::reverse(outline.corners.begin(), outline.corners.end());
      std::reverse(outline.open.begin(), outline.open.end());
      std::rotate(outline.open.begin(), outline.open.begin() + 1, outline.open.end());
    }
  } else {
    const ConvexPolygon triangle = ConvexPolygon::triangle(
        faceCoordinates(face, corners[0]), faceCoordinates(face, corners[1]), faceCoordinates(face, corners[2]));
    for (int i = 0; i < 3; ++i) outline.corners.push_back(triangle[i]);
  }
  face.faceOutline = &outline;
  if (weld && weld->panelSize > 1) {
    const std::array<Vector2r, 3> own{faceCoordinates(face, corners[0]), faceCoordinates(face, corners[1]),
                                      faceCoordinates(face, corners[2])};
    face.owns = [&own, weld](const Vector2r& p) { return facetOwns(own, *weld, p); };
  }
  faceGeometry(mesh, face, motion, out, model);
}

}  // namespace roundedmesh
