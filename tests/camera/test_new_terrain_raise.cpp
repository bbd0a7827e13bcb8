// A finer tile raises the surface under a still camera (Fuji, level 10 -> 14): never below the
// new surface + the minimum clearance, the desired clearance reached smoothly in <= 60 frames.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "camera/camera_controller.hpp"
#include "collision/terrain_raise.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using collision::Response;
using globe::test::kDt;
using globe::test::kWgs84;

struct Spot {
  geo::Cartographic position;  // height: the coarse surface
  double riseMeters = 0.0;     // fine - coarse
};

// Spots where the fine surface rises above the coarse one by `low`..`high` metres.
Spot findSpot(double low, double high, bool largest) {
  const auto& coarse = testing::fujiArray(10);
  const auto& fine = testing::fujiArray(testing::finestLevel());
  Spot best;
  best.riseMeters = largest ? -1e9 : 0.0;
  bool found = false;
  for (int i = 0; i < 80; ++i) {
    for (int j = 0; j < 80; ++j) {
      const geo::Cartographic c =
          geo::Cartographic::fromDegrees(138.62 + 0.22 * i / 79, 35.28 + 0.16 * j / 79);
      const double hc = testing::drawnHeight(coarse, c.longitudeRadians, c.latitudeRadians);
      const double hf = testing::drawnHeight(fine, c.longitudeRadians, c.latitudeRadians);
      const double rise = hf - hc;
      if (hc < 500.0 || hf < 500.0 || rise < low || rise > high) continue;
      if (!found || (largest && rise > best.riseMeters)) {
        best = {{c.longitudeRadians, c.latitudeRadians, hc}, rise};
        found = true;
      }
      if (found && !largest) return best;
    }
  }
  EXPECT_TRUE(found) << low << ".." << high;
  return best;
}

void raiseAt(const Spot& spot, bool nearPlaneCheck) {
  const auto& coarse = testing::fujiArray(10);
  const auto& fine = testing::fujiArray(testing::finestLevel());
  ControllerSettings settings;
  settings.nearPlaneCheck = nearPlaneCheck;
  settings.clearance.minimumEyeMeters = 1.0;  // a floor under the eye clearance: the smooth raise
  const collision::ClearanceSettings& c = settings.clearance;
  CameraPose pose{spot.position, 0.0, 0.0, 0.0};
  pose.position.heightMeters += c.eyeMeters;
  CameraController controller(pose, settings);
  for (int frame = 0; frame < 5; ++frame) {
    EXPECT_EQ(controller.update(kDt, coarse, kWgs84).response, Response::None);
  }
  EXPECT_EQ(controller.pose().position.heightMeters, pose.position.heightMeters);

  const double surface =
      testing::drawnHeight(fine, pose.position.longitudeRadians, pose.position.latitudeRadians);
  // The controller places the eye the contact skin above each clearance, so it never rests
  // nearer the surface than the setting (camera_controller.cpp, responseClearance).
  const double floor = surface + (c.minimumEyeMeters + collision::kContactSkinMeters);
  const double desired = surface + (c.eyeMeters + collision::kContactSkinMeters);
  double previous = pose.position.heightMeters;
  int reachedAt = -1;
  double largestStep = 0.0;
  double firstFrame = 0.0;
  for (int frame = 1; frame <= 120; ++frame) {
    const CollisionState& state = controller.update(kDt, fine, kWgs84);
    const double h = controller.pose().position.heightMeters;
    if (frame == 1) firstFrame = h - surface;
    EXPECT_GE(h, floor - 1e-9) << frame;  // the hard floor, from the first frame on
    EXPECT_GE(h, previous) << frame;      // monotone
    EXPECT_EQ(controller.pose().position.longitudeRadians, pose.position.longitudeRadians);
    EXPECT_EQ(controller.pose().position.latitudeRadians, pose.position.latitudeRadians);
    // Above the floor, at most maxRaiseRate * dt a frame (the floor itself comes at once).
    // (A near-plane push is not a raise: it comes at once.)
    const double step = h - std::max(previous, floor);
    if (!state.nearPlanePushed) {
      EXPECT_LE(step, c.maxRaiseRateMetersPerSecond * kDt + 1e-9) << frame;
      largestStep = std::max(largestStep, step);
    }
    if (reachedAt < 0) {
      if (h == desired || (state.nearPlanePushed && h > desired)) {
        reachedAt = frame;
      } else {
        EXPECT_TRUE(state.raisedForNewTerrain) << frame;
        EXPECT_EQ(state.response, Response::RaisedForNewTerrain);
      }
    } else {
      EXPECT_EQ(h, previous) << frame;  // and it stays there
      EXPECT_GE(h, desired) << frame;
      EXPECT_FALSE(state.raisedForNewTerrain);
    }
    previous = h;
    if (::testing::Test::HasFailure()) return;
  }
  std::printf(
      "surface rose %.2f m under a camera 2 m above it: frame 1 at %.3f m above the new "
      "surface, largest smooth step %.3f m, %.0f m desired reached at frame %d\n",
      spot.riseMeters, firstFrame, largestStep, c.eyeMeters, reachedAt);
  EXPECT_GT(reachedAt, 3);  // smoothly, not at once
  EXPECT_LE(reachedAt, 60);
}

