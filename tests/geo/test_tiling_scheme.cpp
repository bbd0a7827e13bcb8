// Tests for geo/tiling_scheme.hpp: tile counts, exact tiling, the edge rule and lookups.
#include "geo/tiling_scheme.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

namespace globe::geo {
namespace {

using Scheme = GeographicTilingScheme;

std::optional<TileId> lookup(double longitude, double latitude, uint32_t level) {
  return Scheme::positionToTile(longitude, latitude, level);
}

TileId randomTile(std::mt19937_64& rng, uint32_t level) {
  std::uniform_int_distribution<uint32_t> x(0, Scheme::tilesX(level) - 1);
  std::uniform_int_distribution<uint32_t> y(0, Scheme::tilesY(level) - 1);
  return {level, x(rng), y(rng)};
}

TEST(TilingScheme, TileCounts) {
  EXPECT_EQ(Scheme::tilesX(0), 2u);
  EXPECT_EQ(Scheme::tilesY(0), 1u);
  EXPECT_EQ(Scheme::tilesX(1), 4u);
  EXPECT_EQ(Scheme::tilesY(1), 2u);
  EXPECT_EQ(Scheme::tilesX(10), 2048u);
  EXPECT_EQ(Scheme::tilesY(10), 1024u);
  EXPECT_EQ(Scheme::tilesX(kMaxLevel), 2147483648u);
  EXPECT_EQ(Scheme::tilesY(kMaxLevel), 1073741824u);
  EXPECT_EQ(Scheme::tilesX(kMaxLevel + 1), 0u);
  EXPECT_EQ(Scheme::tilesY(kMaxLevel + 1), 0u);
}

TEST(TilingScheme, Validity) {
  EXPECT_TRUE(Scheme::isValid({0, 1, 0}));
  EXPECT_FALSE(Scheme::isValid({0, 2, 0}));
  EXPECT_FALSE(Scheme::isValid({0, 0, 1}));
  EXPECT_TRUE(Scheme::isValid({kMaxLevel, Scheme::tilesX(kMaxLevel) - 1, 0}));
  EXPECT_FALSE(Scheme::isValid({kMaxLevel, 0, Scheme::tilesY(kMaxLevel)}));
  EXPECT_FALSE(Scheme::isValid({kMaxLevel + 1, 0, 0}));
}

TEST(TilingScheme, LevelZeroRectangles) {
  const GlobeRectangle west = Scheme::tileRectangle({0, 0, 0});
  EXPECT_EQ(west.westRadians, -std::numbers::pi);
  EXPECT_EQ(west.eastRadians, 0.0);
  EXPECT_EQ(west.southRadians, -std::numbers::pi / 2.0);
  EXPECT_EQ(west.northRadians, std::numbers::pi / 2.0);
  const GlobeRectangle east = Scheme::tileRectangle({0, 1, 0});
  EXPECT_EQ(east.westRadians, 0.0);
  EXPECT_EQ(east.eastRadians, std::numbers::pi);
  // y grows southwards: row 0 of level 1 is the northern hemisphere.
  const GlobeRectangle north = Scheme::tileRectangle({1, 2, 0});
  EXPECT_EQ(north.southRadians, 0.0);
  EXPECT_EQ(north.northRadians, std::numbers::pi / 2.0);
  EXPECT_EQ(north.westRadians, 0.0);
  EXPECT_EQ(north.eastRadians, std::numbers::pi / 2.0);
}

// Every level's rectangles share edges bit for bit and cover exactly [-pi, pi] x [-pi/2, pi/2].
TEST(TilingScheme, RectanglesTileTheGlobeExactly) {
  for (uint32_t level = 0; level <= 9; ++level) {
    for (uint32_t y = 0; y < Scheme::tilesY(level); ++y) {
      for (uint32_t x = 0; x < Scheme::tilesX(level); ++x) {
        const GlobeRectangle r = Scheme::tileRectangle({level, x, y});
        ASSERT_LT(r.westRadians, r.eastRadians);
        ASSERT_LT(r.southRadians, r.northRadians);
        if (x == 0) {
          ASSERT_EQ(r.westRadians, -std::numbers::pi);
        }
        if (x + 1 == Scheme::tilesX(level)) {
          ASSERT_EQ(r.eastRadians, std::numbers::pi);
        } else {
          ASSERT_EQ(r.eastRadians, Scheme::tileRectangle({level, x + 1, y}).westRadians);
        }
        if (y == 0) {
          ASSERT_EQ(r.northRadians, std::numbers::pi / 2.0);
        }
        if (y + 1 == Scheme::tilesY(level)) {
          ASSERT_EQ(r.southRadians, -std::numbers::pi / 2.0);
        } else {
          ASSERT_EQ(r.southRadians, Scheme::tileRectangle({level, x, y + 1}).northRadians);
        }
      }
    }
  }
}

void expectChildrenPartitionParent(const TileId& tile) {
  const GlobeRectangle r = Scheme::tileRectangle(tile);
  const std::array<TileId, 4> c = tile.children();
  const GlobeRectangle nw = Scheme::tileRectangle(c[0]);
  const GlobeRectangle ne = Scheme::tileRectangle(c[1]);
  const GlobeRectangle sw = Scheme::tileRectangle(c[2]);
  const GlobeRectangle se = Scheme::tileRectangle(c[3]);
  ASSERT_EQ(nw.westRadians, r.westRadians);
  ASSERT_EQ(nw.northRadians, r.northRadians);
  ASSERT_EQ(ne.eastRadians, r.eastRadians);
  ASSERT_EQ(ne.northRadians, r.northRadians);
  ASSERT_EQ(sw.westRadians, r.westRadians);
  ASSERT_EQ(sw.southRadians, r.southRadians);
  ASSERT_EQ(se.eastRadians, r.eastRadians);
  ASSERT_EQ(se.southRadians, r.southRadians);
  ASSERT_EQ(nw.eastRadians, ne.westRadians);
  ASSERT_EQ(sw.eastRadians, se.westRadians);
  ASSERT_EQ(nw.eastRadians, sw.eastRadians);
  ASSERT_EQ(nw.southRadians, sw.northRadians);
  ASSERT_EQ(ne.southRadians, se.northRadians);
  ASSERT_EQ(nw.southRadians, ne.southRadians);
}

TEST(TilingScheme, ChildrenPartitionTheirParentExactly) {
  for (uint32_t level = 0; level <= 7; ++level) {
    for (uint32_t y = 0; y < Scheme::tilesY(level); ++y) {
      for (uint32_t x = 0; x < Scheme::tilesX(level); ++x)
        expectChildrenPartitionParent({level, x, y});
    }
  }
  std::mt19937_64 rng(11);
  for (uint32_t level = 8; level < kMaxLevel; ++level) {
    for (int i = 0; i < 2000; ++i) expectChildrenPartitionParent(randomTile(rng, level));
  }
}

// The tile's own west/north corner maps back to it (edge rule: east/south side wins).
void expectCornerMapsBack(const TileId& tile) {
  const GlobeRectangle r = Scheme::tileRectangle(tile);
  const std::optional<TileId> found = lookup(r.westRadians, r.northRadians, tile.level);
  ASSERT_TRUE(found.has_value());
  ASSERT_EQ(*found, tile) << "level " << tile.level << " x " << tile.x << " y " << tile.y;
}

TEST(TilingScheme, EveryTileCornerMapsBackUpToLevelTen) {
  for (uint32_t level = 0; level <= 10; ++level) {
    for (uint32_t y = 0; y < Scheme::tilesY(level); ++y) {
      for (uint32_t x = 0; x < Scheme::tilesX(level); ++x) expectCornerMapsBack({level, x, y});
    }
  }
}

TEST(TilingScheme, RandomTileCornersMapBackUpToMaxLevel) {
  std::mt19937_64 rng(12);
  for (uint32_t level = 11; level <= kMaxLevel; ++level) {
    for (int i = 0; i < 20000; ++i) expectCornerMapsBack(randomTile(rng, level));
    // The extreme tiles too.
    expectCornerMapsBack({level, 0, 0});
    expectCornerMapsBack({level, Scheme::tilesX(level) - 1, Scheme::tilesY(level) - 1});
  }
}

// Points on edges and corners, and one ulp either side of them, at many levels.
TEST(TilingScheme, EdgeRuleAtEdgesAndCorners) {
  std::mt19937_64 rng(13);
  for (uint32_t level = 0; level <= kMaxLevel; ++level) {
    const uint32_t lastX = Scheme::tilesX(level) - 1;
    const uint32_t lastY = Scheme::tilesY(level) - 1;
    for (int i = 0; i < 500; ++i) {
      const TileId tile = randomTile(rng, level);
      const GlobeRectangle r = Scheme::tileRectangle(tile);
      const double midLongitude = r.center().longitudeRadians;
      const double midLatitude = r.center().latitudeRadians;
      // West edge: this tile; one ulp west: the western neighbour.
      EXPECT_EQ(lookup(r.westRadians, midLatitude, level), tile);
      if (tile.x > 0) {
        EXPECT_EQ(lookup(std::nextafter(r.westRadians, -4.0), midLatitude, level),
                  (TileId{level, tile.x - 1, tile.y}));
      }
      // East edge: the eastern neighbour (or this tile at +180); one ulp west of it: this tile.
      EXPECT_EQ(lookup(r.eastRadians, midLatitude, level),
                (TileId{level, tile.x == lastX ? tile.x : tile.x + 1, tile.y}));
      EXPECT_EQ(lookup(std::nextafter(r.eastRadians, -4.0), midLatitude, level), tile);
      // North edge: this tile; one ulp north: the northern neighbour.
      EXPECT_EQ(lookup(midLongitude, r.northRadians, level), tile);
      if (tile.y > 0) {
        EXPECT_EQ(lookup(midLongitude, std::nextafter(r.northRadians, 4.0), level),
                  (TileId{level, tile.x, tile.y - 1}));
      }
      // South edge: the southern neighbour (or this tile at -90); one ulp north: this tile.
      EXPECT_EQ(lookup(midLongitude, r.southRadians, level),
                (TileId{level, tile.x, tile.y == lastY ? tile.y : tile.y + 1}));
      EXPECT_EQ(lookup(midLongitude, std::nextafter(r.southRadians, 4.0), level), tile);
      // South-east corner: the diagonal neighbour, clamped at +180 / -90.
      EXPECT_EQ(lookup(r.eastRadians, r.southRadians, level),
                (TileId{level, std::min(tile.x + 1, lastX), std::min(tile.y + 1, lastY)}));
    }
  }
}

TEST(TilingScheme, AntimeridianAndPoles) {
  for (uint32_t level = 0; level <= kMaxLevel; ++level) {
    const uint32_t lastX = Scheme::tilesX(level) - 1;
    const uint32_t lastY = Scheme::tilesY(level) - 1;
    EXPECT_EQ(lookup(std::numbers::pi, 0.3, level)->x, lastX);
    EXPECT_EQ(lookup(-std::numbers::pi, 0.3, level)->x, 0u);
    EXPECT_EQ(lookup(0.3, std::numbers::pi / 2.0, level)->y, 0u);
    EXPECT_EQ(lookup(0.3, -std::numbers::pi / 2.0, level)->y, lastY);
    EXPECT_EQ(lookup(std::numbers::pi, -std::numbers::pi / 2.0, level),
              (TileId{level, lastX, lastY}));
    EXPECT_EQ(lookup(-std::numbers::pi, std::numbers::pi / 2.0, level), (TileId{level, 0, 0}));
    // 0 longitude and 0 latitude are edges from level 0/1 on: east and south tiles win.
    EXPECT_EQ(lookup(0.0, 0.0, level)->x, Scheme::tilesX(level) / 2);
    EXPECT_EQ(lookup(-0.0, -0.0, level)->x, Scheme::tilesX(level) / 2);
    if (level > 0) {
      EXPECT_EQ(lookup(0.0, 0.0, level)->y, Scheme::tilesY(level) / 2);
    }
    // Out-of-range longitudes wrap.
    EXPECT_EQ(lookup(-std::numbers::pi - 0.1, 0.3, level),
              lookup(std::numbers::pi - 0.1, 0.3, level));
    EXPECT_EQ(lookup(3.0 * std::numbers::pi, 0.3, level), lookup(-std::numbers::pi, 0.3, level));
    EXPECT_EQ(lookup(0.5 + 4.0 * std::numbers::pi, 0.3, level), lookup(0.5, 0.3, level));
  }
}

TEST(TilingScheme, RejectsBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(lookup(nan, 0.0, 3), std::nullopt);
  EXPECT_EQ(lookup(0.0, nan, 3), std::nullopt);
  EXPECT_EQ(lookup(inf, 0.0, 3), std::nullopt);
  EXPECT_EQ(lookup(-inf, 0.0, 3), std::nullopt);
  EXPECT_EQ(lookup(0.0, inf, 3), std::nullopt);
  EXPECT_EQ(lookup(0.0, std::nextafter(std::numbers::pi / 2.0, 4.0), 3), std::nullopt);
  EXPECT_EQ(lookup(0.0, std::nextafter(-std::numbers::pi / 2.0, -4.0), 3), std::nullopt);
  EXPECT_EQ(lookup(0.0, 0.0, kMaxLevel + 1), std::nullopt);
  EXPECT_EQ(lookup(0.0, 0.0, 1000), std::nullopt);
}

// Random points: the tile found contains the point (closed) and follows the half-open rule.
TEST(TilingScheme, LookupAgreesWithTileRectangle) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> longitude(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> latitude(-std::numbers::pi / 2.0, std::numbers::pi / 2.0);
  std::uniform_int_distribution<uint32_t> level(0, kMaxLevel);
  for (int i = 0; i < 300000; ++i) {
    const double lon = longitude(rng);
    const double lat = latitude(rng);
    const uint32_t l = level(rng);
    const std::optional<TileId> tile = lookup(lon, lat, l);
    ASSERT_TRUE(tile.has_value());
    ASSERT_TRUE(Scheme::isValid(*tile));
    const GlobeRectangle r = Scheme::tileRectangle(*tile);
    ASSERT_TRUE(r.contains(lon, lat)) << lon << " " << lat << " level " << l;
    ASSERT_LT(lon, r.eastRadians);
    ASSERT_GT(lat, r.southRadians);
    // Its parent is the tile found one level up.
    if (l > 0) {
      ASSERT_EQ(tile->parent(), lookup(lon, lat, l - 1));
    }
  }
}

}  // namespace
}  // namespace globe::geo
