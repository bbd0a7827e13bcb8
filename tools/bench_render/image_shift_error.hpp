// The image error of a level-of-detail setting against a finer reference: the fraction of pixels
// with no pixel of the same colour (every channel within a tolerance) anywhere within a small
// shift in the other image, both ways. A 2 px shift forgives the sub-pixel movements of
// silhouettes between LODs; what remains are features drawn wrong or missing.
#pragma once

#include "core/result.hpp"
#include "formats/image_io.hpp"

namespace globe::bench {

struct ShiftErrorOptions {
  int shiftPixels = 2;
  int channelTolerance = 24;  // of 255, as the screenshot goldens
};

struct ShiftError {
  double fraction = 0;            // the larger of the two below
  double imageUnmatched = 0;      // pixels of the image with no match in the reference
  double referenceUnmatched = 0;  // pixels of the reference with no match in the image
};

// Images of different sizes are refused.
Result<ShiftError> shiftError(const formats::ImageRgba& image, const formats::ImageRgba& reference,
                              const ShiftErrorOptions& options = {});

}  // namespace globe::bench