TEST(NewTerrainRaise, AFinerTileRisingAboveTheCameraRaisesItSmoothly) {
  const Spot big = findSpot(5.0, 50.0, true);  // the hard floor applies
  EXPECT_GT(big.riseMeters, 5.0);
  raiseAt(big, false);
  raiseAt(big, true);
  const Spot small = findSpot(0.3, 0.9, false);  // only the smooth part
  raiseAt(small, false);
}

TEST(NewTerrainRaise, TurningOrMovingDuringTheRaiseNeitherSkipsNorUndoesIt) {
  const auto& fine = testing::fujiArray(testing::finestLevel());
  const Spot spot = findSpot(5.0, 50.0, true);
  CameraPose pose{spot.position, 0.0, 0.0, 0.0};
  pose.position.heightMeters += 2.0;
  ControllerSettings settings;
  settings.nearPlaneCheck = false;
  settings.clearance.minimumEyeMeters = 1.0;  // a floor under the eye clearance: the smooth raise
  const double minimum = settings.clearance.minimumEyeMeters;
  const double eye = settings.clearance.eyeMeters;
  // Turning only: the heading is applied at once, the raise goes on.
  CameraController turning(pose, settings);
  turning.update(kDt, testing::fujiArray(10), kWgs84);
  double previous = -1e9;
  for (int frame = 1; frame <= 60; ++frame) {
    CameraPose turned = turning.pose();
    turned.headingRadians += 0.05;
    ASSERT_TRUE(turning.propose(turned));
    const CollisionState& state = turning.update(kDt, fine, kWgs84);
    EXPECT_EQ(turning.pose().headingRadians, turned.headingRadians);
    EXPECT_GE(state.clearanceMeters, minimum - 1e-9);
    EXPECT_GE(turning.pose().position.heightMeters, previous);
    previous = turning.pose().position.heightMeters;
  }
  EXPECT_NEAR(turning.state().clearanceMeters, eye + collision::kContactSkinMeters, 1e-9);
  // Moving level at 1 m/s: never below the floor, the desired clearance reached.
  CameraController moving(pose, settings);
  moving.update(kDt, testing::fujiArray(10), kWgs84);
  ASSERT_TRUE(moving.setVelocity(testing::direction(pose.position, 0.3, 0.0)));
  double lowest = 1e9;
  int reached = -1;
  for (int frame = 1; frame <= 90; ++frame) {
    const CollisionState& state = moving.update(kDt, fine, kWgs84);
    lowest = std::min(lowest, state.clearanceMeters);
    if (reached < 0 && state.clearanceMeters >= eye - 1e-9) {
      reached = frame;
    }
    if (reached > 0) {
      EXPECT_GE(state.clearanceMeters, eye - 1e-9);
    }
  }
  EXPECT_GE(lowest, minimum - 1e-9);
  EXPECT_GT(reached, 3);
  EXPECT_LE(reached, 60);
}

TEST(NewTerrainRaise, AFinerTileBelowTheCameraChangesNothing) {
  const Spot lower = findSpot(-1e9, -3.0, false);
  CameraPose pose{lower.position, 0.0, 0.0, 0.0};
  pose.position.heightMeters += 2.0;
  CameraController controller(pose);
  controller.update(kDt, testing::fujiArray(10), kWgs84);
  const CollisionState& state =
      controller.update(kDt, testing::fujiArray(testing::finestLevel()), kWgs84);
  EXPECT_EQ(state.response, Response::None);
  EXPECT_EQ(controller.pose().position.heightMeters, pose.position.heightMeters);
}

TEST(NewTerrainRaise, APureStepFollowsTheDocumentedLaw) {
  const auto& fine = testing::fujiArray(testing::finestLevel());
  const Spot spot = findSpot(5.0, 50.0, true);
  const double surface =
      testing::drawnHeight(fine, spot.position.longitudeRadians, spot.position.latitudeRadians);
  collision::ClearanceSettings c;
  c.minimumEyeMeters = 1.0;  // a floor under the eye clearance: the smooth raise
  geo::Cartographic at = spot.position;
  at.heightMeters = surface + 1.2;  // above the floor, below the desired clearance
  const auto r =
      collision::raiseForNewTerrain(fine, kWgs84, at, kDt, c, collision::SurfaceModel::Exact);
  ASSERT_TRUE(r.valid);
  EXPECT_FALSE(r.floorApplied);
  const double expected = std::min((1 - std::exp(-kDt / c.raiseTimeConstantSeconds)) * 0.8,
                                   c.maxRaiseRateMetersPerSecond * kDt);
  EXPECT_NEAR(r.position.heightMeters - at.heightMeters, expected, 1e-9);
  // dt = 0: only the floor.
  at.heightMeters = surface - 30.0;
  const auto floor =
      collision::raiseForNewTerrain(fine, kWgs84, at, 0.0, c, collision::SurfaceModel::Exact);
  EXPECT_TRUE(floor.floorApplied);
  EXPECT_NEAR(floor.position.heightMeters, surface + c.minimumEyeMeters, 1e-9);
  EXPECT_NEAR(floor.remainingMeters, c.eyeMeters - c.minimumEyeMeters, 1e-9);
}

}  // namespace
}  // namespace globe::camera
