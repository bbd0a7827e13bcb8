// Structural similarity (SSIM; Wang, Bovik, Sheikh and Simoncelli 2004), the perceptual metric of
// globe regress. Why SSIM: it compares each 8x8 window's mean, contrast and structure, so what a
// driver's rounding moves (a level or two of brightness everywhere, dithering noise) barely lowers
// it, while what a person sees (an edge moved, a line recoloured, a texture blurred) lowers the
// windows it touches. The figure is the lowest, over red, green and blue, of the mean over windows
// and, separately, the lowest window anywhere (a small visible change cannot hide in the mean).
#pragma once

#include "formats/image_io.hpp"

namespace globe::regression {

struct Similarity {
  double meanSsim = 0;    // 1: identical; of the channel with the lowest mean
  double lowestWindowSsim = 0;  // the least similar 8x8 window of any channel
};

// Both images must have the same size (at least 8x8); otherwise both figures are 0.
Similarity structuralSimilarity(const formats::ImageRgba& expected,
                                const formats::ImageRgba& actual);

}  // namespace globe::regression
