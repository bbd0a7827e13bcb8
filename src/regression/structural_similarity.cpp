#include "regression/structural_similarity.hpp"

#include <algorithm>

namespace globe::regression {
namespace {

constexpr int kWindow = 8;
constexpr int kStride = 4;  // windows overlap by half: an edge is never only at a window's rim
// The constants of the paper for 8-bit samples: (0.01 * 255)^2 and (0.03 * 255)^2.
constexpr double kC1 = 6.5025;
constexpr double kC2 = 58.5225;

double windowSsim(const formats::ImageRgba& a, const formats::ImageRgba& b, int x0, int y0, int c) {
  double sumA = 0, sumB = 0, sumAA = 0, sumBB = 0, sumAB = 0;
  for (int y = y0; y < y0 + kWindow; ++y) {
    const size_t row = static_cast<size_t>(y) * static_cast<size_t>(a.widthPixels);
    for (int x = x0; x < x0 + kWindow; ++x) {
      const size_t i = 4 * (row + static_cast<size_t>(x)) + static_cast<size_t>(c);
      const double va = a.pixels[i];
      const double vb = b.pixels[i];
      sumA += va;
      sumB += vb;
      sumAA += va * va;
      sumBB += vb * vb;
      sumAB += va * vb;
    }
  }
  constexpr double n = kWindow * kWindow;
  const double meanA = sumA / n, meanB = sumB / n;
  const double varA = sumAA / n - meanA * meanA;
  const double varB = sumBB / n - meanB * meanB;
  const double cov = sumAB / n - meanA * meanB;
  return ((2 * meanA * meanB + kC1) * (2 * cov + kC2)) /
         ((meanA * meanA + meanB * meanB + kC1) * (varA + varB + kC2));
}

}  // namespace

Similarity structuralSimilarity(const formats::ImageRgba& expected,
                                const formats::ImageRgba& actual) {
  Similarity result;
  if (expected.widthPixels != actual.widthPixels || expected.heightPixels != actual.heightPixels ||
      expected.widthPixels < kWindow || expected.heightPixels < kWindow) {
    return result;
  }
  result.meanSsim = 1;
  result.lowestWindowSsim = 1;
  for (int c = 0; c < 3; ++c) {
    double sum = 0;
    size_t windows = 0;
    for (int y = 0; y + kWindow <= expected.heightPixels; y += kStride) {
      for (int x = 0; x + kWindow <= expected.widthPixels; x += kStride) {
        const double s = windowSsim(expected, actual, x, y, c);
        sum += s;
        ++windows;
        result.lowestWindowSsim = std::min(result.lowestWindowSsim, s);
      }
    }
    result.meanSsim = std::min(result.meanSsim, sum / static_cast<double>(windows));
  }
  return result;
}

}  // namespace globe::regression
