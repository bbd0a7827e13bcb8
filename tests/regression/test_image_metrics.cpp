// The metrics of globe regress on images made to show what each sees: a driver-like shift of a
// level or two everywhere (SSIM barely moves; a zero channel threshold would call every pixel
// different), a line recoloured and an edge moved (SSIM and the pixel count both see them).
#include <gtest/gtest.h>

#include <cstdint>

#include "regression/image_difference.hpp"
#include "regression/structural_similarity.hpp"

namespace globe::regression {
namespace {

formats::ImageRgba gradient(int width, int height) {
  formats::ImageRgba image{width, height, std::vector<uint8_t>(size_t(width) * height * 4, 255)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      uint8_t* p = &image.pixels[4 * (size_t(y) * width + x)];
      p[0] = static_cast<uint8_t>(40 + x * 2);
      p[1] = static_cast<uint8_t>(60 + y * 2);
      p[2] = static_cast<uint8_t>(120 + ((x / 8 + y / 8) % 2) * 60);  // a checker: structure
    }
  }
  return image;
}

void paintRow(formats::ImageRgba& image, int row, uint8_t r, uint8_t g, uint8_t b) {
  for (int x = 0; x < image.widthPixels; ++x) {
    uint8_t* p = &image.pixels[4 * (size_t(row) * image.widthPixels + x)];
    p[0] = r;
    p[1] = g;
    p[2] = b;
  }
}

TEST(ImageMetrics, IdenticalImagesMatchExactly) {
  const auto image = gradient(96, 64);
  const auto difference = compareImages(image, image, 0);
  ASSERT_TRUE(difference.sameSize);
  EXPECT_EQ(difference.differingFraction, 0.0);
  EXPECT_EQ(difference.largestChannelDifference, 0);
  const auto similarity = structuralSimilarity(image, image);
  EXPECT_DOUBLE_EQ(similarity.meanSsim, 1.0);
  EXPECT_DOUBLE_EQ(similarity.lowestWindowSsim, 1.0);
}

TEST(ImageMetrics, ABrightnessShiftOfTwoLevelsIsInvisibleToSsim) {
  const auto expected = gradient(96, 64);
  auto actual = expected;
  for (size_t i = 0; i < actual.pixels.size(); i += 4) {
    for (size_t c = 0; c < 3; ++c) actual.pixels[i + c] = static_cast<uint8_t>(actual.pixels[i + c] + 2);
  }
  EXPECT_EQ(compareImages(expected, actual, 0).differingFraction, 1.0);
  EXPECT_EQ(compareImages(expected, actual, 16).differingFraction, 0.0);
  EXPECT_GT(structuralSimilarity(expected, actual).meanSsim, 0.999);
}

TEST(ImageMetrics, ARecolouredLineIsSeenByBothMetrics) {
  auto expected = gradient(96, 64);
  paintRow(expected, 30, 255, 0, 0);  // a red line
  auto actual = expected;
  paintRow(actual, 30, 0, 0, 255);  // now blue: the same luminance would hide it from grey SSIM
  const auto difference = compareImages(expected, actual, 16);
  EXPECT_NEAR(difference.differingFraction, 1.0 / 64, 1e-12);
  EXPECT_EQ(difference.largestChannelDifference, 255);
  const auto similarity = structuralSimilarity(expected, actual);
  EXPECT_LT(similarity.lowestWindowSsim, 0.8);
  EXPECT_LT(similarity.meanSsim, 0.99);  // fails the default tolerance
  // The diff image: that row red, the rest a dimmed copy of the expected picture.
  EXPECT_EQ(difference.diffRgba[4 * (30 * 96 + 5)], 255);
  EXPECT_EQ(difference.diffRgba[4 * (30 * 96 + 5) + 1], 0);
  EXPECT_EQ(difference.diffRgba[4 * (10 * 96 + 5)], expected.pixels[4 * (10 * 96 + 5)] / 4);
}

TEST(ImageMetrics, AnEdgeMovedTwoPixelsLowersSsim) {
  formats::ImageRgba expected{64, 64, std::vector<uint8_t>(64 * 64 * 4, 255)};
  auto actual = expected;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (x < 30) std::fill_n(&expected.pixels[4 * (y * 64 + x)], 3, uint8_t{20});
      if (x < 32) std::fill_n(&actual.pixels[4 * (y * 64 + x)], 3, uint8_t{20});
    }
  }
  const auto similarity = structuralSimilarity(expected, actual);
  EXPECT_LT(similarity.meanSsim, 0.99);
  EXPECT_LT(similarity.lowestWindowSsim, 0.5);
}

TEST(ImageMetrics, DifferentSizesAreNotCompared) {
  const auto a = gradient(96, 64);
  const auto b = gradient(64, 96);
  EXPECT_FALSE(compareImages(a, b, 16).sameSize);
  EXPECT_EQ(structuralSimilarity(a, b).meanSsim, 0.0);
  const auto tiny = gradient(4, 4);
  EXPECT_EQ(structuralSimilarity(tiny, tiny).meanSsim, 0.0) << "smaller than one 8x8 window";
}

}  // namespace
}  // namespace globe::regression
