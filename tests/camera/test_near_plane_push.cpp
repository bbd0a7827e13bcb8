// Near-plane clearance: 1 m above Fuji's slopes looking down them, a 1 m near plane cuts the drawn
// surface when only the eye is kept clear (Fig. 6(c)); checking its corners pushes the camera up.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "camera/camera_controller.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using collision::Response;
using globe::test::kDt;
using globe::test::kWgs84;

using testing::drawn;
using testing::fuji;

struct Slope {
  geo::Cartographic position;  // on the surface
  double downhillHeadingRadians;
  double slope;  // rise over run
};

// Points on Fuji's flanks with slopes of 25..50 deg over +-5 m, away from the SRTM voids.
std::vector<Slope> steepSlopes() {
  std::vector<Slope> slopes;
  for (int k = 0; k < 32 && slopes.size() < 8; ++k) {
    const geo::Cartographic c = testing::offsetPosition(
        testing::fujiSummit(), k * std::numbers::pi / 16, 1200.0 + 40.0 * k, 0.0);
    const double e = drawn(testing::offsetPosition(c, std::numbers::pi / 2, 5.0, 0.0)) -
                     drawn(testing::offsetPosition(c, 1.5 * std::numbers::pi, 5.0, 0.0));
    const double n = drawn(testing::offsetPosition(c, 0.0, 5.0, 0.0)) -
                     drawn(testing::offsetPosition(c, std::numbers::pi, 5.0, 0.0));
    const double slope = std::hypot(e, n) / 10.0;
    if (drawn(c) < 1000.0 || slope < std::tan(std::numbers::pi * 25 / 180) ||
        slope > std::tan(std::numbers::pi * 50 / 180)) {
      continue;
    }
    slopes.push_back(
        {{c.longitudeRadians, c.latitudeRadians, drawn(c)}, std::atan2(-e, -n), slope});
  }
  return slopes;
}

TEST(NearPlane, LookingDownASlopeOneMetreAboveItIsPushedUp) {
  const std::vector<Slope> slopes = steepSlopes();
  ASSERT_GE(slopes.size(), 4u);
  const NearPlane nearPlane{1.0, std::numbers::pi / 3,
                            16.0 / 9.0};  // a renderer with a fixed 1 m near plane
  ControllerSettings eyeOnly;
  eyeOnly.clearance.eyeMeters = 1.0;
  eyeOnly.clearance.minimumEyeMeters = 0.5;
  eyeOnly.nearPlaneCheck = false;
  eyeOnly.nearPlane = nearPlane;
  ControllerSettings withCorners = eyeOnly;
  withCorners.nearPlaneCheck = true;
  withCorners.lateralCheck = false;  // the corners' own push, straight up
  for (const Slope& s : slopes) {
    CameraPose pose{s.position, s.downhillHeadingRadians, -std::numbers::pi * 55 / 180, 0.0};
    pose.position.heightMeters += 1.0;

    CameraController clipping(pose, eyeOnly);
    const CollisionState before = clipping.update(kDt, fuji(), kWgs84);
    EXPECT_EQ(before.response, Response::None);
    EXPECT_NEAR(before.clearanceMeters, 1.0, 1e-6);
    testing::FrameAudit audit;
    EXPECT_FALSE(audit.check(clipping.pose(), nearPlane, fuji())) << "the near plane cuts";
    EXPECT_LT(audit.lowestCornerClearanceMeters, 0.0);
    EXPECT_NEAR(before.nearPlaneClearanceMeters, audit.lowestCornerClearanceMeters, 1e-9);

    CameraController pushed(pose, withCorners);
    const CollisionState after = pushed.update(kDt, fuji(), kWgs84);
    EXPECT_TRUE(after.collided);
    EXPECT_EQ(after.response, Response::NearPlanePushed);
    EXPECT_TRUE(after.nearPlanePushed);
    testing::FrameAudit check;
    EXPECT_TRUE(check.check(pushed.pose(), nearPlane, fuji()));
    EXPECT_GE(check.lowestCornerClearanceMeters, 0.5 - 1e-9);
    EXPECT_LT(check.lowestCornerClearanceMeters, 0.5 + 0.01);
    // Straight up: longitude and latitude unchanged, raised by the worst miss.
    EXPECT_EQ(pushed.pose().position.longitudeRadians, pose.position.longitudeRadians);
    EXPECT_EQ(pushed.pose().position.latitudeRadians, pose.position.latitudeRadians);
    const double push = pushed.pose().position.heightMeters - pose.position.heightMeters;
    EXPECT_NEAR(push, 0.5 - audit.lowestCornerClearanceMeters, 0.01);
    std::printf(
        "slope %4.1f deg, looking down it at -55 deg with a 1 m near plane, eye 1 m up: "
        "lowest near-plane corner %.3f m (cuts the surface); pushed up %.3f m, now %.3f m\n",
        std::atan(s.slope) * 180 / std::numbers::pi, audit.lowestCornerClearanceMeters, push,
        check.lowestCornerClearanceMeters);

    // The defaults (2 m eye, the renderer's 0.5 m near plane) need no push there.
    CameraPose normal{s.position, s.downhillHeadingRadians, -std::numbers::pi * 55 / 180, 0.0};
    normal.position.heightMeters += 2.0;
    CameraController defaults(normal);
    const CollisionState quiet = defaults.update(kDt, fuji(), kWgs84);
    EXPECT_FALSE(quiet.nearPlanePushed);
    EXPECT_GT(quiet.nearPlaneClearanceMeters, 0.5);
    if (HasFailure()) return;
  }
}

TEST(NearPlane, CornerOffsetsSpanTheFrustumsNearRectangle) {
  const CameraPose pose = CameraPose::fromDegrees(10.0, 20.0, 100.0, 30.0, -10.0, 5.0);
  const CameraFrame frame = cameraFrame(kWgs84, pose);
  const NearPlane near{2.0, std::numbers::pi / 2, 2.0};
  const auto corners = nearPlaneCornerOffsets(frame, near);
  for (const glm::dvec3& c : corners) {
    EXPECT_NEAR(glm::dot(c, frame.forward), 2.0, 1e-12);
    EXPECT_NEAR(std::abs(glm::dot(c, frame.up)), 2.0, 1e-12);     // 2 tan 45
    EXPECT_NEAR(std::abs(glm::dot(c, frame.right)), 4.0, 1e-12);  // times the aspect
  }
  EXPECT_GT(glm::dot(corners[0], frame.up), 0.0);
  EXPECT_LT(glm::dot(corners[0], frame.right), 0.0);
  EXPECT_LT(glm::dot(corners[3], frame.up), 0.0);
  EXPECT_GT(glm::dot(corners[3], frame.right), 0.0);
}

}  // namespace
}  // namespace globe::camera
