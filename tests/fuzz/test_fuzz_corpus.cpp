// Replays every committed fuzz corpus file (tests/fuzz/corpus/<target>/) through its entry point.
#include <gtest/gtest.h>

#include <algorithm>
#include <span>

#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/crc32.hpp"
#include "formats/pack_format.hpp"
#include "formats/pyramid_manifest.hpp"
#include "formats/terrain_layer_json.hpp"
#include "fuzz_entries.hpp"
#include "tests/support/build_paths.hpp"

namespace {

namespace fs = std::filesystem;
const fs::path kCorpus = fs::path(GLOBE_SOURCE_DIR) / "tests/fuzz/corpus";

size_t replay(const char* target) {
  const auto entry = globe::fuzz::entryNamed(target);
  EXPECT_NE(entry, nullptr) << target;
  size_t count = 0;
  for (const auto& file : fs::directory_iterator(kCorpus / target)) {
    std::ifstream in(file.path(), std::ios::binary);
    const std::vector<char> bytes{std::istreambuf_iterator<char>(in), {}};
    SCOPED_TRACE(file.path().string());
    entry(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    ++count;
  }
  return count;
}

TEST(FuzzCorpus, Gtopo30Header) { EXPECT_GT(replay("gtopo30_header"), 0U); }
TEST(FuzzCorpus, Pack) { EXPECT_GT(replay("pack"), 0U); }
TEST(FuzzCorpus, Manifest) { EXPECT_GT(replay("manifest"), 0U); }
TEST(FuzzCorpus, PathJson) { EXPECT_GT(replay("path_json"), 0U); }
TEST(FuzzCorpus, PathKml) { EXPECT_GT(replay("path_kml"), 0U); }
TEST(FuzzCorpus, Remote) { EXPECT_GT(replay("remote"), 0U); }
TEST(FuzzCorpus, ImageTile) { EXPECT_GT(replay("image_tile"), 0U); }
TEST(FuzzCorpus, TerrainTile) { EXPECT_GT(replay("terrain_tile"), 0U); }
TEST(FuzzCorpus, TerrainLayerJson) { EXPECT_GT(replay("terrain_layer_json"), 0U); }
TEST(FuzzCorpus, ElevationImage) { EXPECT_GT(replay("elevation_image"), 0U); }
TEST(FuzzCorpus, Pmtiles) { EXPECT_GT(replay("pmtiles"), 0U); }
TEST(FuzzCorpus, ServiceXml) { EXPECT_GT(replay("service_xml"), 0U); }
TEST(FuzzCorpus, OverlayFile) { EXPECT_GT(replay("overlay_file"), 0U); }
TEST(FuzzCorpus, TileContent) { EXPECT_GT(replay("tile_content"), 0U); }
TEST(FuzzCorpus, ImplicitSubtree) { EXPECT_GT(replay("implicit_subtree"), 0U); }

// The hand-made seeds are valid packs (version 2; 5 with its compressed index; 6 with compressed
// blocks, written by tests/tools/pack_v6_from_v5.py, an encoder of its own); the version-1
// seed (negative samples meant sea then) is refused by name as made by an older globe-tiler.
TEST(FuzzCorpus, PackSeedsDecodeAndTheVersion1SeedIsRefused) {
  auto read = [](const char* name) {
    std::ifstream in(kCorpus / "pack" / name, std::ios::binary);
    const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
    std::vector<std::byte> bytes(chars.size());
    std::memcpy(bytes.data(), chars.data(), chars.size());
    return bytes;
  };
  for (const char* seed :
       {"seed-p1n5.pack", "seed-p2n3.pack", "seed-p4n3-empty.pack", "seed-p1n5-version5.pack",
        "seed-p2n3-version5.pack", "seed-p4n3-empty-version5.pack", "seed-p1n5-version6.pack",
        "seed-p2n3-version6.pack", "seed-p4n3-empty-version6.pack"}) {
    const auto pack = globe::formats::decodePack(read(seed), seed);
    EXPECT_TRUE(pack.ok()) << seed << ": " << pack.error();
  }
  // The independent encoder's version 6 holds what its version-5 source held.
  for (const std::string stem : {"seed-p1n5", "seed-p2n3", "seed-p4n3-empty"}) {
    const auto v5 = globe::formats::decodePack(read((stem + "-version5.pack").c_str()), stem);
    const auto v6 = globe::formats::decodePack(read((stem + "-version6.pack").c_str()), stem);
    ASSERT_TRUE(v5.ok() && v6.ok()) << stem;
    EXPECT_EQ(v6->layout.formatVersion, 6U);
    ASSERT_EQ(v5->entries.size(), v6->entries.size());
    for (size_t slot = 0; slot < v5->entries.size(); ++slot) {
      ASSERT_EQ(v5->entries[slot].present(), v6->entries[slot].present());
      if (!v5->entries[slot].present()) continue;  // an absent slot's samples are never set
      const auto same = [](std::span<const int16_t> a, std::span<const int16_t> b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end());
      };
      EXPECT_TRUE(same(v5->block(slot), v6->block(slot))) << stem << " slot " << slot;
      EXPECT_TRUE(same(v5->apron(slot), v6->apron(slot))) << stem << " slot " << slot;
      EXPECT_EQ(v5->entries[slot].subtreeRange.maximumMeters,
                v6->entries[slot].subtreeRange.maximumMeters);
      EXPECT_EQ(std::bit_cast<uint32_t>(v5->entries[slot].geometricErrorMeters),
                std::bit_cast<uint32_t>(v6->entries[slot].geometricErrorMeters));
    }
  }
  const auto old = globe::formats::decodePack(read("seed-p1n5-version1.pack"), "v1.pack");
  ASSERT_FALSE(old.ok());
  EXPECT_EQ(old.error().rfind("v1.pack: pack format version 1 was made by an older globe-tiler", 0),
            0u)
      << old.error();
}

// Regression: a 16 MiB pack claiming 1024x1024 slots of 1025x1025 vertices (no tiles present)
// once made decodePack allocate 2 TiB for its blocks; it is now refused by name. (Version 4: its
// index uncompressed, as it was found.)
TEST(FuzzRegression, PackWithHugeLayoutIsRefusedWithoutAllocating) {
  const globe::formats::PackLayout layout{1024, 1025, 4};
  std::vector<std::byte> bytes(layout.fileBytes(0));
  const char magic[] = "GLOBEPK1";
  for (size_t i = 0; i < 8; ++i) bytes[i] = static_cast<std::byte>(magic[i]);
  const uint32_t header[8] = {4, 10, 0, 0, layout.tilesPerSide, layout.verticesPerSide, 0, 0};
  for (size_t i = 0; i < 8; ++i) {
    for (size_t b = 0; b < 4; ++b) {
      bytes[8 + 4 * i + b] = static_cast<std::byte>((header[i] >> (24 - 8 * b)) & 0xFFU);
    }
  }
  const size_t body = bytes.size() - 4;
  const uint32_t crc = globe::core::crc32(std::span(bytes).first(body));
  for (size_t b = 0; b < 4; ++b) {
    bytes[body + b] = static_cast<std::byte>((crc >> (24 - 8 * b)) & 0xFFU);
  }
  ASSERT_TRUE(globe::formats::decodePackIndex(bytes, bytes.size(), "huge.pack").ok());
  const auto pack = globe::formats::decodePack(bytes, "huge.pack");
  ASSERT_FALSE(pack.ok());
  EXPECT_NE(pack.error().find("huge.pack"), std::string::npos) << pack.error();
  EXPECT_NE(pack.error().find("MiB in memory"), std::string::npos) << pack.error();
}

// Regression: a float far outside uint32_t (libFuzzer's 1.1e64 as "level") reached nlohmann's
// get<uint32_t>(), a float-to-integer cast with undefined behaviour; now a named error.
TEST(FuzzRegression, ManifestIntegerOutOfRangeIsAnError) {
  const std::string text = R"({"format": "globe-pyramid", "formatVersion": 1, "blockSize": 17,
    "packTilesPerSide": 1e64, "globeModel": "wgs84", "levels": [], "sources": []})";
  const auto manifest = globe::formats::manifestFromJson(text, "m/manifest.json");
  ASSERT_FALSE(manifest.ok());
  EXPECT_NE(manifest.error().find("m/manifest.json"), std::string::npos) << manifest.error();
  EXPECT_NE(manifest.error().find("expected an integer in 0..4294967295"), std::string::npos)
      << manifest.error();
  for (const char* bad : {"-1", "4294967296", "2.5", "\"17\""}) {
    const std::string other =
        R"({"format": "globe-pyramid", "formatVersion": 1, "blockSize": )" + std::string(bad) + "}";
    EXPECT_FALSE(globe::formats::manifestFromJson(other, "m/manifest.json").ok()) << bad;
  }
}

