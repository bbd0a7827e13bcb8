// Land counts per sample: the box filter's fractions against areas computed by hand, even-odd
// holes, and rings that run outside the grid.
#include <gtest/gtest.h>

#include <numeric>

#include "mask_tiling/land_coverage.hpp"

namespace globe::mask_tiling {
namespace {

// 9×9 samples one degree apart, from (0, 8) at the top left to (8, 0).
const TexelGrid kGrid{0.0, 8.0, 1.0, 9};
constexpr int kSuper = 4;
constexpr int kFull = kSuper * kSuper;

std::vector<uint16_t> counts(const std::vector<Ring>& rings) {
  std::vector<uint16_t> out;
  countLandPoints(rings, kGrid, kSuper, out);
  return out;
}
uint16_t at(const std::vector<uint16_t>& c, int row, int column) {
  return c[static_cast<size_t>(row * kGrid.size + column)];
}

TEST(LandCoverage, AHalfPlaneCoversItsSideAndHalfTheSamplesOnTheLine) {
  // Land west of x = 4 (the box reaches beyond the grid on every other side).
  const auto c = counts({{{-5, -5}, {4, -5}, {4, 15}, {-5, 15}}});
  for (int r = 0; r < 9; ++r) {
    EXPECT_EQ(at(c, r, 0), kFull);
    EXPECT_EQ(at(c, r, 3), kFull);
    EXPECT_EQ(at(c, r, 4), kFull / 2);  // the line runs through the sample's box centre
    EXPECT_EQ(at(c, r, 5), 0);
  }
}

TEST(LandCoverage, TheCountsSumToTheArea) {
  // A triangle of 12 square degrees well inside the grid, 256 points per square degree: each
  // point row is off by less than a point (here 64 rows, so < 0.25 square degree).
  std::vector<uint16_t> c;
  countLandPoints({{{1.3, 1.1}, {7.3, 1.1}, {1.3, 5.1}}}, kGrid, 16, c);
  const double total = std::accumulate(c.begin(), c.end(), 0.0);
  EXPECT_NEAR(total / 256, 12.0, 0.25);
}

TEST(LandCoverage, AnInnerRingIsWater) {
  // Land from 1 to 7 with a lake from 3 to 5: the lake's samples are water.
  const auto c = counts({{{1, 1}, {7, 1}, {7, 7}, {1, 7}}, {{3, 3}, {5, 3}, {5, 5}, {3, 5}}});
  EXPECT_EQ(at(c, 2, 2), kFull);      // (2, 6): land
  EXPECT_EQ(at(c, 4, 4), 0);          // (4, 4): the lake
  EXPECT_EQ(at(c, 4, 3), kFull / 2);  // on the lake's shore
  EXPECT_EQ(at(c, 0, 0), 0);          // sea
}

TEST(LandCoverage, AnIslandSmallerThanATexelIsAPartlyLandTexel) {
  // An island 0.15° across holding one of the 16 points of the box around (4, 4).
  const auto c = counts({{{3.8, 3.8}, {3.95, 3.8}, {3.95, 3.95}, {3.8, 3.95}}});
  EXPECT_EQ(at(c, 4, 4), 1);
  EXPECT_EQ(std::accumulate(c.begin(), c.end(), 0), 1);
}

}  // namespace
}  // namespace globe::mask_tiling
