// Image comparison for screenshot regression: per-pixel tolerance, a budget of differing pixels,
// and a diff image that shows where they differ.
#pragma once

#include <cstdint>
#include <vector>

#include "formats/image_io.hpp"

namespace globe::testing {

struct ImageDifference {
  double differingFraction = 1;  // pixels whose largest channel difference exceeds the tolerance
  int largestChannelDifference = 255;
  double meanChannelDifference = 255;  // over the red, green and blue of every pixel
  std::vector<uint8_t> diffRgba;  // differing pixels red over a dimmed copy of the expected image
};

ImageDifference compareImages(const formats::ImageRgba& expected, const formats::ImageRgba& actual,
                              int channelTolerance);

}  // namespace globe::testing
