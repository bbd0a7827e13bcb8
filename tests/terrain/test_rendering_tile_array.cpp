// Tests for terrain/rendering_tile_array.hpp: validation in assign(), the finest-tile rule,
// and the deterministic choice on edges, corners, +-180 deg and the poles, linear and indexed.
#include "collision/terrain_array.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <random>

#include "collision/exact_surface.hpp"
#include "collision/qotcd_height.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/collision/collision_test_support.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using Scheme = geo::GeographicTilingScheme;
using testing::arrayOf;
using testing::makeBlock;

const terrain::HeightBlock& flatBlock() {
  static const terrain::HeightBlock block =
      makeBlock(17, [](uint32_t, uint32_t) { return int16_t{100}; });
  return block;
}

// Both lookups; they must agree. Returns the id, or level 99 for "none".
TileId lookup(const RenderingTileArray& array, double lon, double lat) {
  const ArrayTile* linear = array.findLinear(lon, lat);
  const ArrayTile* indexed = array.findIndexed(lon, lat);
  EXPECT_EQ(linear, indexed) << "lon " << lon << " lat " << lat;
  return linear ? linear->id : TileId{99, 0, 0};
}

TEST(RenderingTileArray, AssignRejectsUnusableTiles) {
  const terrain::HeightBlock& good = flatBlock();
  terrain::HeightBlock wrongSize = makeBlock(16, [](uint32_t, uint32_t) { return int16_t{0}; });
  terrain::HeightBlock shortHeights = good;
  shortHeights.heights.pop_back();
  ArrayTile shifted = makeArrayTile({2, 1, 1}, good);
  shifted.eastRadians += 1e-12;

  std::vector<ArrayTile> tiles{
      makeArrayTile({2, 0, 0}, good),      makeArrayTile({2, 0, 0}, good),  // duplicate
      makeArrayTile({2, 8, 0}, good),                                       // invalid id (x >= 8)
      makeArrayTile({3, 0, 0}, wrongSize), makeArrayTile({3, 1, 0}, shortHeights), shifted,
      makeArrayTile({5, 3, 3}, good),      makeArrayTile({1, 0, 0}, good)};
  tiles[1].maximumHeightMeters = 5;
  ArrayTile noBlock = makeArrayTile({4, 0, 0}, good);
  noBlock.block = nullptr;
  tiles.push_back(noBlock);

  // The readers refuse them too instead of reading outside a block.
  for (const ArrayTile& bad : {noBlock, tiles[4]}) {
    EXPECT_EQ(qotcdTileHeight(bad, -2.0, 1.3).heightCase, HeightCase::None);
    EXPECT_EQ(exactTileSurfaceHeight(bad, geo::Ellipsoid::wgs84(), -2.0, 1.3).triangle,
              SurfaceTriangle::None);
  }

  RenderingTileArray array;
  array.assign(tiles);
  EXPECT_EQ(array.tiles().size(), 3u);
  EXPECT_EQ(array.rejectedTileCount(), 6u);
  ASSERT_EQ(array.levelsFinestFirst().size(), 3u);
  EXPECT_EQ(array.levelsFinestFirst()[0], 5u);
  EXPECT_EQ(array.levelsFinestFirst()[1], 2u);
  EXPECT_EQ(array.levelsFinestFirst()[2], 1u);
  ASSERT_NE(array.find({2, 0, 0}), nullptr);
  EXPECT_EQ(array.find({2, 0, 0})->maximumHeightMeters, 100);  // the first copy is kept
  EXPECT_EQ(array.find({2, 1, 1}), nullptr);

  array.assign({});
  EXPECT_TRUE(array.tiles().empty());
  EXPECT_EQ(array.rejectedTileCount(), 0u);
  EXPECT_EQ(array.findLinear(0.1, 0.1), nullptr);
  EXPECT_EQ(array.findIndexed(0.1, 0.1), nullptr);
}

