// Imagery as photographed (terrain/imagery_exposure.hpp): a layer's exposure from its median
// luminance, the exposure curve, and the light's multiplier that never lifts a photo past itself.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "terrain/imagery_exposure.hpp"

namespace globe::terrain {
namespace {

std::vector<uint8_t> texels(std::initializer_list<std::array<uint8_t, 4>> list) {
  std::vector<uint8_t> out;
  for (const auto& texel : list) out.insert(out.end(), texel.begin(), texel.end());
  return out;
}

TEST(ImageryExposure, TheMedianCountsOnlyOpaqueTexels) {
  // Three opaque greys (20, 60, 200) and two transparent whites: the median is 60's.
  const auto rgba = texels({{20, 20, 20, 255},
                            {255, 255, 255, 0},
                            {60, 60, 60, 255},
                            {255, 255, 255, 128},
                            {200, 200, 200, 255}});
  EXPECT_NEAR(medianOpaqueLuminance(rgba), 60.0 / 255.0, 1e-9);
  EXPECT_TRUE(std::isnan(medianOpaqueLuminance(texels({{9, 9, 9, 0}}))));
  EXPECT_TRUE(std::isnan(medianOpaqueLuminance({})));
  // Luma weighs green most: pure green 100 is brighter than pure blue 255.
  EXPECT_GT(medianOpaqueLuminance(texels({{0, 100, 0, 255}})),
            medianOpaqueLuminance(texels({{0, 0, 255, 255}})));
}

TEST(ImageryExposure, DarkLayersAreLiftedToAReadableMedianAndBrightOnesLeftAlone) {
  for (const double median : {0.02, 0.06, 0.1, 0.2, 0.29}) {
    const double k = exposureForMedianLuminance(median);
    EXPECT_GT(k, 1.0) << median;
    EXPECT_LE(k, kMaximumExposure) << median;
    if (k < kMaximumExposure) {
      EXPECT_NEAR(exposedValue(median, k), kReadableMedianLuminance, 1e-9) << median;
    } else {
      EXPECT_LT(exposedValue(median, k), kReadableMedianLuminance) << median;
    }
  }
  for (const double median : {0.3, 0.5, 0.9, 1.0}) {
    EXPECT_EQ(exposureForMedianLuminance(median), 1.0) << median;
  }
  EXPECT_EQ(exposureForMedianLuminance(std::nan("")), 1.0);
  EXPECT_EQ(exposureForMedianLuminance(0.0), kMaximumExposure);
}

TEST(ImageryExposure, TheCurveKeepsBlackAndWhiteAndTheOrderAndNeverClips) {
  for (const double k : {1.0, 1.7, 3.0}) {
    EXPECT_EQ(exposedValue(0.0, k), 0.0);
    EXPECT_EQ(exposedValue(1.0, k), 1.0);
    double previous = -1.0;
    for (int i = 0; i <= 255; ++i) {
      const double value = exposedValue(i / 255.0, k);
      EXPECT_GT(value, previous) << k << " at " << i;
      EXPECT_LE(value, 1.0);
      previous = value;
    }
  }
  EXPECT_NEAR(exposedValue(0.01, 3.0), 0.03, 1e-3) << "darks x ~k";
  EXPECT_EQ(exposedValue(0.4, 1.0), 0.4) << "k = 1: the photo as it is";
  EXPECT_EQ(exposedValue(-0.5, 2.0), 0.0);
  EXPECT_EQ(exposedValue(1.5, 2.0), 1.0);
}

TEST(ImageryExposure, TheLightNeverLiftsAPhotoPastItself) {
  for (const double level : {0.3, 0.7, 0.97, 1.0}) {
    double previous = -1.0;
    for (double relief = 0.0; relief <= 1.0 / level + 2.0; relief += 0.01) {
      const double multiplier = reliefLightMultiplier(relief, level);
      EXPECT_LE(level * multiplier, 1.0 + 1e-12) << level << " " << relief;
      EXPECT_GE(multiplier, previous) << "monotone: " << level << " " << relief;
      previous = multiplier;
    }
    EXPECT_EQ(reliefLightMultiplier(0.6, level), 0.6) << "shadows darken by the relief";
  }
  // No kink at relief 1: the lit side starts with the slope of the shadowed side.
  EXPECT_NEAR((reliefLightMultiplier(1.001, 0.7) - 1.0) / 0.001, 1.0, 0.01);
  EXPECT_EQ(reliefLightMultiplier(1.5, 1.0), 1.0) << "no headroom: the photo already";
  EXPECT_EQ(reliefLightMultiplier(-1.0, 0.5), 0.0);
  EXPECT_EQ(reliefLightMultiplier(std::nan(""), 0.5), 0.0);
}

}  // namespace
}  // namespace globe::terrain
