// Trapezoid-rule block means over a fine grid.
#include "tools/bench_fill/block_average.hpp"

#include <cmath>

#include "rasters/gtopo30_header.hpp"

namespace globe::bench_fill {

conditioning::DemGrid blockAverage(const conditioning::DemGrid& fine, int64_t factor) {
  conditioning::DemGrid coarse;
  coarse.rows = (fine.rows - 1) / factor;
  coarse.cols = (fine.cols - 1) / factor;
  coarse.columnStepDegrees = fine.columnStepDegrees * static_cast<double>(factor);
  coarse.rowStepDegrees = fine.rowStepDegrees * static_cast<double>(factor);
  coarse.firstColumnLongitudeDegrees =
      fine.firstColumnLongitudeDegrees + 0.5 * coarse.columnStepDegrees;
  coarse.firstRowLatitudeDegrees = fine.firstRowLatitudeDegrees - 0.5 * coarse.rowStepDegrees;
  coarse.samples.assign(static_cast<size_t>(coarse.rows * coarse.cols), rasters::kNoDataHeight);
  auto edgeWeight = [factor](int64_t k) { return k == 0 || k == factor ? 0.5 : 1.0; };
  for (int64_t row = 0; row < coarse.rows; ++row) {
    for (int64_t column = 0; column < coarse.cols; ++column) {
      double sum = 0, weight = 0;
      for (int64_t i = 0; i <= factor; ++i) {
        for (int64_t j = 0; j <= factor; ++j) {
          const int16_t sample = fine.at(row * factor + i, column * factor + j);
          if (sample == rasters::kNoDataHeight) continue;
          const double w = edgeWeight(i) * edgeWeight(j);
          sum += w * sample;
          weight += w;
        }
      }
      if (weight > 0)
        coarse.samples[coarse.index(row, column)] = static_cast<int16_t>(std::lround(sum / weight));
    }
  }
  return coarse;
}

}  // namespace globe::bench_fill