TEST(RenderingTileArray, FinestContainingTileWins) {
  // Overlapping levels (the paper's rule handles them): level 1, a level-3 tile inside it, and a
  // level-2 tile elsewhere in it.
  const RenderingTileArray array = arrayOf({{1, 2, 0}, {3, 9, 1}, {2, 5, 1}}, flatBlock());
  const geo::GlobeRectangle fine = Scheme::tileRectangle({3, 9, 1});
  EXPECT_EQ(lookup(array, fine.center().longitudeRadians, fine.center().latitudeRadians),
            (TileId{3, 9, 1}));
  // Every corner and edge of the fine tile (some shared with the level-1 tile) picks the fine one.
  for (double lon : {fine.westRadians, fine.eastRadians}) {
    for (double lat : {fine.southRadians, fine.northRadians, fine.center().latitudeRadians}) {
      EXPECT_EQ(lookup(array, lon, lat), (TileId{3, 9, 1}));
    }
  }
  const geo::GlobeRectangle mid = Scheme::tileRectangle({2, 5, 1});
  EXPECT_EQ(lookup(array, mid.center().longitudeRadians, mid.center().latitudeRadians),
            (TileId{2, 5, 1}));
  const geo::GlobeRectangle coarse = Scheme::tileRectangle({1, 2, 0});
  EXPECT_EQ(lookup(array, coarse.westRadians + 1e-3, coarse.northRadians - 1e-3),
            (TileId{1, 2, 0}));
  EXPECT_EQ(lookup(array, -1.0, 0.5), (TileId{99, 0, 0}));  // outside all
}

TEST(RenderingTileArray, EdgeBetweenDifferentLevelsTakesTheFinerTile) {
  // (3,5,2) and, east of it, the level-4 tiles (4,12,4) and (4,12,5).
  const RenderingTileArray array = arrayOf({{3, 5, 2}, {4, 12, 4}, {4, 12, 5}}, flatBlock());
  const geo::GlobeRectangle coarse = Scheme::tileRectangle({3, 5, 2});
  const geo::GlobeRectangle fine = Scheme::tileRectangle({4, 12, 4});
  ASSERT_EQ(coarse.eastRadians, fine.westRadians);
  EXPECT_EQ(lookup(array, coarse.eastRadians, coarse.center().latitudeRadians + 0.01),
            (TileId{4, 12, 4}));
  EXPECT_EQ(lookup(array, coarse.eastRadians, fine.southRadians), (TileId{4, 12, 5}));
  EXPECT_EQ(lookup(array, coarse.eastRadians, coarse.northRadians), (TileId{4, 12, 4}));
  EXPECT_EQ(lookup(array, coarse.eastRadians, coarse.southRadians), (TileId{4, 12, 5}));
  EXPECT_EQ(lookup(array, std::nextafter(coarse.eastRadians, -std::numbers::pi), fine.southRadians),
            (TileId{3, 5, 2}));
}

TEST(RenderingTileArray, CornerOfFourTilesFollowsTheHalfOpenRule) {
  // Corner shared by (3,5,2) NW, (3,6,2) NE, (3,5,3) SW, (3,6,3) SE.
  const geo::GlobeRectangle se = Scheme::tileRectangle({3, 6, 3});
  const double lon = se.westRadians, lat = se.northRadians;
  std::vector<TileId> tiles{{3, 5, 2}, {3, 6, 2}, {3, 5, 3}, {3, 6, 3}};
  // Owner (south-east) first, then the southern (south-west), then the eastern (north-east).
  const std::vector<TileId> expected{{3, 6, 3}, {3, 5, 3}, {3, 6, 2}, {3, 5, 2}};
  for (size_t removed = 0; removed < 4; ++removed) {
    const RenderingTileArray array =
        arrayOf(std::vector<TileId>(expected.begin() + static_cast<long>(removed), expected.end()),
                flatBlock());
    EXPECT_EQ(lookup(array, lon, lat), expected[removed]) << removed;
  }
  // A vertical edge: the eastern tile, else the western; a horizontal edge: the southern.
  EXPECT_EQ(lookup(arrayOf(tiles, flatBlock()), lon, lat + 0.01), (TileId{3, 6, 2}));
  EXPECT_EQ(lookup(arrayOf({{3, 5, 2}}, flatBlock()), lon, lat + 0.01), (TileId{3, 5, 2}));
  EXPECT_EQ(lookup(arrayOf(tiles, flatBlock()), lon + 0.01, lat), (TileId{3, 6, 3}));
  EXPECT_EQ(lookup(arrayOf({{3, 6, 2}}, flatBlock()), lon + 0.01, lat), (TileId{3, 6, 2}));
}

