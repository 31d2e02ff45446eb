// A lap timer for the stages inside one pair (EngineOptions' timing = 'stages'): lap() gives the wall seconds since
// the clock was made or last lapped, 0 without reading the clock when it is off, so that an untimed step pays nothing.
#pragma once

#include <chrono>

#include "pkg/common/Types.hpp"

namespace roundedmesh {

class StageClock {
 public:
  explicit StageClock(bool on) : on_(on) {
    if (on_) last_ = std::chrono::steady_clock::now();
  }

  Real lap() {
    if (!on_) return 0;
    const auto now = std::chrono::steady_clock::now();
    const Real seconds = std::chrono::duration<Real>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  bool on_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace roundedmesh
