// The view's controls given non-finite input (NaN, +-inf, overflowing deltas): fly, look, orbit
// and fly-to keep a finite pose, the one they had, so the camera never freezes on a NaN.
#include <gtest/gtest.h>

#include <limits>

#include "camera/camera_pose.hpp"
#include "camera/fly_controls.hpp"
#include "camera/fly_to.hpp"
#include "camera/orbit_controls.hpp"
#include "geo/ecef.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
using globe::test::kWgs84;
const double kBad[] = {kNan, kInf, -kInf};

void expectSamePose(const CameraPose& actual, const CameraPose& expected) {
  EXPECT_TRUE(samePose(actual, expected))
      << actual.position.longitudeRadians << " " << actual.position.latitudeRadians << " "
      << actual.position.heightMeters << " " << actual.headingRadians << " " << actual.pitchRadians;
}

TEST(ControlGuards, FlyStepAndLookIgnoreNonFiniteInput) {
  const CameraPose pose = CameraPose::fromDegrees(138.7, 35.3, 5000, 30, -20, 0);
  for (const double bad : kBad) {
    SCOPED_TRACE(bad);
    expectSamePose(flyStep(kWgs84, pose, {bad, 0, 0}, 0.1), pose);
    expectSamePose(flyStep(kWgs84, pose, {0, 0, 10}, bad), pose);
    expectSamePose(lookByPixels(pose, bad, 0), pose);
    expectSamePose(lookByPixels(pose, 0, bad), pose);
    expectSamePose(lookByRadians(pose, bad, 0), pose);
    expectSamePose(lookByRadians(pose, 0, bad), pose);
    // A non-finite speed factor gives a non-finite velocity, which the step ignores.
    FlyKeys forward;
    forward.forward = true;
    const glm::dvec3 velocity = flyVelocityEcef(kWgs84, pose, forward, 100, bad);
    expectSamePose(flyStep(kWgs84, pose, velocity, 0.1), pose);
  }
  // A finite velocity whose step overflows is ignored as well.
  expectSamePose(flyStep(kWgs84, pose, {1e308, 1e308, 0}, 10), pose);
  // Finite input still moves and turns.
  EXPECT_FALSE(samePose(flyStep(kWgs84, pose, {0, 0, 10}, 0.1), pose));
  EXPECT_FALSE(samePose(lookByPixels(pose, 5, 0), pose));
}

TEST(ControlGuards, OrbitControlsKeepAFinitePose) {
  const CameraPose home = CameraPose::fromDegrees(138.7, 35.3, 5000, 30, -40, 0);
  OrbitControls controls(kWgs84, home, 0.785);
  const CameraPose start = controls.pose();
  for (const double bad : kBad) {
    SCOPED_TRACE(bad);
    controls.rotateByDrag(bad, 3, 720);
    controls.rotateByDrag(3, bad, 720);
    controls.tiltByDrag(bad, 0);
    controls.tiltByDrag(0, bad);
    controls.zoom(bad);
    EXPECT_FALSE(controls.setGroundHeight(bad));
    expectSamePose(controls.pose(), start);
    EXPECT_EQ(controls.groundHeightMeters(), 0.0);
  }
  // Finite input that overflows: a zoom is clamped to the limits, a drag ignored.
  controls.zoom(-1e308);
  EXPECT_TRUE(controls.pose().isFinite());
  EXPECT_LE(controls.pose().position.heightMeters, OrbitLimits{}.maximumHeightMeters);
  const CameraPose zoomedOut = controls.pose();
  controls.rotateByDrag(1e308, -1e308, 720);
  expectSamePose(controls.pose(), zoomedOut);
  // A non-finite home is replaced by the default view.
  OrbitControls fallback(kWgs84, CameraPose::fromDegrees(kNan, 0, 1000), 0.785);
  EXPECT_TRUE(fallback.pose().isFinite());
  EXPECT_TRUE(fallback.home().isFinite());
}

TEST(ControlGuards, FlyToEndsOnANonFiniteTime) {
  const CameraPose from = CameraPose::fromDegrees(138.7, 35.3, 5000, 30, -40, 0);
  const CameraPose to = CameraPose::fromDegrees(138.8, 35.4, 3000, 40, -30, 0);
  const FlyToAnimation animation(kWgs84, from, to, 1.0);
  expectSamePose(animation.poseAt(kNan), to);
  expectSamePose(animation.poseAt(kInf), to);
  EXPECT_TRUE(animation.poseAt(-kInf).isFinite());  // before the start: at the start
  EXPECT_TRUE(animation.finishedAt(kNan));
  EXPECT_TRUE(animation.finishedAt(kInf));
  EXPECT_FALSE(animation.finishedAt(0.5));
  // A non-finite target ends where it started.
  expectSamePose(flyToEndPose(kWgs84, from, {kNan, 0, 0}), from);
  expectSamePose(flyToEndPose(kWgs84, from, {kInf, kInf, kInf}), from);
}

// A start pose beyond orbit mode's limits is changed and each change is said, with both values.
TEST(ControlGuards, AStartPoseOrbitCannotShowIsClampedAndSaid) {
  const CameraPose asked = CameraPose::fromDegrees(138.7, 35.3, 5000, 0, 45, 0);
  const OrbitControls controls(kWgs84, asked, 0.8);
  EXPECT_EQ(controls.home().pitchRadians, 0.0);
  const auto said = describeStartClamp(asked, controls.home());
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find("pitch 45°"), std::string::npos) << said[0];
  EXPECT_NE(said[0].find("starting at 0°"), std::string::npos) << said[0];
  EXPECT_NE(said[0].find("fly mode"), std::string::npos) << said[0];

  const CameraPose polar = CameraPose::fromDegrees(0, 89.9, 5000, 0, -30, 0);
  const auto saidPolar = describeStartClamp(polar, OrbitControls(kWgs84, polar, 0.8).home());
  ASSERT_EQ(saidPolar.size(), 1u);
  EXPECT_NE(saidPolar[0].find("latitude 89.9°"), std::string::npos) << saidPolar[0];
  EXPECT_NE(saidPolar[0].find("starting at 89°"), std::string::npos) << saidPolar[0];

  const CameraPose fine = CameraPose::fromDegrees(138.7, 35.3, 5000, 30, -20, 0);
  EXPECT_TRUE(describeStartClamp(fine, OrbitControls(kWgs84, fine, 0.8).home()).empty());
}

}  // namespace
}  // namespace globe::camera
