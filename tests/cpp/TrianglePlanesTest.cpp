// The tests before S and the contact planes in lanes (TrianglePlanes.hpp) are trianglePlane's bit for bit: for the
// near triangle pairs of random body pairs of the library (icospheres, a distorted icosphere, a spheroid, 1 mm to 1 m,
// from grazing to deep, turned at random: every rejection and pairs that pass), and for random triangle pairs of every
// kind of the robustness suite (general, coplanar, edge on edge; slivers), in batches of 1 to 16 lanes, on every
// instruction set the processor has and the build compiled. Each lane's rejection, and where it passes every field
// trianglePlane fills and P' and Q' as S's lanes take them (ConvexPolygon::triangle's order); and contact normals along
// z and within 1e-12 of it, either side of unitOrthogonal's test. No tolerance: the lanes run trianglePlane's operations
// in its order.
#include <gtest/gtest.h>

#include <string>

#include "pkg/geom/TrianglePlanes.hpp"
#include "pkg/geom/TriangleSphereGeom.hpp"
#include "tests/support/HighwayTargets.hpp"
#include "tests/support/LibraryLanes.hpp"

namespace roundedmesh {
namespace {

using test::sameBits;

struct Tally {
  long lanes = 0, passed = 0;
  long rejected[4] = {0, 0, 0, 0};
};

// Lane k of `planes` against trianglePlane.
void checkLane(const RoundedMesh& mesh1, const RoundedMesh& mesh2, const Matrix3r& rotation, const Vector3r& translation,
               const TrianglePlanes& planes, const TriangleIntersections& clips, int k, int s, int t,
               const std::string& where, Tally& tally) {
  PressureGeom reference, lanes;
  const GeomTest expected = trianglePlane(mesh1, s, PlacedTriangle{mesh2, t, rotation, translation}, reference);
  ASSERT_EQ(planes.result(k).rejection, expected.rejection) << where;
  ++tally.lanes;
  ++tally.rejected[static_cast<int>(expected.rejection)];
  if (!expected) return;
  ++tally.passed;
  planes.get(k, lanes);
  ASSERT_TRUE(sameBits(lanes.centre, reference.centre)) << where;
  ASSERT_TRUE(sameBits(lanes.normal, reference.normal)) << where;
  ASSERT_TRUE(sameBits(lanes.tangent1, reference.tangent1)) << where;
  ASSERT_TRUE(sameBits(lanes.tangent2, reference.tangent2)) << where;
  ASSERT_TRUE(sameBits(lanes.radius, reference.radius)) << where;
  ASSERT_TRUE(sameBits(lanes.sphereOverlap, reference.sphereOverlap)) << where;
  ASSERT_TRUE(sameBits(lanes.contactRadius, reference.contactRadius)) << where;
  ASSERT_TRUE(sameBits(lanes.nodes, reference.nodes)) << where;
  ASSERT_TRUE(sameBits(lanes.partnerNodes, reference.partnerNodes)) << where;
  const ConvexPolygon q = partnerPolygon(reference);
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(sameBits(Vector2r(clips.px[i][k], clips.py[i][k]), reference.polygon[i])) << where << ", P' " << i;
    ASSERT_TRUE(sameBits(Vector2r(clips.qx[i][k], clips.qy[i][k]), q[i])) << where << ", Q' " << i;
  }
}

TEST(TrianglePlanes, EveryLaneIsTrianglePlanesBitForBit) {
  test::forEachInstructionSet([&](int64_t) {
    Tally tally;
    test::forEachLibraryLane(739, 150, [&](const test::LibraryLane& lane) {
      if (HasFatalFailure()) return;
      checkLane(lane.mesh1, lane.mesh2, lane.rotation, lane.translation, lane.planes, lane.clips, lane.k, lane.s, lane.t,
                lane.where, tally);
    });
    if (HasFatalFailure()) return;
    // Random triangle pairs of every kind, each alone in a batch of one lane.
    test::RandomSource random(740);
    TrianglePlanes planes;
    TriangleIntersections clips;
    for (long trial = 0; trial < 20000; ++trial) {
      const test::TrianglePair pair = test::randomTrianglePair(random, test::pairKind(trial));
      planes.size = 1;
      planes.s[0] = planes.t[0] = 0;
      trianglePlanes(pair.p, pair.q, Matrix3r::Identity(), Vector3r::Zero(), planes, clips);
      checkLane(pair.p, pair.q, Matrix3r::Identity(), Vector3r::Zero(), planes, clips, 0, 0, 0,
                "triangle pair " + std::to_string(trial), tally);
      if (HasFatalFailure()) return;
    }
    // Normals along z and within 1e-12 of it, where unitOrthogonal takes its other branch: two triangles stacked
    // along z, body 2 moved sideways by a fraction f of their spheres' distance, either side of that branch's test.
    const std::array<Vector3r, 3> below = {Vector3r(0, 0, 0), Vector3r(1e-2, 0, 0), Vector3r(0, 1e-2, 0)};
    const std::array<Vector3r, 3> above = {below[0] + Vector3r(0, 0, 1e-4), below[2] + Vector3r(0, 0, 1e-4),
                                           below[1] + Vector3r(0, 0, 1e-4)};
    const RoundedMesh p = test::singleTriangle(below, 0.05), q = test::singleTriangle(above, 0.05);
    const Real apart = (q.rounded(0).sphereCentre - p.rounded(0).sphereCentre).norm();
    for (const Real f : {0.0, 0.5e-12, 0.999e-12, 1.001e-12, 2e-12, 1e-6}) {
      planes.size = 1;
      planes.s[0] = planes.t[0] = 0;
      const Vector3r sideways(f * apart, 0, 0);
      trianglePlanes(p, q, Matrix3r::Identity(), sideways, planes, clips);
      const long passed = tally.passed;
      checkLane(p, q, Matrix3r::Identity(), sideways, planes, clips, 0, 0, 0, "stacked, f = " + std::to_string(f), tally);
      if (HasFatalFailure()) return;
      EXPECT_EQ(tally.passed, passed + 1) << "stacked, f = " << f;
      // unitOrthogonal's branch: (0, -n_z, n_y) / |(n_y, n_z)| within 1e-12 of z, else (-n_y, n_x, 0) / |(n_x, n_y)|.
      EXPECT_EQ(planes.tangent1[f < 1e-12 ? 0 : 2][0], 0.0) << "stacked, f = " << f;
    }
    // Each outcome is common, so that every test's mask is exercised both ways (of 323,000 lanes: 55,000 pass, 1,900
    // face away, 73,000 do not overlap, 194,000 miss the circle).
    EXPECT_GT(tally.passed, 20000);
    EXPECT_GT(tally.rejected[static_cast<int>(Rejection::NotFacing)], 1000);
    EXPECT_GT(tally.rejected[static_cast<int>(Rejection::NoOverlap)], 20000);
    EXPECT_GT(tally.rejected[static_cast<int>(Rejection::OutsideCircle)], 20000);
  });
}

}  // namespace
}  // namespace roundedmesh
