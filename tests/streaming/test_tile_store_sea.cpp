// TileStore and the pack format version 2: every block a store loads carries the store's sea
// surface (the one place --sea-floor reaches rendering and collision), and packs of the older
// format (version 1: negative samples meant sea) are refused by name, asking for re-tiling.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>

#include <filesystem>
#include <string>

#include "formats/pack_format.hpp"
#include "streaming/tile_store.hpp"
#include "tests/support/sea_test_pyramid.hpp"
#include "transport/atomic_file.hpp"

namespace globe::streaming {
namespace {

namespace fs = std::filesystem;
using terrain::SeaSurface;

class SeaPyramid : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("globe_sea_store_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "_" +
            std::to_string(::getpid()));
    fs::remove_all(dir_);
    ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir_ / "v2"));
    ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir_ / "v1", 1));
    ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir_ / "v3", formats::kPackFormatVersion + 1));
    ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir_ / "version2", 2));
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SeaPyramid, BlocksCarryTheStoresSeaSurface) {
  for (const SeaSurface sea : {SeaSurface::Water, SeaSurface::SeaFloor}) {
    auto store = TileStore::open(dir_ / "v2", sea);
    ASSERT_TRUE(store) << store.error();
    EXPECT_EQ((*store)->sea(), sea);
    for (const geo::TileId& tile :
         {globe::testing::kSeaTile, globe::testing::kMixedTile, geo::TileId{0, 1, 0}}) {
      auto block = (*store)->loadBlock(tile);
      ASSERT_TRUE(block) << block.error();
      EXPECT_EQ(block->sea, sea);
      EXPECT_EQ(block->heights, globe::testing::seaTestBlock(tile).heights) << "samples as stored";
    }
    auto seaBlock = (*store)->loadBlock(globe::testing::kSeaTile);
    ASSERT_TRUE(seaBlock);
    EXPECT_EQ(seaBlock->surfaceHeightMetersAt(8, 8),
              sea == SeaSurface::Water ? 0.0 : globe::testing::kSeaFloorMeters);
  }
  auto byDefault = TileStore::open(dir_ / "v2");
  ASSERT_TRUE(byDefault);
  EXPECT_EQ((*byDefault)->sea(), SeaSurface::Water);
}

TEST_F(SeaPyramid, Version2PacksStillLoadWithoutApronOrMeasuredError) {
  auto store = TileStore::open(dir_ / "version2");
  ASSERT_TRUE(store) << store.error();
  auto block = (*store)->loadBlock(globe::testing::kMixedTile);
  ASSERT_TRUE(block) << block.error();
  EXPECT_EQ(block->heights, globe::testing::seaTestBlock(globe::testing::kMixedTile).heights);
  EXPECT_FALSE(block->hasApron());
  auto entry = (*store)->entry(globe::testing::kMixedTile);
  ASSERT_TRUE(entry && *entry);
  EXPECT_TRUE(std::isnan((*entry)->geometricErrorMeters));
  // The current version's blocks carry the ring around them.
  auto current = TileStore::open(dir_ / "v2");
  ASSERT_TRUE(current);
  auto withApron = (*current)->loadBlock(globe::testing::kMixedTile);
  ASSERT_TRUE(withApron);
  EXPECT_TRUE(withApron->hasApron());
  EXPECT_EQ(withApron->heights, block->heights);
}

TEST_F(SeaPyramid, PackIndexRangesBoundBothSurfaces) {
  auto store = TileStore::open(dir_ / "v2");
  ASSERT_TRUE(store);
  auto entry = (*store)->entry(globe::testing::kMixedTile);
  ASSERT_TRUE(entry && *entry);
  EXPECT_EQ((*entry)->vertexRange.minimumMeters, terrain::kDeepestSeaFloorMeters);
  EXPECT_EQ((*entry)->vertexRange.maximumMeters, globe::testing::kMixedLandMeters);
  auto open = (*store)->entry(globe::testing::kSeaTile);
  ASSERT_TRUE(open && *open);
  EXPECT_EQ((*open)->vertexRange.minimumMeters, globe::testing::kSeaFloorMeters);
  EXPECT_EQ((*open)->vertexRange.maximumMeters, 0);
}

TEST_F(SeaPyramid, AnOlderPyramidIsRefusedAtOpenNamingThePackAndAskingForRetiling) {
  for (const SeaSurface sea : {SeaSurface::Water, SeaSurface::SeaFloor}) {
    auto store = TileStore::open(dir_ / "v1", sea);
    ASSERT_FALSE(store);
    const std::string& error = store.error();
    EXPECT_NE(error.find((dir_ / "v1" / "L0" / "0_0.pack").string()), std::string::npos) << error;
    EXPECT_NE(error.find("pack format version 1"), std::string::npos) << error;
    EXPECT_NE(error.find("older globe-tiler"), std::string::npos) << error;
    EXPECT_NE(error.find("re-tiled"), std::string::npos) << error;
  }
  auto newer = TileStore::open(dir_ / "v3");
  ASSERT_FALSE(newer);
  EXPECT_NE(newer.error().find("is newer than this globe reads"), std::string::npos)
      << newer.error();
}

TEST_F(SeaPyramid, AnOlderPackAmongNewOnesIsRefusedWhenRead) {
  // Level 0 is current, so the store opens; the level-10 pack is of version 1.
  const formats::PackId deep = formats::packOf(globe::testing::kSeaTile, 64);
  fs::copy_file(formats::packPath(dir_ / "v1", deep), formats::packPath(dir_ / "v2", deep),
                fs::copy_options::overwrite_existing);
  auto store = TileStore::open(dir_ / "v2");
  ASSERT_TRUE(store) << store.error();
  auto block = (*store)->loadBlock(globe::testing::kSeaTile);
  ASSERT_FALSE(block);
  EXPECT_NE(block.error().find(formats::packPath(dir_ / "v2", deep).string()), std::string::npos)
      << block.error();
  EXPECT_NE(block.error().find("older globe-tiler"), std::string::npos) << block.error();
  const auto reported = (*store)->takeNewPackErrors();
  ASSERT_EQ(reported.size(), 1u);
  EXPECT_EQ(reported[0], block.error());
  EXPECT_TRUE((*store)->loadBlock({0, 0, 0})) << "the current packs still load";

  // The whole-pack decoder (the tiler's reader) says the same.
  auto bytes = transport::readWholeFile(formats::packPath(dir_ / "v1", deep), 1 << 24);
  ASSERT_TRUE(bytes);
  auto pack = formats::decodePack(*bytes, "old.pack");
  ASSERT_FALSE(pack);
  EXPECT_EQ(
      pack.error().rfind("old.pack: pack format version 1 was made by an older globe-tiler", 0), 0u)
      << pack.error();
}

}  // namespace
}  // namespace globe::streaming
