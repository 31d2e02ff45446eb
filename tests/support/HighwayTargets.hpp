// For a test that runs a batched kernel on each instruction set the processor has and the build compiled: while a
// TargetForTest lives, Highway's dispatch picks its target; when it goes, even by a failed ASSERT's early return,
// the processor's own best again, so that later tests run as the engine does. sameBits compares a lane's result with
// the reference's bit for bit (a NaN equals the same NaN, and 0 differs from -0).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "hwy/targets.h"

namespace roundedmesh::test {

class TargetForTest {
 public:
  explicit TargetForTest(int64_t target) { hwy::SetSupportedTargetsForTest(target); }
  ~TargetForTest() { hwy::SetSupportedTargetsForTest(0); }
  TargetForTest(const TargetForTest&) = delete;
  TargetForTest& operator=(const TargetForTest&) = delete;
};

// Runs body(target) once on each instruction set, Highway's dispatch choosing it, the target's name in any failure.
template <class Body>
void forEachInstructionSet(const Body& body) {
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  for (const int64_t target : targets) {
    const TargetForTest chosen(target);
    SCOPED_TRACE(hwy::TargetName(target));
    body(target);
  }
}

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

}  // namespace roundedmesh::test
