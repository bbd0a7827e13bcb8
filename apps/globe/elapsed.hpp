// Wall time since a steady-clock instant, in milliseconds: the frame and phase timings of play,
// playback and view.
#pragma once

#include <chrono>

namespace globe::app {

inline double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace globe::app
