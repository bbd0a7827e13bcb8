// Terrain shadows (collision/sun_visibility.hpp): a wall shades the ground behind it from a low
// Sun and not from a high one, the penumbra is in between, night is no shadow; over Zion's real
// canyons a low Sun leaves the deepest floor dark while the highest ground stays lit.
#include "collision/sun_visibility.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "collision/surface_probe.hpp"
#include "geo/ecef.hpp"
#include "terrain/block_grid.hpp"
#include "terrain/tile_mesh.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::collision {
namespace {

using globe::test::kN;
using globe::test::kWgs84;

// The Sun at `elevationDegrees` above the horizon due west of (lon, lat).
glm::dvec3 westernSun(double lonDegrees, double latDegrees, double elevationDegrees) {
  const glm::dvec3 up = geo::geodeticSurfaceNormal(
      kWgs84, geo::Cartographic::fromDegrees(lonDegrees, latDegrees, 0.0));
  const glm::dvec3 east = glm::normalize(glm::cross(glm::dvec3(0, 0, 1), up));
  const double e = geo::degreesToRadians(elevationDegrees);
  return glm::normalize(std::cos(e) * -east + std::sin(e) * up);
}

// One level-13 tile (~76 m between vertices), flat at 100 m but for a 400 m wall on column 8.
struct WallWorld {
  geo::TileId tile{13, 8192, 2000};
  terrain::HeightBlock block = testing::makeBlock(
      kN, [](uint32_t, uint32_t j) { return static_cast<int16_t>(j == 8 ? 400 : 100); });
  RenderingTileArray array = testing::arrayOf({tile}, block);

  glm::dvec3 vertex(uint32_t column) const {
    const terrain::BlockGrid grid{tile, kN};
    return terrain::tileVertexEcefMeters(kWgs84, grid, 8, column,
                                         block.surfaceHeightMetersAt(8, column) + 0.5);
  }
  double lon() const { return terrain::BlockGrid{tile, kN}.longitudeDegrees(8); }
  double lat() const { return terrain::BlockGrid{tile, kN}.latitudeDegrees(8); }
  float seen(uint32_t column, double elevationDegrees) const {
    // Half a cell along the parallel, as tileSunVisibility steps.
    const double step = 0.5 * vertexSpacingMeters(array.tiles()[0], kWgs84) *
                        std::cos(geo::degreesToRadians(lat()));
    return sunVisibility(array, kWgs84, vertex(column), westernSun(lon(), lat(), elevationDegrees),
                         step, 400.0);
  }
};

TEST(SunVisibility, AWallShadesTheGroundBehindItFromALowSun) {
  const WallWorld world;
  // Column 11 is three cells (~320 m at 46°N) east of the wall: 300 m above it, ~43° up.
  EXPECT_EQ(world.seen(11, 10.0), 0.0f) << "in the wall's shadow";
  EXPECT_EQ(world.seen(11, 80.0), 1.0f) << "a high Sun clears the wall";
  EXPECT_EQ(world.seen(4, 10.0), 1.0f) << "the side facing the Sun";
  EXPECT_EQ(world.seen(11, -5.0), 1.0f) << "night is the shader's, not a shadow";
  // Around the grazing elevation (~41°, the wall's top against the Sun's 0.53° disc): dark
  // below, lit above, partly lit between (half-cell steps place the ridge's top within a few
  // tens of metres, so the edge wavers by a degree or two).
  int penumbra = 0;
  for (double elevation = 30.0; elevation <= 60.0; elevation += 0.05) {
    const float seen = world.seen(11, elevation);
    if (elevation <= 37.0) {
      EXPECT_EQ(seen, 0.0f) << elevation;
    }
    if (elevation >= 46.0) {
      EXPECT_EQ(seen, 1.0f) << elevation;
    }
    if (seen > 0.0f && seen < 1.0f) ++penumbra;
  }
  EXPECT_GE(penumbra, 4);
  EXPECT_LE(penumbra, 40);
}

TEST(SunVisibility, PerTileValuesFollowTheWall) {
  const WallWorld world;
  const glm::dvec3 sun = westernSun(world.lon(), world.lat(), 10.0);
  const std::vector<float> values =
      tileSunVisibility(world.array.tiles()[0], world.array, kWgs84, sun);
  ASSERT_EQ(values.size(), size_t{kN} * kN);
  for (uint32_t i = 0; i < kN; ++i) {
    EXPECT_EQ(values[i * kN + 4], 1.0f) << "row " << i << ": west of the wall";
    EXPECT_EQ(values[i * kN + 8], 1.0f) << "row " << i << ": the wall's top";
    EXPECT_EQ(values[i * kN + 10], 0.0f) << "row " << i << ": east of the wall";
  }
}

TEST(SunVisibility, ZionsDeepestFloorIsDarkAtALowSunAndItsHighestGroundLit) {
  auto& zion = testing::RealPyramid::zion();
  const auto tiles = testing::tilesOfLevel(zion, 12, -113.10, 37.20, -112.90, 37.40);
  ASSERT_GT(tiles.size(), 8u);
  const RenderingTileArray array = zion.array(tiles);
  // The lowest and highest vertices of the middle of the area (the edges' rays leave the array).
  glm::dvec3 lowest(0.0), highest(0.0);
  double low = 1e9, high = -1e9;
  for (const ArrayTile& tile : array.tiles()) {
    const terrain::BlockGrid grid{tile.id, tile.block->verticesPerSide};
    for (uint32_t i = 0; i < grid.verticesPerSide; ++i) {
      for (uint32_t j = 0; j < grid.verticesPerSide; ++j) {
        const double lon = grid.longitudeDegrees(j), lat = grid.latitudeDegrees(i);
        if (lon < -113.05 || lon > -112.95 || lat < 37.25 || lat > 37.35) continue;
        const double h = tile.block->surfaceHeightMetersAt(i, j);
        const glm::dvec3 p = terrain::tileVertexEcefMeters(kWgs84, grid, i, j, h + 0.5);
        if (h < low) low = h, lowest = p;
        if (h > high) high = h, highest = p;
      }
    }
  }
  ASSERT_GT(high - low, 500.0) << "a canyon";
  const double spacing = 0.5 * vertexSpacingMeters(array.tiles()[0], kWgs84) * std::cos(0.65);
  const double top = maximumSurfaceHeightMeters(array);
  const glm::dvec3 sun = westernSun(-113.0, 37.3, 4.0);
  EXPECT_LT(sunVisibility(array, kWgs84, lowest, sun, spacing, top), 0.5f) << low << " m";
  EXPECT_EQ(sunVisibility(array, kWgs84, highest, sun, spacing, top), 1.0f) << high << " m";
}

}  // namespace
}  // namespace globe::collision