// Regression: libFuzzer's "endY": 5e66 in a layer.json's "available" reached nlohmann's
// get<uint32_t>() (UBSan: 5e+66 is outside the range of unsigned int); now a named error, as are
// negative, fractional and huge zoom levels. Whole numbers written as floats still read.
TEST(FuzzRegression, TerrainLayerJsonIntegerOutOfRangeIsAnError) {
  const auto layer = [](const std::string& members) {
    return globe::formats::parseTerrainLayerJson(R"({"tiles": ["t"], )" + members + "}", "l.json");
  };
  const auto huge =
      layer(R"("available": [[{"startX": 0, "startY": 0, "endX": 1, "endY": 5e66}]])");
  ASSERT_FALSE(huge);
  EXPECT_NE(huge.error().find("l.json: level 0: \"endY\" is not a whole number in 0..4294967295"),
            std::string::npos)
      << huge.error();
  for (const char* bad : {R"("maxzoom": -1)", R"("minzoom": 2.5)", R"("maxzoom": 4294967296)",
                          R"("metadataAvailability": 1e300)", R"("maxzoom": "12")",
                          R"("available": [[{"startX": 0, "startY": 0, "endX": 1}]])"}) {
    EXPECT_FALSE(layer(bad)) << bad;
  }
  const auto whole = layer(R"("maxzoom": 12.0, "available": [[{"startX": 0.0, "startY": 0,
    "endX": 1, "endY": 0}]], "metadataAvailability": 10)");
  ASSERT_TRUE(whole) << whole.error();
  EXPECT_EQ(whole->available.at(0).at(0).endX, 1u);
  EXPECT_EQ(whole->metadataAvailability, 10u);
}

}  // namespace
