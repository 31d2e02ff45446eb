// For a test that runs a batched kernel on each instruction set the processor has and the build compiled: while a
// TargetForTest lives, Highway's dispatch picks its target; when it goes, even by a failed ASSERT's early return,
// the processor's own best again, so that later tests run as the engine does.
#pragma once

#include <cstdint>

#include "hwy/targets.h"

namespace roundedmesh::test {

class TargetForTest {
 public:
  explicit TargetForTest(int64_t target) { hwy::SetSupportedTargetsForTest(target); }
  ~TargetForTest() { hwy::SetSupportedTargetsForTest(0); }
  TargetForTest(const TargetForTest&) = delete;
  TargetForTest& operator=(const TargetForTest&) = delete;
};

}  // namespace roundedmesh::test
