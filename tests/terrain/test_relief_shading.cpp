// The hill-shading weight on draped imagery: gentle where the imagery is as fine as the terrain,
// full where its texel spans 4 samples or more, log-linear between; and the modes.
#include "terrain/relief_shading.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "terrain/texel_footprint.hpp"

namespace globe::terrain {
namespace {

TEST(ReliefShading, WeightFollowsTheTexelOverTheSampleSpacing) {
  EXPECT_DOUBLE_EQ(reliefShadingWeight(30.0, 90.0), kGentleReliefWeight);  // Landsat on SRTM
  EXPECT_DOUBLE_EQ(reliefShadingWeight(90.0, 90.0), kGentleReliefWeight);
  EXPECT_DOUBLE_EQ(reliefShadingWeight(180.0, 90.0), (1.0 + kGentleReliefWeight) / 2.0);
  EXPECT_DOUBLE_EQ(reliefShadingWeight(360.0, 90.0), 1.0);
  EXPECT_DOUBLE_EQ(reliefShadingWeight(7400.0, 90.0), 1.0);  // Blue Marble on SRTM
  // Unknown texels shade rather than flatten.
  EXPECT_DOUBLE_EQ(reliefShadingWeight(0.0, 90.0), 1.0);
  EXPECT_DOUBLE_EQ(reliefShadingWeight(30.0, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(reliefShadingWeight(std::numeric_limits<double>::quiet_NaN(), 90.0), 1.0);
}

TEST(ReliefShading, ModesAndNames) {
  EXPECT_EQ(imageryLightWeight(ImageryLighting::Off, 7400.0, 90.0), 0.0);
  EXPECT_EQ(imageryLightWeight(ImageryLighting::On, 30.0, 90.0), 1.0);
  EXPECT_EQ(imageryLightWeight(ImageryLighting::Auto, 30.0, 90.0), kGentleReliefWeight);
  for (const auto mode : {ImageryLighting::Auto, ImageryLighting::On, ImageryLighting::Off}) {
    EXPECT_EQ(parseImageryLighting(toString(mode)), mode);
  }
  EXPECT_FALSE(parseImageryLighting("yes").has_value());
  EXPECT_EQ(nextImageryLighting(ImageryLighting::Auto), ImageryLighting::On);
  EXPECT_EQ(nextImageryLighting(ImageryLighting::On), ImageryLighting::Off);
  EXPECT_EQ(nextImageryLighting(ImageryLighting::Off), ImageryLighting::Auto);
}

TEST(ReliefShading, MeridianSpacingIsTheTileHeightOverTheIntervals) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  const geo::TileId tile{12, 7250, 1400};
  const double samples = meridianSpacingMeters(tile, 16, wgs84);
  EXPECT_NEAR(meridianSpacingMeters(tile, 256, wgs84) * 16.0, samples, 1e-9 * samples);
  // The parent's texel is twice the child's.
  EXPECT_NEAR(meridianSpacingMeters({11, 3625, 700}, 256, wgs84),
              2.0 * meridianSpacingMeters(tile, 256, wgs84), 1e-6);
  EXPECT_EQ(meridianSpacingMeters(tile, 0, wgs84), 0.0);
}

}  // namespace
}  // namespace globe::terrain
