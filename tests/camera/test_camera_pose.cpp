// Camera pose conventions: heading/pitch/roll, orthonormal frames, poles, view matrix precision.
#include "camera/camera_pose.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "geo/ecef.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using globe::test::kWgs84;

void expectOrthonormal(const CameraFrame& f) {
  EXPECT_NEAR(glm::length(f.forward), 1, 1e-12);
  EXPECT_NEAR(glm::length(f.up), 1, 1e-12);
  EXPECT_NEAR(glm::length(f.right), 1, 1e-12);
  EXPECT_NEAR(glm::dot(f.forward, f.up), 0, 1e-12);
  EXPECT_NEAR(glm::dot(f.forward, f.right), 0, 1e-12);
  // Right-handed: right × up = −forward (OpenGL camera looks down −z).
  const glm::dvec3 back = glm::cross(f.right, f.up);
  EXPECT_NEAR(glm::dot(back, -f.forward), 1, 1e-12);
}

TEST(CameraPose, StraightDownAtTheEquatorLooksAtTheCentre) {
  const auto f = cameraFrame(kWgs84, CameraPose::fromDegrees(0, 0, 1000, 0, -90, 0));
  expectOrthonormal(f);
  EXPECT_NEAR(f.forward.x, -1, 1e-12);  // towards the geocentre
  EXPECT_NEAR(f.up.z, 1, 1e-12);        // the top of the image is north
  EXPECT_NEAR(f.right.y, 1, 1e-12);     // east on the right
}

TEST(CameraPose, HeadingEastAtTheHorizon) {
  const auto f = cameraFrame(kWgs84, CameraPose::fromDegrees(90, 0, 10, 90, 0, 0));
  expectOrthonormal(f);
  // At (90°E, 0°), east is −x and up is +y.
  EXPECT_NEAR(f.forward.x, -1, 1e-12);
  EXPECT_NEAR(f.up.y, 1, 1e-12);
}

TEST(CameraPose, RollTurnsTheImageClockwise) {
  const auto level = cameraFrame(kWgs84, CameraPose::fromDegrees(0, 0, 10, 0, 0, 0));
  const auto rolled = cameraFrame(kWgs84, CameraPose::fromDegrees(0, 0, 10, 0, 0, 90));
  expectOrthonormal(rolled);
  EXPECT_NEAR(glm::dot(rolled.forward, level.forward), 1, 1e-12);
  EXPECT_NEAR(glm::dot(rolled.up, level.right), 1, 1e-12);
}

TEST(CameraPose, FramesStayOrthonormalAtPolesAndAntimeridian) {
  for (double lat : {90.0, -90.0, 89.9999999, 0.0}) {
    for (double lon : {-180.0, 180.0, 0.0, 137.5}) {
      for (double pitch : {-90.0, -45.0, 0.0, 30.0}) {
        const auto f = cameraFrame(kWgs84, CameraPose::fromDegrees(lon, lat, 2, 33, pitch, 5));
        expectOrthonormal(f);
        EXPECT_TRUE(std::isfinite(f.positionEcefMeters.x));
      }
    }
  }
}

TEST(CameraPose, ViewMatrixPutsTheCameraAtTheOriginExactly) {
  // 1 m above the ground at Earth radius: the view transform must not lose the metre.
  const auto pose = CameraPose::fromDegrees(179.999, 89.99, 1.0, 10, -20, 0);
  const auto f = cameraFrame(kWgs84, pose);
  const glm::dmat4 view = viewMatrix(f);
  const glm::dvec4 eye = view * glm::dvec4(f.positionEcefMeters, 1.0);
  EXPECT_NEAR(glm::length(glm::dvec3(eye)), 0, 1e-8);
  const glm::dvec4 ahead = view * glm::dvec4(f.positionEcefMeters + 3.0 * f.forward, 1.0);
  EXPECT_NEAR(ahead.z, -3, 1e-8);
  const auto ground = geo::cartographicToEcef(
      kWgs84, geo::Cartographic{pose.position.longitudeRadians, pose.position.latitudeRadians, 0});
  const glm::dvec4 below = view * glm::dvec4(ground, 1.0);
  EXPECT_NEAR(glm::length(glm::dvec3(below)), 1.0, 1e-8);
}

TEST(CameraPose, NonFiniteIsDetected) {
  EXPECT_TRUE(CameraPose::fromDegrees(1, 2, 3).isFinite());
  EXPECT_FALSE(CameraPose::fromDegrees(std::nan(""), 2, 3).isFinite());
  EXPECT_FALSE(
      CameraPose::fromDegrees(1, 2, 3, std::numeric_limits<double>::infinity()).isFinite());
}

TEST(Projection, NearFollowsClearanceAndFarPassesTheHorizon) {
  const auto low = projectionForHeight(3002, 2, 0.8, 1.5, kWgs84);
  EXPECT_LE(low.nearMeters, 0.5);  // 2 m above a 3000 m mountain: the ground stays in view
  const auto space = projectionForHeight(2e7, 2e7, 0.8, 1.5, kWgs84);
  EXPECT_GT(space.farMeters, 2e7);  // the whole visible hemisphere
  EXPECT_GT(space.farMeters, std::sqrt(2e7 * (2 * 6.36e6 + 2e7)));
}

}  // namespace
}  // namespace globe::camera
