// Tests for geo/cartographic.hpp: angle conversions and longitude wrapping.
#include "geo/cartographic.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

namespace globe::geo {
namespace {

TEST(Cartographic, DegreeConversionsAreExactAtQuarterTurns) {
  static_assert(degreesToRadians(180.0) == std::numbers::pi);
  static_assert(degreesToRadians(-180.0) == -std::numbers::pi);
  static_assert(degreesToRadians(90.0) == std::numbers::pi / 2.0);
  static_assert(radiansToDegrees(std::numbers::pi) == 180.0);
  static_assert(radiansToDegrees(-std::numbers::pi / 2.0) == -90.0);
  EXPECT_NEAR(degreesToRadians(1.0), 0.017453292519943295, 1e-18);
  EXPECT_NEAR(radiansToDegrees(1.0), 57.29577951308232, 1e-13);
}

TEST(Cartographic, FromDegreesAndBack) {
  const Cartographic c = Cartographic::fromDegrees(-122.5, 37.75, 12.0);
  EXPECT_DOUBLE_EQ(c.longitudeRadians, -122.5 * std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(c.latitudeRadians, 37.75 * std::numbers::pi / 180.0);
  EXPECT_EQ(c.heightMeters, 12.0);
  EXPECT_DOUBLE_EQ(c.longitudeDegrees(), -122.5);
  EXPECT_DOUBLE_EQ(c.latitudeDegrees(), 37.75);
  EXPECT_EQ(Cartographic::fromDegrees(180.0, -90.0).heightMeters, 0.0);
  EXPECT_EQ(Cartographic::fromDegrees(180.0, -90.0).longitudeRadians, std::numbers::pi);
  EXPECT_EQ(Cartographic::fromDegrees(180.0, -90.0).latitudeRadians, -std::numbers::pi / 2.0);
}

TEST(Cartographic, WrapLeavesInRangeValuesUnchanged) {
  for (const double v :
       {0.0, -0.0, 1.0, -1.0, std::numbers::pi, -std::numbers::pi,
        std::nextafter(std::numbers::pi, 0.0), std::nextafter(-std::numbers::pi, 0.0), 1e-300}) {
    EXPECT_EQ(wrapLongitudeRadians(v), v);
    EXPECT_EQ(std::signbit(wrapLongitudeRadians(v)), std::signbit(v));
  }
}

TEST(Cartographic, WrapMapsOutOfRangeValuesIntoRange) {
  EXPECT_DOUBLE_EQ(wrapLongitudeRadians(1.5 * std::numbers::pi), -0.5 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(wrapLongitudeRadians(-1.5 * std::numbers::pi), 0.5 * std::numbers::pi);
  EXPECT_NEAR(wrapLongitudeRadians(2.0 * std::numbers::pi + 0.25), 0.25, 1e-15);
  EXPECT_NEAR(wrapLongitudeRadians(-4.0 * std::numbers::pi - 0.25), -0.25, 1e-14);
  EXPECT_EQ(wrapLongitudeRadians(2.0 * std::numbers::pi), 0.0);
  // Just past +pi comes back just after -pi, and vice versa.
  EXPECT_NEAR(wrapLongitudeRadians(std::nextafter(std::numbers::pi, 4.0)), -std::numbers::pi,
              1e-15);
  EXPECT_NEAR(wrapLongitudeRadians(std::nextafter(-std::numbers::pi, -4.0)), std::numbers::pi,
              1e-15);

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-1.0, 300.0);
  std::bernoulli_distribution negative(0.5);
  for (int i = 0; i < 100000; ++i) {
    const double v = (negative(rng) ? -1.0 : 1.0) * std::pow(10.0, exponent(rng));
    const double wrapped = wrapLongitudeRadians(v);
    ASSERT_GE(wrapped, -std::numbers::pi) << v;
    ASSERT_LE(wrapped, std::numbers::pi) << v;
    if (std::abs(v) < 1e6) {
      // Same angle: differs by a whole number of turns (up to rounding of large v).
      const double turns = (v - wrapped) / (2.0 * std::numbers::pi);
      ASSERT_NEAR(turns, std::round(turns), 1e-9) << v;
    }
  }
}

TEST(Cartographic, WrapPassesNonFiniteThrough) {
  EXPECT_TRUE(std::isnan(wrapLongitudeRadians(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_FALSE(std::isfinite(wrapLongitudeRadians(std::numeric_limits<double>::infinity())));
}

}  // namespace
}  // namespace globe::geo
