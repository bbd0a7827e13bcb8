// A camera driven into Mount Fuji from 16 directions, level/descending/diving, at 1 m/s to 100 km
// a frame: every frame, eye and near-plane corners above the drawn surface (zero violations).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "camera/camera_controller.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using collision::Response;
using collision::SurfaceModel;
using globe::test::kDt;
using testing::FrameAudit;
constexpr int kFrames = 60;
using globe::test::kWgs84;

struct Profile {
  const char* name;
  double pitchDegrees;
  double startAboveMeters;
};
constexpr Profile kProfiles[] = {
    {"level", 0.0, 3.0}, {"descending", -20.0, 300.0}, {"dive", -60.0, 1000.0}};
constexpr double kStepsMeters[] = {1.0 / 30.0, 0.3,    1.0,     3.0,     30.0,    300.0,
                                   1000.0,     3000.0, 10000.0, 30000.0, 100000.0};

struct RunTotals {
  FrameAudit audit;
  int collidedFrames = 0;
  int slidFrames = 0;
  int pushedFrames = 0;
  long probes = 0;
  int maxProbes = 0;
  int runs = 0;
};

// One run: from `distance` towards the summit along bearing + 180 deg at `step` metres a frame.
void drive(const terrain::RenderingTileArray& array, const ControllerSettings& settings,
           const Profile& profile, double bearing, double step, RunTotals& totals) {
  const double distance = std::clamp(step * 20.0, 200.0, 12000.0);
  geo::Cartographic start = testing::offsetPosition(testing::fujiSummit(), bearing, distance, 0.0);
  start.heightMeters = testing::drawnHeight(array, start.longitudeRadians, start.latitudeRadians) +
                       profile.startAboveMeters;
  const double heading = bearing + std::numbers::pi;
  const double pitch = geo::degreesToRadians(profile.pitchDegrees);
  CameraController controller({start, heading, pitch, 0.0}, settings);
  ASSERT_TRUE(controller.setVelocity(testing::direction(start, heading, pitch) * (step / kDt)));
  ++totals.runs;
  for (int frame = 0; frame < kFrames; ++frame) {
    const CollisionState& state = controller.update(kDt, array, kWgs84);
    ASSERT_FALSE(state.inputRejected);
    const bool ok = totals.audit.check(controller.pose(), settings.nearPlane, array);
    ASSERT_TRUE(ok) << profile.name << " bearing " << bearing * 180 / std::numbers::pi << " step "
                    << step << " frame " << frame << " clearance " << state.clearanceMeters
                    << " corners " << state.nearPlaneClearanceMeters;
    totals.collidedFrames += state.collided;
    totals.slidFrames += state.response == Response::Slid;
    totals.pushedFrames += state.nearPlanePushed;
    totals.probes += state.surfaceProbes;
    totals.maxProbes = std::max(totals.maxProbes, state.surfaceProbes);
  }
}

void driveAll(SurfaceModel model, const std::vector<double>& steps, int headings) {
  const terrain::RenderingTileArray& array = testing::fujiArray(testing::finestLevel());
  ControllerSettings settings;
  settings.response.surface = model;
  RunTotals all;
  std::printf("%-6s %10s %5s %7s %8s %6s %7s %9s %10s %8s %9s\n", "model", "m/frame", "runs",
              "frames", "collided", "slid", "pushed", "eye min", "corner min", "probes",
              "ms/frame");
  for (const double step : steps) {
    RunTotals totals;
    const auto t0 = std::chrono::steady_clock::now();
    for (const Profile& profile : kProfiles) {
      for (int k = 0; k < headings; ++k) {
        drive(array, settings, profile, 2.0 * std::numbers::pi * k / headings, step, totals);
        if (::testing::Test::HasFatalFailure()) return;
      }
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("%-6s %10.3f %5d %7d %8d %6d %7d %9.3f %10.3f %8.1f %9.3f\n",
                model == SurfaceModel::Exact ? "exact" : "qotcd", step, totals.runs,
                totals.audit.frames, totals.collidedFrames, totals.slidFrames, totals.pushedFrames,
                totals.audit.lowestEyeClearanceMeters, totals.audit.lowestCornerClearanceMeters,
                static_cast<double>(totals.probes) / totals.audit.frames, ms / totals.audit.frames);
    if (step >= 1.0) {
      EXPECT_GT(totals.collidedFrames, 0) << step;
    }
    all.audit.add(totals.audit);
    all.collidedFrames += totals.collidedFrames;
    all.slidFrames += totals.slidFrames;
  }
  EXPECT_EQ(all.audit.violations, 0);
  EXPECT_EQ(all.audit.nonFinite, 0);
  // The floor holds: the eye keeps its whole clearance, the corners their 0.5 m (QOTCD's H may
  // be up to 1 mm below the drawn surface).
  const double slack = model == SurfaceModel::Exact ? 1e-6 : 1e-3;
  EXPECT_GE(all.audit.lowestEyeClearanceMeters, settings.clearance.eyeMeters - slack);
  EXPECT_GE(all.audit.lowestCornerClearanceMeters, settings.clearance.nearPlaneMeters - slack);
  EXPECT_GT(all.slidFrames, all.audit.frames / 10);
  std::printf(
      "%s: %d frames, %d violations, %d collided, lowest eye %.4f m, lowest corner %.4f m\n",
      model == SurfaceModel::Exact ? "exact" : "qotcd", all.audit.frames, all.audit.violations,
      all.collidedFrames, all.audit.lowestEyeClearanceMeters,
      all.audit.lowestCornerClearanceMeters);
}

TEST(FujiDrive, EveryFrameAboveTheDrawnSurfaceExactModel) {
  driveAll(SurfaceModel::Exact, {std::begin(kStepsMeters), std::end(kStepsMeters)}, 16);
}

TEST(FujiDrive, EveryFrameAboveTheDrawnSurfaceQotcdModel) {
  driveAll(SurfaceModel::Qotcd, {1.0, 1000.0, 100000.0}, 8);
}

}  // namespace
}  // namespace globe::camera