TEST(RenderingTileArray, AntimeridianIsOneMeridian) {
  const uint32_t last = Scheme::tilesX(3) - 1;
  const double lat = 0.6;  // row 2 at level 3, row 4 at level 4
  for (double lon :
       {std::numbers::pi, -std::numbers::pi, 3.0 * std::numbers::pi, -3.0 * std::numbers::pi}) {
    EXPECT_EQ(lookup(arrayOf({{3, last, 2}}, flatBlock()), lon, lat), (TileId{3, last, 2}));
    EXPECT_EQ(lookup(arrayOf({{3, 0, 2}}, flatBlock()), lon, lat), (TileId{3, 0, 2}));
    // Both present: the x = 0 tile owns the meridian ([west, east)); a finer tile wins.
    EXPECT_EQ(lookup(arrayOf({{3, last, 2}, {3, 0, 2}}, flatBlock()), lon, lat), (TileId{3, 0, 2}));
    EXPECT_EQ(lookup(arrayOf({{4, 2 * last + 1, 4}, {3, 0, 2}}, flatBlock()), lon, lat),
              (TileId{4, 2 * last + 1, 4}));
  }
  // Level 0: the two root tiles meet at 0 and at +-180 deg.
  const RenderingTileArray roots = arrayOf({{0, 0, 0}, {0, 1, 0}}, flatBlock());
  EXPECT_EQ(lookup(roots, std::numbers::pi, 0.0), (TileId{0, 0, 0}));
  EXPECT_EQ(lookup(roots, 0.0, 0.0), (TileId{0, 1, 0}));
  EXPECT_EQ(lookup(arrayOf({{0, 1, 0}}, flatBlock()), -std::numbers::pi, -std::numbers::pi / 2.0),
            (TileId{0, 1, 0}));
  // Antimeridian corners.
  const RenderingTileArray corner = arrayOf({{2, 7, 1}, {2, 0, 2}}, flatBlock());
  EXPECT_EQ(lookup(corner, std::numbers::pi, 0.0), (TileId{2, 0, 2}));
  EXPECT_EQ(lookup(arrayOf({{2, 7, 1}}, flatBlock()), -std::numbers::pi, 0.0), (TileId{2, 7, 1}));
}

TEST(RenderingTileArray, PoleIsInEveryTileOfThePolarRow) {
  const double north = std::numbers::pi / 2.0, south = -std::numbers::pi / 2.0;
  // The tile owning the longitude, else the westernmost of the finest level.
  const RenderingTileArray row =
      arrayOf({{3, 2, 0}, {3, 9, 0}, {3, 12, 0}, {2, 0, 0}}, flatBlock());
  const double lonIn9 = Scheme::tileRectangle({3, 9, 0}).center().longitudeRadians;
  EXPECT_EQ(lookup(row, lonIn9, north), (TileId{3, 9, 0}));
  EXPECT_EQ(lookup(row, 0.1, north), (TileId{3, 2, 0}));
  EXPECT_EQ(lookup(row, -std::numbers::pi, north), (TileId{3, 2, 0}));
  EXPECT_EQ(lookup(row, std::numbers::pi, north), (TileId{3, 2, 0}));
  EXPECT_EQ(lookup(row, 0.1, north - 1e-9), (TileId{99, 0, 0}));  // just off the pole
  EXPECT_EQ(lookup(row, 0.1, south), (TileId{99, 0, 0}));
  // South pole: last row of each level.
  const RenderingTileArray southRow = arrayOf({{4, 30, 15}, {4, 1, 15}, {1, 0, 1}}, flatBlock());
  EXPECT_EQ(lookup(southRow, 0.0, south), (TileId{4, 1, 15}));
  EXPECT_EQ(lookup(southRow, Scheme::tileRectangle({4, 30, 15}).westRadians, south),
            (TileId{4, 30, 15}));
  EXPECT_EQ(lookup(southRow, Scheme::tileRectangle({4, 30, 15}).eastRadians, south),
            (TileId{4, 1, 15}));  // owner is x = 31, absent
}

