#include <gtest/gtest.h>

#include "conditioning/condition.hpp"
#include "conditioning/grid_coarser_sources.hpp"
#include "conditioning/sea_classification.hpp"
#include "dem_test_grids.hpp"
#include "terrain/height_block.hpp"

namespace globe::conditioning {
namespace {

using testing::makeGrid;
constexpr int16_t kNoData = terrain::kNoDataHeight;

// A coarse grid (0.05°) over the fine test grids, flat at `height` metres.
DemGrid flatCoarse(int16_t height) {
  return makeGrid(
      20, 20, [=](int64_t, int64_t) { return height; }, 0.05, 9.8, 45.2);
}

TEST(SeaClassification, WithoutACoarserSourceNoDataIsAVoidNeverSea) {
  // West third no data, land elsewhere with a no-data hole inside: nothing says sea.
  const DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    if (c < 10) return kNoData;
    if (r >= 14 && r <= 16 && c >= 19 && c <= 21) return kNoData;
    return 500;
  });
  const SeaClassification result = classifySea(grid, nullptr);
  EXPECT_EQ(result.classes[grid.index(5, 3)], SampleClass::Void);
  EXPECT_EQ(result.classes[grid.index(15, 20)], SampleClass::Void);
  EXPECT_EQ(result.classes[grid.index(15, 25)], SampleClass::Land);
  EXPECT_EQ(result.seaSamples, 0U);
  EXPECT_EQ(result.outsideSamples, 0U);
  EXPECT_EQ(result.voidSamples, 309U);
  EXPECT_EQ(result.noDataSamples, 309U);
}

TEST(SeaClassification, NoDataReachingTheBorderIsOutsideTheFootprintWhereACoarserSourceCovers) {
  // A blanked wedge along the north edge (a reprojection's corner) and an enclosed hole; the
  // coarser grid says 800 m everywhere: the wedge shows the coarser source, the hole is a void.
  const DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    if (r < 3 && c < 24 - 8 * r) return kNoData;
    if (r == 15 && c == 15) return kNoData;
    return 900;
  });
  const DemGrid coarse = flatCoarse(800);
  const GridCoarserSources coarser({&coarse});
  const SeaClassification result = classifySea(grid, &coarser);
  EXPECT_EQ(result.seaSamples, 0U);
  EXPECT_EQ(result.outsideSamples, 24U + 16U + 8U);
  EXPECT_EQ(result.voidSamples, 1U);
  EXPECT_EQ(result.classes[grid.index(2, 7)], SampleClass::Outside);
  EXPECT_EQ(result.classes[grid.index(15, 15)], SampleClass::Void);
  // Without a coarser source the same wedge is a void too: never sea by connectivity.
  const SeaClassification alone = classifySea(grid, nullptr);
  EXPECT_EQ(alone.seaSamples, 0U);
  EXPECT_EQ(alone.voidSamples, 49U);
}

TEST(SeaClassification, AHoleTheGridsEdgeCutsIsAVoidNotOutside) {
  // A gash one sample wide from the west edge into a mountain, and a hole the south edge cuts
  // through (four samples of 30 on the edge): holes in the data, filled, not the footprint's
  // outside. Over coarser water the same gash is that water.
  const DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    if (r == 15 && c < 20) return kNoData;
    if (r >= 26 && c >= 10 && c < 14) return kNoData;
    return 900;
  });
  const DemGrid land = flatCoarse(800);
  const GridCoarserSources overLand({&land});
  const SeaClassification result = classifySea(grid, &overLand);
  EXPECT_EQ(result.outsideSamples, 0U);
  EXPECT_EQ(result.voidSamples, 20U + 16U);
  EXPECT_EQ(result.classes[grid.index(15, 0)], SampleClass::Void);
  EXPECT_EQ(result.classes[grid.index(29, 12)], SampleClass::Void);
  const DemGrid water = flatCoarse(terrain::encodeWater(-30));
  const GridCoarserSources overWater({&water});
  const SeaClassification sea = classifySea(grid, &overWater);
  EXPECT_EQ(sea.voidSamples, 0U);
  EXPECT_EQ(sea.classes[grid.index(15, 0)], SampleClass::Sea);
}

TEST(SeaClassification, NoDataReachingTheBorderIsOutsideOverCoarserLandAndWaterAlike) {
  // No data over the whole west half and an enclosed hole east; the coarser grid is water west
  // of 10.125°E (columns < 12.5) and land east of it.
  const DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    if (c < 15) return kNoData;
    if (r == 20 && c == 22) return kNoData;
    return 40;
  });
  const DemGrid coarse = makeGrid(
      20, 20, [](int64_t, int64_t c) -> int16_t { return c < 4 ? terrain::encodeWater(-30) : 60; },
      0.05, 9.8, 45.2);
  const GridCoarserSources coarser({&coarse});
  const SeaClassification result = classifySea(grid, &coarser);
  for (int64_t r = 0; r < 30; ++r) {
    for (int64_t c = 0; c < 15; ++c) {
      const auto said = coarser.sample(grid.longitudeDegrees(c), grid.latitudeDegrees(r));
      ASSERT_TRUE(said.has_value());
      // Outside the footprint either way; water decided later by the bend from the coarser.
      EXPECT_EQ(result.classes[grid.index(r, c)], SampleClass::Outside) << r << "," << c;
    }
  }
  EXPECT_EQ(result.classes[grid.index(20, 22)], SampleClass::Void);
  EXPECT_EQ(result.seaSamples, 0U);
}

