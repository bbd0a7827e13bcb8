// Where a water mask decides land and water: over terrain much coarser than its texel, not over
// terrain about as fine, smoothly between; unknown resolutions leave the mask in charge.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "terrain/water_mask_weight.hpp"

namespace globe::terrain {
namespace {

TEST(WaterMaskWeight, TheMaskDecidesOverACoarseGridAndNotOverAFineDem) {
  const double maskTexel = 0.0014;                           // GSHHG at level 9, ~150 m
  EXPECT_EQ(waterMaskWeight(maskTexel, 1.0 / 3.0), 1.0);     // the 20' grid
  EXPECT_EQ(waterMaskWeight(maskTexel, 1.0 / 120.0), 1.0);   // GTOPO30
  EXPECT_EQ(waterMaskWeight(maskTexel, 1.0 / 1200.0), 0.0);  // SRTM3: its own coast
}

TEST(WaterMaskWeight, ItChangesSmoothlyBetween) {
  const double a = waterMaskWeight(1.0, 2.0), b = waterMaskWeight(1.0, 2.5);
  EXPECT_GT(a, 0.0);
  EXPECT_LT(a, b);
  EXPECT_LT(b, 1.0);
  EXPECT_EQ(waterMaskWeight(1.0, kTerrainDecidesStepRatio), 0.0);
  EXPECT_EQ(waterMaskWeight(1.0, kMaskDecidesStepRatio), 1.0);
}

TEST(WaterMaskWeight, UnknownResolutionsLeaveTheMaskInCharge) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(waterMaskWeight(nan, 0.1), 1.0);
  EXPECT_EQ(waterMaskWeight(0.001, nan), 1.0);
  EXPECT_EQ(waterMaskWeight(0.0, 0.1), 1.0);
  EXPECT_EQ(waterMaskWeight(0.001, std::numeric_limits<double>::infinity()), 1.0);
}

}  // namespace
}  // namespace globe::terrain
