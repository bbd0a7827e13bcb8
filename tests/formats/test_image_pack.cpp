// The imagery pack format: round trip, and damaged or forged files refused with the file named.
#include <gtest/gtest.h>

#include <cstring>

#include "core/big_endian.hpp"
#include "core/crc32.hpp"
#include "formats/image_io.hpp"
#include "formats/image_pack.hpp"
#include "formats/layer_manifest.hpp"

namespace globe::formats {
namespace {

const std::filesystem::path kPath = "layer/L3/1_0.pack";

std::vector<std::byte> bytesOf(const std::string& text) {
  std::vector<std::byte> bytes(text.size());
  std::memcpy(bytes.data(), text.data(), text.size());
  return bytes;
}

std::vector<std::vector<std::byte>> samplePayloads(uint32_t p) {
  std::vector<std::vector<std::byte>> payloads(size_t{p} * p);
  payloads[0] = bytesOf("first tile");
  payloads[5] = bytesOf("a second, longer tile payload");
  payloads[p * p - 1] = bytesOf("last");
  return payloads;
}

// Rewrites the header+index CRC after a deliberate edit, so only the edit itself is judged.
void resealIndex(std::vector<std::byte>& bytes, uint32_t p) {
  const uint64_t end = imagePackIndexEndOffset(p);
  core::storeBigEndian32(&bytes[bytes.size() - 4], core::crc32(std::span(bytes).first(end)));
}

TEST(ImagePack, RoundTrip) {
  const PackId id{3, 1, 0};
  const auto payloads = samplePayloads(4);
  const auto bytes = encodeImagePack(id, 4, payloads);
  EXPECT_EQ(bytes.size(), imagePackIndexEndOffset(4) + 10 + 29 + 4 + 4);
  auto pack = decodeImagePack(bytes, kPath);
  ASSERT_TRUE(pack) << pack.error();
  EXPECT_EQ(pack->index.id, id);
  EXPECT_EQ(pack->index.tilesPerSide, 4u);
  EXPECT_EQ(pack->index.presentCount(), 3u);
  EXPECT_EQ(pack->payloads, payloads);
  EXPECT_FALSE(pack->index.entries[1].present());
}

TEST(ImagePack, EmptyPackRoundTrips) {
  const auto bytes = encodeImagePack({0, 0, 0}, 2, std::vector<std::vector<std::byte>>(4));
  auto pack = decodeImagePack(bytes, kPath);
  ASSERT_TRUE(pack) << pack.error();
  EXPECT_EQ(pack->index.presentCount(), 0u);
}

TEST(ImagePack, CorruptPayloadIsRefusedNamingTheFile) {
  auto bytes = encodeImagePack({3, 1, 0}, 4, samplePayloads(4));
  bytes[imagePackIndexEndOffset(4) + 12] ^= std::byte{1};  // inside the second payload
  auto pack = decodeImagePack(bytes, kPath);
  ASSERT_FALSE(pack);
  EXPECT_NE(pack.error().find(kPath.string()), std::string::npos) << pack.error();
  EXPECT_NE(pack.error().find("CRC mismatch in tile slot 5"), std::string::npos) << pack.error();
}

TEST(ImagePack, CorruptIndexIsRefused) {
  auto bytes = encodeImagePack({3, 1, 0}, 4, samplePayloads(4));
  bytes[kImagePackHeaderBytes + 5 * kImagePackEntryBytes + 9] ^= std::byte{4};  // a length
  auto pack = decodeImagePack(bytes, kPath);
  ASSERT_FALSE(pack);
  EXPECT_NE(pack.error().find(kPath.string() + ": CRC mismatch in the header and index"),
            std::string::npos)
      << pack.error();
}

TEST(ImagePack, TruncatedPackIsRefused) {
  const auto bytes = encodeImagePack({3, 1, 0}, 4, samplePayloads(4));
  for (size_t keep : {size_t{0}, size_t{20}, size_t{100}, bytes.size() - 1}) {
    auto pack = decodeImagePack(std::span(bytes).first(keep), kPath);
    ASSERT_FALSE(pack) << keep;
    EXPECT_NE(pack.error().find(kPath.string()), std::string::npos) << pack.error();
  }
}

TEST(ImagePack, HostileIndexEntriesAreRefused) {
  const auto original = encodeImagePack({3, 1, 0}, 4, samplePayloads(4));
  const size_t entry5 = kImagePackHeaderBytes + 5 * kImagePackEntryBytes;
  struct Forgery {
    const char* what;
    uint64_t offset;
    uint32_t length;
  };
  const Forgery forgeries[] = {
      {"offset past the end", uint64_t{1} << 40, 29},
      {"offset into the index", 8, 29},
      {"length past the end", imagePackIndexEndOffset(4) + 10, 0xFFFFFF00u},
      {"length over the maximum", imagePackIndexEndOffset(4) + 10, kImageTileMaximumBytes + 1},
      {"zero length", imagePackIndexEndOffset(4) + 10, 0},
      {"overlapping the first payload", imagePackIndexEndOffset(4), 29},
  };
  for (const Forgery& f : forgeries) {
    auto bytes = original;
    core::storeBigEndian64(&bytes[entry5], f.offset);
    core::storeBigEndian32(&bytes[entry5 + 8], f.length);
    resealIndex(bytes, 4);
    auto pack = decodeImagePack(bytes, kPath);
    ASSERT_FALSE(pack) << f.what;
    EXPECT_NE(pack.error().find(kPath.string()), std::string::npos) << f.what;
  }
  // A header claiming a huge pack: refused before anything of that size is allocated.
  auto bytes = original;
  core::storeBigEndian32(&bytes[24], 100000);
  resealIndex(bytes, 4);
  auto pack = decodeImagePack(bytes, kPath);
  ASSERT_FALSE(pack);
  EXPECT_NE(pack.error().find("tiles per side 100000 out of range"), std::string::npos)
      << pack.error();
}

TEST(ImagePack, WrongMagicOrVersionIsRefused) {
  auto bytes = encodeImagePack({3, 1, 0}, 4, samplePayloads(4));
  auto other = bytes;
  other[6] = std::byte{'K'};  // GLOBEPK1: a terrain pack
  EXPECT_FALSE(decodeImagePack(other, kPath));
  core::storeBigEndian32(&bytes[8], 2);
  resealIndex(bytes, 4);
  auto pack = decodeImagePack(bytes, kPath);
  ASSERT_FALSE(pack);
  EXPECT_NE(pack.error().find("format version 2"), std::string::npos) << pack.error();
}

TEST(LayerManifest, JsonRoundTrip) {
  LayerManifest m;
  m.packTilesPerSide = 8;
  m.levels.push_back({0, 2, {-180, -90, 180, 90}, {{0, 0, 0}}});
  m.levels.push_back({1, 3, {-180, 0, 0, 90}, {{1, 0, 0}}});
  m.sources.push_back({"a.tif",
                       "GTiff",
                       400,
                       360,
                       "EPSG:32618",
                       0.0027,
                       {-78, 24, -77, 25},
                       1,
                       "RGB, nodata transparent",
                       ""});
  m.bounds = {-180, -90, 180, 90};
  m.planFingerprint = "crc32:01234567";
  auto back = layerManifestFromJson(layerManifestToJson(m), "layer.json");
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->maxLevel(), 1u);
  EXPECT_EQ(back->tileCount(), 5u);
  EXPECT_EQ(back->packTilesPerSide, 8u);
  EXPECT_EQ(back->sources, m.sources);
  EXPECT_EQ(back->levels[1].packs, m.levels[1].packs);
  EXPECT_EQ(back->bounds, m.bounds);
  EXPECT_EQ(back->planFingerprint, m.planFingerprint);
}

// Version 2 carries the pixel grid; area layers are still written as version 1 (older readers
// draw them right) and version 1 reads as area.
TEST(LayerManifest, ThePixelGridRoundTripsAndVersionOneReadsAsArea) {
  LayerManifest m;
  m.levels.push_back({0, 1, {-180, -90, 0, 90}, {{0, 0, 0}}});
  for (const ImageryPixelGrid grid : {ImageryPixelGrid::Area, ImageryPixelGrid::Edges}) {
    m.pixelGrid = grid;
    const std::string text = layerManifestToJson(m);
    EXPECT_NE(text.find(grid == ImageryPixelGrid::Edges ? "\"formatVersion\": 2"
                                                        : "\"formatVersion\": 1"),
              std::string::npos);
    auto back = layerManifestFromJson(text, "layer.json");
    ASSERT_TRUE(back) << back.error();
    EXPECT_EQ(back->pixelGrid, grid);
  }
  m.pixelGrid = ImageryPixelGrid::Edges;
  std::string text = layerManifestToJson(m);
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\"pixelGrid\": \"edges\"",
                                                                     "\"pixelGrid\": \"corners\""},
                                 {"\"formatVersion\": 2", "\"formatVersion\": 3"}}) {
    std::string bad = text;
    bad.replace(bad.find(from), from.size(), to);
    auto parsed = layerManifestFromJson(bad, "x/layer.json");
    ASSERT_FALSE(parsed) << to;
    EXPECT_NE(parsed.error().find("x/layer.json"), std::string::npos) << parsed.error();
  }
}

