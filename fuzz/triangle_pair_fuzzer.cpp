// The whole triangle contact, as ContactRobustnessTest drives it (triangleSphereGeom with contactSphere ->
// Law2 -> node forces -> Coulomb friction), on pairs made by the suite's generator (tests/support/
// RandomPairs.hpp) from the fuzzer's bytes instead of a random engine: slivers, radii from the circumradius to
// 1e4 times it, general, coplanar and edge-on-edge poses, any relative motion, then q moved by a shift the
// bytes also choose (up to the triangles' size each way, so both sides of every contact boundary). Any
// non-finite force, moment, node force or effective point traps. Needs no seeds: every input is a valid pair.
#include "fuzz/FuzzSupport.hpp"
#include "tests/support/RandomPairs.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace roundedmesh;
  fuzz::ByteSource bytes(data, size);
  const test::PairKind kind = test::pairKind(bytes.u32() % 4);
  const HertzPhys phys{bytes.uniform(1e3, 1e11), bytes.uniform(0, 1e-2), bytes.uniform(0, 1), bytes.uniform(0, 10)};
  // Bytes that collapse a triangle to a segment or a point make RoundedMesh refuse it, as it should.
  fuzz::refusalsOnly([&] {
    const test::TrianglePair pair = test::randomTrianglePair(bytes, kind);
    const Vector3r shift = bytes.uniform(0, pair.size) * bytes.direction();
    if (!test::evaluatePair(pair.p, pair.q, shift, pair.motion, phys).finite) fuzz::finding("non-finite triangle contact");
  });
  return 0;
}
