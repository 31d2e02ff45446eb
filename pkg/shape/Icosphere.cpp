#include "pkg/shape/Icosphere.hpp"

#include <cmath>
#include <map>
#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>

#include "pkg/shape/Distortion.hpp"

namespace roundedmesh {

TriangleSurface icosphereSurface(Real radius, int subdivisions) {
  if (!(std::isfinite(radius) && radius > 0))
    throw std::invalid_argument("radius must be positive and finite, got " + std::to_string(radius));
  if (subdivisions < 0 || subdivisions > 8)
    throw std::invalid_argument("subdivisions must be between 0 and 8, got " + std::to_string(subdivisions));

  const Real phi = (1 + std::sqrt(Real(5))) / 2;
  std::vector<Vector3r> unit = {{-1, phi, 0}, {1, phi, 0},  {-1, -phi, 0}, {1, -phi, 0},
                                {0, -1, phi}, {0, 1, phi},  {0, -1, -phi}, {0, 1, -phi},
                                {phi, 0, -1}, {phi, 0, 1},  {-phi, 0, -1}, {-phi, 0, 1}};
  for (Vector3r& v : unit) v.normalize();
  std::vector<Triangle> triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int i, int j) {
      const auto key = std::minmax(i, j);
      const auto found = midpoints.find(key);
      if (found != midpoints.end()) return found->second;
      unit.push_back((unit[i] + unit[j]).normalized());
      const int index = static_cast<int>(unit.size()) - 1;
      midpoints.emplace(key, index);
      return index;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * triangles.size());
    for (const Triangle& t : triangles) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    triangles = std::move(finer);
  }

  for (Vector3r& v : unit) v *= radius;
  return {std::move(unit), std::move(triangles)};
}

RoundedMesh icosphere(Real radius, int subdivisions) {
  TriangleSurface s = icosphereSurface(radius, subdivisions);
  const std::vector<Real> radii(s.triangles.size(), radius);
  return RoundedMesh(std::move(s.vertices), std::move(s.triangles), radii);
}

namespace {

// Incidence of triangles on nodes, for moving one node at a time.
std::vector<std::vector<int>> trianglesAroundNodes(const TriangleSurface& s) {
  std::vector<std::vector<int>> around(s.vertices.size());
  for (int t = 0; t < static_cast<int>(s.triangles.size()); ++t)
    for (int corner : s.triangles[t]) around[corner].push_back(t);
  return around;
}

// Outward (not folded over) and not collapsed: the sphere's centre sees the triangle counter-clockwise.
bool valid(const TriangleSurface& s, int t, Real minimumArea) {
  const Vector3r &a = s.vertices[s.triangles[t][0]], &b = s.vertices[s.triangles[t][1]], &c = s.vertices[s.triangles[t][2]];
  const Vector3r doubleAreaNormal = (b - a).cross(c - a);
  return doubleAreaNormal.dot(a + b + c) > 0 && doubleAreaNormal.norm() > 2 * minimumArea;
}

}  // namespace

TriangleSurface distortedIcosphereSurface(Real radius, int subdivisions, Real targetDistortion, std::uint32_t seed) {
  TriangleSurface s = icosphereSurface(radius, subdivisions);
  const Real regular = distortion(s);
  if (!(std::isfinite(targetDistortion) && targetDistortion >= regular && targetDistortion <= 1.5))
    throw std::invalid_argument("distortion must lie between " + std::to_string(regular) + " (the regular " +
                                "icosphere's own) and 1.5, got " + std::to_string(targetDistortion));
  const std::vector<std::vector<int>> around = trianglesAroundNodes(s);
  std::vector<Real> areas = triangleAreas(s);
  const int count = static_cast<int>(areas.size());
  Real sum = 0, sumOfSquares = 0;
  for (Real a : areas) sum += a, sumOfSquares += a * a;  // updated with every accepted step
  const Real meanEdge = std::sqrt(4 * sum / count / std::sqrt(3.0));
  auto currentDistortion = [&] { return std::sqrt(std::max(sumOfSquares / count - std::pow(sum / count, 2), Real(0))) / (sum / count); };

  // A random walk of the nodes along the sphere, one node at a time, each step refused if it would fold a
  // triangle over; D grows with the walk, and it stops the moment D reaches the target.
  std::mt19937 random(seed);
  std::normal_distribution<Real> gaussian;
  std::uniform_real_distribution<Real> uniform;
  const Real minimumArea = 1e-4 * sum / count;
  for (int sweep = 0; sweep < 1000; ++sweep)
    for (std::size_t node = 0; node < s.vertices.size(); ++node) {
      if (currentDistortion() >= targetDistortion) return s;
      const Vector3r old = s.vertices[node], n = old.normalized();
      Vector3r direction(gaussian(random), gaussian(random), gaussian(random));
      direction = (direction - direction.dot(n) * n).normalized();
      s.vertices[node] = (old + 0.1 * meanEdge * uniform(random) * direction).normalized() * radius;
      const bool accepted = std::all_of(around[node].begin(), around[node].end(), [&](int t) { return valid(s, t, minimumArea); });
      if (!accepted) {
        s.vertices[node] = old;
        continue;
      }
      for (int t : around[node]) {
        const Real updated = triangleArea(s, t);
        sum += updated - areas[t];
        sumOfSquares += updated * updated - areas[t] * areas[t];
        areas[t] = updated;
      }
    }
  throw std::invalid_argument("distortion " + std::to_string(targetDistortion) + " was not reached (D = " +
                              std::to_string(currentDistortion()) + " after 1000 sweeps)");
}

}  // namespace roundedmesh
