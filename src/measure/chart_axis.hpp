// Axis ticks a reader can add up in their head: steps of 1, 2 or 5 × 10^n, and the value range
// widened to whole steps.
#pragma once

namespace globe::measure {

// The smallest step of 1, 2 or 5 × 10^n that cuts `span` (> 0) into at most maxTicks (>= 1)
// intervals.
double niceStep(double span, int maxTicks);

struct AxisRange {
  double low = 0;
  double high = 0;
  double step = 0;  // ticks at every multiple of step from low to high
};

// [low, high] widened outwards to multiples of a nice step, at most maxTicks intervals; an empty
// or nearly empty range gets a span of at least minSpan.
AxisRange niceAxis(double low, double high, int maxTicks, double minSpan);

}  // namespace globe::measure
