// Tests for collision/height_service.hpp: sampleHeight in both modes on a synthetic array.
#include "collision/height_service.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geo/tiling_scheme.hpp"
#include "tests/collision/collision_test_support.hpp"

namespace globe::collision {
namespace {

using geo::TileId;
using testing::gridLatitude;
using testing::gridLongitude;
using testing::makeBlock;

TEST(HeightService, BothModesTheTileAndItsLevel) {
  const terrain::HeightBlock coarse = makeBlock(17, [](uint32_t, uint32_t) { return int16_t{10}; });
  const terrain::HeightBlock fine =
      makeBlock(17, [](uint32_t i, uint32_t j) { return static_cast<int16_t>(100 * i + j); });
  const TileId fineId{5, 40, 9};
  RenderingTileArray array;
  array.assign({makeArrayTile({2, 5, 1}, coarse), makeArrayTile(fineId, fine)});
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const double lon = gridLongitude(fineId, 17, 3.25), lat = gridLatitude(fineId, 17, 6.5);
  const auto qotcd = sampleHeight(array, wgs84, lon, lat, HeightMode::Qotcd);
  const auto exact = sampleHeight(array, wgs84, lon, lat, HeightMode::Exact);
  ASSERT_TRUE(qotcd && exact);
  EXPECT_EQ(qotcd->tile, fineId);
  EXPECT_EQ(qotcd->level, 5u);
  EXPECT_EQ(qotcd->heightMeters, 704.0);
  EXPECT_EQ(qotcd->heightCase, HeightCase::Quad);
  EXPECT_EQ(exact->tile, fineId);
  EXPECT_EQ(exact->triangle, SurfaceTriangle::SouthWest);  // row fraction 0.5 >= column 0.25
  EXPECT_LT(exact->heightMeters, 704.0);
  EXPECT_GT(exact->heightMeters, 602.0);
  // Longitudes are wrapped.
  const auto wrapped =
      sampleHeight(array, wgs84, lon + 2.0 * std::numbers::pi, lat, HeightMode::Qotcd);
  ASSERT_TRUE(wrapped);
  EXPECT_EQ(wrapped->heightMeters, qotcd->heightMeters);
  // Elsewhere in the coarse tile; nothing outside; invalid input.
  const geo::GlobeRectangle c = geo::GeographicTilingScheme::tileRectangle({2, 5, 1});
  const auto flat =
      sampleHeight(array, wgs84, c.westRadians + 0.01, c.northRadians - 0.01, HeightMode::Exact);
  ASSERT_TRUE(flat);
  EXPECT_EQ(flat->level, 2u);
  EXPECT_LT(flat->heightMeters, 10.0);
  EXPECT_FALSE(sampleHeight(array, wgs84, -1.0, -1.0, HeightMode::Qotcd));
  EXPECT_FALSE(sampleHeight(array, wgs84, std::nan(""), 0.5, HeightMode::Qotcd));
  EXPECT_FALSE(sampleHeight(array, wgs84, 0.5, 1.7, HeightMode::Exact));
}

}  // namespace
}  // namespace globe::collision
