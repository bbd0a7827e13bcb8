// Panning and zooming keep the heading the user had (north up stays up), as in Google Earth and
// CesiumJS (rotate3D about the polar axis): only the explicit turn changes it. Measured where it
// shows, at the ground point at the centre of the view; from space, near the ground, and looking
// straight down at a pole (no NaN there).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

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
const glm::dvec2 kViewCentre(kWidth / 2.0, kHeight / 2.0);

// One frame, the proposal adopted as it is (nothing collides).
Navigator navigatorAt(const CameraPose& start) {
  Navigator navigator(kWgs84, start, kFovY, hill);
  navigator.setViewport(kWidth, kHeight);
  return navigator;
}

void step(Navigator& navigator) {
  const auto proposal = navigator.update(1.0 / 60);
  const CameraPose pose = proposal ? proposal->pose : navigator.pose();
  CollisionState state;
  state.terrainFound = true;
  state.terrainHeightMeters = *hill(pose.position.longitudeRadians, pose.position.latitudeRadians);
  state.clearanceMeters = pose.position.heightMeters - state.terrainHeightMeters;
  navigator.adopt(pose, state);
}

// The heading of screen-up on the ground at the centre of the view, degrees: the direction of
// the camera's up vector in the east-north-up frame there (the view looks down).
double headingAtCentreDegrees(const Navigator& navigator) {
  const auto centre = navigator.groundAt(kViewCentre);
  EXPECT_TRUE(centre.has_value());
  if (!centre) return std::nan("");
  const auto there = geo::ecefToCartographic(kWgs84, *centre);
  const EastNorthUp enu = eastNorthUp(kWgs84, *there);
  const glm::dvec3 up = cameraFrame(kWgs84, navigator.pose()).up;
  return geo::radiansToDegrees(std::atan2(glm::dot(up, enu.east), glm::dot(up, enu.north)));
}

double turnDegrees(double fromDegrees, double toDegrees) {
  return std::remainder(toDegrees - fromDegrees, 360.0);
}

// The heading kept is the camera's own (the HUD's); north up (heading 0), and any heading
// looking straight down, show the same at the centre of the view. A tilted view at another
// heading sees it there turned by the meridians' convergence between camera and centre.
void expectHeadingKept(const Navigator& navigator, double headingDegrees, double pitchDegrees,
                       const char* what) {
  EXPECT_NEAR(turnDegrees(headingDegrees, geo::radiansToDegrees(navigator.pose().headingRadians)),
              0, 0.5)
      << what;
  if (headingDegrees == 0 || pitchDegrees == -90) {
    EXPECT_NEAR(turnDegrees(headingDegrees, headingAtCentreDegrees(navigator)), 0, 0.5) << what;
  }
}