TEST(RenderingTileArray, IndexedCostDoesNotGrowWithTheTileCount) {
  // Every tile of level 6 (8192) plus levels 0..2: linear examines all, indexed a few per level.
  std::vector<TileId> tiles;
  for (uint32_t level : {0u, 1u, 2u, 6u}) {
    for (uint32_t y = 0; y < Scheme::tilesY(level); ++y) {
      for (uint32_t x = 0; x < Scheme::tilesX(level); ++x) tiles.push_back({level, x, y});
    }
  }
  const RenderingTileArray array = arrayOf(tiles, flatBlock());
  ASSERT_EQ(array.tiles().size(), tiles.size());
  const TileLookup linear = array.lookupLinear(0.5, 0.5);
  const TileLookup indexed = array.lookupIndexed(0.5, 0.5);
  EXPECT_EQ(linear.tile, indexed.tile);
  EXPECT_EQ(linear.tilesExamined, tiles.size());
  EXPECT_EQ(indexed.tilesExamined, 1u);  // found at the finest level, first probe
  // A corner of level-6 tiles: at most 4 probes for that level.
  const geo::GlobeRectangle r = Scheme::tileRectangle({6, 40, 20});
  const TileLookup corner = array.lookupIndexed(r.westRadians, r.northRadians);
  EXPECT_LE(corner.tilesExamined, 4u);
  EXPECT_EQ(corner.tile->id, (TileId{6, 40, 20}));
  // Timing over many points (printed, not asserted): linear grows with the tiles, indexed not.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> lon(-std::numbers::pi, std::numbers::pi),
      lat(-std::numbers::pi / 2, std::numbers::pi / 2);
  double linearSeconds = 0, indexedSeconds = 0;
  for (int k = 0; k < 2000; ++k) {
    const double x = lon(rng), y = lat(rng);
    const auto t0 = std::chrono::steady_clock::now();
    const ArrayTile* a = array.findLinear(x, y);
    const auto t1 = std::chrono::steady_clock::now();
    const ArrayTile* b = array.findIndexed(x, y);
    const auto t2 = std::chrono::steady_clock::now();
    ASSERT_EQ(a, b);
    linearSeconds += std::chrono::duration<double>(t1 - t0).count();
    indexedSeconds += std::chrono::duration<double>(t2 - t1).count();
  }
  std::printf("%zu tiles: linear %.0f ns, indexed %.0f ns per lookup\n", tiles.size(),
              linearSeconds / 2000 * 1e9, indexedSeconds / 2000 * 1e9);
  // Invalid points.
  for (auto [badLon, badLat] : {std::pair{std::nan(""), 0.0}, std::pair{0.0, 2.0},
                                std::pair{std::numeric_limits<double>::infinity(), 0.0},
                                std::pair{0.0, -std::numbers::pi}}) {
    EXPECT_EQ(array.findLinear(badLon, badLat), nullptr);
    EXPECT_EQ(array.findIndexed(badLon, badLat), nullptr);
  }
}

TEST(RenderingTileArray, CopiesAreIndependentOfTheOriginal) {
  auto original =
      std::make_unique<RenderingTileArray>(arrayOf({{3, 4, 0}, {3, 9, 7}, {2, 1, 1}}, flatBlock()));
  const RenderingTileArray copy = *original;
  original.reset();
  EXPECT_EQ(copy.tiles().size(), 3u);
  EXPECT_EQ(lookup(copy, 0.3, std::numbers::pi / 2.0), (TileId{3, 4, 0}));
  EXPECT_EQ(lookup(copy, 0.3, -std::numbers::pi / 2.0), (TileId{3, 9, 7}));
  const geo::GlobeRectangle r = Scheme::tileRectangle({2, 1, 1});
  EXPECT_EQ(lookup(copy, r.westRadians, r.northRadians), (TileId{2, 1, 1}));
}

}  // namespace
}  // namespace globe::collision
