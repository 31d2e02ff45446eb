#include "pkg/shape/FacetSurface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>

#include "pkg/math/ConvexHull.hpp"
#include "pkg/math/Segment.hpp"
#include "pkg/shape/Facet.hpp"

namespace roundedmesh {
namespace {

// Relative tolerance of "in one plane" and "on one line": far above round-off, far below any contact's size.
constexpr Real kFlat = 1e-9;
// The most corners a panel's outline takes; a larger convex panel is split (a seam between two panels is flat and
// closed, so a body across it loses nothing but the equality with a Wall's force to round-off).
constexpr int kOutlineCorners = 32;
// The most facets a panel grown greedily (from a flat surface that is not convex) takes: the growth costs the square of
// it.
constexpr int kGreedyMembers = 64;

// Corners that coincide within the tolerance -> one vertex index per corner (a hash of the tolerance's grid, each
// corner compared with the vertices of its cell and the 26 cells around it).
std::vector<std::array<int, 3>> weldVertices(const std::vector<std::array<Vector3r, 3>>& facets, Real tolerance,
                                             std::vector<Vector3r>& vertices) {
  struct CellHash {
    size_t operator()(const std::array<long long, 3>& c) const {
      return std::hash<long long>()(c[0] * 73856093LL ^ c[1] * 19349663LL ^ c[2] * 83492791LL);
    }
  };
  std::unordered_map<std::array<long long, 3>, std::vector<int>, CellHash> cells;
  auto cellOf = [&](const Vector3r& x) {
    return std::array<long long, 3>{std::llround(x.x() / tolerance), std::llround(x.y() / tolerance),
                                    std::llround(x.z() / tolerance)};
  };
  std::vector<std::array<int, 3>> indices(facets.size());
  for (size_t f = 0; f < facets.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const Vector3r& x = facets[f][i];
      const std::array<long long, 3> cell = cellOf(x);
      int found = -1;
      for (long long dx = -1; dx <= 1 && found < 0; ++dx)
        for (long long dy = -1; dy <= 1 && found < 0; ++dy)
          for (long long dz = -1; dz <= 1 && found < 0; ++dz) {
            const auto near = cells.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
            if (near == cells.end()) continue;
            for (int v : near->second)
              if ((vertices[v] - x).norm() <= tolerance) {
                found = v;
                break;
              }
          }
      if (found < 0) {
        found = static_cast<int>(vertices.size());
        vertices.push_back(x);
        cells[cell].push_back(found);
      }
      indices[f][i] = found;
    }
  return indices;
}

Real polygonArea(const std::vector<Vector2r>& polygon) {
  Real twice = 0;
  for (size_t i = 0; i < polygon.size(); ++i) twice += cross2(polygon[i], polygon[(i + 1) % polygon.size()]);
  return 0.5 * twice;
}

constexpr Real kNone = std::numeric_limits<Real>::infinity();

struct EdgeSide {
  int facet, edge;
};

}  // namespace

Real weldTolerance(const std::vector<std::array<Vector3r, 3>>& facets) {
  Real scale = 0;
  for (const auto& c : facets)
    for (int i = 0; i < 3; ++i) scale = std::max({scale, c[i].cwiseAbs().maxCoeff(), (c[(i + 1) % 3] - c[i]).norm()});
  return 1e-6 * scale;
}

std::vector<FacetWeld> weldFacets(const std::vector<std::array<Vector3r, 3>>& facets, Real tolerance) {
  const int count = static_cast<int>(facets.size());
  std::vector<FacetWeld> welds(count);
  std::vector<Vector3r> vertices;
  const std::vector<std::array<int, 3>> index = weldVertices(facets, tolerance, vertices);

  std::vector<Vector3r> normals(count);
  std::vector<bool> degenerate(count);
  std::vector<Real> sizes(count);
  for (int f = 0; f < count; ++f) {
    const auto& c = facets[f];
    sizes[f] = std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()});
    // A facet without area (collinear corners, as CAD exports leave some) has no plane: it is welded to nothing.
    degenerate[f] = !hasArea(c);
    normals[f] = degenerate[f] ? Vector3r::UnitZ() : Vector3r((c[1] - c[0]).cross(c[2] - c[0]).normalized());
  }
  std::map<std::array<int, 2>, std::vector<EdgeSide>> edges;
  std::vector<std::vector<int>> vertexFacets(vertices.size());
  for (int f = 0; f < count; ++f)
    for (int i = 0; i < 3 && !degenerate[f]; ++i) {
      const int a = index[f][i], b = index[f][(i + 1) % 3];
      if (a != b) edges[{std::min(a, b), std::max(a, b)}].push_back({f, i});
      vertexFacets[a].push_back(f);
    }

  // Across each edge: which way each facet beyond goes, seen from this one; flat neighbours make panels.
  std::vector<std::array<std::vector<int>, 3>> flatAcross(count);
  std::vector<std::array<int, 3>> across(count, {-1, -1, -1});  // the facet beyond whose corner is `beyond`
  std::vector<std::array<Real, 3>> sharpest(count, {kNone, kNone, kNone});
  for (const auto& [key, sides] : edges)
    for (const EdgeSide& here : sides)
      for (const EdgeSide& there : sides) {
        if (here.facet == there.facet) continue;
        const auto& c = facets[here.facet];
        const Vector3r p = c[here.edge], d = (c[(here.edge + 1) % 3] - p).normalized();
        const Vector3r& n = normals[here.facet];
        Vector3r outward = d.cross(n);
        if (outward.dot(c[(here.edge + 2) % 3] - p) > 0) outward = -outward;
        Vector3r u = facets[there.facet][(there.edge + 2) % 3] - p;
        u -= u.dot(d) * d;
        const Real up = u.dot(n);
        const bool flat = std::abs(up) <= kFlat * u.norm() && u.dot(outward) > 0;
        SidePair& closed = welds[here.facet].edgeClosed[here.edge];
        closed[0] = closed[0] || flat || up > 0;
        closed[1] = closed[1] || flat || up < 0;
        if (flat) {
          flatAcross[here.facet][here.edge].push_back(there.facet);
          continue;
        }
        const Real turn = std::abs(std::atan2(up, u.dot(outward)));
        if (turn < sharpest[here.facet][here.edge]) {  // of several facets beyond (a plate on a seam), the flattest
          sharpest[here.facet][here.edge] = turn;
          welds[here.facet].beyond[here.edge] = facets[there.facet][(there.edge + 2) % 3];
          across[here.facet][here.edge] = there.facet;
        }
      }

  // Panels: a flat component of the surface whose union is convex is one; another is split into convex panels grown
  // greedily from its facet of lowest index.
  std::vector<int> panelOf(count, -1);
  for (int seed = 0; seed < count; ++seed) {
    if (panelOf[seed] >= 0) continue;
    if (degenerate[seed]) {  // alone, its corners its outline, every edge free
      panelOf[seed] = seed;
      welds[seed].panel = seed;
      welds[seed].outline.assign(facets[seed].begin(), facets[seed].end());
      welds[seed].outlineClosed.assign(3, SidePair{false, false});
      welds[seed].outlineBeyond.assign(3, Vector3r::Constant(kNaN));
      continue;
    }
    const auto& s = facets[seed];
    const Vector3r e1 = (s[1] - s[0]).normalized(), e2 = normals[seed].cross(e1);
    auto inPlane = [&](const Vector3r& x) { return Vector2r((x - s[0]).dot(e1), (x - s[0]).dot(e2)); };
    auto triangleArea = [&](int f) {
      const auto& c = facets[f];
      return 0.5 * std::abs(cross2(inPlane(c[1]) - inPlane(c[0]), inPlane(c[2]) - inPlane(c[0])));
    };
    // The flat component: facets reached over flat edges, all corners in the seed's plane.
    std::vector<int> component{seed};
    std::vector<bool> inComponent(count, false);
    inComponent[seed] = true;
    for (size_t next = 0; next < component.size(); ++next)
      for (int e = 0; e < 3; ++e)
        for (int g : flatAcross[component[next]][e]) {
          if (inComponent[g] || panelOf[g] >= 0) continue;
          bool inSeedPlane = true;
          for (const Vector3r& x : facets[g])
            inSeedPlane = inSeedPlane && std::abs(normals[seed].dot(x - s[0])) <= kFlat * (sizes[seed] + sizes[g]);
          if (!inSeedPlane) continue;
          inComponent[g] = true;
          component.push_back(g);
        }
    auto hullOf = [&](const std::vector<int>& members, Real& scale) {
      std::vector<Vector2r> points;
      scale = 0;
      for (int f : members) {
        scale = std::max(scale, sizes[f]);
        for (const Vector3r& x : facets[f]) points.push_back(inPlane(x));
      }
      return convexHull(points, kFlat * scale * scale);
    };
    auto convexUnion = [&](const std::vector<Vector2r>& hull, Real area, Real scale) {
      return polygonArea(hull) <= area * (1 + kFlat) + kFlat * scale * scale &&
             static_cast<int>(hull.size()) <= kOutlineCorners;
    };
    Real scale = 0, area = 0;
    for (int f : component) area += triangleArea(f);
    std::vector<int> members = component;
    std::vector<Vector2r> hull = hullOf(members, scale);
    if (!convexUnion(hull, area, scale)) {
      members = {seed};
      hull = hullOf(members, scale);
      area = triangleArea(seed);
      std::vector<bool> taken(count, false), touching(count, false);
      auto take = [&](int f) {
        taken[f] = true;
        for (int e = 0; e < 3; ++e)
          for (int g : flatAcross[f][e]) touching[g] = true;
      };
      take(seed);
      for (bool grew = true; grew && static_cast<int>(members.size()) < kGreedyMembers;) {
        grew = false;
        for (int g : component) {
          if (taken[g] || !touching[g]) continue;
          std::vector<int> trial = members;
          trial.push_back(g);
          Real trialScale;
          std::vector<Vector2r> trialHull = hullOf(trial, trialScale);
          if (!convexUnion(trialHull, area + triangleArea(g), trialScale)) continue;
          members = std::move(trial);
          hull = std::move(trialHull);
          scale = trialScale;
          area += triangleArea(g);
          take(g);
          grew = true;
        }
      }
    }
    for (int f : members) panelOf[f] = seed;

    // What lies beyond each stretch of the outline, from the member edges on it (those with no member across).
    std::vector<SidePair> closed(hull.size(), SidePair{true, true});
    std::vector<bool> covered(hull.size(), false);
    std::vector<Vector3r> beyond(hull.size(), Vector3r::Constant(kNaN));
    const Real onLine = kFlat * scale + tolerance;
    for (int f : members)
      for (int e = 0; e < 3; ++e) {
        const bool inner = std::any_of(flatAcross[f][e].begin(), flatAcross[f][e].end(),
                                       [&](int g) { return panelOf[g] == seed; });
        if (inner) continue;
        const Vector2r a = inPlane(facets[f][e]), b = inPlane(facets[f][(e + 1) % 3]);
        const bool sameSide = normals[f].dot(normals[seed]) > 0;
        for (size_t k = 0; k < hull.size(); ++k) {
          const Vector2r &p = hull[k], &q = hull[(k + 1) % hull.size()];
          const bool onStretch = (a - closestOnSegment(a, p, q)).norm() <= onLine &&
                                 (b - closestOnSegment(b, p, q)).norm() <= onLine;
          if (!onStretch) continue;
          const SidePair& edge = welds[f].edgeClosed[e];
          closed[k][0] = closed[k][0] && edge[sameSide ? 0 : 1];
          closed[k][1] = closed[k][1] && edge[sameSide ? 1 : 0];
          // A stretch whose member edges do not all have a facet beyond has none (no strip, no trim).
          const Vector3r& there = welds[f].beyond[e];
          beyond[k] = !covered[k] || beyond[k].allFinite() ? there : Vector3r::Constant(kNaN);
          covered[k] = true;
        }
      }
    for (size_t k = 0; k < hull.size(); ++k)
      if (!covered[k]) closed[k] = {false, false};

    for (int f : members) {
      FacetWeld& weld = welds[f];
      weld.panel = seed;
      weld.panelSize = static_cast<int>(members.size());
      const bool sameSide = normals[f].dot(normals[seed]) > 0;
      for (const Vector2r& x : hull) weld.outline.push_back(s[0] + x.x() * e1 + x.y() * e2);
      weld.outlineClosed = closed;
      weld.outlineBeyond = beyond;
      if (!sameSide) {  // counter-clockwise about this member's normal, sides named from it
        std::reverse(weld.outline.begin(), weld.outline.end());
        std::reverse(weld.outlineClosed.begin(), weld.outlineClosed.end());
        std::rotate(weld.outlineClosed.begin(), weld.outlineClosed.begin() + 1, weld.outlineClosed.end());
        std::reverse(weld.outlineBeyond.begin(), weld.outlineBeyond.end());
        std::rotate(weld.outlineBeyond.begin(), weld.outlineBeyond.begin() + 1, weld.outlineBeyond.end());
        for (SidePair& side : weld.outlineClosed) std::swap(side[0], side[1]);
      }
      for (int e = 0; e < 3; ++e)
        for (int g : flatAcross[f][e])
          if (panelOf[g] == seed && g < f) weld.ownsEdge[e] = false;
      for (int i = 0; i < 3; ++i)
        for (int g : vertexFacets[index[f][i]])
          if (panelOf[g] == seed && g < f) weld.ownsCorner[i] = false;
    }
  }
  // Each rounded edge between two panels is computed once, by the facets on the side of the panel of lower index; a
  // free edge's by its facet.
  for (int f = 0; f < count; ++f)
    for (int e = 0; e < 3; ++e)
      welds[f].ownsStrip[e] = across[f][e] >= 0 ? panelOf[f] < panelOf[across[f][e]] : flatAcross[f][e].empty();
  return welds;
}

}  // namespace roundedmesh
