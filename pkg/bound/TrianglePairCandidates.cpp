#include "pkg/bound/TrianglePairCandidates.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "pkg/bound/BatchedCandidates.hpp"
#include "pkg/bound/CapReach.hpp"
#include "pkg/shape/TriangleCorners.hpp"

namespace roundedmesh {
namespace {

// The corners of a triangle projected on the plane through c with normal n (axes u, v).
std::array<Vector2r, 3> projected(const std::array<Vector3r, 3>& x, const Vector3r& c, const Vector3r& u, const Vector3r& v) {
  std::array<Vector2r, 3> p;
  for (int i = 0; i < 3; ++i) p[i] = Vector2r((x[i] - c).dot(u), (x[i] - c).dot(v));
  return p;
}

// A lower bound of the distance between two plane triangles: the largest gap between their extents along
// the normals of their edges (0 if they overlap).
Real separation(const std::array<Vector2r, 3>& a, const std::array<Vector2r, 3>& b) {
  Real gap = 0;
  for (const std::array<Vector2r, 3>* edges : {&a, &b})
    for (int i = 0; i < 3; ++i) {
      const Vector2r e = (*edges)[(i + 1) % 3] - (*edges)[i];
      const Real length = e.norm();
      if (!(length > 0)) continue;
      const Vector2r axis(-e.y() / length, e.x() / length);
      Real minA = a[0].dot(axis), maxA = minA, minB = b[0].dot(axis), maxB = minB;
      for (int k = 1; k < 3; ++k) {
        minA = std::min(minA, a[k].dot(axis));
        maxA = std::max(maxA, a[k].dot(axis));
        minB = std::min(minB, b[k].dot(axis));
        maxB = std::max(maxB, b[k].dot(axis));
      }
      gap = std::max({gap, minB - maxA, minA - maxB});
    }
  return gap;
}

// The distance from the origin to a plane triangle (0 inside).
Real distanceFromOrigin(const std::array<Vector2r, 3>& t) {
  const Real orientation = cross2(t[1] - t[0], t[2] - t[0]);
  bool inside = true;
  Real best = INFINITY;
  for (int i = 0; i < 3; ++i) {
    const Vector2r& a = t[i];
    const Vector2r e = t[(i + 1) % 3] - a;
    if (cross2(e, -a) * orientation < 0) inside = false;
    const Real lengthSq = e.squaredNorm();
    const Real s = lengthSq > 0 ? std::clamp(-a.dot(e) / lengthSq, Real(0), Real(1)) : Real(0);
    best = std::min(best, (a + s * e).norm());
  }
  return inside ? 0 : best;
}

// Filters 2-4 for triangles p and q (q placed in mesh 1's frame). With `full`, also filter 5.
bool canTouch(const RoundedMesh& mesh1, int s, const RoundedMesh& mesh2, int t, const Matrix3r& rotation,
              const Vector3r& translation, Real skin, Real reach, bool full) {
  const RoundedTriangle& p = mesh1.rounded(s);
  const RoundedTriangle& q = mesh2.rounded(t);
  const Real balls = p.circumradius + q.circumradius + reach;
  const Vector3r qCircumcentre = rotation * q.circumcentre + translation;
  if ((qCircumcentre - p.circumcentre).squaredNorm() > balls * balls) return false;
  const Vector3r d = rotation * q.sphereCentre + translation - p.sphereCentre;
  const Real distance = d.norm();
  const Real bound2 = mesh2.sphereBoundRadius();
  const Real turn = skin / bound2;  // the largest rotation within the skin [rad]
  const Real moved = skin * std::max(Real(1), q.sphereCentre.norm() / bound2);
  // The centres' distance is the same seen from either body, so it changes by at most the smaller of their motions
  // relative to the other body: s_t's in body 1's frame (moved), s_s's in body 2's, whose origin lies at
  // `translation` (a flat or concave triangle's sphere centre lies the mesh's largest contact radius, by default 100
  // r_eq, behind it: its own motion would admit nearly every pair).
  const Real apart = skin * std::max(Real(1), std::min(q.sphereCentre.norm(), (p.sphereCentre - translation).norm()) / bound2);
  const Real overlap = p.radius + q.radius - distance;
  if (overlap <= -apart) return false;
  if (p.normal.dot(d) <= -moved || (rotation * q.normal).dot(d) >= moved + turn * (distance + moved)) return false;
  if (!full) return true;
  // The contact circle now, and how far the motion can move it: its centre c = s_p + x n moves by at most the change
  // of x (|dx/dd| = |1/2 + (R_t^2 - R_s^2) / (2 d^2)| times that of the distance d, at most `apart`) plus x times the
  // turn of n (at most 2 moved / distance); its radius grows at most to a_max.
  const Real nearest = distance - apart;
  if (!(nearest > 0)) return true;
  const Vector3r n = d / distance;
  const Real x = ((distance - q.radius) * (distance + q.radius) + p.radius * p.radius) / (2 * distance);
  const Vector3r c = p.sphereCentre + x * n;
  const Real tilt = std::min(Real(2), 2 * moved / distance);
  const Real aMax = std::sqrt(std::max(overlap + apart, Real(0)) * p.radius * q.radius / (p.radius + q.radius));
  const Real stretch = Real(0.5) + std::abs(q.radius - p.radius) * (q.radius + p.radius) / (2 * nearest * nearest);
  const Real shift = stretch * apart + std::abs(x) * tilt;
  // A point at distance l from c shifts in the plane by at most shift + l tilt, and the partner's corners also
  // move by at most skin. First the projected circumcircles, which hold the projected triangles: each must come
  // within a_max of c.
  for (const auto& [centre, radius] : {std::pair<Vector3r, Real>(p.circumcentre, p.circumradius),
                                       std::pair<Vector3r, Real>(qCircumcentre, q.circumradius)}) {
    const Vector3r offset = centre - c;
    const Real reachable = aMax + radius + shift + (offset.norm() + radius) * tilt + skin;
    if (offset.squaredNorm() - std::pow(offset.dot(n), 2) > reachable * reachable) return false;
  }
  // Then the projected triangles themselves, on the plane now.
  const Vector3r u = n.unitOrthogonal(), v = n.cross(u);
  const std::array<Vector3r, 3> xp = triangleCorners(mesh1, s);
  std::array<Vector3r, 3> xq = triangleCorners(mesh2, t);
  for (Vector3r& x : xq) x = rotation * x + translation;
  Real far = 0;
  for (int i = 0; i < 3; ++i) far = std::max({far, (xp[i] - c).norm(), (xq[i] - c).norm()});
  const Real slack = shift + far * tilt + skin;
  const std::array<Vector2r, 3> pp = projected(xp, c, u, v), pq = projected(xq, c, u, v);
  // S = P' n Q' must meet the contact circle: both projections within a_max of c, and overlapping.
  if (std::max(distanceFromOrigin(pp), distanceFromOrigin(pq)) > aMax + slack) return false;
  return separation(pp, pq) <= 2 * slack;
}

}  // namespace

bool passesFilters2to4(const RoundedMesh& mesh1, int s, const RoundedMesh& mesh2, int t, const Matrix3r& rotation,
                       const Vector3r& translation, Real skin, Real reach) {
  return canTouch(mesh1, s, mesh2, t, rotation, translation, skin, reach, false);
}

void nearTrianglePairs(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                       const Vector3r& translation, Real skin, Real depth, Real shallow,
                       std::vector<TrianglePair>& pairs) {
  pairs.clear();
  const Matrix3r back = rotation.transpose();
  const Vector3r backTranslation = -(back * translation);
  auto bothReach = [&](int s, int t) {
    return capReaches(mesh1, s, PlacedMesh{mesh2, rotation, translation}, 2 * skin) &&
           capReaches(mesh2, t, PlacedMesh{mesh1, back, backTranslation}, 2 * skin);
  };
  // The pairs of the trees within `margin` (filter 1) that pass filters 2-4, in the trees' order.
  auto searchTrees = [&](Real margin, std::vector<TrianglePair>& found) {
    TriangleTree::queryPairs(mesh1.tree(), mesh2.tree(), rotation, translation, margin,
                             [&found](int s, int t) { found.push_back({s, t}); });
    keepPassingFilters2to4Batched(mesh1, mesh2, rotation, translation, skin, depth + skin, found);
  };
  // A list up to twice the Hertz range: every pair of the trees within depth + skin, those farther apart than
  // shallow + skin only if both caps reach the other body.
  if (depth <= 2 * shallow) {
    if (depth <= shallow) {
      searchTrees(depth + skin, pairs);
      return;
    }
    thread_local std::vector<TrianglePair> found;
    found.clear();
    searchTrees(depth + skin, found);
    const AlignedBox3r* boxes1 = mesh1.tree().triangleBoxes().data();
    for (const auto& [s, t] : found) {
      const bool onlyDeep = !boxes1[s].intersects(
          transformedBox(mesh2.tree().triangleBox(t), rotation, translation, shallow + skin));
      if (!onlyDeep || bothReach(s, t)) pairs.push_back({s, t});
    }
    return;
  }
  // Deeper (a pair past the Hertz range holds a list as deep as the bodies: pkg/engine/CandidateLists.hpp), the same pairs
  // without searching every pair of the trees within that depth: those within shallow + skin from the trees, the
  // others among the few triangles whose caps reach the other body (the ones in or at it).
  searchTrees(shallow + skin, pairs);
  std::vector<int> reaching1, reaching2;
  for (int s = 0; s < mesh1.triangleCount(); ++s)
    if (capReaches(mesh1, s, PlacedMesh{mesh2, rotation, translation}, 2 * skin)) reaching1.push_back(s);
  if (reaching1.empty()) return;
  for (int t = 0; t < mesh2.triangleCount(); ++t)
    if (capReaches(mesh2, t, PlacedMesh{mesh1, back, backTranslation}, 2 * skin)) reaching2.push_back(t);
  // These are many (every pair of the triangles at and in the other body: tens of millions for two of YADE's GTS
  // horses of 9,514 triangles), and few of them can touch: all five filters, batched, for this list's skin. Filter 5
  // holds for a pose within the skin of this one if the pair can touch there, so the lists taken from this one lose no
  // pair they would keep.
  appendTouchableShellPairsBatched(mesh1, mesh2, rotation, translation, skin, depth, shallow + skin, reaching1,
                                   reaching2, pairs);
}

bool touchablePair(const RoundedMesh& mesh1, int s, const RoundedMesh& mesh2, int t, const Matrix3r& rotation,
                   const Matrix3r& absRotation, const Vector3r& translation, Real skin, Real depth) {
  const Real reach = depth + skin;
  // Filter 1 again, for this skin and depth (transformedBox with |R| formed once).
  const AlignedBox3r& b = mesh2.tree().triangleBox(t);
  const Vector3r centre = rotation * b.center() + translation;
  const Vector3r half = (absRotation * (0.5 * b.sizes())).array() + reach;
  if (!mesh1.tree().triangleBox(s).intersects(AlignedBox3r(centre - half, centre + half))) return false;
  return canTouch(mesh1, s, mesh2, t, rotation, translation, skin, reach, true);
}

void touchableTrianglePairs(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation,
                            const Vector3r& translation, Real skin, Real depth, const std::vector<TrianglePair>& near,
                            std::vector<TrianglePair>& pairs) {
  pairs.clear();
  const Matrix3r absRotation = rotation.cwiseAbs();
  for (const TrianglePair& st : near)
    if (touchablePair(mesh1, st[0], mesh2, st[1], rotation, absRotation, translation, skin, depth)) pairs.push_back(st);
}

}  // namespace roundedmesh
