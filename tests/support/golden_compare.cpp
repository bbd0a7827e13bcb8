#include "tests/support/golden_compare.hpp"

#include <algorithm>
#include <cstdlib>

namespace globe::testing {

ImageDifference compareImages(const formats::ImageRgba& expected, const formats::ImageRgba& actual,
                              int channelTolerance) {
  ImageDifference result;
  if (expected.widthPixels != actual.widthPixels || expected.heightPixels != actual.heightPixels) {
    return result;
  }
  const size_t pixels = static_cast<size_t>(expected.widthPixels) * expected.heightPixels;
  result.diffRgba.resize(pixels * 4);
  size_t differing = 0;
  int largest = 0;
  double sum = 0.0;
  for (size_t p = 0; p < pixels; ++p) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int{expected.pixels[4 * p + c]} - int{actual.pixels[4 * p + c]});
      worst = std::max(worst, d);
      sum += d;
    }
    largest = std::max(largest, worst);
    const bool differs = worst > channelTolerance;
    differing += differs ? 1 : 0;
    for (size_t c = 0; c < 3; ++c) {
      const auto dimmed = static_cast<uint8_t>(expected.pixels[4 * p + c] / 4);
      result.diffRgba[4 * p + c] = differs ? (c == 0 ? uint8_t{255} : uint8_t{0}) : dimmed;
    }
    result.diffRgba[4 * p + 3] = 255;
  }
  result.differingFraction = static_cast<double>(differing) / static_cast<double>(pixels);
  result.largestChannelDifference = largest;
  result.meanChannelDifference = sum / (3.0 * static_cast<double>(pixels));
  return result;
}

}  // namespace globe::testing
