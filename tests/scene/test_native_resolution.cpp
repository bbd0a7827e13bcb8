// The data's own resolution at a tile: the finest source holding the tile's centre, whatever
// level the tile is drawn at; extents across ±180°; NaN where no source holds it.
#include "scene/native_resolution.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geo/cartographic.hpp"
#include "geo/tiling_scheme.hpp"

namespace globe::scene {
namespace {

formats::SourceInfo source(double stepDegrees, formats::BoundsDegrees bounds) {
  formats::SourceInfo s;
  s.stepDegrees = stepDegrees;
  s.bounds = bounds;
  return s;
}

geo::TileId tileAt(double lonDegrees, double latDegrees, uint32_t level) {
  return *geo::GeographicTilingScheme::positionToTile(geo::degreesToRadians(lonDegrees),
                                                      geo::degreesToRadians(latDegrees), level);
}

TEST(NativeResolution, TheFinestSourceAtTheTilesCentreAtEveryLevel) {
  const std::vector<formats::SourceInfo> sources{
      source(1.0 / 3.0, {-180, -90, 180, 90}),                 // the world grid
      source(1.0 / 1200.0, {-113.24, 37.13, -112.85, 37.51}),  // Zion's SRTM
      source(0.0, {-114, 37, -112, 38}),                       // no step known: ignored
  };
  for (uint32_t level = 9; level <= 16; ++level) {
    EXPECT_DOUBLE_EQ(finestStepDegreesAt(sources, tileAt(-113.0, 37.3, level)), 1.0 / 1200.0)
        << "level " << level;
  }
  // A tile much larger than the fine source takes the source at its centre: the world grid.
  EXPECT_DOUBLE_EQ(finestStepDegreesAt(sources, tileAt(-113.0, 37.3, 2)), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(finestStepDegreesAt(sources, tileAt(10.0, 50.0, 12)), 1.0 / 3.0);
  EXPECT_TRUE(std::isnan(finestStepDegreesAt({}, tileAt(10.0, 50.0, 12))));
}

// Corners: neighbouring tiles agree on their shared corners (so the weight interpolated across
// them is continuous), and a tile whose east edge is a source's west edge has the fine step on
// its eastern corners only: the change runs across that tile.
TEST(NativeResolution, CornersAreSharedAndTheChangeRunsAcrossATile) {
  const std::vector<formats::SourceInfo> sources{
      source(1.0 / 3.0, {-180, -90, 180, 90}),
      source(1.0 / 120.0, {-2.0, 52.0, 0.0, 54.0}),  // W002N52
  };
  const geo::TileId west = tileAt(-0.01, 52.9, 12);
  const geo::TileId east{west.level, west.x + 1, west.y};
  const auto w = finestStepDegreesAtCorners(sources, west);
  const auto e = finestStepDegreesAtCorners(sources, east);
  EXPECT_EQ(w[1], e[0]);  // north-east of the west tile is north-west of the east one
  EXPECT_EQ(w[3], e[2]);
  EXPECT_DOUBLE_EQ(e[0], 1.0 / 120.0);  // on 0°: inside W002N52 (extents are closed)
  EXPECT_DOUBLE_EQ(e[1], 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(w[0], 1.0 / 120.0);
}

TEST(NativeResolution, ExtentsAcrossTheAntimeridian) {
  std::vector<formats::ImagerySourceInfo> sources(2);
  sources[0].pixelDegrees = 0.001;
  sources[0].bounds = {179.0, -18.0, -179.0, -15.0};  // west > east: across ±180°
  sources[1].pixelDegrees = 0.002;
  sources[1].bounds = {-181.0, -18.0, -179.5, -15.0};  // written beyond -180°
  EXPECT_DOUBLE_EQ(finestTexelDegreesAt(sources, tileAt(179.5, -16.5, 12)), 0.001);
  EXPECT_DOUBLE_EQ(finestTexelDegreesAt(sources, tileAt(-179.7, -16.5, 12)), 0.001);
  EXPECT_DOUBLE_EQ(finestTexelDegreesAt(sources, tileAt(179.2, -16.5, 14)), 0.001);
  sources[0].pixelDegrees = 0.0;  // unknown: the other one
  EXPECT_DOUBLE_EQ(finestTexelDegreesAt(sources, tileAt(179.5, -16.5, 12)), 0.002);
  EXPECT_TRUE(std::isnan(finestTexelDegreesAt(sources, tileAt(170.0, -16.5, 12))));
}

}  // namespace
}  // namespace globe::scene
