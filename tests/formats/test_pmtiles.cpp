// PMTiles v3: the real archives' headers and directories, Hilbert tile ids from the spec's
// examples, and refusals by name (another version, truncation).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "compression/gzip_bytes.hpp"
#include "formats/pmtiles.hpp"
#include "tests/support/build_paths.hpp"

namespace {

namespace fs = std::filesystem;
using namespace globe::formats;

std::vector<std::byte> archiveBytes(const char* name) {
  std::ifstream in(fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/pmtiles" / name,
                   std::ios::binary);
  const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
  std::vector<std::byte> bytes(chars.size());
  std::memcpy(bytes.data(), chars.data(), chars.size());
  return bytes;
}

TEST(Pmtiles, TileIdsFollowTheHilbertCurveLevelByLevel) {
  EXPECT_EQ(pmtilesTileId(0, 0, 0), 0u);
  // Zoom 1 in Hilbert order: (0,0) (0,1) (1,1) (1,0).
  EXPECT_EQ(pmtilesTileId(1, 0, 0), 1u);
  EXPECT_EQ(pmtilesTileId(1, 0, 1), 2u);
  EXPECT_EQ(pmtilesTileId(1, 1, 1), 3u);
  EXPECT_EQ(pmtilesTileId(1, 1, 0), 4u);
  EXPECT_EQ(pmtilesTileId(2, 0, 0), 5u);
  // The spec's test values (protomaps/PMTiles spec/v3 and its reference implementations).
  EXPECT_EQ(pmtilesTileId(12, 3423, 1763), 19078479u);
  // Every id of a zoom is used once.
  std::vector<bool> seen(64, false);
  for (uint64_t x = 0; x < 8; ++x)
    for (uint64_t y = 0; y < 8; ++y) seen[pmtilesTileId(3, x, y) - 21] = true;
  EXPECT_EQ(std::count(seen.begin(), seen.end(), true), 64);
}

TEST(Pmtiles, RealArchivesHeadersAndRootDirectories) {
  const auto toner = archiveBytes("stamen_toner(raster)CC-BY+ODbL_z3.pmtiles");
  auto h = decodePmtilesHeader(toner, toner.size(), "toner");
  ASSERT_TRUE(h) << h.error();
  EXPECT_EQ(h->tileType, PmtilesTileType::Png);
  EXPECT_EQ(h->internalCompression, PmtilesCompression::Gzip);
  EXPECT_EQ(h->minZoom, 0);
  EXPECT_EQ(h->maxZoom, 3);
  EXPECT_EQ(h->addressedTiles, 85u);
  EXPECT_EQ(h->tileEntries, 84u);
  EXPECT_EQ(h->tileContents, 80u);
  auto root =
      globe::compression::gunzipIfNeeded(std::span(toner).subspan(h->rootOffset, h->rootLength), "toner", 1 << 24);
  ASSERT_TRUE(root);
  auto entries = decodePmtilesDirectory(*root, "toner");
  ASSERT_TRUE(entries) << entries.error();
  EXPECT_EQ(entries->size(), 84u);
  uint64_t addressed = 0;
  for (const PmtilesEntry& e : *entries) {
    addressed += e.runLength;
    EXPECT_LE(e.offset + e.length, h->tileDataLength);
  }
  EXPECT_EQ(addressed, 85u);  // one entry runs over two tiles
  // Every tile of zoom 0-3 is found, and lies in the data section.
  for (uint32_t z = 0; z <= 3; ++z) {
    for (uint64_t x = 0; x < (1u << z); ++x) {
      for (uint64_t y = 0; y < (1u << z); ++y) {
        const auto e = findPmtilesEntry(*entries, pmtilesTileId(z, x, y));
        ASSERT_TRUE(e) << z << "/" << x << "/" << y;
        EXPECT_GT(e->runLength, 0u);
      }
    }
  }
  const auto whitney = archiveBytes("usgs-mt-whitney-8-15-webp-512.pmtiles");
  auto w = decodePmtilesHeader(whitney, whitney.size(), "whitney");
  ASSERT_TRUE(w) << w.error();
  EXPECT_EQ(w->tileType, PmtilesTileType::Webp);
  EXPECT_EQ(w->minZoom, 8);
  EXPECT_EQ(w->maxZoom, 15);
  EXPECT_NEAR(w->westDegrees, -118.31982, 1e-5);
  EXPECT_NEAR(w->northDegrees, 36.59301, 1e-5);
}

TEST(Pmtiles, OtherVersionsAndTruncationAreRefusedByName) {
  auto bytes = archiveBytes("stamen_toner(raster)CC-BY+ODbL_z3.pmtiles");
  bytes[7] = std::byte{1};
  auto v1 = decodePmtilesHeader(bytes, bytes.size(), "old.pmtiles");
  ASSERT_FALSE(v1);
  EXPECT_EQ(v1.error().rfind("old.pmtiles: PMTiles version 1", 0), 0u) << v1.error();
  bytes[7] = std::byte{3};
  auto cut = decodePmtilesHeader(bytes, 20000, "cut.pmtiles");
  ASSERT_FALSE(cut);
  EXPECT_NE(cut.error().find("beyond the archive's 20000 bytes"), std::string::npos) << cut.error();
  auto header = decodePmtilesHeader(bytes, bytes.size(), "t");
  ASSERT_TRUE(header);
  auto root = globe::compression::gunzipIfNeeded(std::span(bytes).subspan(header->rootOffset, header->rootLength), "t",
                             1 << 24);
  ASSERT_TRUE(root);
  for (size_t size = 0; size + 1 < root->size(); ++size) {
    auto entries = decodePmtilesDirectory(std::span(*root).first(size), "t");
    EXPECT_FALSE(entries) << size;
  }
}

}  // namespace
