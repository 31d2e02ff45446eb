// Contact geometry of one rounded triangle of body 1 against a sphere of body 2 (Appendix B): either the
// encompassing sphere of a rounded triangle of body 2 (triangle-triangle contact), or a whole analytic
// sphere (a YADE Sphere). All in body 1's frame.
//   facing check (Eq. B.5), first:  n1 . (s2 - s1) > 0  and, for a triangle,  n2 . (s1 - s2) > 0
//   overlap (Eq. 10):               delta_s = R1 + R2 - |s2 - s1|,  n12 = (s2 - s1) / |s2 - s1|
//   contact plane:                  the spheres' radical plane, through c = s1 + x n12 with
//                                   x = (d^2 + R1^2 - R2^2) / (2 d): where the two sphere surfaces cross,
//                                   and the foot of s1 on the partner in the limit R2 -> infinity (a plane)
//   combined radius (Eq. 3):        R* = R1 R2 / (R1 + R2),  contact circle (Eq. 5): a = sqrt(delta_s R*)
//   polygon S:                      the orthogonal projection P' of triangle 1, intersected with Q' of
//                                   triangle 2 (3 to 6 corners; empty if they only touch)
//   c_eff, h:                       the point of S closest to c, h = |c_eff - c|
//   effective overlap (Eq. B.4):    delta_eff = delta_s - R1 - R2 + sqrt(R1^2 - h^2) + sqrt(R2^2 - h^2)
// Rejects the candidate (leaving geom unspecified) unless the contact circle meets S (h < a): only then can
// the pressure of Eq. 9 act. h < a < sqrt(2 R* delta_s) keeps delta_eff > 0 for overlaps small beside the radii.
#pragma once

#include <array>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

// Body 2's sphere in body 1's frame. For a rounded triangle: its outward normal and corners, and its index.
struct ContactSphere {
  Vector3r centre;
  Real radius;
  int triangle = -1;                   // -1: a whole sphere, no facing check, S = P'
  Vector3r normal = Vector3r::Zero();  // the triangle's outward normal
  std::array<Vector3r, 3> corners;     // the triangle's corners, in body 2's mesh order
  const RoundedMesh* mesh = nullptr;   // for a triangle: body 2's mesh, placed by rotation and translation
  Matrix3r rotation = Matrix3r::Identity();
  Vector3r translation = Vector3r::Zero();
};

// Body 2's rounded triangle t, moved into body 1's frame by x1 = rotation * x2 + translation.
ContactSphere contactSphere(const RoundedMesh& mesh2, int t, const Matrix3r& rotation, const Vector3r& translation);

// Body 2's rounded triangle as it lies in its own mesh, with the pose that places it in body 1's frame
// (x1 = rotation * x2 + translation): what the engine's hot path passes, so that the corners are moved only
// for candidates that pass the facing, overlap and circle tests.
struct PlacedTriangle {
  const RoundedMesh& mesh;
  int triangle;
  const Matrix3r& rotation;
  const Vector3r& translation;
};

// With CurvatureModel::Principal a contact the circle accepts then takes the ellipse of EllipticalContact.hpp.
GeomTest triangleSphereGeom(const RoundedMesh& mesh, int triangle, const ContactSphere& sphere,
                            const RelativeMotion& motion, PressureGeom& geom,
                            CurvatureModel model = CurvatureModel::Mean);
GeomTest triangleSphereGeom(const RoundedMesh& mesh, int triangle, const PlacedTriangle& partner,
                            const RelativeMotion& motion, PressureGeom& geom,
                            CurvatureModel model = CurvatureModel::Mean);

// triangleSphereGeom of a triangle partner in two stages around S; together they give triangleSphereGeom's result and
// geom bit for bit. They are the references of the batched narrow phase's lanes (TrianglePlanes.hpp,
// PolygonContacts.hpp), and the batched narrow phase takes the second for a lane whose S overflows and for ellipses.
//   trianglePlane: the tests before S, and the contact plane; P' -> geom.polygon, Q's corners -> geom.partnerNodes.
//   triangleContactOnPolygon: with S = P' ∩ Q' in geom.polygon and, if S is not empty, its point closest to c in
//   geom.effectivePoint: the rest.
GeomTest trianglePlane(const RoundedMesh& mesh, int triangle, const PlacedTriangle& partner, PressureGeom& geom);
GeomTest triangleContactOnPolygon(const RoundedMesh& mesh, int triangle, const PlacedTriangle& partner,
                                  const RelativeMotion& motion, PressureGeom& geom, CurvatureModel model);

// Q' of a triangle partner, as S is clipped by it: the triangle of geom.partnerNodes.
inline ConvexPolygon partnerPolygon(const PressureGeom& geom) {
  return ConvexPolygon::triangle(geom.partnerNodes[0], geom.partnerNodes[1], geom.partnerNodes[2]);
}

// Between the two stages, one candidate at a time: S = P' ∩ Q' -> geom.polygon and, if S is not empty, its point
// closest to c -> geom.effectivePoint.
void clipByPartner(PressureGeom& geom);

}  // namespace roundedmesh
