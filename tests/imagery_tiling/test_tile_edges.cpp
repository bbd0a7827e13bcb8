// Exact edge samples inside JPEG tiles (formats/tile_edges.hpp): written by the tiler's encoder,
// put back by decodeImageRgba, skipped by decoders that do not know them, ignored when damaged.
#include "formats/tile_edges.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "formats/image_io.hpp"
#include "imagery_tiling/imagery_encoding.hpp"

namespace globe::imagery_tiling {
namespace {

// A noisy opaque 256×256 tile: JPEG cannot keep its pixels exactly.
formats::ImageRgba noisyTile() {
  formats::ImageRgba image{256, 256, std::vector<uint8_t>(256 * 256 * 4, 255)};
  uint32_t state = 12345;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    if (i % 4 == 3) continue;
    state = state * 1664525u + 1013904223u;
    image.pixels[i] = static_cast<uint8_t>(96 + (i / 4 % 256) / 4 + (state >> 28));
  }
  return image;
}

size_t ringDifferences(const formats::ImageRgba& a, const formats::ImageRgba& b) {
  size_t differing = 0;
  for (const auto& [row, column] : formats::ringOrder(a.widthPixels, a.heightPixels)) {
    const size_t i = (static_cast<size_t>(row) * a.widthPixels + column) * 4;
    for (int c = 0; c < 3; ++c) differing += a.pixels[i + c] != b.pixels[i + c] ? 1 : 0;
  }
  return differing;
}

TEST(TileEdges, TheRingComesBackExactlyAndTheRestAsJpeg) {
  const formats::ImageRgba tile = noisyTile();
  auto plain = encodeJpegFast(tile, 85);
  auto exact = encodeJpegFast(tile, 85, true);
  ASSERT_TRUE(plain && exact);
  EXPECT_GT(exact->size(), plain->size());
  EXPECT_LT(exact->size(), plain->size() + 4000);  // ~3 KB of ring, compressed
  auto a = formats::decodeImageRgba(*plain, "plain");
  auto b = formats::decodeImageRgba(*exact, "exact");
  ASSERT_TRUE(a && b);
  EXPECT_GT(ringDifferences(*a, tile), 100u);  // JPEG rounds the ring
  EXPECT_EQ(ringDifferences(*b, tile), 0u);    // the segment restores it
  // Inside, both are the same JPEG decoding.
  const size_t middle = (128 * 256 + 128) * 4;
  EXPECT_EQ(a->pixels[middle], b->pixels[middle]);
}

TEST(TileEdges, AbsentOrDamagedSegmentsLeaveTheJpegAsItIs) {
  const formats::ImageRgba tile = noisyTile();
  auto exact = encodeJpegFast(tile, 85, true);
  auto plain = encodeJpegFast(tile, 85);
  ASSERT_TRUE(exact && plain);
  auto reference = formats::decodeImageRgba(*plain, "plain");
  ASSERT_TRUE(reference);
  // Find the segment's tag and corrupt the zlib stream right after its head.
  std::vector<std::byte> damaged = *exact;
  size_t tag = 0;
  for (size_t i = 0; i + formats::kTileEdgesTagBytes < damaged.size(); ++i) {
    if (std::equal(formats::kTileEdgesTag, formats::kTileEdgesTag + formats::kTileEdgesTagBytes,
                   reinterpret_cast<const char*>(&damaged[i]))) {
      tag = i;
      break;
    }
  }
  ASSERT_GT(tag, 0u);
  for (size_t k = 0; k < 16; ++k)
    damaged[tag + formats::kTileEdgesTagBytes + 4 + k] ^= std::byte{0x5A};
  auto decoded = formats::decodeImageRgba(damaged, "damaged");
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(decoded->pixels, reference->pixels);  // the JPEG's own ring, not garbage
  // A segment for another size is not applied.
  formats::ImageRgba other{128, 128, std::vector<uint8_t>(128 * 128 * 4, 0)};
  EXPECT_FALSE(formats::restoreTileEdges(*exact, other));
  // Not a JPEG, or a JPEG without the segment: nothing.
  EXPECT_FALSE(formats::restoreTileEdges(std::vector<std::byte>(10), other));
  formats::ImageRgba copy = *reference;
  EXPECT_FALSE(formats::restoreTileEdges(*plain, copy));
}

// A served tile is untrusted: random damage to the segment (its length, tag, sizes, stream) and
// truncation anywhere never read out of bounds or crash (run under ASan in CI), and a restore
// that fails leaves the pixels as they were.
TEST(TileEdges, RandomDamageIsHandled) {
  auto exact = encodeJpegFast(noisyTile(), 85, true);
  ASSERT_TRUE(exact);
  size_t tag = 0;
  for (size_t i = 0; i + formats::kTileEdgesTagBytes < exact->size() && tag == 0; ++i) {
    if (std::equal(formats::kTileEdgesTag, formats::kTileEdgesTag + formats::kTileEdgesTagBytes,
                   reinterpret_cast<const char*>(&(*exact)[i]))) {
      tag = i;
    }
  }
  ASSERT_GT(tag, 4u);
  uint32_t state = 7;
  auto next = [&] { return state = state * 1664525u + 1013904223u; };
  size_t restored = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    std::vector<std::byte> bytes = *exact;
    const int flips = 1 + static_cast<int>(next() % 4);
    for (int f = 0; f < flips; ++f) {
      // Mostly in the segment's marker, length, head and stream; sometimes anywhere before it.
      const size_t at = tag - 4 + next() % 64;
      bytes[at] = std::byte(static_cast<uint8_t>(next() >> 24));
    }
    if (trial % 5 == 0) bytes.resize(next() % bytes.size());
    formats::ImageRgba image{256, 256, std::vector<uint8_t>(256 * 256 * 4, 7)};
    if (formats::restoreTileEdges(bytes, image)) {
      ++restored;
    } else {
      EXPECT_TRUE(
          std::all_of(image.pixels.begin(), image.pixels.end(), [](uint8_t v) { return v == 7; }));
    }
  }
  EXPECT_LT(restored, 3000u);
}

}  // namespace
}  // namespace globe::imagery_tiling
