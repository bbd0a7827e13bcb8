#include "regression/image_difference.hpp"

#include <algorithm>
#include <cstdlib>

namespace globe::regression {

ImageDifference compareImages(const formats::ImageRgba& expected, const formats::ImageRgba& actual,
                              int channelThreshold) {
  ImageDifference result;
  if (expected.widthPixels != actual.widthPixels || expected.heightPixels != actual.heightPixels) {
    return result;
  }
  result.sameSize = true;
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
    const bool differs = worst > channelThreshold;
    differing += differs ? 1 : 0;
    for (size_t c = 0; c < 3; ++c) {
      const auto dimmed = static_cast<uint8_t>(expected.pixels[4 * p + c] / 4);
      result.diffRgba[4 * p + c] = differs ? (c == 0 ? uint8_t{255} : uint8_t{0}) : dimmed;
    }
    result.diffRgba[4 * p + 3] = 255;
  }
  const double count = pixels == 0 ? 1.0 : static_cast<double>(pixels);
  result.differingFraction = static_cast<double>(differing) / count;
  result.largestChannelDifference = largest;
  result.meanChannelDifference = sum / (3.0 * count);
  return result;
}

}  // namespace globe::regression
