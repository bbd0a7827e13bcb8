// formats::encodePngRgb: RGB PNGs (colour type 2) that decode to the same pixels, opaque, with
// the adaptive filters at level 6 and with Up at level 1 (the elevation tiles' encoding).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "formats/image_io.hpp"
#include "formats/png_encoder.hpp"

namespace globe::formats {
namespace {

TEST(PngEncoder, RgbDecodesToTheSamePixelsWithEitherEncoding) {
  constexpr int kWidth = 37, kHeight = 23;
  std::vector<uint8_t> rgb;
  for (int i = 0; i < kWidth * kHeight; ++i) {
    // A smooth field in the high bytes, noise in the low one, as in a Terrarium tile.
    rgb.push_back(static_cast<uint8_t>(128 + i / 300));
    rgb.push_back(static_cast<uint8_t>(i * 7 / 5));
    rgb.push_back(static_cast<uint8_t>((i * 2654435761U) >> 24));
  }
  for (const PngEncoding encoding : {PngEncoding{}, PngEncoding{1, false}}) {
    auto png = encodePngRgb(rgb, kWidth, kHeight, encoding);
    ASSERT_TRUE(png) << png.error();
    ASSERT_GT(png->size(), 26U);
    EXPECT_EQ((*png)[25], std::byte{2}) << "colour type RGB";
    auto image = decodeImageRgba(*png, "rgb.png");
    ASSERT_TRUE(image) << image.error();
    ASSERT_EQ(image->widthPixels, kWidth);
    ASSERT_EQ(image->heightPixels, kHeight);
    for (size_t i = 0; i < rgb.size() / 3; ++i) {
      for (size_t k = 0; k < 3; ++k) ASSERT_EQ(image->pixels[i * 4 + k], rgb[i * 3 + k]) << i;
      ASSERT_EQ(image->pixels[i * 4 + 3], 255) << i;
    }
  }
}

TEST(PngEncoder, RgbRefusesAWrongSizeAndAnUnknownLevel) {
  const std::vector<uint8_t> rgb(3 * 4 * 4, 100);
  EXPECT_FALSE(encodePngRgb(rgb, 4, 5));
  auto png = encodePngRgb(rgb, 4, 4, PngEncoding{13, true});
  ASSERT_FALSE(png);
  EXPECT_NE(png.error().find("deflate level 13"), std::string::npos) << png.error();
  EXPECT_FALSE(encodePngRgb(rgb, 4, 4, PngEncoding{0, true}));
}

}  // namespace
}  // namespace globe::formats
