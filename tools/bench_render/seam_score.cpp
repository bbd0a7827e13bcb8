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

// The worst ratio over the steps between neighbouring columns (or rows when transposed), and the
// largest excess of a step over its neighbours' median.
WorstLine worstLine(const formats::ImageRgba& image, bool transposed) {
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
  WorstLine worst;
  std::vector<double> around;
  for (int k = 0; k < static_cast<int>(steps.size()); ++k) {
    around.clear();
    for (int m = std::max(0, k - kNeighbours);
         m <= std::min(static_cast<int>(steps.size()) - 1, k + kNeighbours); ++m) {
      if (m != k) around.push_back(steps[static_cast<size_t>(m)]);
    }
    if (around.empty()) continue;
    auto middle = around.begin() + static_cast<std::ptrdiff_t>(around.size() / 2);
    std::nth_element(around.begin(), middle, around.end());
    worst.excessLevels = std::max(worst.excessLevels, steps[static_cast<size_t>(k)] - *middle);
    if (*middle <= 0) continue;
    const double ratio = steps[static_cast<size_t>(k)] / *middle;
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

}  // namespace globe::bench
