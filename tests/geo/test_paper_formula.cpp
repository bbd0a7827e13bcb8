// Demonstrates the flaws of the paper's formula (1) against the robust ecefToCartographic:
// quadrant loss of atan(x/z) and the ill-conditioning of asin near the poles.
#include "tests/support/paper_formula.hpp"

#include <cmath>
#include <iostream>
#include <numbers>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "geo/ecef.hpp"

namespace globe::geo {
namespace {

TEST(PaperFormula, FrameMapping) {
  EXPECT_EQ(globe::testing::ecefToPaperYUp({1.0, 2.0, 3.0}), glm::dvec3(2.0, 3.0, 1.0));
}

TEST(PaperFormula, AgreesInTheFrontHemisphere) {
  const Ellipsoid sphere = Ellipsoid::sphere();
  for (const double lonDegrees : {0.0, 45.0, -45.0, 89.0, -89.0}) {
    const Cartographic c = Cartographic::fromDegrees(lonDegrees, 30.0, 500.0);
    const globe::testing::PaperSphereCoordinates paper = globe::testing::paperFormula1(
        globe::testing::ecefToPaperYUp(cartographicToEcef(sphere, c)));
    EXPECT_NEAR(paper.longitudeRadians, c.longitudeRadians, 1e-14);
    EXPECT_NEAR(paper.latitudeRadians, c.latitudeRadians, 1e-14);
    EXPECT_NEAR(paper.radiusMeters, 6371500.0, 1e-8);
  }
}

// Flaw (a): atan(x/z) cannot tell (x, z) from (-x, -z), so the back hemisphere comes out off
// by pi; atan2 keeps the quadrant.
TEST(PaperFormula, LongitudeLosesTheQuadrant) {
  const Ellipsoid sphere = Ellipsoid::sphere();
  for (const double lonDegrees : {135.0, -135.0, 180.0, -180.0, 91.0, -100.0}) {
    const Cartographic c = Cartographic::fromDegrees(lonDegrees, -20.0, 0.0);
    const glm::dvec3 ecef = cartographicToEcef(sphere, c);
    const globe::testing::PaperSphereCoordinates paper =
        globe::testing::paperFormula1(globe::testing::ecefToPaperYUp(ecef));
    EXPECT_NEAR(std::abs(paper.longitudeRadians - c.longitudeRadians), std::numbers::pi, 1e-14)
        << lonDegrees;
    const std::optional<Cartographic> robust = ecefToCartographic(sphere, ecef);
    ASSERT_TRUE(robust);
    // +-180 deg are the same meridian; compare the wrapped difference.
    EXPECT_NEAR(
        std::remainder(robust->longitudeRadians - c.longitudeRadians, 2.0 * std::numbers::pi), 0.0,
        1e-15)
        << lonDegrees;
  }
  // On the 90 deg meridians z_gl = x_ecef is ~0 and atan(x/z) divides by (nearly) zero; at the
  // geocentre the formula gives NaN where ecefToCartographic says "undefined".
  EXPECT_TRUE(std::isnan(globe::testing::paperFormula1(glm::dvec3{0.0}).longitudeRadians));
  EXPECT_FALSE(ecefToCartographic(sphere, glm::dvec3{0.0}).has_value());
}

// Flaw (b): near the poles y/R is within ~1e-16 of 1, where doubles are spaced 1.1e-16 and
// asin'(x) blows up; the latitude error is ~sqrt(2 * 1.1e-16) rad, centimetres on the ground.
// atan2(z, hypot(x, y)) keeps full precision.
TEST(PaperFormula, LatitudeLosesPrecisionNearThePoles) {
  const Ellipsoid sphere = Ellipsoid::sphere();
  const double radius = sphere.semiMajorAxisMeters;
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> longitude(-std::numbers::pi, std::numbers::pi);
  std::uniform_real_distribution<double> logDistance(-12.0, -8.0);
  double paperMaxError = 0.0;
  double robustMaxError = 0.0;
  for (int i = 0; i < 10000; ++i) {
    // Within 1e-12..1e-8 rad of either pole.
    const double fromPole = std::pow(10.0, logDistance(rng));
    const double latitude = (i % 2 == 0 ? 1.0 : -1.0) * (std::numbers::pi / 2.0 - fromPole);
    const Cartographic c{longitude(rng), latitude, 0.0};
    const glm::dvec3 ecef = cartographicToEcef(sphere, c);
    const globe::testing::PaperSphereCoordinates paper =
        globe::testing::paperFormula1(globe::testing::ecefToPaperYUp(ecef));
    const std::optional<Cartographic> robust = ecefToCartographic(sphere, ecef);
    ASSERT_TRUE(robust);
    paperMaxError = std::max(paperMaxError, std::abs(paper.latitudeRadians - latitude) * radius);
    robustMaxError =
        std::max(robustMaxError, std::abs(robust->latitudeRadians - latitude) * radius);
  }
  std::cout << "[ near-pole latitude error at the surface ] paper asin: " << paperMaxError
            << " m, atan2: " << robustMaxError << " m\n";
  ::testing::Test::RecordProperty("paper_latitude_error_m", std::to_string(paperMaxError));
  ::testing::Test::RecordProperty("robust_latitude_error_m", std::to_string(robustMaxError));
  EXPECT_GT(paperMaxError, 1e-2);
  EXPECT_LT(robustMaxError, 1e-9);
}

}  // namespace
}  // namespace globe::geo
