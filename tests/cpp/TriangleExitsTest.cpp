// Where a line entering a closed mesh can leave it (TriangleExits.hpp), against brute force: lines entering
// through random points of random triangles at random angles, followed through every triangle of the mesh. A
// segment said to be clear of its triangle's exits crosses no triangle, and a segment no longer than the reach is
// said to stay inside exactly when it crosses no triangle. On a meshed sphere,
// a fat torus (saddles: concave around the hole) and a thin one (lines leave within 0.1). And the distance between
// two triangles (TriangleDistance.hpp) against dense sampling of both.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "pkg/math/SegmentCrossing.hpp"
#include "pkg/math/TriangleDistance.hpp"
#include "pkg/shape/Icosphere.hpp"
#include "tests/cpp/TestSupport.hpp"

namespace roundedmesh {
namespace {

std::array<Vector3r, 3> corners(const RoundedMesh& mesh, int t) {
  const Triangle& c = mesh.triangles()[t];
  return {mesh.vertices()[c[0]], mesh.vertices()[c[1]], mesh.vertices()[c[2]]};
}

RoundedMesh flatTorus(Real R, Real r, int around, int tube) {
  const TriangleSurface s = test::torus(R, r, around, tube);
  return RoundedMesh(s.vertices, s.triangles, std::vector<Real>(s.triangles.size(), 1e3));
}

// How far the segment from `entry` (on triangle t) to `end` runs before it first crosses another triangle, as a
// fraction of its length; infinity if it crosses none. Started within t as TriangleExits does.
Real firstCrossing(const RoundedMesh& mesh, int t, const Vector3r& entry, const Vector3r& end) {
  const auto own = corners(mesh, t);
  const Vector3r shift = startWithin(own[0], own[1], own[2], entry);
  Real first = kInfinity;
  for (int j = 0; j < mesh.triangleCount(); ++j) {
    if (j == t) continue;
    const auto c = corners(mesh, j);
    const Real at = crossing(entry + shift, end + shift, c[0], c[1], c[2]);
    if (at >= 0) first = std::min(first, at);
  }
  return first;
}

// `mustTest`: how many segments of lines that leave within reach must be said clear (on a sphere or a fat torus,
// only grazing lines leave that soon, and a neighbour of their triangle is then an exit at distance 0).
void expectExitsAsBruteForce(const RoundedMesh& mesh, const std::string& name, int mustTest = 0) {
  const TriangleExits& exits = mesh.exits();
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> uniform(0, 1);
  std::normal_distribution<Real> normal;
  int leaving = 0, staying = 0, tested = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const int t = std::uniform_int_distribution<int>(0, mesh.triangleCount() - 1)(rng);
    const auto c = corners(mesh, t);
    Real a = uniform(rng), b = uniform(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    const Vector3r entry = c[0] + a * (c[1] - c[0]) + b * (c[2] - c[0]);
    // An inward direction at an angle up to 89 deg from the inward normal.
    const Vector3r inward = -mesh.rounded(t).normal;
    Vector3r side = Vector3r(normal(rng), normal(rng), normal(rng));
    side = (side - side.dot(inward) * inward).normalized();
    const Real theta = (M_PI / 180) * 89 * uniform(rng);
    const Vector3r direction = std::cos(theta) * inward + std::sin(theta) * side;
    const Real length = exits.reach() * uniform(rng);
    const Vector3r end = entry + length * direction;
    const Real first = firstCrossing(mesh, t, entry, end);
    const bool crosses = first <= 1;
    EXPECT_EQ(exits.keepsInside(mesh, t, entry, end), !crosses) << name << ", trial " << trial;
    // A segment said to be clear of exits crosses no triangle; counted where the line does leave within reach.
    const bool clear = exits.clear(t, std::cos(theta), length);
    EXPECT_FALSE(clear && crosses) << name << ", trial " << trial;
    tested += clear && firstCrossing(mesh, t, entry, entry + exits.reach() * direction) <= 1;
    ++(crosses ? leaving : staying);
  }
  // Both answers occur often enough to test.
  std::printf("[ %s ] %d segments leave, %d stay; %d clear segments of lines that leave within reach\n",
              name.c_str(), leaving, staying, tested);
  EXPECT_GT(leaving, 30) << name;
  EXPECT_GT(staying, 200) << name;
  EXPECT_GE(tested, mustTest) << name;
}

TEST(TriangleExits, AsBruteForceOnAMeshedSphere) { expectExitsAsBruteForce(icosphere(1.0, 3), "icosphere"); }

TEST(TriangleExits, AsBruteForceOnAFatTorus) { expectExitsAsBruteForce(flatTorus(1.0, 0.5, 48, 24), "fat torus"); }

TEST(TriangleExits, AsBruteForceOnAThinTorus) { expectExitsAsBruteForce(flatTorus(1.0, 0.04, 64, 12), "thin torus", 400); }

// The least distance of dense samples of both triangles (barycentric grids of step 1/n) exceeds the exact distance,
// by at most the samples' spacing on each (the longest edge / n).
TEST(TriangleDistance, AsDenseSamplingOfBothTriangles) {
  std::mt19937 rng(3);
  std::normal_distribution<Real> normal;
  const int n = 40;
  auto samples = [&](const std::array<Vector3r, 3>& c) {
    std::vector<Vector3r> out;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) out.push_back(c[0] + (Real(i) / n) * (c[1] - c[0]) + (Real(j) / n) * (c[2] - c[0]));
    return out;
  };
  auto spacing = [&](const std::array<Vector3r, 3>& c) {
    return std::max({(c[1] - c[0]).norm(), (c[2] - c[1]).norm(), (c[0] - c[2]).norm()}) / n;
  };
  for (int trial = 0; trial < 60; ++trial) {
    std::array<Vector3r, 3> first, second;
    for (Vector3r& x : first) x = Vector3r(normal(rng), normal(rng), normal(rng));
    const Vector3r offset = 3 * Vector3r(normal(rng), normal(rng), normal(rng));
    for (Vector3r& x : second) x = offset + Vector3r(normal(rng), normal(rng), normal(rng));
    // Crossing triangles are not what the function is for: keep pairs whose sampled distance is positive.
    Real sampled = kInfinity;
    for (const Vector3r& p : samples(first))
      for (const Vector3r& q : samples(second)) sampled = std::min(sampled, (p - q).norm());
    const Real exact = triangleDistance(first, second);
    if (sampled < spacing(first) + spacing(second)) continue;
    EXPECT_LE(exact, sampled + 1e-12) << "trial " << trial;
    EXPECT_GE(exact, sampled - spacing(first) - spacing(second)) << "trial " << trial;
  }
  // Shared corner: 0. Parallel edges one unit apart: 1.
  const std::array<Vector3r, 3> base{Vector3r(0, 0, 0), Vector3r(1, 0, 0), Vector3r(0, 1, 0)};
  EXPECT_EQ(triangleDistance(base, {Vector3r(0, 0, 0), Vector3r(-1, 0, 0), Vector3r(0, 0, 1)}), 0);
  EXPECT_NEAR(triangleDistance(base, {Vector3r(0, 0, 1), Vector3r(1, 0, 1), Vector3r(0, -1, 2)}), 1, 1e-15);
  EXPECT_NEAR(segmentDistance(Vector3r(0, 0, 0), Vector3r(1, 0, 0), Vector3r(0.5, -1, 1), Vector3r(0.5, 1, 1)), 1,
              1e-15);
}

}  // namespace
}  // namespace roundedmesh
