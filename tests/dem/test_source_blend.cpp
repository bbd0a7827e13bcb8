#include <gtest/gtest.h>

#include <cmath>

#include "dem/grid_coarser_sources.hpp"
#include "dem/source_blend.hpp"
#include "dem_test_grids.hpp"
#include "terrain/height_block.hpp"

namespace globe::dem {
namespace {

using testing::makeGrid;

// Fine grid 10.00..10.99 E, 45.00..44.01 N at 0.01°, 300 m above a flat 1000 m coarse grid.
struct Scene {
  DemGrid coarse = makeGrid(
      60, 60, [](int64_t, int64_t) { return int16_t{1000}; }, 0.05, 9.0, 46.0);
  DemGrid fine = makeGrid(100, 100, [](int64_t, int64_t) { return int16_t{1300}; });
};

TEST(SourceBlend, TheFineSourceMeetsTheCoarserOneAtItsEdgeWithoutAWall) {
  Scene s;
  const GridCoarserSources coarser({&s.coarse});
  const uint64_t changed = blendIntoCoarser(
      s.fine, coarser, [](double, double) { return false; }, 0.1);
  EXPECT_GT(changed, 0U);
  // Edge samples (half a step inside) are within a few metres of the coarse surface.
  EXPECT_LE(std::abs(s.fine.at(50, 0) - 1000), 5);
  EXPECT_LE(std::abs(s.fine.at(0, 50) - 1000), 5);
  EXPECT_LE(std::abs(s.fine.at(99, 99) - 1000), 5);
  // Beyond the margin the fine source is untouched.
  EXPECT_EQ(s.fine.at(50, 50), 1300);
  EXPECT_EQ(s.fine.at(15, 50), 1300);
  // No step between neighbours larger than the ramp's steepest (1.5 × 300 m / 10 samples).
  for (int64_t r = 0; r < 100; ++r) {
    for (int64_t c = 1; c < 100; ++c)
      EXPECT_LE(std::abs(s.fine.at(r, c) - s.fine.at(r, c - 1)), 46);
  }
}

TEST(SourceBlend, EdgesWhereAnEquallyFineSourceContinuesAreLeftAlone) {
  Scene s;
  const GridCoarserSources coarser({&s.coarse});
  // An equally fine neighbour east of 10.995°E: the east edge stays, the others blend.
  blendIntoCoarser(
      s.fine, coarser, [](double lon, double) { return lon > 10.995; }, 0.1);
  EXPECT_EQ(s.fine.at(50, 99), 1300);
  EXPECT_LE(std::abs(s.fine.at(50, 0) - 1000), 5);
}

TEST(SourceBlend, WaterIsLeftAlone) {
  Scene s;
  for (int64_t r = 0; r < 100; ++r) s.fine.samples[s.fine.index(r, 0)] = terrain::kNoDataHeight;
  const GridCoarserSources coarser({&s.coarse});
  blendIntoCoarser(
      s.fine, coarser, [](double, double) { return false; }, 0.1);
  EXPECT_EQ(s.fine.at(50, 0), terrain::kNoDataHeight);
}

}  // namespace
}  // namespace globe::dem
