// Per-query timing for the accuracy mode: the time-stamp counter (x86-64) calibrated against
// steady_clock, with the timer's own cost measured and subtracted; steady_clock elsewhere.
#pragma once

#include <cstdint>

namespace globe::bench {

class QueryTimer {
 public:
  // Calibrates (about 0.2 s).
  QueryTimer();
  static uint64_t now();
  // Nanoseconds between two now() values, less the median cost of an empty measurement.
  double nanoseconds(uint64_t start, uint64_t end) const;
  double overheadNanoseconds() const { return overheadTicks_ * nanosecondsPerTick_; }
  double nanosecondsPerTick() const { return nanosecondsPerTick_; }

 private:
  double nanosecondsPerTick_ = 1.0;
  double overheadTicks_ = 0.0;
};

}  // namespace globe::bench
