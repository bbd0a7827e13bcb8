// surface::PyramidSurface: the height of the finest tile present (down to a chosen level), the
// water of its nearest vertex, across a gap of levels, at ±180°, against collision's exact
// surface on real blocks, and an unreadable pack named.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "collision/exact_surface.hpp"
#include "geo/tiling_scheme.hpp"
#include "streaming/tile_store.hpp"
#include "surface/pyramid_surface.hpp"
#include "terrain/rendering_tile_array.hpp"
#include "tests/support/sea_test_pyramid.hpp"
#include "tests/support/test_io_util.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::surface {
namespace {

namespace fs = std::filesystem;
using globe::testing::kMixedTile;
using globe::testing::kSeaTestVerticesPerSide;

constexpr double kRadiansPerDegree = std::numbers::pi / 180;

// The position of vertex (row, column) of a tile, in radians.
struct Radians {
  double longitude = 0, latitude = 0;
};
Radians vertexOf(const geo::TileId& tile, uint32_t row, uint32_t column) {
  const auto rect = geo::GeographicTilingScheme::tileRectangle(tile);
  const double last = kSeaTestVerticesPerSide - 1;
  return {rect.westRadians + (rect.eastRadians - rect.westRadians) * column / last,
          rect.northRadians - (rect.northRadians - rect.southRadians) * row / last};
}

// Collision's exact surface of one stored tile at a point.
double exactHeightOf(streaming::TileStore& store, const geo::TileId& tile, double lon, double lat) {
  const auto block = store.loadBlock(tile);
  EXPECT_TRUE(block) << block.error();
  if (!block) return 0;
  return collision::exactTileSurfaceHeight(terrain::makeArrayTile(tile, *block),
                                           geo::Ellipsoid::wgs84(), lon, lat)
      .heightMeters;
}

class SeaPyramidSurface : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_TRUE(globe::testing::writeSeaTestPyramid(dir_.path()));
    auto opened = streaming::TileStore::open(dir_.path());
    ASSERT_TRUE(opened) << opened.error();
    store_ = std::move(*opened);
  }
  globe::testing::TempDir dir_;
  std::unique_ptr<streaming::TileStore> store_;
};

TEST_F(SeaPyramidSurface, FinestTileHeightsAndWater) {
  PyramidSurface surface(*store_, geo::Ellipsoid::wgs84());
  // Columns 12..16 of the mixed tile are land at 250 m, 8..11 land at -400 m, 0..3 water.
  const Radians land = vertexOf(kMixedTile, 8, 13);
  auto height = surface.heightMeters(land.longitude, land.latitude);
  ASSERT_TRUE(height) << height.error();
  EXPECT_NEAR(*height, globe::testing::kMixedLandMeters, 1e-3);
  const Radians low = vertexOf(kMixedTile, 8, 10);
  EXPECT_NEAR(*surface.heightMeters(low.longitude, low.latitude),
              globe::testing::kMixedLandBelowSeaLevelMeters, 1e-3);
  EXPECT_FALSE(*surface.isWater(land.longitude, land.latitude));
  const Radians sea = vertexOf(kMixedTile, 8, 1);
  EXPECT_TRUE(*surface.isWater(sea.longitude, sea.latitude));
  EXPECT_NEAR(*surface.heightMeters(sea.longitude, sea.latitude), 0.0, 1e-3) << "water at 0 m";
}

TEST_F(SeaPyramidSurface, MaxLevelSkipsTheGapToLevelZero) {
  PyramidSurface surface(*store_, geo::Ellipsoid::wgs84());
  const Radians land = vertexOf(kMixedTile, 8, 13);
  // Levels 1..9 have no tiles: below level 10 the level-0 tile (water of unknown depth, its mesh
  // a chord far below the ellipsoid this far from its vertices) answers.
  const auto levelZero =
      *geo::GeographicTilingScheme::positionToTile(land.longitude, land.latitude, 0);
  const double chordMeters = exactHeightOf(*store_, levelZero, land.longitude, land.latitude);
  EXPECT_LT(chordMeters, -1000.0);
  for (const uint32_t maxLevel : {9u, 5u, 0u}) {
    auto height = surface.heightMeters(land.longitude, land.latitude, maxLevel);
    ASSERT_TRUE(height) << height.error();
    EXPECT_DOUBLE_EQ(*height, chordMeters) << "max level " << maxLevel;
    EXPECT_TRUE(*surface.isWater(land.longitude, land.latitude, maxLevel));
  }
  EXPECT_NEAR(*surface.heightMeters(land.longitude, land.latitude, 10), 250.0, 1e-3);
}

TEST_F(SeaPyramidSurface, AnUnreadablePackIsNamed) {
  // Zero every pack past its header: the blocks fail their checks when read.
  for (const auto& entry : fs::recursive_directory_iterator(dir_.path())) {
    if (entry.path().extension() != ".pack") continue;
    const auto size = fs::file_size(entry.path());
    std::fstream file(entry.path(), std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(size / 2));
    const std::string zeros(size - size / 2, '\0');
    file.write(zeros.data(), static_cast<std::streamsize>(zeros.size()));
  }
  auto reopened = streaming::TileStore::open(dir_.path());
  ASSERT_TRUE(reopened) << reopened.error();
  PyramidSurface surface(**reopened, geo::Ellipsoid::wgs84());
  const Radians land = vertexOf(kMixedTile, 8, 13);
  auto height = surface.heightMeters(land.longitude, land.latitude);
  ASSERT_FALSE(height) << "read " << *height << " m from a damaged pack";
  EXPECT_NE(height.error().find(".pack"), std::string::npos) << height.error();
}

// On real blocks (the bundled pyramid): the finest tile present's exact mesh height, as collision
// computes it, and the same height a turn of longitude away.
TEST(BundledPyramidSurface, AgreesWithCollisionsExactSurfaceAndWrapsLongitude) {
  auto store = streaming::TileStore::open(globe::testing::bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  const auto ellipsoid = geo::Ellipsoid::wgs84();
  PyramidSurface surface(**store, ellipsoid);
  const struct {
    double lonDegrees, latDegrees;
  } points[] = {{138.7274, 35.3606}, {-112.95, 37.28}, {179.999, -16.5}, {-179.999, 65.0}};
  for (const auto& p : points) {
    const double lon = p.lonDegrees * kRadiansPerDegree, lat = p.latDegrees * kRadiansPerDegree;
    double expected = 0;
    for (uint32_t level = (*store)->manifest().maxLevel() + 1; level-- > 0;) {
      const auto tile = *geo::GeographicTilingScheme::positionToTile(lon, lat, level);
      if (!*(*store)->summary(tile)) continue;
      expected = exactHeightOf(**store, tile, lon, lat);
      break;
    }
    auto height = surface.heightMeters(lon, lat);
    ASSERT_TRUE(height) << height.error();
    EXPECT_DOUBLE_EQ(*height, expected) << p.lonDegrees << ", " << p.latDegrees;
    auto turned = surface.heightMeters(lon + 2 * std::numbers::pi, lat);
    ASSERT_TRUE(turned);
    EXPECT_NEAR(*turned, expected, 1e-6) << "a turn east of " << p.lonDegrees;
  }
}

}  // namespace
}  // namespace globe::surface
