// Per-pixel comparison of a rendered view with its reference: how many pixels differ by more than
// a channel threshold, and a diff image that shows where.
#pragma once

#include <cstdint>
#include <vector>

#include "formats/image_io.hpp"

namespace globe::regression {

struct ImageDifference {
  bool sameSize = false;          // false: nothing else is filled in
  double differingFraction = 1;   // pixels whose largest channel difference exceeds the threshold
  int largestChannelDifference = 255;
  double meanChannelDifference = 255;  // over the red, green and blue of every pixel
  std::vector<uint8_t> diffRgba;  // differing pixels red over a dimmed copy of the expected image
};

// Alpha is ignored (snapshots are opaque). channelThreshold 0..255.
ImageDifference compareImages(const formats::ImageRgba& expected, const formats::ImageRgba& actual,
                              int channelThreshold);

}  // namespace globe::regression
