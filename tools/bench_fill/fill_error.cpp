// Error statistics over hole samples and the border-range check.
#include "tools/bench_fill/fill_error.hpp"

#include <algorithm>
#include <cmath>

#include "rasters/gtopo30_header.hpp"

namespace globe::bench_fill {

ErrorSummary summariseErrors(const std::vector<int16_t>& filled, const std::vector<int16_t>& truth,
                             const std::vector<Hole>& holes) {
  std::vector<double> absolute;
  double sumSquares = 0, sum = 0;
  for (const Hole& hole : holes) {
    for (size_t index : hole.samples) {
      const double error = static_cast<double>(filled[index]) - truth[index];
      absolute.push_back(std::abs(error));
      sumSquares += error * error;
      sum += error;
    }
  }
  ErrorSummary summary;
  summary.samples = absolute.size();
  if (absolute.empty()) return summary;
  const auto n = static_cast<double>(absolute.size());
  summary.rmseMeters = std::sqrt(sumSquares / n);
  summary.biasMeters = sum / n;
  std::sort(absolute.begin(), absolute.end());
  const auto rank = static_cast<size_t>(std::ceil(0.99 * n));
  summary.p99Meters = absolute[std::clamp<size_t>(rank, 1, absolute.size()) - 1];
  summary.maxMeters = absolute.back();
  return summary;
}

BorderCheck checkBorderRange(const conditioning::DemGrid& filled,
                             const conditioning::DemGrid& truth, const std::vector<Hole>& holes,
                             const std::vector<uint8_t>& isVoid) {
  BorderCheck check;
  for (size_t i = 0; i < isVoid.size(); ++i) {
    if (isVoid[i] || truth.samples[i] == rasters::kNoDataHeight)
      continue;  // GDAL fills all no-data
    if (filled.samples[i] != truth.samples[i]) ++check.changedOutsideHoles;
  }
  for (const Hole& hole : holes) {
    int16_t low = INT16_MAX, high = INT16_MIN;
    for (size_t index : hole.samples) {
      const auto row = static_cast<int64_t>(index) / truth.cols;
      const auto column = static_cast<int64_t>(index) % truth.cols;
      const size_t neighbours[] = {truth.index(row - 1, column), truth.index(row + 1, column),
                                   truth.index(row, column - 1), truth.index(row, column + 1)};
      for (size_t n : neighbours) {
        if (isVoid[n]) continue;
        low = std::min(low, truth.samples[n]);
        high = std::max(high, truth.samples[n]);
      }
    }
    for (size_t index : hole.samples) {
      ++check.holeSamples;
      const int16_t value = filled.samples[index];
      if (value < low || value > high) ++check.outsideBorderRange;
    }
  }
  return check;
}

}  // namespace globe::bench_fill
