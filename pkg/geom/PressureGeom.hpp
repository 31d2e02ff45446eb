// IGeom of one rounded triangle of body 1 against a partner (Section 2.3, Appendix B), in the frame of
// body 1. The contact plane has origin c (centre of the contact circle), unit normal n12 pointing from
// body 1 to body 2, and in-plane axes t1, t2 with t1 x t2 = n12; plane coordinates are taken relative to c.
// An elliptical contact (EllipticalContact.hpp) also carries the map y = T (x - x*) that takes its ellipse to
// a circle of radius contactRadius; radius and sphereOverlap are then those for which Eq. 9 on that circle is
// Hertz's elliptical pressure.
#pragma once

#include <array>
#include <vector>

#include "pkg/math/ConvexPolygon.hpp"

namespace roundedmesh {

struct PressureGeom {
  int triangle;                  // index of the triangle in body 1's mesh
  int partnerTriangle = -1;      // index of the triangle in body 2's mesh; -1 if body 2 is not a mesh
  Vector3r centre;               // c [m]
  Vector3r normal;               // n12
  Vector3r tangent1, tangent2;   // t1, t2
  Real radius;                   // combined radius of curvature R* (Eq. 3) [m]
  Real sphereOverlap;            // delta_s, overlap of the encompassing spheres (Eq. 10) [m]
  Real overlapRate;              // d(delta_s)/dt at c, positive while approaching [m/s]
  Vector2r overlapRateSlope = Vector2r::Zero();  // its gradient over the plane: at plane point x the two sides
                                                 // approach at overlapRate + overlapRateSlope . x [1/s]
  Real contactRadius;            // a = sqrt(delta_s R*) (Eq. 5) [m]
  ConvexPolygon polygon;         // S: the projected triangle(s), intersected (Fig. 2)
  std::array<Vector2r, 3> nodes;         // body 1's triangle corners projected on the plane, in mesh order
  std::array<Vector2r, 3> partnerNodes;  // body 2's, when body 2 is a mesh
  Vector2r effectivePoint;       // c_eff: the point of S closest to c
  Real effectiveOverlap;         // delta_eff (Eq. B.4) [m]
  Vector3r slip;                 // tangential velocity of body 2 relative to body 1 at c_eff [m/s]
  bool elliptical = false;       // curvature='principal': the pressure is Hertz's elliptical one
  Vector2r ellipseCentre = Vector2r::Zero();     // x*, in plane coordinates [m]
  Matrix2r toCircle = Matrix2r::Identity();      // T, det T = 1
};

// How a contact's curvature is modelled: the paper's one mean radius per triangle (a circle), or both principal
// curvatures (an ellipse; EllipticalContact.hpp).
enum class CurvatureModel { Mean, Principal };

// S where the pressure is circular, about its centre: T (x - x*) for an elliptical contact, S itself otherwise.
inline ConvexPolygon circlePolygon(const PressureGeom& geom) {
  if (!geom.elliptical) return geom.polygon;
  ConvexPolygon mapped;
  for (int i = 0; i < geom.polygon.size(); ++i) mapped.push(geom.toCircle * (geom.polygon[i] - geom.ellipseCentre));
  return mapped;
}

// How the narrow phase of one candidate ended: a contact, or the first of its tests (Appendix B, in the order
// they run, then the deep-contact criterion of DeepContactCriterion.hpp) that rejected it. Converts to true for a contact.
enum class Rejection { None, NotFacing, NoOverlap, OutsideCircle, EmptyPolygon, BeyondContactCircle, ThroughBody };

struct GeomTest {
  Rejection rejection;
  explicit operator bool() const { return rejection == Rejection::None; }
};

// The funnel of the narrow phase: candidates tested, and how many each test rejected.
struct NarrowPhaseCounts {
  long candidates = 0;
  long notFacing = 0;
  long noOverlap = 0;
  long outsideCircle = 0;
  long emptyPolygon = 0;
  long beyondContactCircle = 0;
  long throughBody = 0;

  void count(GeomTest result) {
    ++candidates;
    switch (result.rejection) {
      case Rejection::None: break;
      case Rejection::NotFacing: ++notFacing; break;
      case Rejection::NoOverlap: ++noOverlap; break;
      case Rejection::OutsideCircle: ++outsideCircle; break;
      case Rejection::EmptyPolygon: ++emptyPolygon; break;
      case Rejection::BeyondContactCircle: ++beyondContactCircle; break;
      case Rejection::ThroughBody: ++throughBody; break;
    }
  }
  NarrowPhaseCounts& operator+=(const NarrowPhaseCounts& o) {
    candidates += o.candidates;
    notFacing += o.notFacing;
    noOverlap += o.noOverlap;
    outsideCircle += o.outsideCircle;
    emptyPolygon += o.emptyPolygon;
    beyondContactCircle += o.beyondContactCircle;
    throughBody += o.throughBody;
    return *this;
  }
};

// The Ig2 functors' output: the triangle contacts found, and the funnel counts of every candidate tested.
struct GeomOutput {
  GeomOutput(std::vector<PressureGeom>& found, NarrowPhaseCounts* funnel = nullptr) : geoms(found), counts(funnel) {}

  std::vector<PressureGeom>& geoms;
  NarrowPhaseCounts* counts;

  void add(GeomTest result, const PressureGeom& geom) {
    if (counts) counts->count(result);
    if (result) geoms.push_back(geom);
  }
};

// Velocity of body 2's material relative to body 1's at a point x of body 1's frame: linear + angular x x.
struct RelativeMotion {
  Vector3r linear = Vector3r::Zero();
  Vector3r angular = Vector3r::Zero();
  Vector3r at(const Vector3r& x) const { return linear + angular.cross(x); }
};

// A point of the contact plane in body 1's frame.
inline Vector3r planePoint(const PressureGeom& geom, const Vector2r& p) {
  return geom.centre + p.x() * geom.tangent1 + p.y() * geom.tangent2;
}

// How fast the two sides approach at plane point x [m/s]: rigid motions make it affine over the plane.
inline Real overlapRateAt(const PressureGeom& geom, const Vector2r& x) {
  return geom.overlapRate + geom.overlapRateSlope.dot(x);
}

// Fills overlapRate (at c) with its slope over the plane, and slip (at c_eff), once the plane and c_eff are known.
inline void setRelativeVelocity(PressureGeom& geom, const RelativeMotion& motion) {
  geom.overlapRate = -geom.normal.dot(motion.at(geom.centre));
  geom.overlapRateSlope = Vector2r(-geom.normal.dot(motion.angular.cross(geom.tangent1)),
                                   -geom.normal.dot(motion.angular.cross(geom.tangent2)));
  const Vector3r v = motion.at(planePoint(geom, geom.effectivePoint));
  geom.slip = v - v.dot(geom.normal) * geom.normal;
}

}  // namespace roundedmesh
