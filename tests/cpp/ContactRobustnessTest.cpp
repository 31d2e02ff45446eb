// 10,000 random pairs of rounded triangles, sizes from slivers up, radii from the circumradius to 1e4 times
// it, in general position, exactly coplanar and edge on edge: the whole triangle contact (Ig2, Law2, node
// forces, friction) gives finite forces, and moving one triangle by a tiny step changes them by little. The
// same for random pairs of meshed bodies through resolvePair. The generators and checks are shared with the
// stress program (bench/stress_pairs.cpp, 10^6 pairs, doc/reliability.md): tests/support/RandomPairs.hpp,
// where the bounds kSwitchJump and kSmoothSlope are derived.
#include <gtest/gtest.h>

#include <iostream>

#include "tests/support/RandomPairs.hpp"

namespace roundedmesh::test {
namespace {

TEST(ContactRobustness, RandomTrianglePairsGiveFiniteContinuousForces) {
  RandomSource random(11);
  const HertzPhys phys{2e6, 1e-3, 0.5, 3.0};
  int contacts = 0, switches = 0;
  Real worstSmooth = 0, worstSwitch = 0;
  for (int trial = 0; trial < 10000; ++trial) {
    const TrianglePair pair = randomTrianglePair(random, pairKind(trial));
    const PairCheck check = checkTrianglePair(pair, phys, random);
    EXPECT_TRUE(check.finite) << "trial " << trial;
    if (!check.contact) continue;
    ++contacts;
    switches += check.switches;
    worstSmooth = std::max(worstSmooth, check.slope);
    worstSwitch = std::max(worstSwitch, check.jump);
    EXPECT_LE(check.slope, kSmoothSlope) << "trial " << trial;
    EXPECT_LE(check.jump, kSwitchJump) << "trial " << trial;
  }
  EXPECT_GT(contacts, 2000);
  EXPECT_GT(switches, 500);
  std::cout << contacts << " contacts, " << switches << " switches; worst slope " << worstSmooth
            << " (step / delta_s), worst jump at a switch " << worstSwitch << " (of the whole-circle Hertz force)\n";
}

// 200 body pairs, grazing to deep: finite wrenches, and every triangle contact within the bounds of the
// triangle pairs, for a step of 1e-7 of the radius (slope) and at the switches of a move of 1e-4 (jump).
TEST(ContactRobustness, RandomBodyPairsGiveFiniteContinuousForces) {
  RandomSource random(12);
  BodyLibrary bodies(HertzMaterial{1e6, 0.4, 2000, 1e-3, 0.5, 20});
  int touching = 0, switches = 0;
  Real worstSlope = 0, worstJump = 0;
  for (int trial = 0; trial < 200; ++trial) {
    BodyPairCase c = randomBodyPair(random, bodies);
    const BodyPairCheck check = checkBodyPair(c, random);
    EXPECT_TRUE(check.finite) << "trial " << trial;
    EXPECT_LE(check.worstSlope, kSmoothSlope) << "trial " << trial;
    EXPECT_LE(check.worstJump, kSwitchJump) << "trial " << trial;
    touching += check.contacts > 0;
    switches += check.switches;
    worstSlope = std::max(worstSlope, check.worstSlope);
    worstJump = std::max(worstJump, check.worstJump);
  }
  // Overlaps down to 1e-7 of the size between vertex hulls leave some pairs apart (the caps are what touch);
  // a switch within a move of 1e-4 is rare (about one pair in a hundred), so the jump is checked at least once.
  EXPECT_GT(touching, 100);
  EXPECT_GT(switches, 0);
  std::cout << touching << " pairs touching, " << switches << " switches; worst slope " << worstSlope
            << ", worst jump at a switch " << worstJump << "\n";
}

}  // namespace
}  // namespace roundedmesh::test
