// The time-stamp counter read between load fences, and its calibration.
#include "tools/bench/query_timer.hpp"

#include <algorithm>
#include <chrono>
#include <vector>

#if defined(__x86_64__)
#include <x86intrin.h>
#endif

namespace globe::bench {

uint64_t QueryTimer::now() {
#if defined(__x86_64__)
  _mm_lfence();
  const uint64_t ticks = __rdtsc();
  _mm_lfence();
  return ticks;
#else
  return static_cast<uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                   std::chrono::steady_clock::now().time_since_epoch())
                                   .count());
#endif
}

QueryTimer::QueryTimer() {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point wallStart = Clock::now();
  const uint64_t tickStart = now();
  while (Clock::now() - wallStart < std::chrono::milliseconds(200)) {
  }
  const uint64_t tickEnd = now();
  const double wall = std::chrono::duration<double, std::nano>(Clock::now() - wallStart).count();
  if (tickEnd > tickStart) nanosecondsPerTick_ = wall / static_cast<double>(tickEnd - tickStart);
  std::vector<uint64_t> empty(20001);
  for (uint64_t& ticks : empty) {
    const uint64_t start = now();
    ticks = now() - start;
  }
  std::nth_element(empty.begin(), empty.begin() + empty.size() / 2, empty.end());
  overheadTicks_ = static_cast<double>(empty[empty.size() / 2]);
}

double QueryTimer::nanoseconds(uint64_t start, uint64_t end) const {
  return std::max(0.0, (static_cast<double>(end - start) - overheadTicks_) * nanosecondsPerTick_);
}

}  // namespace globe::bench
