// Contact geometry of one rounded triangle against a flat, rigid-shaped partner face (Appendix B with the
// partner's radius R2 -> infinity): the contact plane is the face itself and c is the foot of the
// encompassing sphere's centre on it.
//   facing check (Eq. B.5):  n_triangle . n12 > 0
//   overlap (Eq. 10):        delta_s = R - dist(sphere centre, plane)
//   contact circle (Eq. 5):  a = sqrt(delta_s R)
//   polygon S:               projected triangle, clipped to the face when the face is finite
//   effective overlap (B.4): delta_eff = delta_s - R + sqrt(R^2 - h^2), h = |c_eff - c|
// Rejects the candidate (leaving geom unspecified) unless the contact circle meets S (h < a): only then can
// the pressure of Eq. 9 act on the triangle.
#pragma once

#include <array>
#include <functional>
#include <limits>
#include <vector>

#include "pkg/geom/PressureGeom.hpp"
#include "pkg/shape/RoundedMesh.hpp"

namespace roundedmesh {

// The outline of a finite face: corners counter-clockwise about n12, in (t1, t2) coordinates relative to the face's
// origin; for a sheet, whether a cap can come round each edge (corners i, i + 1): a free or convex edge, not a seam
// where the surface goes on toward the body (FacetSurface.hpp); and where a rounded edge trims the face.
struct FaceOutline {
  explicit FaceOutline(std::vector<Vector2r> corners, std::vector<bool> open = {}, std::vector<Real> inset = {},
                       std::vector<Real> slack = {});

  std::vector<Vector2r> corners;
  std::vector<bool> open;    // empty: every edge
  std::vector<Real> inset;   // how far S stops short of each edge [m] (a rounded edge takes over there); empty: 0
  std::vector<Real> slack;   // for the sheet rule, how much farther a cap must reach to come round each edge [m]:
                             // the depth of a rounded edge's axis behind it; empty: 0
  // Each edge moved in by its inset, from -> to, and its line: x is inside where inward . x >= offset.
  struct Line {
    Vector2r from, to, inward;
    Real offset;
  };
  std::vector<Line> lines;
};

// A face of the partner in body 1's frame: a point on it, the normal n12 pointing into the partner, and
// in-plane axes with t1 x t2 = n12. faceOutline, if given, bounds a finite face. A sheet (a Facet: zero thickness)
// has nothing behind it: see faceGeometry. owns, if set, keeps only the contacts whose c_eff (in outline
// coordinates) it holds: the face is a panel of several facets, each computing the panel's contacts and keeping
// its own.
struct ContactFace {
  Vector3r origin;
  Vector3r normal;
  Vector3r tangent1, tangent2;
  const FaceOutline* faceOutline = nullptr;
  bool sheet = false;
  std::function<bool(const Vector2r&)> owns;
  const FaceOutline* owned = nullptr;  // with owns: a convex region (outline coordinates) holding every point it keeps,
                                       // so that only caps over it are tested
};

// A point x of the face's plane in the (t1, t2) coordinates of its outline, relative to its origin.
inline Vector2r faceCoordinates(const ContactFace& face, const Vector3r& x) {
  return Vector2r((x - face.origin).dot(face.tangent1), (x - face.origin).dot(face.tangent2));
}

// With CurvatureModel::Principal a contact the circle accepts then takes the ellipse of EllipticalContact.hpp.
GeomTest trianglePlaneGeom(const RoundedMesh& mesh, int triangle, const ContactFace& face,
                           const RelativeMotion& motion, PressureGeom& geom,
                           CurvatureModel model = CurvatureModel::Mean);

// Every flat partner's Ig2 (a Plane or Wall, a Facet, each face of a Box; doc/physics.md, "What each partner's
// surface is"): trianglePlaneGeom for each triangle whose cap box reaches the face's plane (crosses it) and, for a
// finite face, meets the prism over its outline. One culling for all, so that a Wall, a Facet and a Box face
// give the same triangle contacts wherever the contact lies inside the face. Behind a sheet there is no solid, only
// its other side: a triangle's cap behind a sheet's plane touches the sheet only where the body reaches through it,
// the path along n12 from the triangle (behind the sheet) to the sheet's point c_eff running inside the body
// (pathInsideBody, DeepContactCriterion.hpp); elsewhere the cap has gone past the sheet's edge on another side of it
// (a body resting on one face of a ridge of Facets, or wrapped around it), and the candidate is rejected as
// ThroughBody. So is a cap deeper behind a sheet than c_eff lies from the sheet's nearest open edge: the cap has come
// round the edge (a lifter's ridge cutting into a body straddling it), and moving it past the edge parts it from the
// sheet sooner than pushing it back through. A seam where the surface goes on toward the body is no such edge, and a
// cap whose c_eff lies farther from every open edge than the body is wide cannot have come round one: its path is not
// asked for (a body pressed deep into a large Facet, or into a drum's wall, meets it as a Wall).
// With `candidates`, only those of the candidates that the culling passes, in their order: the same contacts as the
// tree's query when the candidates hold every triangle it visits, in the tree's order (faceCandidates).
void faceGeometry(const RoundedMesh& mesh, const ContactFace& face, const RelativeMotion& motion, GeomOutput out,
                  CurvatureModel model = CurvatureModel::Mean, const std::vector<int>* candidates = nullptr);

// faceGeometry's culling: whether a triangle's box may hold a cap it tests. With a margin [m], whether it may once the
// face has moved relative to the body so that no point of the box moves by more than the margin: each test's plane or
// line is moved out by it (a box meets a half-space exactly where its farthest corner along the normal does, so that
// test stays exact in any frame), and the prism's box, taken in the body's frame, is left out (it turns with the face).
class FaceReach {
 public:
  FaceReach(const RoundedMesh& mesh, const ContactFace& face, Real margin);
  bool operator()(const AlignedBox3r& box) const { return reaches(box, 0); }
  // A node of the tree passes where a box it holds may: each test is exact for a box, up to round-off, which a
  // billionth of the body's size covers.
  bool node(const AlignedBox3r& box) const { return reaches(box, nodeSlack_); }

