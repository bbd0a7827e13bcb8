#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "conditioning/condition.hpp"
#include "conditioning/footprint_bend.hpp"
#include "conditioning/grid_coarser_sources.hpp"
#include "conditioning/harmonic_fill.hpp"
#include "dem_test_grids.hpp"
#include "terrain/height_block.hpp"

namespace globe::conditioning {
namespace {

using testing::makeGrid;
constexpr int16_t kNoDataSample = terrain::kNoDataHeight;
constexpr double kMarginDegrees = 0.3;  // thirty fine samples
constexpr int64_t kBlanked = 40;        // west columns without data

// A 0.05° coarse grid over the fine ones (0.01°, 10.00..10.99 E, 45.00..44.01 N).
DemGrid coarseGrid(int16_t sample) {
  return makeGrid(
      60, 60, [=](int64_t, int64_t) { return sample; }, 0.05, 9.0, 46.0);
}

// Fine land sloping eastwards (1300 m + 2 m a column) with its west columns blanked.
DemGrid blankedWest() {
  return makeGrid(100, 100, [](int64_t, int64_t c) -> int16_t {
    return c < kBlanked ? kNoDataSample : static_cast<int16_t>(1300 + 2 * c);
  });
}

// The largest step between row neighbours of the footprint within 5 samples of (row, column).
int largestFootprintStep(const DemGrid& original, int64_t row, int64_t column) {
  int largest = 0;
  for (int64_t r = std::max<int64_t>(0, row - 5); r <= std::min<int64_t>(99, row + 5); ++r) {
    for (int64_t c = std::max<int64_t>(1, column - 5); c <= std::min<int64_t>(99, column + 5);
         ++c) {
      if (original.at(r, c) == kNoDataSample || original.at(r, c - 1) == kNoDataSample) continue;
      largest = std::max(largest, std::abs(original.at(r, c) - original.at(r, c - 1)));
    }
  }
  return largest;
}

TEST(FootprintBend, TheFootprintIsUntouchedAndTheCoarserSurfaceMeetsItsEdgeWithoutAWall) {
  const DemGrid original = blankedWest();
  DemGrid grid = original;
  const DemGrid coarse = coarseGrid(1000);
  const GridCoarserSources coarser({&coarse});
  const ConditionStats stats = conditionGrid(grid, &coarser, {{}, kMarginDegrees});
  EXPECT_EQ(stats.outsideSamples, 4000U);
  EXPECT_EQ(stats.voidSamples, 0U);
  EXPECT_EQ(stats.seaSamples, 0U);
  for (int64_t r = 0; r < 100; ++r) {
    for (int64_t c = kBlanked; c < 100; ++c) ASSERT_EQ(grid.at(r, c), original.at(r, c));
    // Next to the edge the bent surface is the edge's height; from the margin on, the coarser.
    EXPECT_LE(std::abs(grid.at(r, kBlanked - 1) - original.at(r, kBlanked)), 2);
    for (int64_t c = 0; c <= 9; ++c) ASSERT_EQ(grid.at(r, c), 1000);
    // The step across the edge is no larger than 1.5x the finer source's own steps there.
    EXPECT_LE(std::abs(grid.at(r, kBlanked) - grid.at(r, kBlanked - 1)),
              1.5 * largestFootprintStep(original, r, kBlanked));
    // The bend itself: no step steeper than the smoothstep's (1.5 × 380 m / 30 samples).
    for (int64_t c = 1; c < kBlanked; ++c) {
      ASSERT_LE(std::abs(grid.at(r, c) - grid.at(r, c - 1)), 20);
    }
  }
}

TEST(FootprintBend, FinerLandMeetingCoarserWaterBecomesAShoreNotACliffOrAMoat) {
  DemGrid grid = blankedWest();
  const DemGrid coarse = coarseGrid(terrain::encodeWater(-40));
  const GridCoarserSources coarser({&coarse});
  conditionGrid(grid, &coarser, {{}, kMarginDegrees});
  for (int64_t r = 0; r < 100; ++r) {
    // Land next to the edge, falling monotonically into water that is the coarser sea's.
    EXPECT_FALSE(terrain::isWater(grid.at(r, kBlanked - 1)));
    for (int64_t c = 1; c < kBlanked; ++c) {
      ASSERT_LE(terrain::seaFloorMeters(grid.at(r, c - 1)), terrain::seaFloorMeters(grid.at(r, c)));
    }
    for (int64_t c = 0; c <= 9; ++c) ASSERT_EQ(grid.at(r, c), terrain::encodeWater(-40));
    EXPECT_TRUE(terrain::isWater(grid.at(r, 12)));
  }
}

TEST(FootprintBend, WithoutACoarserSourceTheBlankedPartIsFilledNotSea) {
  DemGrid grid = blankedWest();
  const ConditionStats stats = conditionGrid(grid, nullptr, {});
  EXPECT_EQ(stats.seaSamples, 0U);
  EXPECT_EQ(stats.voidSamples, 4000U);
  for (int64_t r = 0; r < 100; ++r) {
    for (int64_t c = 0; c < kBlanked; ++c) ASSERT_FALSE(terrain::isWater(grid.at(r, c)));
  }
}

TEST(FootprintBend, BentSampleRules) {
  EXPECT_EQ(bentSample(500, 0.0), 500);
  EXPECT_EQ(bentSample(500, 300.0), 800);
  // Coarser water raised to finer land is a shore: land above 0 m, water at or below.
  EXPECT_EQ(bentSample(kNoDataSample, 50.0), 50);
  EXPECT_EQ(bentSample(kNoDataSample, -20.0), terrain::encodeWater(-20));
  const int16_t floor = bentSample(terrain::encodeWater(-100), 50.0);
  EXPECT_TRUE(terrain::isWater(floor));
  EXPECT_EQ(terrain::seaFloorMeters(floor), -50.0);
  // Coarser land lowered to a finer sea stays land, at 0 m at the lowest: sea only where the
  // coarser surface says water, and no dry pit below sea level.
  EXPECT_EQ(bentSample(50, -50.0), 0);
  EXPECT_EQ(bentSample(50, -80.0), 0);
  EXPECT_EQ(bentSample(-400, 10.0), -390);
  EXPECT_EQ(bentSample(-400, -10.0), -400);
  // Weights: 1 at the edge, 0 from the margin on, smooth between.
  EXPECT_EQ(bendWeight(0.0, 0.1), 1.0);
  EXPECT_EQ(bendWeight(0.1, 0.1), 0.0);
  EXPECT_NEAR(bendWeight(0.05, 0.1), 0.5, 1e-12);
  EXPECT_EQ(bendWeight(0.05, 0.0), 0.0);
}

TEST(FootprintBend, TheEdgesFineDetailFadesInsteadOfStreaking) {
  // A ridged edge (±100 m every 4 samples) over a flat coarser source: next to the edge the bent
  // surface follows the ridges; a few of their wavelengths out they have faded (harmonic), while
  // a streak would carry them to the margin.
  DemGrid grid = makeGrid(100, 100, [](int64_t r, int64_t c) -> int16_t {
    if (c < kBlanked) return kNoDataSample;
    return static_cast<int16_t>(1300 + (r % 4 < 2 ? 100 : -100));
  });
  const DemGrid coarse = coarseGrid(1000);
  const GridCoarserSources coarser({&coarse});
  conditionGrid(grid, &coarser, {{}, kMarginDegrees});
  auto ripple = [&](int64_t column) {
    int low = 32767, high = -32768;
    for (int64_t r = 10; r < 90; ++r)
      low = std::min<int>(low, grid.at(r, column)), high = std::max<int>(high, grid.at(r, column));
    return high - low;
  };
  EXPECT_GT(ripple(kBlanked - 1), 40);
  EXPECT_LT(ripple(kBlanked - 12), 20);  // a streak: ~130 m (200 m × the weight there)
  // The broad difference (300 m) still reaches well out.
  EXPECT_GT(grid.at(50, kBlanked - 12), 1100);
}

TEST(FootprintBend, AThinRingIsRelaxedOnItsOwnSamplesToTheSameSurface) {
  // A ring three samples wide round a 200×200 grid (a no-data collar): fixed at a slope on its
  // inner side, free at the grid's edge. Relaxed on its own samples (thin) it is the surface the
  // dense solve over the whole box finds.
  const DemGrid grid = makeGrid(200, 200, [](int64_t, int64_t) { return int16_t{0}; });
  std::vector<uint8_t> ring(grid.samples.size(), 0);
  std::vector<size_t> region;
  for (int64_t r = 0; r < 200; ++r) {
    for (int64_t c = 0; c < 200; ++c) {
      if (r < 3 || c < 3 || r >= 197 || c >= 197) {
        ring[grid.index(r, c)] = 1;
        region.push_back(grid.index(r, c));
      }
    }
  }
  const auto slope = [](int64_t r, int64_t c) { return 100.0 + 2.0 * double(r) - 0.5 * double(c); };
  const auto dense = solveHarmonic(grid, ring, region, slope, 1e-4);
  const auto thin = solveHarmonic(grid, ring, region, slope, 1e-4, 7.0);
  ASSERT_TRUE(dense && thin);
  double worst = 0;
  for (size_t k = 0; k < region.size(); ++k)
    worst = std::max(worst, std::abs((*dense)[k] - (*thin)[k]));
  EXPECT_LT(worst, 0.01);
}

}  // namespace
}  // namespace globe::conditioning
