// The paper's responses on Mount Fuji's real 3" surface: a static camera is stopped, linear
// motion slides up the slope, angular motion is heightened with its angle applied in full.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/geometric.hpp>

#include "camera/camera_motion.hpp"
#include "collision/collision_response.hpp"
#include "collision/height_service.hpp"
#include "geo/ecef.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::collision {
namespace {

using camera::testing::drawnHeight;
using camera::testing::fujiArray;
using camera::testing::fujiSummit;
using camera::testing::offsetPosition;
using globe::test::kClearance;
using globe::test::kWgs84;

using camera::testing::drawn;
using camera::testing::fuji;

// A point on Fuji's slope `distance` from the summit towards `bearing`, `above` the surface.
geo::Cartographic onSlope(double bearingRadians, double distanceMeters, double aboveMeters) {
  geo::Cartographic c = offsetPosition(fujiSummit(), bearingRadians, distanceMeters, 0.0);
  c.heightMeters = drawn(c) + aboveMeters;
  return c;
}

TEST(StaticResponse, AJumpIntoFujiIsRefusedAndOneAboveItAccepted) {
  const double summit = drawn(fujiSummit());
  ASSERT_GT(summit, 3700.0);
  const geo::Cartographic from = fujiSummit(summit + 500.0);
  const ResponseSettings settings;
  for (const double below : {-0.5, 1.5, 30.0, 1000.0}) {
    const geo::Cartographic into = fujiSummit(summit - below);
    const MotionResult refused = respondStatic(fuji(), kWgs84, from, into, kClearance, settings);
    ASSERT_TRUE(refused.valid);
    EXPECT_EQ(refused.response, Response::Stopped) << below;
    EXPECT_EQ(refused.position.longitudeRadians, from.longitudeRadians);
    EXPECT_EQ(refused.position.latitudeRadians, from.latitudeRadians);
    EXPECT_EQ(refused.position.heightMeters, from.heightMeters);
  }
  const geo::Cartographic above = fujiSummit(summit + kClearance + 0.5);
  const MotionResult accepted = respondStatic(fuji(), kWgs84, from, above, kClearance, settings);
  ASSERT_TRUE(accepted.valid);
  EXPECT_EQ(accepted.response, Response::None);
  EXPECT_EQ(accepted.position.heightMeters, above.heightMeters);
  EXPECT_DOUBLE_EQ(accepted.position.longitudeRadians, above.longitudeRadians);
}

TEST(StaticResponse, ThePapersQotcdModelIsMoreConservativeOnSlopes) {
  // Where QOTCD's H (the quad's highest vertex) is well above the drawn triangle, a jump to
  // 2.5 m above the drawn surface is accepted by the exact model and refused by QOTCD's.
  ResponseSettings qotcd;
  qotcd.surface = SurfaceModel::Qotcd;
  int compared = 0;
  for (int k = 0; k < 64 && compared < 8; ++k) {
    const geo::Cartographic to = onSlope(k * std::numbers::pi / 32.0, 1500.0 + 20.0 * k, 2.5);
    const auto h =
        sampleHeight(fuji(), kWgs84, to.longitudeRadians, to.latitudeRadians, HeightMode::Qotcd);
    ASSERT_TRUE(h);
    if (h->heightMeters < to.heightMeters) continue;
    const geo::Cartographic from{to.longitudeRadians, to.latitudeRadians, 6000.0};
    EXPECT_EQ(respondStatic(fuji(), kWgs84, from, to, kClearance, {}).response, Response::None);
    EXPECT_EQ(respondStatic(fuji(), kWgs84, from, to, kClearance, qotcd).response,
              Response::Stopped);
    ++compared;
  }
  EXPECT_EQ(compared, 8);
}

TEST(LinearResponse, HorizontalMotionIntoTheSlopeSlidesUpIt) {
  for (const double bearing :
       {0.0, std::numbers::pi / 2, std::numbers::pi, 1.5 * std::numbers::pi}) {
    const geo::Cartographic start = onSlope(bearing, 3000.0, kClearance + 0.5);
    // Towards the summit, level in the start's tangent plane, 200 m in one frame.
    const glm::dvec3 towards = camera::testing::direction(start, bearing + std::numbers::pi, 0.0);
    for (const bool sweep : {true, false}) {
      ResponseSettings settings;
      settings.sweep = sweep;
      const MotionResult r =
          respondLinear(fuji(), kWgs84, start, 200.0 * towards, kClearance, settings);
      ASSERT_TRUE(r.valid);
      EXPECT_EQ(r.response, Response::Slid);
      EXPECT_GE(r.slideIterations, 1);
      const glm::dvec3 moved =
          geo::cartographicToEcef(kWgs84, r.position) - geo::cartographicToEcef(kWgs84, start);
      const double progress = glm::dot(moved, towards);
      const double climb = r.position.heightMeters - start.heightMeters;
      const double clearance = r.position.heightMeters - drawn(r.position);
      std::printf(
          "bearing %3.0f deg sweep %d: progress %6.1f m, climb %6.1f m, clearance %.3f m, "
          "%d contacts, %u probes\n",
          bearing * 180 / std::numbers::pi, sweep, progress, climb, clearance, r.slideIterations,
          r.samples);
      EXPECT_GT(progress, 20.0);                              // tangential progress
      EXPECT_GT(climb, 0.1 * progress);                       // the height follows the slope up
      EXPECT_GE(clearance, kClearance - kContactSkinMeters);  // never below
      EXPECT_LT(clearance, kClearance + 0.5 * progress);
      EXPECT_GT(glm::dot(r.contactNormal, geo::geodeticSurfaceNormal(kWgs84, r.position)), 0.5);
      if (!sweep) continue;
      // The way to the first contact kept the clearance (sampled every metre).
      const glm::dvec3 a = geo::cartographicToEcef(kWgs84, start);
      const glm::dvec3 b = geo::cartographicToEcef(kWgs84, r.firstContact);
      const int n = static_cast<int>(glm::length(b - a)) + 1;
      double lowest = 1e9;
      for (int i = 0; i <= n; ++i) {
        const auto p = *geo::ecefToCartographic(kWgs84, a + (b - a) * (double(i) / n));
        lowest = std::min(lowest, p.heightMeters - drawn(p));
      }
      EXPECT_GE(lowest, kClearance - kContactSkinMeters - 0.05);
    }
  }
}

TEST(LinearResponse, MotionStraightDownOnASlopeSlidesDownIt) {
  for (const double bearing : {std::numbers::pi / 4, 1.25 * std::numbers::pi}) {
    const geo::Cartographic start = onSlope(bearing, 2000.0, 50.0);
    const glm::dvec3 down = -geo::geodeticSurfaceNormal(kWgs84, start);
    const MotionResult r = respondLinear(fuji(), kWgs84, start, 500.0 * down, kClearance, {});
    ASSERT_TRUE(r.valid);
    EXPECT_EQ(r.response, Response::Slid);
    EXPECT_GE(r.position.heightMeters - drawn(r.position), kClearance - kContactSkinMeters);
    EXPECT_LT(r.position.heightMeters, start.heightMeters - 45.0);
    // It moved along the surface, downhill on the last triangle slid along.
    const glm::dvec3 up = geo::geodeticSurfaceNormal(kWgs84, start);
    const glm::dvec3 moved =
        geo::cartographicToEcef(kWgs84, r.position) - geo::cartographicToEcef(kWgs84, start);
    const glm::dvec3 horizontal = moved - glm::dot(moved, up) * up;
    const glm::dvec3 downhill = r.contactNormal - glm::dot(r.contactNormal, up) * up;
    EXPECT_GT(glm::length(horizontal), 1.0);
    EXPECT_GT(glm::dot(horizontal, downhill), 0.0);
  }
}

TEST(AngularResponse, HeightenedToTheSurfaceWithTheAngleAppliedInFull) {
  for (const double bearing : {std::numbers::pi / 2, 1.5 * std::numbers::pi}) {
    const geo::Cartographic from = onSlope(bearing, 3000.0, kClearance);
    const glm::dvec3 p = geo::cartographicToEcef(kWgs84, from);
    // About the polar axis towards the summit: 80 m along the parallel in one frame.
    const double sign = bearing < std::numbers::pi ? -1.0 : 1.0;
    const double angle = 80.0 / std::hypot(p.x, p.y);
    const auto to =
        geo::ecefToCartographic(kWgs84, camera::rotateAboutGeocentre(p, {0, 0, sign * angle}));
    ASSERT_TRUE(to);
    ASSERT_LT(to->heightMeters, drawn(*to) + kClearance - 1.0) << "the rotation climbs into Fuji";
    for (const bool sweep : {false, true}) {
      ResponseSettings settings;
      settings.sweep = sweep;
      const MotionResult r = respondAngular(fuji(), kWgs84, from, *to, kClearance, settings);
      ASSERT_TRUE(r.valid);
      EXPECT_EQ(r.response, Response::Heightened);
      // The angular position is exactly the rotation's; only the height changed.
      EXPECT_EQ(r.position.longitudeRadians, to->longitudeRadians);
      EXPECT_EQ(r.position.latitudeRadians, to->latitudeRadians);
      EXPECT_NEAR(r.position.longitudeRadians - from.longitudeRadians, sign * angle, 1e-15);
      const double target = drawn(*to) + kClearance;
      if (sweep) {
        EXPECT_GE(r.position.heightMeters, target - 1e-9);
        EXPECT_LT(r.position.heightMeters, target + 20.0);
      } else {
        EXPECT_NEAR(r.position.heightMeters, target, 1e-9);
      }
      EXPECT_NEAR(r.liftMeters, r.position.heightMeters - to->heightMeters, 1e-9);
    }
  }
}

TEST(AngularResponse, OnThePapersSphereTheGeocentricDirectionIsKeptExactly) {
  // On the sphere the Oriented Ray points at the centre: heightening is radial, and the camera's
  // direction from the centre is the rotated one.
  const geo::Ellipsoid sphere = geo::Ellipsoid::sphere();
  geo::Cartographic from = offsetPosition(fujiSummit(), std::numbers::pi / 2, 3000.0, 0.0);
  from.heightMeters = drawn(from) + kClearance;
  const glm::dvec3 p = geo::cartographicToEcef(sphere, from);
  const glm::dvec3 rotated = camera::rotateAboutGeocentre(p, {0, 0, -80.0 / std::hypot(p.x, p.y)});
  const auto to = geo::ecefToCartographic(sphere, rotated);
  ASSERT_TRUE(to);
  const MotionResult r = respondAngular(fuji(), sphere, from, *to, kClearance, {});
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.response, Response::Heightened);
  const glm::dvec3 end = geo::cartographicToEcef(sphere, r.position);
  EXPECT_NEAR(glm::length(glm::cross(glm::normalize(end), glm::normalize(rotated))), 0.0, 1e-15);
  EXPECT_GT(glm::length(end), glm::length(rotated));
}

