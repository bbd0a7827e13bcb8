// ImageryStore: one read per tile with its CRC checked, absent tiles nullopt, each bad pack
// reported once.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "formats/image_pack.hpp"
#include "formats/layer_manifest.hpp"
#include "streaming/imagery_store.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/atomic_file.hpp"

namespace globe::streaming {
namespace {

namespace fs = std::filesystem;

std::vector<std::byte> payloadFor(const geo::TileId& t) {
  const std::string text =
      "tile " + std::to_string(t.level) + "/" + std::to_string(t.x) + "/" + std::to_string(t.y);
  std::vector<std::byte> bytes(text.size());
  std::memcpy(bytes.data(), text.data(), text.size());
  return bytes;
}

// Levels 0 and 1 with 2×2-tile packs: level 0 has both tiles, level 1 only tiles with even x.
fs::path makeLayer(const std::string& name) {
  const fs::path dir = globe::testing::freshTempDir("imagery-store-" + name);  // removed at exit
  formats::LayerManifest m;
  m.packTilesPerSide = 2;
  m.levels.push_back({0, 2, {-180, -90, 180, 90}, {{0, 0, 0}}});
  m.levels.push_back({1, 4, {-180, -90, 90, 90}, {{1, 0, 0}, {1, 1, 0}}});
  m.bounds = {-180, -90, 180, 90};
  EXPECT_TRUE(formats::writeLayerManifest(dir, m));
  for (const auto& [level, packs] : std::vector<std::pair<uint32_t, std::vector<formats::PackId>>>{
           {0, m.levels[0].packs}, {1, m.levels[1].packs}}) {
    for (const formats::PackId& id : packs) {
      std::vector<std::vector<std::byte>> payloads(4);
      for (size_t slot = 0; slot < 4; ++slot) {
        const geo::TileId t = formats::tileOfSlot(id, slot, 2);
        if (t.x >= (2u << level) || t.y >= (1u << level)) continue;
        if (level == 1 && t.x % 2 == 1) continue;
        payloads[slot] = payloadFor(t);
      }
      fs::create_directories(formats::packPath(dir, id).parent_path());
      EXPECT_TRUE(transport::writeFileAtomically(formats::packPath(dir, id),
                                                 formats::encodeImagePack(id, 2, payloads)));
    }
  }
  return dir;
}

TEST(ImageryStore, LoadsEachTileWithOneReadAndIndexesEachPackOnce) {
  const fs::path dir = makeLayer("loads");
  auto store = ImageryStore::open(dir);
  ASSERT_TRUE(store) << store.error();
  ImageryStore& s = **store;
  EXPECT_EQ(s.manifest().maxLevel(), 1u);
  EXPECT_EQ(s.manifest().tileSizePixels, 256u);
  for (const geo::TileId t : {geo::TileId{0, 0, 0}, geo::TileId{0, 1, 0}, geo::TileId{1, 0, 0},
                              geo::TileId{1, 0, 1}, geo::TileId{1, 2, 1}}) {
    auto bytes = s.loadEncoded(t);
    ASSERT_TRUE(bytes) << bytes.error();
    ASSERT_TRUE(bytes->has_value()) << t.level << "/" << t.x << "/" << t.y;
    EXPECT_EQ(**bytes, payloadFor(t));
  }
  EXPECT_EQ(s.tileReads(), 5u);
  EXPECT_EQ(s.packIndexReads(), 3u);
  auto again = s.loadEncoded({1, 2, 0});
  ASSERT_TRUE(again && again->has_value());
  EXPECT_EQ(s.packIndexReads(), 3u);  // the pack's index came from memory
  EXPECT_EQ(s.tileReads(), 6u);
  EXPECT_EQ(s.packFileOf({1, 3, 1}), (dir / "L1" / "1_0.pack").string());
  EXPECT_TRUE(s.takeNewPackErrors().empty());
}

TEST(ImageryStore, AbsentTilesAreNullopt) {
  auto store = ImageryStore::open(makeLayer("absent"));
  ASSERT_TRUE(store) << store.error();
  for (const geo::TileId t : {geo::TileId{1, 1, 0}, geo::TileId{1, 3, 1}, geo::TileId{2, 0, 0},
                              geo::TileId{9, 100, 100}}) {
    auto bytes = (*store)->loadEncoded(t);
    ASSERT_TRUE(bytes) << bytes.error();
    EXPECT_FALSE(bytes->has_value());
    auto has = (*store)->hasTile(t);
    ASSERT_TRUE(has) << has.error();
    EXPECT_FALSE(*has);
  }
  auto has = (*store)->hasTile({1, 2, 1});
  ASSERT_TRUE(has);
  EXPECT_TRUE(*has);
  EXPECT_EQ((*store)->tileReads(), 0u);
}

TEST(ImageryStore, DamagedPackIsReportedOnce) {
  const fs::path dir = makeLayer("damaged");
  const fs::path pack = dir / "L1" / "1_0.pack";
  // Corrupt a payload byte: the index still opens, the tile's own CRC catches it.
  auto bytes = transport::readWholeFile(pack, 1 << 20);
  ASSERT_TRUE(bytes);
  (*bytes)[bytes->size() - 6] ^= std::byte{0x20};
  ASSERT_TRUE(transport::writeFileAtomically(pack, *bytes));
  // And a missing pack the manifest lists.
  fs::remove(dir / "L0" / "0_0.pack");

  auto store = ImageryStore::open(dir);
  ASSERT_TRUE(store) << store.error();
  for (int attempt = 0; attempt < 3; ++attempt) {
    auto bad = (*store)->loadEncoded({1, 2, 1});
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().find(pack.string()), std::string::npos) << bad.error();
    EXPECT_NE(bad.error().find("CRC mismatch"), std::string::npos) << bad.error();
    auto missing = (*store)->loadEncoded({0, 1, 0});
    ASSERT_FALSE(missing);
    EXPECT_NE(missing.error().find("0_0.pack"), std::string::npos) << missing.error();
  }
  const auto errors = (*store)->takeNewPackErrors();
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_TRUE((*store)->takeNewPackErrors().empty());
  // The good tile of the damaged pack still loads.
  auto good = (*store)->loadEncoded({1, 2, 0});
  ASSERT_TRUE(good) << good.error();
  EXPECT_TRUE(good->has_value());
  // After a repair, forgetFailedPacks lets the packs open again.
  fs::remove_all(dir);
  const fs::path repaired = makeLayer("damaged");
  ASSERT_EQ(repaired, dir);
  (*store)->forgetFailedPacks();
  auto fixed = (*store)->loadEncoded({0, 1, 0});
  ASSERT_TRUE(fixed) << fixed.error();
  EXPECT_TRUE(fixed->has_value());
}

TEST(ImageryStore, TruncatedPackIsRefusedNamingIt) {
  const fs::path dir = makeLayer("truncated");
  const fs::path pack = dir / "L1" / "0_0.pack";
  fs::resize_file(pack, fs::file_size(pack) - 3);
  auto store = ImageryStore::open(dir);
  ASSERT_TRUE(store);
  auto has = (*store)->hasTile({1, 0, 0});
  ASSERT_FALSE(has);
  EXPECT_NE(has.error().find(pack.string()), std::string::npos) << has.error();
  EXPECT_EQ((*store)->takeNewPackErrors().size(), 1u);
}

TEST(ImageryStore, MissingManifestIsAnError) {
  auto store = ImageryStore::open(fs::temp_directory_path() / "globe-no-such-layer");
  ASSERT_FALSE(store);
  EXPECT_NE(store.error().find("layer.json"), std::string::npos) << store.error();
}

}  // namespace
}  // namespace globe::streaming
