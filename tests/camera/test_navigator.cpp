// The navigator on plain events, as `globe view` feeds it, over a real-sized hill: what is under
// the cursor or the centre stays there, a double-click and a go-to end looking at their target,
// the compass turns north up, a user move cancels a fly-to, fly keys move and stop. Each frame's
// proposal is adopted as the controller would when nothing collides.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "camera/navigator.hpp"
#include "geo/ecef.hpp"
#include "tests/camera/hill_view.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using globe::test::kFovY;
using globe::test::kWgs84;
using testing::hill;
using testing::kHeight;
using testing::kWidth;
using testing::pixelsOff;
const glm::dvec2 kCentre(kWidth / 2.0, kHeight / 2.0);

Navigator makeNavigator(const CameraPose& start) {
  Navigator navigator(kWgs84, start, kFovY, hill);
  navigator.setViewport(kWidth, kHeight);
  return navigator;
}

// One frame: the proposal adopted as it is, with the hill's height under the camera.
void frame(Navigator& navigator, double dtSeconds = 1.0 / 60) {
  const auto proposal = navigator.update(dtSeconds);
  const CameraPose pose = proposal ? proposal->pose : navigator.pose();
  CollisionState state;
  state.terrainFound = true;
  state.terrainHeightMeters = *hill(pose.position.longitudeRadians, pose.position.latitudeRadians);
  state.clearanceMeters = pose.position.heightMeters - state.terrainHeightMeters;
  navigator.adopt(pose, state);
}

double distanceTo(const CameraPose& pose, const glm::dvec3& point) {
  return glm::distance(cameraFrame(kWgs84, pose).positionEcefMeters, point);
}

TEST(Navigator, ScrollZoomsTowardTheGroundUnderTheCursor) {
  for (const CameraPose start : {CameraPose::fromDegrees(138.60, 35.20, 12000, 30, -35),
                                 CameraPose::fromDegrees(138.73, 35.36, 60000, 0, -90)}) {
    Navigator navigator = makeNavigator(start);
    const glm::dvec2 cursor(1000, 180);
    const auto ground = navigator.groundAt(cursor);
    ASSERT_TRUE(ground);
    const double before = distanceTo(navigator.pose(), *ground);
    navigator.zoomAt(2, cursor);
    frame(navigator);
    EXPECT_NEAR(distanceTo(navigator.pose(), *ground) / before, 0.64, 1e-6);
    EXPECT_LT(pixelsOff(navigator.pose(), cursor, *ground), 0.5);
    navigator.zoomAt(-4, cursor);  // and out, past where it started (straight down included)
    frame(navigator);
    EXPECT_LT(pixelsOff(navigator.pose(), cursor, *ground), 0.5);
    EXPECT_GT(distanceTo(navigator.pose(), *ground), before);
  }
}

TEST(Navigator, TiltAndTurnKeepTheCentreGroundAndDragKeepsTheGrabbedGround) {
  Navigator navigator = makeNavigator(CameraPose::fromDegrees(138.60, 35.20, 15000, 30, -50));
  const auto pivot = navigator.groundAt(kCentre);
  ASSERT_TRUE(pivot);
  navigator.tilt(120, -60);
  frame(navigator);
  EXPECT_LT(pixelsOff(navigator.pose(), kCentre, *pivot), 0.5);
  // Turned by the drag (the camera's own heading differs by the meridians' convergence).
  EXPECT_NEAR(navigator.pose().headingRadians, geo::degreesToRadians(30) + 120 * 0.005, 0.01);

  const glm::dvec2 press(400, 500);
  const auto grabbed = navigator.groundAt(press);
  ASSERT_TRUE(grabbed);
  navigator.grab(press);
  glm::dvec2 cursor = press;
  for (int move = 0; move < 10; ++move) {
    cursor += glm::dvec2(25, -12);
    navigator.dragTo(cursor, 25, -12);
    frame(navigator);
    EXPECT_LT(pixelsOff(navigator.pose(), cursor, *grabbed), 1.0) << move;
  }
  navigator.release();
}

TEST(Navigator, DoubleClickFliesToThePointUnderTheCursorFromAStraightDownView) {
  Navigator navigator = makeNavigator(CameraPose::fromDegrees(138.73, 35.36, 200000, 0, -90));
  const glm::dvec2 click(300, 200);
  const auto target = navigator.groundAt(click);
  ASSERT_TRUE(target);
  const double before = distanceTo(navigator.pose(), *target);
  ASSERT_TRUE(navigator.flyToPixel(click));
  EXPECT_TRUE(navigator.flyingTo());
  for (int i = 0; i < 120 && navigator.flyingTo(); ++i) frame(navigator);
  EXPECT_FALSE(navigator.flyingTo());
  // Nearer, and the clicked point (off the centre before) now at the centre: the camera flew
  // along to it, not only down.
  EXPECT_GT(pixelsOff(CameraPose::fromDegrees(138.73, 35.36, 200000, 0, -90), kCentre, *target),
            100);
  EXPECT_LT(pixelsOff(navigator.pose(), kCentre, *target), 1.0);
  EXPECT_LT(distanceTo(navigator.pose(), *target), 0.8 * before);
  // The sky is not a target.
  Navigator level = makeNavigator(CameraPose::fromDegrees(138.73, 35.36, 5000, 0, 0));
  EXPECT_FALSE(level.flyToPixel({640, 5}));
  EXPECT_FALSE(level.flyingTo());
}

