#include "tools/bench_render/seam_score.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace globe::bench {
namespace {

constexpr int kNeighbours = 12;

// Rec. 709 luma of pixel (x, y), or of (y, x) when transposed.
double luma(const formats::ImageRgba& image, int x, int y) {
  const uint8_t* p = &image.pixels[(static_cast<size_t>(y) * image.widthPixels + x) * 4];
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

struct WorstLine {
  double ratio = 0;
  int where = 0;
  double excessLevels = 0;
};

// The mean luma step between each column and the next (rows when transposed).
std::vector<double> lineSteps(const formats::ImageRgba& image, bool transposed) {
  const int lines = transposed ? image.heightPixels : image.widthPixels;
  const int along = transposed ? image.widthPixels : image.heightPixels;
  std::vector<double> steps(static_cast<size_t>(std::max(lines - 1, 0)));
  for (int k = 0; k + 1 < lines; ++k) {
    double sum = 0;
    for (int t = 0; t < along; ++t) {
      sum += transposed ? std::abs(luma(image, t, k + 1) - luma(image, t, k))
                        : std::abs(luma(image, k + 1, t) - luma(image, k, t));
    }
    steps[static_cast<size_t>(k)] = sum / along;
  }
  return steps;
}

// The median of the steps within kNeighbours of k, k excluded; NaN when there are none.
double medianAround(const std::vector<double>& steps, int k) {
  std::vector<double> around;
  for (int m = std::max(0, k - kNeighbours);
       m <= std::min(static_cast<int>(steps.size()) - 1, k + kNeighbours); ++m) {
    if (m != k) around.push_back(steps[static_cast<size_t>(m)]);
  }
  if (around.empty()) return std::nan("");
  auto middle = around.begin() + static_cast<std::ptrdiff_t>(around.size() / 2);
  std::nth_element(around.begin(), middle, around.end());
  return *middle;
}

// The worst ratio over the steps between neighbouring columns (or rows when transposed), and the
// largest excess of a step over its neighbours' median.
WorstLine worstLine(const formats::ImageRgba& image, bool transposed) {
  const std::vector<double> steps = lineSteps(image, transposed);
  WorstLine worst;
  for (int k = 0; k < static_cast<int>(steps.size()); ++k) {
    const double median = medianAround(steps, k);
    if (std::isnan(median)) continue;
    worst.excessLevels = std::max(worst.excessLevels, steps[static_cast<size_t>(k)] - median);
    if (median <= 0) continue;
    const double ratio = steps[static_cast<size_t>(k)] / median;
    if (ratio > worst.ratio) worst.ratio = ratio, worst.where = k;
  }
  return worst;
}

}  // namespace

SeamScore seamScore(const formats::ImageRgba& image) {
  SeamScore s;
  const WorstLine columns = worstLine(image, false);
  const WorstLine rows = worstLine(image, true);
  s.columns = columns.ratio;
  s.worstColumn = columns.where;
  s.rows = rows.ratio;
  s.worstRow = rows.where;
  s.score = std::max(s.columns, s.rows);
  s.excessStepLevels = std::max(columns.excessLevels, rows.excessLevels);
  return s;
}

LineStep columnStep(const formats::ImageRgba& image, int column) {
  const std::vector<double> steps = lineSteps(image, false);
  if (column < 0 || column >= static_cast<int>(steps.size())) return {};
  return {steps[static_cast<size_t>(column)], medianAround(steps, column)};
}

}  // namespace globe::bench