TEST(LayerManifest, BadManifestsAreRefusedNamingTheFile) {
  LayerManifest m;
  m.levels.push_back({0, 1, {-180, -90, 0, 90}, {{0, 0, 0}}});
  const std::string good = layerManifestToJson(m);
  const std::pair<std::string, std::string> edits[] = {
      {"\"kind\": \"imagery\"", "\"kind\": \"terrain\""},
      {"\"tileSizePixels\": 256", "\"tileSizePixels\": 512"},
      {"\"packTilesPerSide\": 16", "\"packTilesPerSide\": 0"},
      {"\"level\": 0", "\"level\": 1"},
      {"\"formatVersion\": 1", "\"formatVersion\": 1e64"},
  };
  for (const auto& [from, to] : edits) {
    std::string text = good;
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    auto parsed = layerManifestFromJson(text, "x/layer.json");
    ASSERT_FALSE(parsed) << to;
    EXPECT_NE(parsed.error().find("x/layer.json"), std::string::npos) << parsed.error();
  }
  EXPECT_FALSE(layerManifestFromJson("{", "x/layer.json"));
}

ImageRgba gradient(int width, int height, bool transparentCorner) {
  ImageRgba image{width, height, std::vector<uint8_t>(size_t(width) * height * 4)};
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      uint8_t* p = &image.pixels[(size_t(r) * width + c) * 4];
      p[0] = static_cast<uint8_t>(c * 4), p[1] = static_cast<uint8_t>(r * 4), p[2] = 128;
      p[3] = transparentCorner && r < 8 && c < 8 ? 0 : 255;
    }
  }
  return image;
}