TEST(Navigator, GoToEndsAbout15KmAwayLookingAtThePlaceAndAMoveCancelsIt) {
  Navigator navigator = makeNavigator(CameraPose::fromDegrees(130.0, 30.0, 2e6, 0, -90));
  const double lon = geo::degreesToRadians(138.73), lat = geo::degreesToRadians(35.36);
  const glm::dvec3 place = geo::cartographicToEcef(kWgs84, {lon, lat, *hill(lon, lat)});
  navigator.goTo(lon, lat);
  int frames = 0;
  for (; frames < 600 && navigator.flyingTo(); ++frames) frame(navigator);
  EXPECT_FALSE(navigator.flyingTo());
  EXPECT_GT(frames, 60);  // a long way takes longer than a second
  EXPECT_LT(pixelsOff(navigator.pose(), kCentre, place), 1.0);
  EXPECT_NEAR(distanceTo(navigator.pose(), place), 15000, 100);
  EXPECT_LE(navigator.pose().pitchRadians, geo::degreesToRadians(-35) + 1e-9);

  navigator.goTo(geo::degreesToRadians(0.0), geo::degreesToRadians(0.0));
  frame(navigator);
  ASSERT_TRUE(navigator.flyingTo());
  navigator.zoomAt(1, kCentre);  // the user takes over
  EXPECT_FALSE(navigator.flyingTo());
  navigator.goTo(std::nan(""), 0.0);  // refused, nothing starts
  EXPECT_FALSE(navigator.flyingTo());
}

TEST(Navigator, NorthUpTurnsAboutTheCentreInOrbitAndLevelsTheLookInFly) {
  Navigator navigator = makeNavigator(CameraPose::fromDegrees(138.60, 35.20, 15000, 140, -40));
  const auto pivot = navigator.groundAt(kCentre);
  ASSERT_TRUE(pivot);
  navigator.northUp();
  frame(navigator);
  EXPECT_NEAR(std::remainder(navigator.pose().headingRadians, 2 * std::numbers::pi), 0, 1e-3);
  EXPECT_LT(pixelsOff(navigator.pose(), kCentre, *pivot), 1.0);

  navigator.toggleMode();
  ASSERT_EQ(navigator.mode(), NavigationMode::Fly);
  navigator.look(300, 200);
  frame(navigator);
  EXPECT_GT(std::abs(std::remainder(navigator.pose().headingRadians, 2 * std::numbers::pi)), 0.5);
  navigator.northUp();
  frame(navigator);
  EXPECT_NEAR(std::remainder(navigator.pose().headingRadians, 2 * std::numbers::pi), 0, 1e-12);
  EXPECT_NEAR(navigator.pose().pitchRadians, 0, 1e-12);
}

TEST(Navigator, FlyKeysMoveAtTheClearanceSpeedAndStopWhenReleased) {
  Navigator navigator = makeNavigator(CameraPose::fromDegrees(138.40, 35.10, 3000, 90, 0));
  navigator.toggleMode();
  frame(navigator);
  const double clearance = 3000 - *hill(navigator.pose().position.longitudeRadians,
                                        navigator.pose().position.latitudeRadians);
  FlyKeys keys;
  keys.forward = true;
  navigator.setFlyKeys(keys);
  EXPECT_TRUE(navigator.animating());
  const glm::dvec3 from = cameraFrame(kWgs84, navigator.pose()).positionEcefMeters;
  for (int i = 0; i < 60; ++i) frame(navigator);
  const double travelled =
      glm::distance(cameraFrame(kWgs84, navigator.pose()).positionEcefMeters, from);
  EXPECT_NEAR(travelled, clearance, 0.05 * clearance);  // one second at the clearance speed
  navigator.changeSpeed(2);
  EXPECT_EQ(navigator.speed().factor(), 4.0);
  navigator.setFlyKeys({});
  EXPECT_FALSE(navigator.animating());
  frame(navigator);
  const CameraPose stopped = navigator.pose();
  frame(navigator);
  EXPECT_TRUE(samePose(stopped, navigator.pose()));
  EXPECT_FALSE(navigator.update(1.0 / 60).has_value());  // nothing to propose
  // Orbit events do nothing in fly mode.
  navigator.zoomAt(3, kCentre);
  navigator.tilt(100, 100);
  EXPECT_FALSE(navigator.update(1.0 / 60).has_value());
}

TEST(Navigator, ResetGoesHomeAndNonFiniteEventsChangeNothing) {
  const CameraPose home = CameraPose::fromDegrees(138.60, 35.20, 15000, 30, -50);
  Navigator navigator = makeNavigator(home);
  navigator.zoomAt(std::nan(""), kCentre);
  navigator.zoomAt(1, {std::nan(""), 0});
  navigator.tilt(std::nan(""), 1);
  navigator.dragTo({std::nan(""), 1}, std::nan(""), 1);
  frame(navigator, std::nan(""));
  EXPECT_TRUE(samePose(navigator.pose(), navigator.home()));
  navigator.zoomAt(3, kCentre);
  frame(navigator);
  EXPECT_LT(navigator.pose().position.heightMeters, 14000);
  navigator.reset();
  frame(navigator);
  EXPECT_TRUE(samePose(navigator.pose(), navigator.home()));
}

}  // namespace
}  // namespace globe::camera
