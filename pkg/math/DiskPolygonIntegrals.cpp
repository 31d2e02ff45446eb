#include "pkg/math/DiskPolygonIntegrals.hpp"

#include <algorithm>
#include <cmath>

namespace roundedmesh {
namespace {

Real angleBetween(const Vector2r& u, const Vector2r& v) { return std::atan2(cross2(u, v), u.dot(v)); }

// The antiderivatives along an edge's line, in its coordinate s from the foot of the origin, h its signed
// distance, A = a^2 - h^2 > 0, w = sqrt(A - s^2), for |s| <= sqrt(A):
//   arc     asin(s / sqrt(A))
//   p3      integral of w^3 ds            = (s / 8)(5 A - 2 s^2) w + (3 A^2 / 8) arc
//   cone1   h times the integral of w^3 / (h^2 + s^2) ds
//           = a^3 sgn(h) atan2(a s, |h| w) - h (a^2 + A / 2) arc - h s w / 2
//   cone2   h times the integral of w^5 / (h^2 + s^2) ds = a^2 cone1 - h p3
// (w^3 / (h^2 + s^2) = a^2 w / (h^2 + s^2) - w and w / (h^2 + s^2) = a^2 / ((h^2 + s^2) w) - 1 / w, with
// integral of ds / ((h^2 + s^2) w) = atan(a s / (|h| w)) / (|h| a).)
struct EdgeTerms {
  Real cone1, cone2, p3;
};

Real arcOf(Real A, Real s) { return std::asin(std::clamp(s / std::sqrt(A), Real(-1), Real(1))); }

Real p3(Real A, Real s, Real w, Real arc) { return s / 8 * (5 * A - 2 * s * s) * w + 3 * A * A / 8 * arc; }

EdgeTerms edgeTerms(Real a, Real h, Real A, Real s, Real w) {
  const Real arc = arcOf(A, s);
  const Real sign = h > 0 ? 1 : h < 0 ? -1 : 0;
  const Real cone1 = a * a * a * sign * std::atan2(a * s, std::abs(h) * w) - h * (a * a + A / 2) * arc - h * s * w / 2;
  const Real along = p3(A, s, w, arc);
  return {cone1, a * a * cone1 - h * along, along};
}

// The triangle (origin, p, q) cut by the disc, signed: adds to `sum`.
void addTriangle(const Vector2r& p, const Vector2r& q, Real a, DiskPolygonIntegrals& sum) {
  const Vector2r d = q - p;
  const Real length = d.norm();
  if (length == 0) return;
  const Real a3 = a * a * a / 3, a5 = a3 * a * a * 3 / 5;
  // Points p + t d on the circle: as in CirclePolygonArea.cpp.
  const Real b = p.dot(d), c = p.squaredNorm() - a * a, lengthSq = length * length;
  const Real discriminant = b * b - lengthSq * c;
  const Real root = discriminant > 0 ? std::sqrt(discriminant) : 0;
  const Real tIn = std::max((-b - root) / lengthSq, Real(0));
  const Real tOut = std::min((-b + root) / lengthSq, Real(1));
  if (discriminant <= 0 || tIn >= tOut) {  // the edge stays outside: a sector of F(a) = a^3/3 (and a^5/5)
    const Real angle = angleBetween(p, q);
    sum.pressure += a3 * angle;
    sum.energy += a5 * angle;
    return;
  }
  const Vector2r enter = p + tIn * d, leave = p + tOut * d;
  const Real outside = (tIn > 0 ? angleBetween(p, enter) : 0) + (tOut < 1 ? angleBetween(leave, q) : 0);
  sum.pressure += a3 * outside;
  sum.energy += a5 * outside;
  const Vector2r t = d / length;
  const Real h = cross2(p, t);  // > 0: the origin lies to the edge's left
  const Real A = a * a - h * h;
  if (!(A > 0)) return;  // the line only touches the circle
  // Where the edge crosses the circle, s = -+sqrt(A) and w = 0 exactly: sqrt(A - s^2) of a rounded s would be
  // about sqrt(1e-16) a, an error of 1e-8 in the atan2 and w terms. Elsewhere w is well conditioned.
  const Real halfChord = std::sqrt(A);
  const Real s0 = tIn > 0 ? -halfChord : enter.dot(t), s1 = tOut < 1 ? halfChord : leave.dot(t);
  auto w = [&](Real s) { return std::sqrt(std::max((halfChord - s) * (halfChord + s), Real(0))); };
  const EdgeTerms e0 = edgeTerms(a, h, A, s0, tIn > 0 ? 0 : w(s0)), e1 = edgeTerms(a, h, A, s1, tOut < 1 ? 0 : w(s1));
  // The inside part: integral over its angle of F(rho), F(rho) = (a^3 - w(rho)^3) / 3 (and (a^5 - w^5) / 5);
  // d(angle) = h ds / (h^2 + s^2), so the angle is sgn(h) atan2(s, |h|) between the ends, taken from s rather than
  // from the points: for a line through the origin up to round-off, the angle and the atan2 term of cone1 both jump
  // by pi at s = 0 and must cancel. An edge through the origin (h = 0) sweeps no area.
  const Real angle = (h > 0 ? 1 : h < 0 ? -1 : 0) * (std::atan2(s1, std::abs(h)) - std::atan2(s0, std::abs(h)));
  sum.pressure += a3 * angle - (e1.cone1 - e0.cone1) / 3;
  sum.energy += a5 * angle - (e1.cone2 - e0.cone2) / 5;
  const Vector2r outward(t.y(), -t.x());
  sum.pressureMoment -= outward * (e1.p3 - e0.p3) / 3;
}

}  // namespace

SegmentIntegrals segmentIntegrals(Real radius, const Vector2r& A, const Vector2r& B, Real l0, Real l1) {
  SegmentIntegrals sum;
  const Vector2r d = B - A;
  const Real length = d.norm();
  if (!(length > 0) || !(l1 > l0) || !(radius > 0)) return sum;
  const Vector2r t = d / length;
  const Real h = cross2(A, t), along = A.dot(t);  // x = foot + s t, s = along + l length
  const Real chordSq = radius * radius - h * h;
  if (!(chordSq > 0)) return sum;
  const Real halfChord = std::sqrt(chordSq);
  const Real s0 = std::max(along + l0 * length, -halfChord), s1 = std::min(along + l1 * length, halfChord);
  if (!(s1 > s0)) return sum;
  auto w = [&](Real s) { return std::sqrt(std::max((halfChord - s) * (halfChord + s), Real(0))); };
  const Real w0 = s0 == -halfChord ? 0 : w(s0), w1 = s1 == halfChord ? 0 : w(s1);
  // At the circle's crossings the arc is -+pi/2 exactly (w = 0 there).
  const Real arc0 = w0 == 0 ? -M_PI / 2 : arcOf(chordSq, s0), arc1 = w1 == 0 ? M_PI / 2 : arcOf(chordSq, s1);
  sum.energy = p3(chordSq, s1, w1, arc1) - p3(chordSq, s0, w0, arc0);
  // integral of s w^3 ds = -w^5 / 5; l = (s - along) / length. (w^5 by products: std::pow costs a library call.)
  auto fifth = [](Real w) { return w * w * w * w * w; };
  const Real sMoment = (fifth(w0) - fifth(w1)) / 5;
  sum.energyMoment = (sMoment - along * sum.energy) / length;
  return sum;
}

DiskPolygonIntegrals diskPolygonIntegrals(Real radius, const ConvexPolygon& polygon) {
  DiskPolygonIntegrals sum;
  if (polygon.empty() || !(radius > 0)) return sum;
  for (int i = 0; i < polygon.size(); ++i) addTriangle(polygon[i], polygon[(i + 1) % polygon.size()], radius, sum);
  // Round-off may leave a tiny negative integral for a polygon that barely meets the disc.
  sum.pressure = std::max(sum.pressure, Real(0));
  sum.energy = std::max(sum.energy, Real(0));
  return sum;
}

}  // namespace roundedmesh
