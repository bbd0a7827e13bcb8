#include "tools/bench_render/image_shift_error.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

namespace globe::bench {
namespace {

// Fraction of a's pixels with no pixel in b within the shift whose channels are all within the
// tolerance.
double unmatched(const formats::ImageRgba& a, const formats::ImageRgba& b,
                 const ShiftErrorOptions& o) {
  const int w = a.widthPixels, h = a.heightPixels;
  auto at = [w](const formats::ImageRgba& image, int x, int y) {
    return &image.pixels[(static_cast<size_t>(y) * w + x) * 4];
  };
  size_t missing = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const uint8_t* p = at(a, x, y);
      bool found = false;
      for (int dy = -o.shiftPixels; dy <= o.shiftPixels && !found; ++dy) {
        const int yy = y + dy;
        if (yy < 0 || yy >= h) continue;
        for (int dx = -o.shiftPixels; dx <= o.shiftPixels && !found; ++dx) {
          const int xx = x + dx;
          if (xx < 0 || xx >= w) continue;
          const uint8_t* q = at(b, xx, yy);
          found = std::abs(p[0] - q[0]) <= o.channelTolerance &&
                  std::abs(p[1] - q[1]) <= o.channelTolerance &&
                  std::abs(p[2] - q[2]) <= o.channelTolerance;
        }
      }
      missing += found ? 0 : 1;
    }
  }
  return w * h == 0 ? 0.0 : static_cast<double>(missing) / (static_cast<double>(w) * h);
}

}  // namespace

Result<ShiftError> shiftError(const formats::ImageRgba& image, const formats::ImageRgba& reference,
                              const ShiftErrorOptions& options) {
  if (image.widthPixels != reference.widthPixels || image.heightPixels != reference.heightPixels) {
    return makeError("images differ in size: " + std::to_string(image.widthPixels) + "x" +
                     std::to_string(image.heightPixels) + " and " +
                     std::to_string(reference.widthPixels) + "x" +
                     std::to_string(reference.heightPixels));
  }
  ShiftError error;
  error.imageUnmatched = unmatched(image, reference, options);
  error.referenceUnmatched = unmatched(reference, image, options);
  error.fraction = std::max(error.imageUnmatched, error.referenceUnmatched);
  return error;
}

}  // namespace globe::bench