 private:
  bool reaches(const AlignedBox3r& box, Real slack) const;

  static constexpr int kRegionSides = 8;
  // An edge line of the face's region in body 1's frame: a box reaches inside it where its farthest corner along
  // `inward` does, inward . centre + spread . half-sizes >= offset (spread = |inward| componentwise).
  struct RegionSide {
    Vector3r inward, spread;
    Real offset;
  };
  Vector3r normal_, origin_;
  Real margin_, nodeSlack_;
  Real deepest_ = std::numeric_limits<Real>::infinity();  // how far behind the plane a kept cap's box can lie
  AlignedBox3r prism_{Vector3r::Constant(-std::numeric_limits<Real>::infinity()),
                      Vector3r::Constant(std::numeric_limits<Real>::infinity())};
  std::array<RegionSide, kRegionSides> sides_;
  int sideCount_ = 0;
};

inline bool FaceReach::reaches(const AlignedBox3r& box, Real slack) const {
  const Vector3r centre = box.center(), half = 0.5 * box.sizes();
  const Real behind = normal_.dot(centre - origin_);
  const Real across = normal_.cwiseAbs().dot(half);
  const Real out = margin_ + slack;
  if (!(behind > -across - out && behind - across <= deepest_ + out)) return false;
  // The prism's AABB is taken in the body's frame: it turns with the face, and is left out of a margin's test.
  if (margin_ == 0 && !box.intersects(prism_)) return false;
  for (int i = 0; i < sideCount_; ++i)
    if (sides_[i].inward.dot(centre) + sides_[i].spread.dot(half) < sides_[i].offset - slack) return false;
  return true;
}

// The triangles of the body whose boxes pass FaceReach with `margin` [m], in the order of the tree's query: while no
// point of the body's tree moves by more than the margin relative to the face, faceGeometry over them finds what it
// finds over the whole tree.
void faceCandidates(const RoundedMesh& mesh, const ContactFace& face, Real margin, std::vector<int>& triangles);

}  // namespace roundedmesh
