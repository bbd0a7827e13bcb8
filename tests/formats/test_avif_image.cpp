// AVIF imagery: a real 512 px WebP map tile (USGS topo over Mt Whitney) written as a lossless
// AVIF decodes to the same pixels; broken, oversized and non-AVIF bytes are told apart.
#include <gtest/gtest.h>

#include <cstddef>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "formats/avif_image.hpp"
#include "formats/image_io.hpp"
#include "tests/support/avif_encoder.hpp"

namespace globe::formats {
namespace {

std::vector<std::byte> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  const auto* p = reinterpret_cast<const std::byte*>(text.data());
  return {p, p + text.size()};
}

ImageRgba realTile() {
  const auto bytes = readBytes(std::string(GLOBE_SOURCE_DIR) +
                               "/tests/data/interop/raster-tiles/"
                               "xyz-usgs-topo-mt-whitney-webp512/11/350/800.webp");
  auto image = decodeImageRgba(bytes, "800.webp");
  EXPECT_TRUE(image) << image.error();
  return image ? *image : ImageRgba{};
}

TEST(AvifImage, ALosslessRealTileDecodesToItsPixels) {
  const ImageRgba tile = realTile();
  ASSERT_EQ(tile.widthPixels, 512);
  const std::vector<std::byte> avif = testing::encodeAvifLossless(tile);
  ASSERT_FALSE(avif.empty());
  EXPECT_TRUE(isAvif(avif));
  auto decoded = decodeImageRgba(avif, "tile.avif");  // found by its bytes, as a service's tile is
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(decoded->widthPixels, 512);
  EXPECT_EQ(decoded->heightPixels, 512);
  EXPECT_EQ(decoded->pixels, tile.pixels);
}

TEST(AvifImage, BrokenOversizedAndOtherBytesAreToldApart) {
  ImageRgba tile = realTile();
  std::vector<std::byte> avif = testing::encodeAvifLossless(tile);
  ASSERT_GT(avif.size(), 1000u);
  // Cut short: an error naming the tile, never pixels.
  const std::vector<std::byte> cut(avif.begin(), avif.begin() + static_cast<long>(avif.size() / 2));
  auto broken = decodeImageRgba(cut, "cut.avif");
  ASSERT_FALSE(broken);
  EXPECT_NE(broken.error().find("cut.avif"), std::string::npos) << broken.error();
  // Wider than the decoder takes: refused from its header.
  ImageRgba wide;
  wide.widthPixels = kMaxDecodedImageSide + 1;
  wide.heightPixels = 2;
  wide.pixels.assign(static_cast<size_t>(wide.widthPixels) * 2 * 4, 200);
  const std::vector<std::byte> wideAvif = testing::encodeAvifLossless(wide);
  ASSERT_FALSE(wideAvif.empty());
  auto refused = decodeAvif(wideAvif, "wide.avif");
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("wide.avif"), std::string::npos) << refused.error();
  // PNG, WebP and an ISO-BMFF file of another brand (an MP4) are not AVIF.
  const auto webp = readBytes(std::string(GLOBE_SOURCE_DIR) +
                              "/tests/data/interop/raster-tiles/"
                              "xyz-usgs-topo-mt-whitney-webp512/11/350/800.webp");
  EXPECT_FALSE(isAvif(webp));
  auto png = encodePng(tile);
  ASSERT_TRUE(png);
  EXPECT_FALSE(isAvif(*png));
  std::vector<std::byte> mp4 = avif;
  const size_t ftypBytes = std::to_integer<size_t>(mp4[3]);  // "ftyp" boxes are short
  ASSERT_EQ(
      std::to_integer<int>(mp4[0]) + std::to_integer<int>(mp4[1]) + std::to_integer<int>(mp4[2]),
      0);
  for (size_t i = 8; i < ftypBytes; ++i) mp4[i] = std::byte{'x'};  // every brand
  EXPECT_FALSE(isAvif(mp4));
}

}  // namespace
}  // namespace globe::formats
