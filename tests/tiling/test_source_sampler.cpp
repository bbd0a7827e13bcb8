// The tiler's sampling rule at the hard places: exact samples, edges, no data, wrapping, poles.
#include "tiling/source_sampler.hpp"

#include <gtest/gtest.h>

#include "rasters/gtopo30.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiling/source_set.hpp"

namespace globe::tiling {
namespace {

TEST(FinestLevel, FromTheSourceResolution) {
  EXPECT_EQ(finestLevelForStep(1.0 / 3, 17), 6u);       // 20′: 180/(16·64) = 0.176° ≤ 0.333°
  EXPECT_EQ(finestLevelForStep(1.0 / 120, 17), 11u);    // 30″ GTOPO30
  EXPECT_EQ(finestLevelForStep(1.0 / 1200, 17), 14u);   // 3″ SRTM
  EXPECT_EQ(finestLevelForStep(11.25, 17), 0u);         // exactly level 0's spacing
  EXPECT_EQ(finestLevelForStep(1.0 / 1200, 257), 10u);  // bigger blocks, fewer levels
}

class SamplerOnRealData : public ::testing::Test {
 protected:
  void SetUp() override {
    auto opened = openSources(globe::testing::bundledInputs(), {17, std::nullopt});
    ASSERT_TRUE(opened) << opened.error();
    sources_ = std::move(*opened);
    // The sampler reads the rasters as they are (unconditioned): open them again.
    for (TilerSource& source : sources_) ASSERT_TRUE(openRaster(source));
  }
  std::vector<TilerSource> sources_;
};

TEST_F(SamplerOnRealData, VertexOnASampleReturnsItExactly) {
  auto fuji = rasters::readGtopo30(globe::testing::bundledInputs()[2]);
  ASSERT_TRUE(fuji) << fuji.error();
  SourceSampler sampler(sources_, 14, 138.0, 139.0);
  // SRTM samples lie on 3″ steps from 138°E, 36°N.
  for (int row : {0, 1, 600, 1199, 1200}) {
    for (int col : {0, 7, 600, 1200}) {
      auto h = sampler.sample(138.0 + col / 1200.0, 36.0 - row / 1200.0);
      ASSERT_TRUE(h) << h.error();
      EXPECT_EQ(*h, fuji->at(row, col)) << row << "," << col;
    }
  }
}

TEST_F(SamplerOnRealData, FinestSourceWinsAndCoarserFillsTheRest) {
  SourceSampler fine(sources_, 14, 137.0, 140.0);
  SourceSampler coarse(sources_, 6, 137.0, 140.0);
  auto summitFine = fine.sample(138.7275, 35.3606);
  auto summitCoarse = coarse.sample(138.7275, 35.3606);
  ASSERT_TRUE(summitFine && summitCoarse);
  EXPECT_GT(*summitFine, 3600);             // SRTM resolves the summit
  EXPECT_LT(*summitCoarse, 3000);           // 20′ ETOPO20 smooths it away
  auto outside = fine.sample(139.5, 35.5);  // east of the Fuji tile: ETOPO20
  auto outsideCoarse = coarse.sample(139.5, 35.5);
  ASSERT_TRUE(outside && outsideCoarse);
  EXPECT_EQ(*outside, *outsideCoarse);
}

TEST_F(SamplerOnRealData, NoDataWhereTheNearestSampleIsSea) {
  auto england = rasters::readGtopo30(globe::testing::bundledInputs()[1]);
  ASSERT_TRUE(england) << england.error();
  int seaChecked = 0;
  SourceSampler sampler(sources_, 11, -2.0, 0.0);
  for (int64_t row = 0; row < 240; row += 7) {
    for (int64_t col = 0; col < 240; col += 5) {
      if (england->at(row, col) != -9999) continue;
      auto h = sampler.sample(-2.0 + (static_cast<double>(col) + 0.5) / 120.0,
                              54.0 - (static_cast<double>(row) + 0.5) / 120.0);
      ASSERT_TRUE(h);
      EXPECT_EQ(*h, -9999);
      ++seaChecked;
    }
  }
  EXPECT_GT(seaChecked, 5);
}

TEST_F(SamplerOnRealData, AntimeridianAndPoles) {
  SourceSampler west(sources_, 6, -180.0, -170.0);
  SourceSampler east(sources_, 6, 170.0, 180.0);
  for (double lat : {-89.9, -60.0, -16.5, 0.0, 52.0, 71.3}) {
    auto a = west.sample(-180.0, lat);
    auto b = east.sample(180.0, lat);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(*a, *b) << "lat " << lat;
  }
  auto north1 = west.sample(-180.0, 90.0), north2 = east.sample(123.0, 90.0);
  auto south1 = west.sample(-45.0, -90.0), south2 = east.sample(179.0, -90.0);
  ASSERT_TRUE(north1 && north2 && south1 && south2);
  EXPECT_EQ(*north1, *north2);
  EXPECT_EQ(*south1, *south2);
  EXPECT_GT(*south1, 2000);  // Antarctic ice sheet
}

}  // namespace
}  // namespace globe::tiling
