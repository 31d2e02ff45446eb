// The stress run of doc/reliability.md: N random rounded-triangle pairs and N / 10 random rounded-body pairs
// (the generators and checks of tests/support/RandomPairs.hpp, which the test suite runs on 10,000 triangle
// pairs and 200 body pairs), reporting how many were in contact, how many regime, sliding or contact switches
// were crossed, the worst change without a switch and the worst jump at one against their bounds, and how
// many forces were not finite. Exits 1 on any violation.
//   roundedmesh_stress [--pairs N] [--seed S]      N = 10^6 by default
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "tests/support/RandomPairs.hpp"

using namespace roundedmesh;
using namespace roundedmesh::test;

int main(int argc, char** argv) {
  long pairs = 1000000;
  unsigned seed = 1;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--pairs") == 0) pairs = std::atol(argv[i + 1]);
    else if (std::strcmp(argv[i], "--seed") == 0) seed = unsigned(std::atol(argv[i + 1]));
    else return std::fprintf(stderr, "usage: %s [--pairs N] [--seed S]\n", argv[0]), 2;
  }
  const auto start = std::chrono::steady_clock::now();
  RandomSource random(seed);

  // The suite's materials: a frictional, damped contact (mu = 0.5, c = 3 N s/m).
  const HertzPhys phys{2e6, 1e-3, 0.5, 3.0};
  long contacts = 0, switches = 0, nonFinite = 0, slopeViolations = 0, jumpViolations = 0;
  Real worstSlope = 0, worstJump = 0;
  for (long trial = 0; trial < pairs; ++trial) {
    const PairCheck check = checkTrianglePair(randomTrianglePair(random, pairKind(trial)), phys, random);
    nonFinite += !check.finite;
    if (!check.contact) continue;
    ++contacts;
    switches += check.switches;
    worstSlope = std::max(worstSlope, check.slope);
    worstJump = std::max(worstJump, check.jump);
    slopeViolations += check.slope > kSmoothSlope;
    jumpViolations += check.jump > kSwitchJump;
  }
  std::printf("triangle pairs: %ld, in contact %ld, switches crossed %ld, non-finite %ld\n", pairs, contacts,
              switches, nonFinite);
  std::printf("  worst change without a switch %.3g (bound %.3g, per whole-circle force and step / delta_s), "
              "%ld over\n", worstSlope, kSmoothSlope, slopeViolations);
  std::printf("  worst jump at a switch %.4g (bound %.3g, of the whole-circle force), %ld over\n", worstJump,
              kSwitchJump, jumpViolations);

  BodyLibrary bodies(HertzMaterial{1e6, 0.4, 2000, 1e-3, 0.5, 20});
  const long bodyPairs = pairs / 10;
  long touching = 0, triangleContacts = 0, bodySwitches = 0, bodyNonFinite = 0, bodySlopeViolations = 0,
       bodyJumpViolations = 0;
  Real bodyWorstSlope = 0, bodyWorstJump = 0;
  for (long trial = 0; trial < bodyPairs; ++trial) {
    BodyPairCase c = randomBodyPair(random, bodies);
    const BodyPairCheck check = checkBodyPair(c, random);
    bodyNonFinite += !check.finite;
    touching += check.contacts > 0;
    triangleContacts += check.contacts;
    bodySwitches += check.switches;
    bodyWorstSlope = std::max(bodyWorstSlope, check.worstSlope);
    bodyWorstJump = std::max(bodyWorstJump, check.worstJump);
    bodySlopeViolations += check.worstSlope > kSmoothSlope;
    bodyJumpViolations += check.worstJump > kSwitchJump;
  }
  std::printf("body pairs: %ld, touching %ld, triangle contacts %ld, switches crossed %ld, non-finite %ld\n",
              bodyPairs, touching, triangleContacts, bodySwitches, bodyNonFinite);
  std::printf("  worst change without a switch %.3g (bound %.3g), %ld pairs over\n", bodyWorstSlope, kSmoothSlope,
              bodySlopeViolations);
  std::printf("  worst jump at a switch %.4g (bound %.3g), %ld pairs over\n", bodyWorstJump, kSwitchJump,
              bodyJumpViolations);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long violations = nonFinite + slopeViolations + jumpViolations + bodyNonFinite + bodySlopeViolations +
                          bodyJumpViolations;
  std::printf("%s in %.0f s\n", violations ? "VIOLATIONS" : "all within bounds", seconds);
  return violations ? 1 : 0;
}
