// The physically based sky (src/atmosphere): blue overhead by day, red towards a low Sun and
// darker overhead, black by night and where a ray from space misses the air, the lit limb from
// space; finite everywhere; the elevation mapping and its inverse agree.
#include "atmosphere/sky_view.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace globe::atmosphere {
namespace {

const SkyTables& tables() { return SkyTables::earth(); }
constexpr double kGround = 6'360'000.0;

glm::dvec3 seen(double heightMeters, double elevationDegrees, double azimuthDegrees,
                double sunElevationDegrees) {
  const double e = elevationDegrees * std::numbers::pi / 180.0;
  const double a = azimuthDegrees * std::numbers::pi / 180.0;
  const double s = sunElevationDegrees * std::numbers::pi / 180.0;
  const glm::dvec3 direction(std::cos(e) * std::cos(a), std::cos(e) * std::sin(a), std::sin(e));
  const glm::dvec3 sun(std::cos(s), 0.0, std::sin(s));
  return toneMapped(skyRadiance(tables(), kGround + heightMeters, direction, sun));
}

TEST(SkyView, BlueByDayRedAtSunsetBlackAtNight) {
  const glm::dvec3 noonZenith = seen(100, 90, 0, 60);
  std::printf("noon zenith %.3f %.3f %.3f\n", noonZenith.r, noonZenith.g, noonZenith.b);
  EXPECT_GT(noonZenith.b, noonZenith.g);
  EXPECT_GT(noonZenith.g, noonZenith.r);
  EXPECT_GT(noonZenith.b, 0.5);
  // The Sun 1° up: towards it the horizon is red and yellow, not blue; overhead darker than noon.
  const glm::dvec3 sunsetHorizon = seen(100, 2, 0, 1);
  const glm::dvec3 sunsetZenith = seen(100, 90, 0, 1);
  std::printf("sunset horizon %.3f %.3f %.3f zenith %.3f %.3f %.3f\n", sunsetHorizon.r,
              sunsetHorizon.g, sunsetHorizon.b, sunsetZenith.r, sunsetZenith.g, sunsetZenith.b);
  EXPECT_GT(sunsetHorizon.r, sunsetHorizon.b);
  EXPECT_LT(sunsetZenith.b, noonZenith.b);
  // The Sun 18° down: night.
  const glm::dvec3 night = seen(100, 45, 90, -18);
  EXPECT_LT(night.r + night.g + night.b, 0.05);
}

TEST(SkyView, FromSpaceTheLitLimbGlowsAndTheVoidIsBlack) {
  const double height = 20'000'000.0;
  const double horizon = horizonElevation(tables().atmosphere(), kGround + height) * 180.0 / std::numbers::pi;
  const glm::dvec3 up = seen(height, 30, 0, 30);
  EXPECT_EQ(up.r + up.g + up.b, 0.0) << "away from the globe: no air";
  // Just above the ground's edge, towards the Sun: the air lit edge-on.
  const glm::dvec3 limb = seen(height, horizon + 0.05, 0, 0);
  const glm::dvec3 darkLimb = seen(height, horizon + 0.05, 180, 0);
  std::printf("limb lit %.3f %.3f %.3f dark side %.3f %.3f %.3f\n", limb.r, limb.g, limb.b,
              darkLimb.r, darkLimb.g, darkLimb.b);
  EXPECT_GT(limb.b, 0.2);
  EXPECT_GT(limb.b, 4.0 * darkLimb.b + 0.01);
}

TEST(SkyView, FiniteEverywhereAndTheRowMappingInverts) {
  for (const double height : {0.0, 1.0, 8'000.0, 60'000.0, 99'000.0, 101'000.0, 4e7}) {
    const double h = horizonElevation(tables().atmosphere(), kGround + height);
    for (double v = 0.0; v <= 1.0; v += 0.125) {
      EXPECT_NEAR(skyViewRow(skyViewElevation(v, h), h), v, 1e-9) << height << " " << v;
    }
    for (const double sun : {-90.0, -5.0, 0.0, 3.0, 90.0}) {
      for (const double elevation : {-90.0, -10.0, -0.5, 0.0, 0.5, 45.0, 90.0}) {
        const glm::dvec3 c = seen(height, elevation, 37.0, sun);
        for (int k = 0; k < 3; ++k) {
          EXPECT_TRUE(std::isfinite(c[k]) && c[k] >= 0.0 && c[k] <= 1.0)
              << height << " m, sun " << sun << ", elevation " << elevation;
        }
      }
    }
  }
}

TEST(SkyView, TheImageHoldsTheSameSky) {
  const SkyViewImage image = skyView(tables(), kGround + 100.0, std::sin(0.5), 64, 48);
  ASSERT_EQ(image.rgba.size(), 64u * 48u * 4u);
  // Straight up (v = 1): the zenith's colour at any azimuth.
  const glm::dvec3 zenith = seen(100, 90, 0, 0.5 * 180.0 / std::numbers::pi);
  const glm::dvec3 fromImage = image.at(0.3, 1.0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(fromImage[k], zenith[k], 2.0 / 255.0);
}

}  // namespace
}  // namespace globe::atmosphere
