// The tiling plan: which tiles exist at each level, at tile edges and when inputs are mixed.
#include "tiling/tiling_plan.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "geo/tiling_scheme.hpp"

namespace globe::tiling {
namespace {

TEST(TilesTouching, ExtentStrictlyInsideOneTile) {
  // Level 2 tiles are 45° wide: lon 10..20, lat 50..60 lies in x = 4, y = 0 (lat 90..45).
  const TileRange r = tilesTouching({10, 50, 20, 60}, 2);
  EXPECT_EQ(r.x0, 4u);
  EXPECT_EQ(r.x1, 4u);
  EXPECT_EQ(r.y0, 0u);
  EXPECT_EQ(r.y1, 0u);
}

TEST(TilesTouching, ExtentOnTileEdgesTouchesTheNeighbours) {
  // lon 0..45 at level 2 is exactly tile x = 4; its closed edges touch x = 3 and x = 5.
  const TileRange r = tilesTouching({0, 0, 45, 45}, 2);
  EXPECT_EQ(r.x0, 3u);
  EXPECT_EQ(r.x1, 5u);
  EXPECT_EQ(r.y0, 0u);  // lat 45 is the edge between y = 0 and y = 1
  EXPECT_EQ(r.y1, 2u);  // lat 0 is the edge between y = 1 and y = 2
}

TEST(TilesTouching, WholeGlobeClampsToValidTiles) {
  for (uint32_t level : {0u, 3u, 11u}) {
    const TileRange r = tilesTouching({-180, -90, 180, 90}, level);
    EXPECT_EQ(r.x0, 0u);
    EXPECT_EQ(r.y0, 0u);
    EXPECT_EQ(r.x1, geo::GeographicTilingScheme::tilesX(level) - 1);
    EXPECT_EQ(r.y1, geo::GeographicTilingScheme::tilesY(level) - 1);
  }
}

TEST(TilingPlan, LevelsDeepenOnlyWhereFinerDataExists) {
  // A whole-globe source good to level 6 plus a 1°×1° source good to level 14 (Mount Fuji).
  const TilingPlan plan({{-180, -90, 180, 90}, {138, 35, 139, 36}}, {6, 14}, 64);
  EXPECT_EQ(plan.maxLevel(), 14u);
  EXPECT_EQ(plan.tileCount(0), 2u);
  EXPECT_EQ(plan.tileCount(6), 128u * 64u);
  for (uint32_t level = 7; level <= 14; ++level) {
    const double tileDegrees = 180.0 / (1u << level);
    const uint64_t expectedMax =
        static_cast<uint64_t>((1 / tileDegrees + 4) * (1 / tileDegrees + 4));
    EXPECT_LE(plan.tileCount(level), expectedMax) << "level " << level;
    EXPECT_GT(plan.tileCount(level), 0u);
    // Nothing far from Fuji exists at a deep level.
    const auto far = geo::GeographicTilingScheme::positionToTile(0.0, 0.0, level);
    ASSERT_TRUE(far);
    EXPECT_FALSE(plan.exists(*far));
    const auto fuji = geo::GeographicTilingScheme::positionToTile(
        138.7 * std::numbers::pi / 180, 35.36 * std::numbers::pi / 180, level);
    ASSERT_TRUE(fuji);
    EXPECT_TRUE(plan.exists(*fuji));
  }
}

TEST(TilingPlan, EveryTileHasItsParent) {
  const TilingPlan plan(
      {{-180, -90, 180, 90}, {-2, 52, 0, 54}, {137.9995, 34.9995, 139.0005, 36.0005}}, {6, 11, 14},
      16);
  for (uint32_t level = 1; level <= plan.maxLevel(); ++level) {
    for (const formats::PackId& pack : plan.packs(level)) {
      for (const geo::TileId& tile : plan.tilesInPack(pack)) {
        ASSERT_TRUE(plan.exists(tile.parent())) << level << "/" << tile.x << "/" << tile.y;
      }
    }
  }
}

TEST(TilingPlan, TilesComeInFamiliesOfFour) {
  const TilingPlan plan(
      {{-180, -90, 180, 90}, {-2, 52, 0, 54}, {137.9995, 34.9995, 139.0005, 36.0005}}, {6, 11, 14},
      16);
  for (uint32_t level = 1; level <= plan.maxLevel(); ++level) {
    for (const formats::PackId& pack : plan.packs(level)) {
      for (const geo::TileId& tile : plan.tilesInPack(pack)) {
        for (const geo::TileId& sibling : tile.parent().children()) {
          ASSERT_TRUE(plan.exists(sibling)) << level << "/" << sibling.x << "/" << sibling.y;
        }
      }
    }
  }
}

TEST(TilingPlan, PacksHoldOnlyPlannedTiles) {
  const TilingPlan plan({{138, 35, 139, 36}}, {12}, 8);
  uint64_t total = 0;
  for (const formats::PackId& pack : plan.packs(12)) {
    const auto tiles = plan.tilesInPack(pack);
    EXPECT_FALSE(tiles.empty());
    for (const geo::TileId& t : tiles) {
      EXPECT_EQ(formats::packOf(t, 8), pack);
      EXPECT_TRUE(plan.exists(t));
    }
    total += tiles.size();
  }
  EXPECT_EQ(total, plan.tileCount(12));
}

}  // namespace
}  // namespace globe::tiling
