// The spring record (pkg/io/SpringRecord.hpp): exact round trips, the bytes Python's base64 gives for the same
// springs (the format scenes saved before the record moved to C++ hold), refusals of damaged text, and mutations
// of a valid record (libFuzzer explores further: fuzz/spring_record_fuzzer.cpp).
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <random>
#include <stdexcept>

#include "pkg/io/SpringRecord.hpp"

namespace roundedmesh {
namespace {

SpringEntry entry(int id1, int id2, const Vector3r& u, Real twist, const Vector3r& n, Real energy) {
  TangentialSpring s;
  s.displacement = u;
  s.twist = twist;
  s.normal = n;
  s.energy = energy;
  return {id1, id2, s};
}

void expectSameBits(const SpringEntry& a, const SpringEntry& b) {
  EXPECT_EQ(a.id1, b.id1);
  EXPECT_EQ(a.id2, b.id2);
  EXPECT_EQ(std::memcmp(a.spring.displacement.data(), b.spring.displacement.data(), 3 * sizeof(Real)), 0);
  EXPECT_EQ(std::memcmp(a.spring.normal.data(), b.spring.normal.data(), 3 * sizeof(Real)), 0);
  EXPECT_EQ(std::memcmp(&a.spring.twist, &b.spring.twist, sizeof(Real)), 0);
  EXPECT_EQ(std::memcmp(&a.spring.energy, &b.spring.energy, sizeof(Real)), 0);
}

std::vector<SpringEntry> randomSprings(int count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<Real> any(-1, 1);
  std::uniform_int_distribution<int> id(0, 1 << 20);
  std::vector<SpringEntry> springs;
  for (int k = 0; k < count; ++k)
    springs.push_back(entry(id(random), id(random), Vector3r(any(random), any(random), any(random)) * 1e-3,
                            any(random), Vector3r(any(random), any(random), any(random)).normalized(),
                            std::abs(any(random)) * 1e-5));
  return springs;
}

// Every count modulo 3 of the bytes (the base64 padding), infinities and the extremes of int32 and double survive
// bit for bit.
TEST(SpringRecord, RoundTripsExactly) {
  for (int count : {0, 1, 2, 3, 250}) {
    std::vector<SpringEntry> springs = randomSprings(count, 7 + count);
    if (count == 3) {
      springs[0] = entry(std::numeric_limits<std::int32_t>::max(), std::numeric_limits<std::int32_t>::min(),
                         Vector3r::Constant(std::numeric_limits<Real>::max()), -0.0,
                         Vector3r::Constant(std::numeric_limits<Real>::denorm_min()),
                         std::numeric_limits<Real>::infinity());
    }
    const std::vector<SpringEntry> back = decodeSprings(encodeSprings(springs));
    ASSERT_EQ(back.size(), springs.size());
    for (size_t k = 0; k < springs.size(); ++k) expectSameBits(back[k], springs[k]);
  }
}

// Independent reference: Python's base64.b64encode(b"RMSPRING1" + struct.pack("<2i8d", 3, 7, 1e-3, -2e-4, 0.0,
// 0.125, 0.0, 0.6, 0.8, 2.5e-6)), the record Python wrote before it moved to C++.
TEST(SpringRecord, MatchesTheRecordsPythonWrote) {
  const std::string python =
      "Uk1TUFJJTkcxAwAAAAcAAAD8qfHSTWJQPy1DHOviNiq/AAAAAAAAAAAAAAAAAADAPwAAAAAAAAAAMzMzMzMz4z+amZmZmZnpP/Fo44i1+MQ+";
  const SpringEntry e = entry(3, 7, Vector3r(1e-3, -2e-4, 0), 0.125, Vector3r(0, 0.6, 0.8), 2.5e-6);
  EXPECT_EQ(encodeSprings({e}), python);
  const std::vector<SpringEntry> back = decodeSprings(python);
  ASSERT_EQ(back.size(), 1u);
  expectSameBits(back[0], e);
  EXPECT_EQ(encodeSprings({}), "Uk1TUFJJTkcx");
}

TEST(SpringRecord, RefusesDamagedText) {
  const std::string valid = encodeSprings(randomSprings(2, 1));
  for (const std::string& bad :
       {valid.substr(0, valid.size() - 1), valid.substr(0, valid.size() - 4), std::string("Uk1TUFJJTkcx="),
        std::string("QUJD"), "*" + valid.substr(1), valid.substr(0, 8) + "=" + valid.substr(9), std::string("A===")})
    EXPECT_THROW(decodeSprings(bad), std::invalid_argument) << bad;
  try {
    decodeSprings("QUJD");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("RMSPRING1"), std::string::npos) << e.what();
  }
}

// 20,000 mutations of a valid record (bytes changed, cut, repeated): each is refused with std::invalid_argument and
// a message, or decodes to springs that survive a round trip.
TEST(SpringRecord, MutatedRecordsAreRefusedOrRoundTrip) {
  const std::string valid = encodeSprings(randomSprings(5, 3));
  std::mt19937 random(42);
  int decoded = 0;
  for (int n = 0; n < 20000; ++n) {
    std::string text = valid;
    const int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits; ++e) {
      const size_t at = random() % text.size();
      switch (random() % 4) {
        case 0: text[at] = static_cast<char>(random()); break;
        case 1: text.resize(at); break;
        case 2: text.insert(at, text.substr(0, random() % 16)); break;
        default: text[at] = "AQgw+/="[random() % 7]; break;
      }
      if (text.empty()) text = "A";
    }
    std::vector<SpringEntry> springs;
    try {
      springs = decodeSprings(text);
    } catch (const std::invalid_argument& e) {
      ASSERT_GT(std::string(e.what()).size(), 0u);
      continue;
    }
    ++decoded;
    const std::vector<SpringEntry> back = decodeSprings(encodeSprings(springs));
    ASSERT_EQ(back.size(), springs.size());
    for (size_t k = 0; k < springs.size(); ++k) expectSameBits(back[k], springs[k]);
  }
  EXPECT_GT(decoded, 100);  // the mutations reach the decoder's success path too
}

}  // namespace
}  // namespace roundedmesh
