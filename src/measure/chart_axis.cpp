#include "measure/chart_axis.hpp"

#include <algorithm>
#include <cmath>

namespace globe::measure {

double niceStep(double span, int maxTicks) {
  const double rough = span / std::max(maxTicks, 1);
  const double decade = std::pow(10.0, std::floor(std::log10(rough)));
  for (const double mantissa : {1.0, 2.0, 5.0, 10.0}) {
    // A hair of tolerance: 0.3 / 3 must give 0.1, not 0.2, despite rounding.
    if (mantissa * decade >= rough * (1 - 1e-9)) return mantissa * decade;
  }
  return 10 * decade;
}

AxisRange niceAxis(double low, double high, int maxTicks, double minSpan) {
  if (high - low < minSpan) {
    const double middle = (low + high) / 2;
    low = middle - minSpan / 2;
    high = middle + minSpan / 2;
  }
  // Widening to whole steps can add an interval at each end: choose the step for the widened
  // range, growing it until the ticks fit.
  double step = niceStep(high - low, maxTicks);
  for (;;) {
    const double lowTick = std::floor(low / step + 1e-9) * step;
    const double highTick = std::ceil(high / step - 1e-9) * step;
    if ((highTick - lowTick) / step <= maxTicks + 1e-9) return {lowTick, highTick, step};
    step = niceStep(step * 1.01, 1);  // the next nice step up
  }
}

}  // namespace globe::measure
