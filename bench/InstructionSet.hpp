// The vector unit a benchmark's Highway kernels run on: the best the processor has, or the one named in
// ROUNDEDMESH_BENCH_TARGET (Highway's name: AVX3, AVX2, SSE4, SSSE3, EMU128, ...), so that one processor can measure
// what a kernel costs on a narrower unit. Exits naming the variable and the units there are on an unknown name.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include "hwy/targets.h"

namespace roundedmesh {

inline void chooseInstructionSet() {
  const char* named = std::getenv("ROUNDEDMESH_BENCH_TARGET");
  if (!named || !*named) return;
  std::string available;
  for (const int64_t target : hwy::SupportedAndGeneratedTargets()) {
    if (std::string(hwy::TargetName(target)) == named) {
      hwy::SetSupportedTargetsForTest(target);
      return;
    }
    available += std::string(available.empty() ? "" : ", ") + hwy::TargetName(target);
  }
  std::cerr << "ROUNDEDMESH_BENCH_TARGET: '" << named << "' is not one of this processor's units: " << available << "\n";
  std::exit(2);
}

}  // namespace roundedmesh
