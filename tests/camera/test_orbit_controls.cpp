// Orbit mode as in Google Earth and CesiumJS: scroll zooms toward the ground under the cursor
// (that ground point stays under the cursor), tilting and turning pivot about the ground at the
// centre (it stays at the centre). Pure math over the WGS84 ellipsoid and Mount Fuji-like heights.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

#include <glm/geometric.hpp>

#include "camera/camera_pose.hpp"
#include "camera/fly_to.hpp"
#include "camera/orbit_controls.hpp"
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

glm::dvec3 groundUnder(const CameraPose& pose, glm::dvec2 pixel) {
  const CameraFrame frame = cameraFrame(kWgs84, pose);
  const glm::dvec3 ray = pixelRayEcef(frame, pixel.x, pixel.y, kWidth, kHeight, kFovY);
  const auto hit = intersectTerrain(kWgs84, frame.positionEcefMeters, ray, hill);
  EXPECT_TRUE(hit.has_value());
  return hit.value_or(glm::dvec3(0.0));
}

TEST(OrbitControls, ZoomKeepsTheGroundUnderTheCursor) {
  for (const CameraPose start : {CameraPose::fromDegrees(138.60, 35.20, 12000, 30, -35, 0),
                                 CameraPose::fromDegrees(138.73, 35.36, 60000, 0, -90, 0),
                                 CameraPose::fromDegrees(138.0, 34.5, 300000, 45, -60, 0)}) {
    OrbitControls controls(kWgs84, start, kFovY);
    const glm::dvec2 cursor(1000, 180);  // well off the centre
    const glm::dvec3 ground = groundUnder(controls.pose(), cursor);
    const double before =
        glm::distance(cameraFrame(kWgs84, controls.pose()).positionEcefMeters, ground);
    controls.zoomToward(3, ground);
    const double after =
        glm::distance(cameraFrame(kWgs84, controls.pose()).positionEcefMeters, ground);
    EXPECT_NEAR(after / before, std::pow(OrbitControls::kZoomFactorPerNotch, 3), 1e-6);
    SCOPED_TRACE(start.position.heightMeters);
    EXPECT_LT(pixelsOff(controls.pose(), cursor, ground), 0.5);
    controls.zoomToward(-5, ground);  // and out again
    // Heading and pitch are kept (straight down stays straight down): the camera is placed
    // where it sees the point under the cursor still.
    EXPECT_LT(pixelsOff(controls.pose(), cursor, ground), 0.5);
    EXPECT_GE(controls.pose().pitchRadians, -std::numbers::pi / 2 - 1e-12);
  }
}

TEST(OrbitControls, ZoomStopsAtTheMinimumDistanceAndIgnoresNaN) {
  OrbitControls controls(kWgs84, CameraPose::fromDegrees(138.60, 35.20, 12000, 30, -35, 0), kFovY);
  const glm::dvec3 ground = groundUnder(controls.pose(), {640, 360});
  controls.zoomToward(200, ground);
  const double distance =
      glm::distance(cameraFrame(kWgs84, controls.pose()).positionEcefMeters, ground);
  EXPECT_GE(distance, OrbitLimits{}.minimumClearanceMeters - 1e-6);
  const CameraPose kept = controls.pose();
  controls.zoomToward(std::nan(""), ground);
  controls.zoomToward(1, glm::dvec3(std::nan("")));
  EXPECT_TRUE(samePose(kept, controls.pose()));
}

// A left-drag holds the grabbed ground point under the cursor, step after step, near the ground
// and from space; a cursor off the globe is refused (the caller falls back to a plain pan).
TEST(OrbitControls, DragKeepsTheGrabbedGroundUnderTheCursor) {
  for (const CameraPose start : {CameraPose::fromDegrees(138.60, 35.20, 15000, 30, -40, 0),
                                 CameraPose::fromDegrees(138.73, 35.36, 200000, 0, -90, 0),
                                 CameraPose::fromDegrees(138.0, 30.0, 8e6, 0, -90, 0)}) {
    SCOPED_TRACE(start.position.heightMeters);
    OrbitControls controls(kWgs84, start, kFovY);
    glm::dvec2 cursor(500, 420);
    const glm::dvec3 grabbed = groundUnder(controls.pose(), cursor);
    for (int step = 0; step < 10; ++step) {
      cursor += glm::dvec2(25, -12);
      const auto frame = cameraFrame(kWgs84, controls.pose());
      ASSERT_TRUE(controls.dragGrabbed(
          grabbed, pixelRayEcef(frame, cursor.x, cursor.y, kWidth, kHeight, kFovY)));
      EXPECT_LT(pixelsOff(controls.pose(), cursor, grabbed), 1.0) << step;
    }
  }
  OrbitControls space(kWgs84, CameraPose::fromDegrees(138.0, 30.0, 2e7, 0, -90, 0), kFovY);
  const glm::dvec3 grabbed = groundUnder(space.pose(), {640, 360});
  const auto frame = cameraFrame(kWgs84, space.pose());
  const CameraPose kept = space.pose();
  EXPECT_FALSE(space.dragGrabbed(grabbed, pixelRayEcef(frame, 5, 5, kWidth, kHeight, kFovY)));
  EXPECT_TRUE(samePose(kept, space.pose()));
}

TEST(OrbitControls, TiltAndTurnKeepTheCentreGroundPointAtTheCentre) {
  OrbitControls controls(kWgs84, CameraPose::fromDegrees(138.60, 35.20, 15000, 30, -40, 0), kFovY);
  const glm::dvec2 centre(kWidth / 2.0, kHeight / 2.0);
  const glm::dvec3 pivot = groundUnder(controls.pose(), centre);
  const double distance =
      glm::distance(cameraFrame(kWgs84, controls.pose()).positionEcefMeters, pivot);
  const double pitchBefore = controls.pose().pitchRadians;
  for (const auto& [dx, dy] :
       {std::pair{120.0, 0.0}, {0.0, -60.0}, {-300.0, 80.0}, {40.0, 500.0}}) {
    controls.tiltAbout(dx, dy, pivot);
    EXPECT_LT(pixelsOff(controls.pose(), centre, pivot), 0.5) << dx << "," << dy;
    EXPECT_NEAR(glm::distance(cameraFrame(kWgs84, controls.pose()).positionEcefMeters, pivot),
                distance, 1e-3 * distance);
    EXPECT_LE(controls.pose().pitchRadians, 0.0);
  }
  EXPECT_NE(controls.pose().pitchRadians, pitchBefore);
  // Dragging up far tilts toward the horizon but never past it: the pivot stays in view.
  controls.tiltAbout(0, -5000, pivot);
  EXPECT_LT(pixelsOff(controls.pose(), centre, pivot), 0.5);
  EXPECT_LT(controls.pose().pitchRadians, 0.0);
}

}  // namespace
}  // namespace globe::camera
