// Tests for geo/bounding_region.hpp: the conservative lattice hull and horizon culling.
#include "geo/bounding_region.hpp"

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "region_sampling.hpp"

namespace globe::geo {
namespace {

using testing::randomHeights;
using testing::sampleRegionPoint;

BoundingRegion tileRegion(const TileId& tile, double minimum, double maximum) {
  return {GeographicTilingScheme::tileRectangle(tile), minimum, maximum};
}

TEST(BoundingRegion, Validity) {
  const GlobeRectangle r = GlobeRectangle::fromDegrees(-10, -5, 10, 5);
  EXPECT_TRUE((BoundingRegion{r, -11000, 9000}.isValid()));
  EXPECT_TRUE((BoundingRegion{r, 0, 0}.isValid()));
  EXPECT_TRUE((BoundingRegion{GlobeRectangle::fromDegrees(-180, -90, 180, 90), 0, 1}.isValid()));
  EXPECT_FALSE((BoundingRegion{r, 10, 0}.isValid()));
  EXPECT_FALSE((BoundingRegion{r, -2e6, 0}.isValid()));
  EXPECT_FALSE((BoundingRegion{r, 0, std::numeric_limits<double>::infinity()}.isValid()));
  EXPECT_FALSE((BoundingRegion{GlobeRectangle::fromDegrees(10, -5, -10, 5), 0, 0}.isValid()));
  EXPECT_FALSE((BoundingRegion{GlobeRectangle::fromDegrees(-10, -95, 10, 5), 0, 0}.isValid()));
  EXPECT_FALSE((BoundingRegion{{std::nan(""), 0, 1, 1}, 0, 0}.isValid()));
  EXPECT_FALSE(RegionVolume::fromRegion({r, 10, 0}, Ellipsoid::wgs84()).bounded);
}

TEST(BoundingRegion, VolumeSizes) {
  const Ellipsoid e = Ellipsoid::wgs84();
  // Level 0: 8x8 cells at two heights; level 4 and deeper: the 8 corners only.
  const RegionVolume big = RegionVolume::fromRegion(tileRegion({0, 0, 0}, -100, 100), e);
  EXPECT_EQ(big.pointsEcefMeters.size(), 162u);
  const RegionVolume small = RegionVolume::fromRegion(tileRegion({4, 3, 5}, -100, 100), e);
  EXPECT_EQ(small.pointsEcefMeters.size(), 8u);
  const RegionVolume flat = RegionVolume::fromRegion(tileRegion({4, 3, 5}, 7, 7), e);
  EXPECT_EQ(flat.pointsEcefMeters.size(), 4u);
  // The bulge margin shrinks with the square of the tile size.
  const RegionVolume level10 = RegionVolume::fromRegion(tileRegion({10, 3, 500}, 0, 100), e);
  EXPECT_LT(level10.marginMeters, 20.0);
  EXPECT_GT(level10.marginMeters, 5.0);
  const RegionVolume level20 = RegionVolume::fromRegion(tileRegion({20, 3, 500}, 0, 100), e);
  EXPECT_LT(level20.marginMeters, 0.01);
  EXPECT_NEAR(small.occluderRadiusMeters, e.semiMinorAxisMeters - 11000.0, 1e-9);
}

// The hull property itself: for any direction, no sampled region point sticks out further than
// the hull points plus the margin. Also checks the margin is not wildly loose.
TEST(BoundingRegion, HullPlusMarginContainsTheRegion) {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<uint32_t> level(0, 12);
  for (const Ellipsoid& e : {Ellipsoid::wgs84(), Ellipsoid::sphere()}) {
    for (int trial = 0; trial < 2000; ++trial) {
      const uint32_t l = level(rng);
      const TileId tile{l, std::uniform_int_distribution<uint32_t>(0, (2u << l) - 1)(rng),
                        std::uniform_int_distribution<uint32_t>(0, (1u << l) - 1)(rng)};
      double minimum = 0.0;
      double maximum = 0.0;
      randomHeights(rng, minimum, maximum);
      const BoundingRegion region = tileRegion(tile, minimum, maximum);
      const RegionVolume volume = RegionVolume::fromRegion(region, e);
      ASSERT_TRUE(volume.bounded);
      for (int d = 0; d < 20; ++d) {
        const glm::dvec3 direction = glm::normalize(glm::dvec3{unit(rng), unit(rng), unit(rng)});
        double hullMax = -std::numeric_limits<double>::infinity();
        for (const glm::dvec3& p : volume.pointsEcefMeters) {
          hullMax = std::max(hullMax, glm::dot(direction, p));
        }
        for (int s = 0; s < 50; ++s) {
          const glm::dvec3 q = sampleRegionPoint(rng, region, e);
          ASSERT_LE(glm::dot(direction, q), hullMax + volume.marginMeters);
          ASSERT_LE(glm::distance(q, volume.centerEcefMeters), volume.radiusMeters);
        }
      }
    }
  }
  // Tightness: the middle of a one-cell region at its top sticks out by most of the margin.
  const Ellipsoid e = Ellipsoid::wgs84();
  const BoundingRegion region{GlobeRectangle::fromDegrees(0, 0, 10, 10), 0, 1000};
  const RegionVolume volume = RegionVolume::fromRegion(region, e);
  const Cartographic middle{region.rectangle.center().longitudeRadians,
                            region.rectangle.center().latitudeRadians, 1000.0};
  const glm::dvec3 up = geodeticSurfaceNormal(e, middle);
  double hullMax = -std::numeric_limits<double>::infinity();
  for (const glm::dvec3& p : volume.pointsEcefMeters) hullMax = std::max(hullMax, glm::dot(up, p));
  const double bulge = glm::dot(up, cartographicToEcef(e, middle)) - hullMax;
  EXPECT_GT(bulge, 0.8 * volume.marginMeters);
  EXPECT_LE(bulge, volume.marginMeters);
}

// Whether the segment from the camera to the point passes through the occluding sphere.
bool hiddenBySphere(const glm::dvec3& camera, const glm::dvec3& point, double radius) {
  const glm::dvec3 v = point - camera;
  const double t = std::clamp(-glm::dot(camera, v) / glm::dot(v, v), 0.0, 1.0);
  return glm::length(camera + t * v) < radius;
}

TEST(Horizon, FarSideIsHiddenFromTwentyThousandKilometres) {
  for (const Ellipsoid& e : {Ellipsoid::wgs84(), Ellipsoid::sphere()}) {
    const glm::dvec3 camera = cartographicToEcef(e, Cartographic::fromDegrees(0, 0, 2e7));
    const BoundingRegion farSide{GlobeRectangle::fromDegrees(170, -10, 180, 10), -11000, 9000};
    EXPECT_TRUE(isBelowHorizon(camera, farSide, e));
    // Whole far-side level-1 tiles, and even tiles just beyond the horizon (~76 deg away).
    EXPECT_TRUE(isBelowHorizon(camera, tileRegion({1, 0, 0}, -11000, 9000), e));
    EXPECT_TRUE(isBelowHorizon(camera, {GlobeRectangle::fromDegrees(90, -5, 95, 5), 0, 0}, e));
    // Facing the camera, or on the horizon: visible.
    EXPECT_FALSE(isBelowHorizon(camera, {GlobeRectangle::fromDegrees(0, 0, 10, 10), 0, 0}, e));
    EXPECT_FALSE(isBelowHorizon(camera, {GlobeRectangle::fromDegrees(75, 0, 80, 5), 0, 0}, e));
    // A tall enough region behind the horizon pokes above it.
    EXPECT_FALSE(isBelowHorizon(camera, {GlobeRectangle::fromDegrees(90, -5, 95, 5), 0, 3e6}, e));
  }
}

TEST(Horizon, CamerasInsideTheOccluderOrInvalidCullNothing) {
  const Ellipsoid e = Ellipsoid::wgs84();
  const BoundingRegion farSide{GlobeRectangle::fromDegrees(170, -10, 180, 10), 0, 100};
  EXPECT_FALSE(isBelowHorizon(glm::dvec3{0.0}, farSide, e));
  // Under the sea floor at the pole: inside the occluding sphere.
  EXPECT_FALSE(isBelowHorizon({0.0, 0.0, e.semiMinorAxisMeters - 12000.0}, farSide, e));
  EXPECT_FALSE(isBelowHorizon({std::nan(""), 0.0, 0.0}, farSide, e));
  EXPECT_FALSE(isBelowHorizon({1e8, 0.0, 0.0}, {farSide.rectangle, 100, 0}, e));
  // A camera 9 km below sea level (a submarine view) is outside the sphere: it still culls.
  EXPECT_TRUE(
      isBelowHorizon(cartographicToEcef(e, Cartographic::fromDegrees(0, 0, -9000)), farSide, e));
}

// Conservativeness: whenever a sampled region point is visible past the occluding sphere, the
// region must not be reported below the horizon. Regions are picked near the camera's horizon.
TEST(Horizon, ConservativeForRandomCamerasAndRegions) {
  std::mt19937_64 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int culled = 0;
  int kept = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Ellipsoid e = trial % 2 == 0 ? Ellipsoid::wgs84() : Ellipsoid::sphere();
    const Cartographic cameraCarto{(2.0 * unit(rng) - 1.0) * std::numbers::pi,
                                   std::asin(2.0 * unit(rng) - 1.0),
                                   std::pow(10.0, 1.0 + 7.0 * unit(rng))};
    const glm::dvec3 camera = cartographicToEcef(e, cameraCarto);
    // A point at the horizon's central angle (give or take 15 deg) in a random azimuth.
    const double r = e.semiMinorAxisMeters;
    const double horizonAngle = std::acos(std::min(1.0, r / glm::length(camera)));
    const double angle = std::max(0.0, horizonAngle + (unit(rng) - 0.5) * 0.5);
    const double azimuth = 2.0 * std::numbers::pi * unit(rng);
    const glm::dvec3 up = glm::normalize(camera);
    const glm::dvec3 east = glm::normalize(
        glm::cross(std::abs(up.z) < 0.9 ? glm::dvec3{0, 0, 1} : glm::dvec3{1, 0, 0}, up));
    const glm::dvec3 north = glm::cross(up, east);
    const glm::dvec3 target = std::cos(angle) * up + std::sin(angle) * (std::cos(azimuth) * east +
                                                                        std::sin(azimuth) * north);
    const uint32_t level = static_cast<uint32_t>(unit(rng) * 16.0);
    const std::optional<TileId> tile = GeographicTilingScheme::positionToTile(
        std::atan2(target.y, target.x), std::asin(std::clamp(target.z, -1.0, 1.0)), level);
    ASSERT_TRUE(tile);
    double minimum = 0.0;
    double maximum = 0.0;
    testing::randomHeights(rng, minimum, maximum);
    const BoundingRegion region = tileRegion(*tile, minimum, maximum);
    const RegionVolume volume = RegionVolume::fromRegion(region, e);
    if (!isBelowHorizon(camera, volume)) {
      ++kept;
      continue;
    }
    ++culled;
    for (int s = 0; s < 200; ++s) {
      const glm::dvec3 q = sampleRegionPoint(rng, region, e);
      ASSERT_TRUE(hiddenBySphere(camera, q, volume.occluderRadiusMeters))
          << "trial " << trial << " level " << level << " camera height "
          << cameraCarto.heightMeters;
    }
  }
  std::cout << "[ horizon ] culled " << culled << ", kept " << kept << "\n";
  EXPECT_GT(culled, 2000);
  EXPECT_GT(kept, 2000);
}

}  // namespace
}  // namespace globe::geo