TEST(AngularResponse, AFreeRotationIsNotTouched) {
  const geo::Cartographic from = fujiSummit(9000.0);
  const glm::dvec3 p = geo::cartographicToEcef(kWgs84, from);
  const auto to = geo::ecefToCartographic(kWgs84, camera::rotateAboutGeocentre(p, {0, 0, 1e-3}));
  const MotionResult r = respondAngular(fuji(), kWgs84, from, *to, kClearance, {});
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.response, Response::None);
  EXPECT_EQ(r.position.heightMeters, to->heightMeters);
}

TEST(Responses, NonFiniteInputIsInvalidAndKeepsTheStart) {
  const geo::Cartographic from = fujiSummit(5000.0);
  const double nan = std::nan("");
  const double inf = std::numeric_limits<double>::infinity();
  for (const geo::Cartographic bad :
       {geo::Cartographic{nan, 0.6, 10.0}, geo::Cartographic{2.4, inf, 10.0},
        geo::Cartographic{2.4, 0.6, nan}, geo::Cartographic{2.4, 2.0, 10.0}}) {
    for (const MotionResult& r : {respondStatic(fuji(), kWgs84, from, bad, kClearance, {}),
                                  respondAngular(fuji(), kWgs84, from, bad, kClearance, {}),
                                  respondStatic(fuji(), kWgs84, bad, from, kClearance, {})}) {
      EXPECT_FALSE(r.valid);
      EXPECT_EQ(r.response, Response::None);
    }
  }
  for (const glm::dvec3 d : {glm::dvec3(nan, 0, 0), glm::dvec3(0, inf, 0), glm::dvec3(1e300)}) {
    const MotionResult r = respondLinear(fuji(), kWgs84, from, d, kClearance, {});
    EXPECT_FALSE(r.valid);
    EXPECT_EQ(r.position.heightMeters, from.heightMeters);
  }
}

}  // namespace
}  // namespace globe::collision
