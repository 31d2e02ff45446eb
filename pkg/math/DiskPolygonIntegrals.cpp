#include "pkg/math/DiskPolygonIntegrals.hpp"

#include <algorithm>
#include <cmath>

namespace roundedmesh {
namespace {

// The edge p + t (q - p), t in [0, 1], against the disc of radius a about the origin: its part inside, and along
// its line, in the coordinate s from the foot of the origin (x = foot + s unit), h the origin's signed distance
// (> 0: the origin lies to the edge's left), A = a^2 - h^2, w = sqrt(a^2 - r^2) = sqrt(A - s^2) for |s| <= sqrt(A):
//   arc  asin(s / sqrt(A)) = atan2(s, w)
//   p3   integral of w^3 ds = (s / 8)(5 A - 2 s^2) w + (3 A^2 / 8) arc.
struct EdgeInDisc {
  bool inside = false;  // whether part of it lies inside the circle (a chord of positive length)
  Real length = 0;      // |q - p|
  Vector2r unit = Vector2r::Zero();
  Real h = 0, A = 0;
  Real sP = 0, sQ = 0;  // s at p and q
  Real s0 = 0, s1 = 0;  // s at the inside part's ends
  Real w0 = 0, w1 = 0;  // w there
  Real arc = 0;         // arc(s1) - arc(s0), in [0, pi]
  Real energy = 0;      // integral of w^3 ds from s0 to s1 [m^4]
};

EdgeInDisc edgeInDisc(const Vector2r& p, const Vector2r& q, Real a) {
  EdgeInDisc e;
  const Vector2r d = q - p;
  e.length = d.norm();
  if (!(e.length > 0)) return e;
  // Points p + t d on the circle: as in CirclePolygonArea.cpp.
  const Real b = p.dot(d), c = p.squaredNorm() - a * a, lengthSq = e.length * e.length;
  const Real discriminant = b * b - lengthSq * c;
  if (!(discriminant > 0)) return e;
  const Real root = std::sqrt(discriminant);
  const Real tIn = std::max((-b - root) / lengthSq, Real(0));
  const Real tOut = std::min((-b + root) / lengthSq, Real(1));
  e.unit = d / e.length;
  e.h = cross2(p, e.unit);
  e.A = a * a - e.h * e.h;
  e.inside = tIn < tOut && e.A > 0;  // not where the line only touches the circle
  if (!e.inside) return e;
  // Where the edge crosses the circle, s = -+sqrt(A) and w = 0 exactly: sqrt(A - s^2) of a rounded s would be
  // about sqrt(1e-16) a, an error of 1e-8 in the atan2 and w terms. Elsewhere w is well conditioned.
  const Real halfChord = std::sqrt(e.A);
  auto w = [&](Real s) { return std::sqrt(std::max((halfChord - s) * (halfChord + s), Real(0))); };
  e.sP = p.dot(e.unit);
  e.sQ = q.dot(e.unit);
  e.s0 = tIn > 0 ? -halfChord : e.sP;
  e.s1 = tOut < 1 ? halfChord : e.sQ;
  e.w0 = tIn > 0 ? 0 : w(e.s0);
  e.w1 = tOut < 1 ? 0 : w(e.s1);
  // A difference of two angles as one atan2 of the ends' cross and dot products: atan2(s, w) rises with s (its
  // derivative is 1 / w), so the difference lies in [0, pi] and the cross product is >= 0 but for round-off.
  e.arc = std::atan2(std::abs(e.w0 * e.s1 - e.s0 * e.w1), e.w0 * e.w1 + e.s0 * e.s1);
  auto p3Polynomial = [&](Real s, Real w) { return s / 8 * (5 * e.A - 2 * s * s) * w; };
  e.energy = p3Polynomial(e.s1, e.w1) - p3Polynomial(e.s0, e.w0) + 3 * e.A * e.A / 8 * e.arc;
  return e;
}

// The triangle (origin, p, q) cut by the disc, signed: its share of the integrals. Over the angle it spans, the
// integral of F(min(rho, a)), F(rho) = (a^3 - w(rho)^3) / 3 (and (a^5 - w^5) / 5): F(a) times the whole angle, less,
// where the edge runs inside, the integral over its angle of w^3 / 3 (and w^5 / 5); with d(angle) = h ds / (h^2 + s^2),
//   cone1  h times the integral of w^3 / (h^2 + s^2) ds
//          = a^3 sgn(h) atan2(a s, |h| w) - h (a^2 + A / 2) arc - h s w / 2
//   cone2  h times the integral of w^5 / (h^2 + s^2) ds = a^2 cone1 - h p3
// between the ends (w^3 / (h^2 + s^2) = a^2 w / (h^2 + s^2) - w and w / (h^2 + s^2) = a^2 / ((h^2 + s^2) w) - 1 / w,
// with integral of ds / ((h^2 + s^2) w) = atan(a s / (|h| w)) / (|h| a)). The whole angle is that between the
// edge's ends, sgn(h) (atan2(sQ, |h|) - atan2(sP, |h|)), taken from s rather than from the points: for a line
// through the origin up to round-off, it and cone1's atan2 term both jump by pi at s = 0 and must cancel. Both rise
// with s, so each difference of angles is one atan2 in [0, pi], as the arc's. An edge through the origin (h = 0)
// spans no area.
DiskPolygonIntegrals triangleShare(const Vector2r& p, const Vector2r& q, Real a) {
  const Real a3 = a * a * a / 3, a5 = a3 * a * a * 3 / 5;
  const EdgeInDisc e = edgeInDisc(p, q, a);
  DiskPolygonIntegrals share;
  if (!(e.length > 0)) return share;  // a repeated corner spans nothing (atan2 of two signed zeros may give pi)
  if (!e.inside) {  // a sector of F(a) = a^3/3 (and a^5/5)
    const Real angle = std::atan2(cross2(p, q), p.dot(q));
    share.pressure = a3 * angle;
    share.energy = a5 * angle;
    return share;
  }
  const Real sign = e.h > 0 ? 1 : e.h < 0 ? -1 : 0, absH = std::abs(e.h);
  const Real angle = std::atan2(absH * e.length, e.h * e.h + e.sP * e.sQ);
  const Real coneAngle =
      std::atan2(a * absH * std::abs(e.w0 * e.s1 - e.s0 * e.w1), e.h * e.h * e.w0 * e.w1 + a * a * e.s0 * e.s1);
  const Real cone1 =
      a * a * a * sign * coneAngle - e.h * (a * a + e.A / 2) * e.arc - e.h * (e.s1 * e.w1 - e.s0 * e.w0) / 2;
  share.pressure = a3 * sign * angle - cone1 / 3;
  share.energy = a5 * sign * angle - (a * a * cone1 - e.h * e.energy) / 5;
  // The first moments by the divergence theorem (the header): -(1/3) n_e times the integral of w^3 along the edge.
  share.pressureMoment = -Vector2r(e.unit.y(), -e.unit.x()) * (e.energy / 3);
  return share;
}

}  // namespace

EdgeIntegrals edgeIntegrals(Real radius, const Vector2r& P, const Vector2r& Q) {
  if (!(radius > 0)) return {};
  const EdgeInDisc e = edgeInDisc(P, Q, radius);
  if (!e.inside) return {};
  // integral of s w^3 ds = -w^5 / 5; lambda = (s - sP) / length. (w^5 by products: std::pow costs a library call.)
  auto fifth = [](Real w) { return w * w * w * w * w; };
  const Real sMoment = (fifth(e.w0) - fifth(e.w1)) / 5;
  return {e.energy, (sMoment - e.sP * e.energy) / e.length};
}

DiskPolygonIntegrals diskPolygonIntegrals(Real radius, const ConvexPolygon& polygon) {
  DiskPolygonIntegrals sum;
  if (polygon.empty() || !(radius > 0)) return sum;
  for (int i = 0; i < polygon.size(); ++i) {
    const DiskPolygonIntegrals share = triangleShare(polygon[i], polygon[(i + 1) % polygon.size()], radius);
    sum.pressure += share.pressure;
    sum.pressureMoment += share.pressureMoment;
    sum.energy += share.energy;
  }
  // Round-off may leave a tiny negative integral for a polygon that barely meets the disc.
  sum.pressure = std::max(sum.pressure, Real(0));
  sum.energy = std::max(sum.energy, Real(0));
  return sum;
}

}  // namespace roundedmesh
