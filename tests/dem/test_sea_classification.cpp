#include <gtest/gtest.h>

#include "dem/condition.hpp"
#include "dem/grid_coarser_sources.hpp"
#include "dem/sea_classification.hpp"
#include "dem_test_grids.hpp"
#include "terrain/height_block.hpp"

namespace globe::dem {
namespace {

using testing::makeGrid;
constexpr int16_t kNoData = terrain::kNoDataHeight;

// A coarse grid (0.05°) over the fine test grids, flat at `height` metres.
DemGrid flatCoarse(int16_t height) {
  return makeGrid(
      20, 20, [=](int64_t, int64_t) { return height; }, 0.05, 9.8, 45.2);
}

TEST(SeaClassification, NoDataTouchingTheBorderIsSeaAndEnclosedNoDataIsAVoid) {
  // West third no data (sea), land elsewhere with a no-data hole inside.
  const DemGrid grid = makeGrid(30, 30, [](int64_t r, int64_t c) -> int16_t {
    if (c < 10) return kNoData;
    if (r >= 14 && r <= 16 && c >= 19 && c <= 21) return kNoData;
    return 500;
  });
  const SeaClassification result = classifySea(grid, nullptr);
  EXPECT_EQ(result.classes[grid.index(5, 3)], SampleClass::Sea);
  EXPECT_EQ(result.classes[grid.index(15, 20)], SampleClass::Void);
  EXPECT_EQ(result.classes[grid.index(15, 25)], SampleClass::Land);
  EXPECT_EQ(result.seaSamples, 300U);
  EXPECT_EQ(result.voidSamples, 9U);
  EXPECT_EQ(result.noDataSamples, 309U);
}

TEST(SeaClassification, NoDataConnectedToTheBorderIsAVoidWhereTheCoarserSourceSaysLand) {
  // A no-data gash from the border into a mountain; the coarser grid says 800 m everywhere.
  const DemGrid grid = makeGrid(
      30, 30, [](int64_t r, int64_t c) -> int16_t { return r == 15 && c < 20 ? kNoData : 900; });
  const DemGrid coarse = flatCoarse(800);
  const GridCoarserSources coarser({&coarse});
  const SeaClassification result = classifySea(grid, &coarser);
  EXPECT_EQ(result.seaSamples, 0U);
  EXPECT_EQ(result.voidSamples, 20U);
  // Without a coarser source the same gash reaches open sea: sea.
  EXPECT_EQ(classifySea(grid, nullptr).seaSamples, 20U);
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
  // A sea reaching the border only through a one-sample diagonal channel.
  const DemGrid grid = makeGrid(20, 20, [](int64_t r, int64_t c) -> int16_t {
    if (r >= 10 && r <= 15 && c >= 10 && c <= 15) return kNoData;
    if (r == c && r < 10) return kNoData;
    return 200;
  });
  EXPECT_EQ(classifySea(grid, nullptr).voidSamples, 0U);
}

TEST(Condition, SeaIsWrittenAsWaterKeepingMeasuredDepthAndLandKeepsItsHeights) {
  // Border-connected sea: no data, 0 m and -250 m; land at 10 m; a land depression at -5 m.
  DemGrid grid = makeGrid(10, 10, [](int64_t r, int64_t c) -> int16_t {
    if (c == 0) return kNoData;
    if (c == 1) return 0;
    if (c == 2) return -250;
    if (r == 5 && c == 7) return -5;
    return 10;
  });
  const ConditionStats stats = conditionGrid(grid, nullptr, {});
  EXPECT_EQ(grid.at(3, 0), kNoData);
  EXPECT_EQ(grid.at(3, 1), kNoData);
  EXPECT_TRUE(terrain::isWater(grid.at(3, 2)));
  EXPECT_EQ(terrain::seaFloorMeters(grid.at(3, 2)), -250.0);
  EXPECT_EQ(grid.at(5, 7), -5);
  EXPECT_EQ(grid.at(5, 8), 10);
  EXPECT_EQ(stats.seaSamples, 30U);
  EXPECT_FALSE(stats.allNoData());
}

TEST(Condition, AllNoDataIsReported) {
  DemGrid grid = makeGrid(8, 8, [](int64_t, int64_t) { return kNoData; });
  EXPECT_TRUE(conditionGrid(grid, nullptr, {}).allNoData());
}

}  // namespace
}  // namespace globe::dem