TEST(ImageCodecs, PngRoundTripsExactlyAndJpegClosely) {
  const ImageRgba image = gradient(64, 48, true);
  auto png = encodePng(image);
  ASSERT_TRUE(png) << png.error();
  auto back = decodeImageRgba(*png, "png");
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->widthPixels, 64);
  EXPECT_EQ(back->pixels, image.pixels);

  auto jpeg = encodeJpeg(gradient(64, 48, false), 90);
  ASSERT_TRUE(jpeg) << jpeg.error();
  auto decoded = decodeImageRgba(*jpeg, "jpeg");
  ASSERT_TRUE(decoded) << decoded.error();
  ASSERT_EQ(decoded->pixels.size(), image.pixels.size());
  for (size_t i = 0; i < image.pixels.size(); i += 4) {
    EXPECT_NEAR(decoded->pixels[i], image.pixels[i], 8) << i;
    EXPECT_EQ(decoded->pixels[i + 3], 255);
  }
  EXPECT_FALSE(encodeJpeg(image, 0));
  EXPECT_FALSE(encodePng(ImageRgba{4, 4, {}}));
}

TEST(ImageCodecs, DecodeRefusesGarbageAndHugeImagesNamingThem) {
  const auto garbage = bytesOf("not an image at all");
  auto bad = decodeImageRgba(garbage, "L3/1_0.pack slot 5");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("L3/1_0.pack slot 5"), std::string::npos) << bad.error();
  // A PNG whose header claims 5000×1 pixels: refused from the header, before decoding.
  auto png = encodePng(gradient(1, 1, false));
  ASSERT_TRUE(png);
  core::storeBigEndian32(&(*png)[16], 5000);
  auto huge = decodeImageRgba(*png, "huge.png");
  ASSERT_FALSE(huge);
  EXPECT_NE(huge.error().find("huge.png"), std::string::npos) << huge.error();
}

}  // namespace
}  // namespace globe::formats