TEST(SeaClassification, SrtmZeroMetreSeaIsSeaOnlyWhereTheCoarserSourceAllowsIt) {
  // South half exactly 0 m (how SRTM writes the sea), north half land.
  const DemGrid grid =
      makeGrid(30, 30, [](int64_t r, int64_t) -> int16_t { return r >= 15 ? 0 : 120; });
  const DemGrid sea = flatCoarse(-30);
  const DemGrid land = flatCoarse(40);
  const GridCoarserSources seaSource({&sea});
  EXPECT_EQ(classifySea(grid, &seaSource).seaSamples, 450U);
  // A coarser source that says land: a flat 0 m plain, kept as land.
  const GridCoarserSources landSource({&land});
  const SeaClassification plain = classifySea(grid, &landSource);
  EXPECT_EQ(plain.seaSamples, 0U);
  EXPECT_EQ(plain.voidSamples, 0U);
}

TEST(SeaClassification, LandBelowSeaLevelAwayFromTheSeaStaysLand) {
  // A depression (-30 m) enclosed by land: measured, not connected to the sea.
  const DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    return (r > 10 && r < 20 && c > 10 && c < 20) ? -30 : 50;
  });
  const SeaClassification result = classifySea(grid, nullptr);
  EXPECT_EQ(result.seaSamples, 0U);
  EXPECT_EQ(result.classes[grid.index(15, 15)], SampleClass::Land);
}

TEST(SeaClassification, AnEnclosedDeepLargeBasinIsASeaAndASmallOneIsNot) {
  // A 20′ grid (37 km cells) with an enclosed basin 4000 m deep: 6×6 cells ≈ 40,000 km².
  auto basin = [](int64_t size) {
    return [size](int64_t r, int64_t c) -> int16_t {
      return (r >= 5 && r < 5 + size && c >= 5 && c < 5 + size) ? -4000 : 300;
    };
  };
  const DemGrid large = makeGrid(20, 20, basin(6), 1.0 / 3.0, 30.0, 45.0);
  EXPECT_EQ(classifySea(large, nullptr).seaSamples, 36U);
  const DemGrid small = makeGrid(20, 20, basin(1), 1.0 / 3.0, 30.0, 45.0);
  EXPECT_EQ(classifySea(small, nullptr).seaSamples, 0U);
}

TEST(SeaClassification, DiagonalChannelsConnectTheSea) {
  // A 0 m sea reaching the border only through a one-sample diagonal channel.
  const DemGrid grid = makeGrid(20, 20, [](int64_t r, int64_t c) -> int16_t {
    if (r >= 10 && r <= 15 && c >= 10 && c <= 15) return 0;
    if (r == c && r < 10) return 0;
    return 200;
  });
  EXPECT_EQ(classifySea(grid, nullptr).seaSamples, 46U);
}

TEST(SeaClassification, MeasuredZeroMetresReachingCoarserWaterIsSea) {
  // An enclosed 0 m lagoon touching an enclosed no-data patch under coarser water: sea.
  const DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    if (r >= 10 && r < 20 && c >= 10 && c < 20) return c < 15 ? kNoData : 0;
    return 300;
  });
  const DemGrid sea = flatCoarse(terrain::encodeWater(-30));
  const GridCoarserSources coarser({&sea});
  const SeaClassification result = classifySea(grid, &coarser);
  EXPECT_EQ(result.seaSamples, 100U);
  EXPECT_EQ(result.classes[grid.index(15, 17)], SampleClass::Sea);
}

TEST(Condition, SeaIsWrittenAsWaterKeepingMeasuredDepthAndLandKeepsItsHeights) {
  // Border-connected sea: 0 m and -250 m; land at 10 m; a land depression at -5 m; an enclosed
  // no-data hole, a void: filled as land, not sea.
  DemGrid grid = makeGrid(10, 10, [](int64_t r, int64_t c) -> int16_t {
    if (c == 1 || c == 0) return 0;
    if (c == 2) return -250;
    if (r == 5 && c == 7) return -5;
    if (r == 2 && c == 6) return kNoData;
    return 10;
  });
  const ConditionStats stats = conditionGrid(grid, nullptr, {});
  EXPECT_EQ(grid.at(3, 0), kNoData);
  EXPECT_EQ(grid.at(3, 1), kNoData);
  EXPECT_TRUE(terrain::isWater(grid.at(3, 2)));
  EXPECT_EQ(terrain::seaFloorMeters(grid.at(3, 2)), -250.0);
  EXPECT_EQ(grid.at(5, 7), -5);
  EXPECT_EQ(grid.at(5, 8), 10);
  EXPECT_EQ(grid.at(2, 6), 10);
  EXPECT_EQ(stats.seaSamples, 30U);
  EXPECT_EQ(stats.voidSamples, 1U);
  EXPECT_FALSE(stats.allNoData());
}

TEST(Condition, NoDataUnderCoarserWaterIsThatWaterWithItsFloor) {
  // An enclosed no-data patch in a 0 m bay; the coarser source is sea 30 m deep.
  DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    if (r >= 10 && r < 20 && c >= 10 && c < 20) return kNoData;
    return c > 20 ? 100 : 0;
  });
  const DemGrid sea = flatCoarse(terrain::encodeWater(-30));
  const GridCoarserSources coarser({&sea});
  conditionGrid(grid, &coarser, {});
  EXPECT_TRUE(terrain::isWater(grid.at(15, 15)));
  EXPECT_EQ(terrain::seaFloorMeters(grid.at(15, 15)), -30.0);
  EXPECT_EQ(grid.at(15, 25), 100);
}

TEST(Condition, AllNoDataIsReported) {
  DemGrid grid = makeGrid(8, 8, [](int64_t, int64_t) { return kNoData; });
  EXPECT_TRUE(conditionGrid(grid, nullptr, {}).allNoData());
}

}  // namespace
}  // namespace globe::conditioning
