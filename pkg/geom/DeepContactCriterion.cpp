#include "pkg/geom/DeepContactCriterion.hpp"

#include <algorithm>
#include <cmath>

namespace roundedmesh {
namespace {

// Where the segment from `from` to `to` crosses triangle abc (Moller-Trumbore), as a parameter in (0, 1]; -1 if it
// does not (a segment in the triangle's plane does not pass through it).
Real crossing(const Vector3r& from, const Vector3r& to, const Vector3r& a, const Vector3r& b, const Vector3r& c) {
  const Vector3r d = to - from, e1 = b - a, e2 = c - a;
  const Vector3r h = d.cross(e2);
  const Real det = e1.dot(h);
  if (det == 0) return -1;
  const Real inverse = 1 / det;
  const Vector3r s = from - a;
  const Real u = inverse * s.dot(h);
  if (u < 0 || u > 1) return -1;
  const Vector3r q = s.cross(e1);
  const Real v = inverse * d.dot(q);
  if (v < 0 || u + v > 1) return -1;
  const Real t = inverse * e2.dot(q);
  return t > 0 && t <= 1 ? t : -1;
}

}  // namespace

bool pathInsideBody(const RoundedMesh& mesh, int s, const Vector3r& from, const Vector3r& x) {
  // `from` is often a corner of s (c_eff is often a corner of S): start within s instead, as far from the corner as
  // round-off could blur (1e-6 of the way to its centroid), so that the path starts on s alone, then runs parallel.
  const Triangle& own = mesh.triangles()[s];
  const Vector3r centroid = (mesh.vertices()[own[0]] + mesh.vertices()[own[1]] + mesh.vertices()[own[2]]) / 3;
  const Vector3r shift = 1e-6 * (centroid - from);
  const Vector3r a = from + shift, b = x + shift;
  const AlignedBox3r path = AlignedBox3r(a.cwiseMin(b), a.cwiseMax(b));
  int crossings = 0, last = -1;
  Real lastAt = 0;
  mesh.tree().query([&](const AlignedBox3r& box) { return box.intersects(path); }, [&](int t) {
    if (t == s) return;
    const Triangle& corners = mesh.triangles()[t];
    const Real at = crossing(a, b, mesh.vertices()[corners[0]], mesh.vertices()[corners[1]], mesh.vertices()[corners[2]]);
    if (at < 0) return;
    ++crossings;
    if (at > lastAt) {
      lastAt = at;
      last = t;
    }
  });
  if (crossings % 2 == 0) return true;
  // Out of the flat solid through triangle `last`: still in the rounded one if within its cap (the lens of its
  // sphere beyond its plane).
  const RoundedTriangle& exit = mesh.rounded(last);
  return (x - exit.sphereCentre).squaredNorm() <= exit.radius * exit.radius;
}

bool overlapInsideBoth(const RoundedMesh& mesh1, int s, const PlacedMesh& body2, int t, const PressureGeom& geom) {
  const RoundedTriangle& p = mesh1.rounded(s);
  const RoundedTriangle& q = body2.mesh.rounded(t);
  const Vector3r sphere2 = body2.rotation * q.sphereCentre + body2.translation;
  // The line along n12 through c_eff, offset from the line of centres by `lateral`.
  const Vector3r lateral = planePoint(geom, geom.effectivePoint) - geom.centre;
  const Real hSq = lateral.squaredNorm();
  const Vector3r q1 = p.sphereCentre + lateral + std::sqrt(std::max(p.radius * p.radius - hSq, Real(0))) * geom.normal;
  const Vector3r q2 = sphere2 + lateral - std::sqrt(std::max(q.radius * q.radius - hSq, Real(0))) * geom.normal;
  const Vector3r middle = 0.5 * (q1 + q2);
  return insidePlaced(body2, q1) && insidePlaced(body2, middle) && insideRoundedSolid(mesh1, q2) && insideRoundedSolid(mesh1, middle);
}

}  // namespace roundedmesh
