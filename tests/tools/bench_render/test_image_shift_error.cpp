// The render benchmark's image error: forgiving up to the shift, strict beyond it.
#include <gtest/gtest.h>

#include "tools/bench_render/image_shift_error.hpp"

namespace globe::bench {
namespace {

// A white 8×8 square on black, its corner at (x0, y0), in a 40×30 image.
formats::ImageRgba square(int x0, int y0) {
  formats::ImageRgba image{40, 30, std::vector<uint8_t>(40 * 30 * 4, 0)};
  for (int y = y0; y < y0 + 8; ++y) {
    for (int x = x0; x < x0 + 8; ++x) {
      for (int c = 0; c < 3; ++c) image.pixels[(static_cast<size_t>(y) * 40 + x) * 4 + c] = 255;
    }
  }
  return image;
}

TEST(ImageShiftError, ZeroForTheSameImageAndWithinTheShift) {
  auto same = shiftError(square(10, 10), square(10, 10));
  ASSERT_TRUE(same);
  EXPECT_EQ(same->fraction, 0.0);
  auto shifted = shiftError(square(12, 8), square(10, 10));
  ASSERT_TRUE(shifted);
  EXPECT_EQ(shifted->fraction, 0.0);
}

TEST(ImageShiftError, CountsWhatMovedFurtherOrVanished) {
  auto moved = shiftError(square(13, 10), square(10, 10));
  ASSERT_TRUE(moved);
  // Its east column is 3 px from any white (8 pixels), and the middle of the black column it
  // left behind is more than 2 px from any black (4 pixels); the same the other way round.
  EXPECT_EQ(moved->imageUnmatched, 12.0 / 1200.0);
  EXPECT_EQ(moved->referenceUnmatched, 12.0 / 1200.0);
  formats::ImageRgba black{40, 30, std::vector<uint8_t>(40 * 30 * 4, 0)};
  auto vanished = shiftError(black, square(10, 10));
  ASSERT_TRUE(vanished);
  EXPECT_EQ(vanished->imageUnmatched, 16.0 / 1200.0);  // black more than 2 px inside the square
  EXPECT_EQ(vanished->referenceUnmatched, 64.0 / 1200.0);
  EXPECT_EQ(vanished->fraction, 64.0 / 1200.0);
}

TEST(ImageShiftError, RefusesImagesOfDifferentSizes) {
  formats::ImageRgba small{4, 4, std::vector<uint8_t>(64, 0)};
  auto error = shiftError(small, square(0, 0));
  ASSERT_FALSE(error);
  EXPECT_NE(error.error().find("differ in size"), std::string::npos);
}

}  // namespace
}  // namespace globe::bench
