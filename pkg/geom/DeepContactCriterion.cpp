#include "pkg/geom/DeepContactCriterion.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "pkg/math/SegmentCrossing.hpp"
#include "pkg/shape/TriangleCorners.hpp"

namespace roundedmesh {
namespace {

// How deep in both bodies the middle of a deep pair's segment must lie, as a fraction of its length: a real contact
// at a slant of up to 66 degrees to the bodies' overlap passes (deepAtItsMiddle).
constexpr Real kMiddleDepthFraction = 0.2;

struct Crossing {
  Real at;  // along the path, in (0, 1]
  int triangle;
};

// Where the path from `from`, a point of triangle s, to x crosses the mesh's flat surface (each triangle but s whose
// box meets the path's, tested exactly), in order along it; in a buffer of the thread's, kept between calls.
const std::vector<Crossing>& crossings(const RoundedMesh& mesh, int s, const Vector3r& from, const Vector3r& x,
                                       Vector3r& a, Vector3r& b) {
  const auto own = triangleCorners(mesh, s);
  const Vector3r shift = startWithin(own[0], own[1], own[2], from);
  a = from + shift;
  b = x + shift;
  const AlignedBox3r path = AlignedBox3r(a.cwiseMin(b), a.cwiseMax(b));
  thread_local std::vector<Crossing> found;
  found.clear();
  mesh.tree().query([&](const AlignedBox3r& box) { return box.intersects(path); }, [&](int t) {
    if (t == s) return;
    const Triangle& corners = mesh.triangles()[t];
    const Real at = crossing(a, b, mesh.vertices()[corners[0]], mesh.vertices()[corners[1]], mesh.vertices()[corners[2]]);
    if (at >= 0) found.push_back({at, t});
  });
  std::sort(found.begin(), found.end(), [](const Crossing& p, const Crossing& q) { return p.at < q.at; });
  return found;
}

bool inCap(const RoundedMesh& mesh, int t, const Vector3r& x) {
  const RoundedTriangle& cap = mesh.rounded(t);
  return (x - cap.sphereCentre).squaredNorm() <= cap.radius * cap.radius;
}

// Whether the middle of the segment q1 q2 (body 1's frame) lies kMiddleDepthFraction of the segment's length deep in
// both bodies. At a real deep contact it lies about half the segment deep in each, or cos(theta) / 2 of it at a slant
// theta to the bodies' overlap; a segment inside both bodies along a thin sheet where they overlap lies a sheet's
// half-thickness deep: two parallel cylinders 4 m long overlapping by 1 cm along their sides, their flat ends facing
// each other through that sheet, 4 m apart (scene S5). The depths are the distance fields', so the test asks no more
// than a field can tell: each body's requirement is capped at its field's band (a field reads no deeper), and its
// tolerance is allowed; it rejects only segments longer than about five times the sheet's half-thickness plus that
// tolerance.
bool deepAtItsMiddle(const RoundedMesh& mesh1, const PlacedMesh& body2, const Vector3r& q1, const Vector3r& q2) {
  const Vector3r middle = 0.5 * (q1 + q2);
  const Real required = kMiddleDepthFraction * (q1 - q2).norm();
  auto deepIn = [required](const SolidDistance& field, const Vector3r& x) {
    return -field.signedAt(x) + field.tolerance() >= std::min(required, field.band());
  };
  return deepIn(mesh1.solidDistance(), middle) &&
         deepIn(body2.mesh.solidDistance(), body2.rotation.transpose() * (middle - body2.translation));
}

}  // namespace

bool pathInsideBody(const RoundedMesh& mesh, int s, const Vector3r& from, const Vector3r& x) {
  Vector3r a, b;
  const std::vector<Crossing>& found = crossings(mesh, s, from, x, a, b);
  // Out of the flat solid through the last triangle crossed: still in the rounded one if within its cap (the lens
  // of its sphere beyond its plane).
  return found.size() % 2 == 0 || inCap(mesh, found.back().triangle, x);
}

bool pathStaysInsideBody(const RoundedMesh& mesh, int s, const Vector3r& from, const Vector3r& x) {
  Vector3r a, b;
  const std::vector<Crossing>& found = crossings(mesh, s, from, x, a, b);
  // Each stretch out of the flat solid, from a crossing out to the next one in (or to x), must lie in the cap of the
  // triangle it left through or of the one it comes back through (a ball holds a segment whose ends it holds).
  for (size_t k = 0; k < found.size(); k += 2) {
    const Vector3r out = a + found[k].at * (b - a);
    const bool back = k + 1 < found.size();
    const Vector3r in = back ? Vector3r(a + found[k + 1].at * (b - a)) : x;
    const int left = found[k].triangle, entered = back ? found[k + 1].triangle : left;
    if (!(inCap(mesh, left, out) && inCap(mesh, left, in)) && !(inCap(mesh, entered, out) && inCap(mesh, entered, in)))
      return false;
  }
  return true;
}

bool overlapInsideBoth(const RoundedMesh& mesh1, int s, const PlacedMesh& body2, int t, const PressureGeom& geom,
                       bool deep) {
  const RoundedTriangle& p = mesh1.rounded(s);
  const RoundedTriangle& q = body2.mesh.rounded(t);
  const Vector3r& n = geom.normal;
  const Vector3r sphere2 = body2.rotation * q.sphereCentre + body2.translation;
  // The line along n12 through c_eff, offset from the line of centres by `lateral`.
  const Vector3r line = planePoint(geom, geom.effectivePoint);
  const Vector3r lateral = line - geom.centre;
  const Real hSq = lateral.squaredNorm();
  const Vector3r q1 = p.sphereCentre + lateral + std::sqrt(std::max(p.radius * p.radius - hSq, Real(0))) * n;
  const Vector3r q2 = sphere2 + lateral - std::sqrt(std::max(q.radius * q.radius - hSq, Real(0))) * n;
  if (deep && !deepAtItsMiddle(mesh1, body2, q1, q2)) return false;
  // Where the line crosses each flat triangle, and how far the other body's end of the segment lies behind it, in
  // the flat solid: the stretch that solid must hold (none where that end lies in the triangle's own cap). It does,
  // surely, where it crosses none of the triangle's exits.
  const Matrix3r back = body2.rotation.transpose();
  const Vector3r line2 = back * (line - body2.translation), normal2 = back * n;
  const Vector3r entry1 = line + lineToTriangle(mesh1, s, line, n) * n;
  const Vector3r entry2 = line2 + lineToTriangle(body2.mesh, t, line2, normal2) * normal2;
  const Vector3r end2 = back * (q1 - body2.translation);
  const bool sure1 = (entry1 - q2).dot(n) <= 0 || mesh1.exits().keepsInside(mesh1, s, entry1, q2);
  const bool sure2 = (end2 - entry2).dot(normal2) <= 0 || body2.mesh.exits().keepsInside(body2.mesh, t, entry2, end2);
  if (sure1 && sure2) return true;
  if (deep) {
    // The fields reject most false deep pairs before the exact paths are followed. Between its ends, the segment
    // is sampled no farther apart than the finer field's tolerance: three points (the ends and the middle) let a
    // segment run out of one body and back in, along a thin sheet where two bodies overlap by 3 mm, and score
    // 33 mm (two gummy bears side by side in S1).
    if (!insidePlaced(body2, q1) || !insideRoundedSolid(mesh1, q2)) return false;
    const Real spacing = std::min(mesh1.solidDistance().tolerance(), body2.mesh.solidDistance().tolerance());
    const int samples = static_cast<int>(std::ceil((q1 - q2).norm() / spacing));
    for (int k = 1; k < samples; ++k) {
      const Vector3r x = q1 + (q2 - q1) * (Real(k) / samples);
      if (!insidePlaced(body2, x) || !insideRoundedSolid(mesh1, x)) return false;
    }
  }
  return (sure1 || pathStaysInsideBody(mesh1, s, entry1, q2)) &&
         (sure2 || pathStaysInsideBody(body2.mesh, t, entry2, end2));
}

}  // namespace roundedmesh