TEST(NorthKept, DraggingAndZoomingKeepTheHeadingFromSpaceAndNearTheGround) {
  for (const double heading : {0.0, 40.0}) {
    for (const CameraPose start : {CameraPose::fromDegrees(10, 30, 8e6, heading, -90),
                                   CameraPose::fromDegrees(10, 30, 3e6, heading, -60),
                                   CameraPose::fromDegrees(138.60, 35.20, 15000, heading, -45)}) {
      SCOPED_TRACE(::testing::Message()
                   << "heading " << heading << ", height " << start.position.heightMeters
                   << ", pitch " << geo::radiansToDegrees(start.pitchRadians));
      Navigator navigator = navigatorAt(start);
      const double pitch = geo::radiansToDegrees(start.pitchRadians);
      expectHeadingKept(navigator, heading, pitch, "start");
      // A drag of 200 pixels toward the east (the cursor right), in moves of 20.
      const glm::dvec2 press(560, 400);
      const auto grabbed = navigator.groundAt(press);
      ASSERT_TRUE(grabbed);
      navigator.grab(press);
      glm::dvec2 cursor = press;
      for (int move = 0; move < 10; ++move) {
        cursor += glm::dvec2(20, 0);
        navigator.dragTo(cursor, 20, 0);
        step(navigator);
        EXPECT_LT(pixelsOff(navigator.pose(), cursor, *grabbed), 1.0) << move;
      }
      navigator.release();
      expectHeadingKept(navigator, heading, pitch, "drag");
      // And a diagonal drag (toward the north-west).
      navigator.grab(kViewCentre);
      const auto centreGround = navigator.groundAt(kViewCentre);
      ASSERT_TRUE(centreGround);
      navigator.dragTo(kViewCentre + glm::dvec2(-150, -120), -150, -120);
      step(navigator);
      navigator.release();
      EXPECT_LT(pixelsOff(navigator.pose(), kViewCentre + glm::dvec2(-150, -120), *centreGround),
                1.0);
      expectHeadingKept(navigator, heading, pitch, "diagonal drag");
      // Zooms toward an off-centre cursor, in and out: the point stays under it.
      for (const auto& [notches, pixel] :
           {std::pair{2.0, glm::dvec2(960, 300)}, {-3.0, glm::dvec2(300, 560)}}) {
        const auto ground = navigator.groundAt(pixel);
        ASSERT_TRUE(ground);
        navigator.zoomAt(notches, pixel);
        step(navigator);
        EXPECT_LT(pixelsOff(navigator.pose(), pixel, *ground), 0.5) << notches;
        expectHeadingKept(navigator, heading, pitch, notches > 0 ? "zoom in" : "zoom out");
      }
      // The explicit turn still turns.
      const double before = geo::radiansToDegrees(navigator.pose().headingRadians);
      navigator.tilt(100, 0);
      step(navigator);
      EXPECT_GT(turnDegrees(before, geo::radiansToDegrees(navigator.pose().headingRadians)), 20);
    }
  }
}

// The arrow keys (and a drag off the globe) pan by latitude and longitude: the heading kept too.
TEST(NorthKept, ArrowKeysKeepTheHeading) {
  Navigator navigator = navigatorAt(CameraPose::fromDegrees(10, 30, 8e6, 0, -90));
  navigator.panByKey(200, 0);
  step(navigator);
  navigator.panByKey(0, -150);
  step(navigator);
  EXPECT_NEAR(headingAtCentreDegrees(navigator), 0, 0.5);
}

// Straight down at a pole: the heading there is only a convention, but nothing may become NaN.
TEST(NorthKept, StraightDownAtAPoleStaysFinite) {
  for (const double latitude : {90.0, -90.0}) {
    Navigator navigator = navigatorAt(CameraPose::fromDegrees(0, latitude, 5e6, 0, -90));
    // Orbit keeps off the exact pole (89 degrees); a pose the controller settled on may be on it.
    CollisionState state;
    state.terrainFound = true;
    state.clearanceMeters = 5e6;
    navigator.adopt(CameraPose::fromDegrees(0, latitude, 5e6, 0, -90), state);
    const auto expectFinite = [&](const char* what) {
      EXPECT_TRUE(navigator.pose().isFinite()) << what << " at " << latitude;
      EXPECT_TRUE(std::isfinite(headingAtCentreDegrees(navigator))) << what << " at " << latitude;
    };
    navigator.grab(kViewCentre);
    navigator.dragTo(kViewCentre + glm::dvec2(200, 0), 200, 0);
    step(navigator);
    navigator.dragTo(kViewCentre + glm::dvec2(200, 150), 0, 150);
    step(navigator);
    navigator.release();
    expectFinite("drag");
    navigator.zoomAt(2, glm::dvec2(1000, 180));
    step(navigator);
    expectFinite("zoom in");
    navigator.zoomAt(-2, kViewCentre);
    step(navigator);
    expectFinite("zoom out");
    navigator.adopt(CameraPose::fromDegrees(0, latitude, 5e6, 0, -90), state);
    navigator.zoomAt(1, kViewCentre);
    step(navigator);
    navigator.grab(kViewCentre);
    navigator.dragTo(kViewCentre + glm::dvec2(0, 100), 0, 100);
    step(navigator);
    navigator.panByKey(50, 50);
    step(navigator);
    expectFinite("on the pole");
  }
}

}  // namespace
}  // namespace globe::camera
