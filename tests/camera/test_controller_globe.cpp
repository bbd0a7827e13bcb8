// The controller low over both poles, across the antimeridian, along tile edges and onto tile
// corners, over real data: no frame below the drawn surface, no NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/geometric.hpp>

#include "camera/camera_controller.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using globe::test::kDt;
using globe::test::kWgs84;
using testing::FrameAudit;

geo::Cartographic above(const terrain::RenderingTileArray& array, double longitudeDegrees,
                        double latitudeDegrees, double aboveMeters) {
  geo::Cartographic c = geo::Cartographic::fromDegrees(longitudeDegrees, latitudeDegrees);
  c.heightMeters = testing::drawnHeight(array, c.longitudeRadians, c.latitudeRadians) + aboveMeters;
  return c;
}

// Runs the controller for `frames` frames, auditing each; returns the audit.
template <class PerFrame>
FrameAudit run(CameraController& controller, const terrain::RenderingTileArray& array, int frames,
               PerFrame perFrame) {
  FrameAudit audit;
  for (int frame = 0; frame < frames; ++frame) {
    const CollisionState& state = controller.update(kDt, array, kWgs84);
    EXPECT_FALSE(state.inputRejected) << frame;
    audit.check(controller.pose(), controller.settings().nearPlane, array);
    perFrame(frame, state);
  }
  EXPECT_EQ(audit.violations, 0);
  EXPECT_EQ(audit.nonFinite, 0);
  return audit;
}

TEST(GlobeController, FlyingLowOverBothPolesLinearly) {
  const auto& array = testing::globalArray();
  for (const double pole : {90.0, -90.0}) {
    for (const double step : {100.0, 3000.0}) {
      for (const double longitude : {0.0, 123.4, -180.0}) {
        // 20 frames from the pole, heading for it, 5 m above the surface, level.
        const double offset = geo::radiansToDegrees(20.0 * step / 6356752.0);
        const geo::Cartographic start =
            above(array, longitude, pole > 0 ? pole - offset : pole + offset, 5.0);
        const double heading = pole > 0 ? 0.0 : std::numbers::pi;
        CameraController controller({start, heading, 0.0, 0.0});
        ASSERT_TRUE(controller.setVelocity(testing::direction(start, heading, 0.0) * (step / kDt)));
        double nearest = 90.0;
        const FrameAudit audit = run(controller, array, 60, [&](int, const CollisionState&) {
          nearest =
              std::min(nearest, 90.0 - std::abs(controller.pose().position.latitudeDegrees()));
        });
        // It went over the pole (within a step of it) and came down the other side (sliding on
        // the triangles there turns it a little off the meridian plane).
        EXPECT_LT(nearest, geo::radiansToDegrees(step / 6356752.0) + 1e-9);
        const double turned = std::abs(geo::wrapLongitudeRadians(
            controller.pose().position.longitudeRadians - start.longitudeRadians));
        EXPECT_NEAR(turned, std::numbers::pi, 1e-3);
        std::printf(
            "pole %+.0f, lon %6.1f, %4.0f m/frame: nearest %.5f deg, lowest eye %.3f m, "
            "corner %.3f m\n",
            pole, longitude, step, nearest, audit.lowestEyeClearanceMeters,
            audit.lowestCornerClearanceMeters);
      }
    }
  }
}

TEST(GlobeController, OrbitingLowOverBothPolesAboutTheGeocentre) {
  const auto& array = testing::globalArray();
  for (const double pole : {90.0, -90.0}) {
    const geo::Cartographic start = above(array, 30.0, pole > 0 ? 87.0 : -87.0, 5.0);
    // About the local east axis: towards the pole, 10 km a frame.
    const glm::dvec3 east = eastNorthUp(kWgs84, start).east;
    const double rate = 10000.0 / 6356752.0 / kDt;
    CameraController controller({start, pole > 0 ? 0.0 : std::numbers::pi, -0.2, 0.0});
    ASSERT_TRUE(controller.setAngularVelocity((pole > 0 ? -rate : rate) * east));
    int heightened = 0;
    double nearest = 90.0;
    const FrameAudit audit = run(controller, array, 70, [&](int, const CollisionState& state) {
      heightened += state.response == collision::Response::Heightened;
      nearest = std::min(nearest, 90.0 - std::abs(controller.pose().position.latitudeDegrees()));
    });
    EXPECT_LT(nearest, 0.1);
    // 70 frames of 10 km: 6.31 deg of arc, 3 of them to the pole (geodetic and geocentric
    // latitudes differ by < 0.03 deg there).
    const double arcDegrees = 70.0 * rate * kDt * 180.0 / std::numbers::pi;
    EXPECT_NEAR(std::abs(controller.pose().position.latitudeDegrees()), 90.0 - (arcDegrees - 3.0),
                0.05);
    std::printf("orbit over pole %+.0f: nearest %.4f deg, %d heightened, lowest eye %.3f m\n", pole,
                nearest, heightened, audit.lowestEyeClearanceMeters);
  }
}

TEST(GlobeController, CrossingTheAntimeridianLowOverChukotka) {
  const auto& array = testing::globalArray();
  const geo::Cartographic start = above(array, 179.8, 66.0, 3.0);
  ASSERT_GT(start.heightMeters, 50.0) << "land under the track";
  // Linear, level and descending into the terrain, and angular about the polar axis.
  for (const double pitch : {0.0, -0.1}) {
    CameraController controller({start, std::numbers::pi / 2, pitch, 0.0});
    ASSERT_TRUE(controller.setVelocity(testing::direction(start, std::numbers::pi / 2, pitch) *
                                       (300.0 / kDt)));
    double previous = start.longitudeRadians;
    int crossed = 0, slid = 0;
    run(controller, array, 90, [&](int frame, const CollisionState& state) {
      const double now = controller.pose().position.longitudeRadians;
      const double moved = geo::wrapLongitudeRadians(now - previous);
      EXPECT_GT(moved, 0.0) << frame;   // eastwards every frame
      EXPECT_LT(moved, 1e-3) << frame;  // never the long way round
      crossed += previous > 0.0 && now < 0.0;
      slid += state.response == collision::Response::Slid;
      previous = now;
    });
    EXPECT_EQ(crossed, 1);
    EXPECT_LT(controller.pose().position.longitudeDegrees(), -179.0);
    if (pitch < 0.0) {
      EXPECT_GT(slid, 10);
    }
  }
  CameraController orbit({start, std::numbers::pi / 2, 0.0, 0.0});
  const double rate = 300.0 / (6378137.0 * std::cos(geo::degreesToRadians(66.0))) / kDt;
  ASSERT_TRUE(orbit.setAngularVelocity({0.0, 0.0, rate}));
  double previous = start.longitudeRadians;
  run(orbit, array, 90, [&](int frame, const CollisionState&) {
    const double now = orbit.pose().position.longitudeRadians;
    EXPECT_NEAR(geo::wrapLongitudeRadians(now - previous), rate * kDt, 1e-12) << frame;
    EXPECT_NEAR(orbit.pose().position.latitudeRadians, start.latitudeRadians, 1e-12);
    previous = now;
  });
  EXPECT_LT(orbit.pose().position.longitudeDegrees(), -179.0);
}

TEST(GlobeController, AlongTileEdgesAndOntoTileCorners) {
  const auto& array = testing::fujiArray(testing::finestLevel());
  // The north-west corner of the finest tile 1.5 km east of the summit.
  const geo::Cartographic near =
      testing::offsetPosition(testing::fujiSummit(), std::numbers::pi / 2, 1500.0, 0.0);
  const auto tile = geo::GeographicTilingScheme::positionToTile(
      near.longitudeRadians, near.latitudeRadians, testing::finestLevel());
  ASSERT_TRUE(tile);
  const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(*tile);
  geo::Cartographic corner{r.westRadians, r.northRadians, 0.0};
  corner.heightMeters =
      testing::drawnHeight(array, corner.longitudeRadians, corner.latitudeRadians) + 2.0;

  // Straight down onto the corner: stays on it at the clearance.
  CameraController down({corner, 0.0, -std::numbers::pi / 2, 0.0});
  ASSERT_TRUE(down.setVelocity(-geo::geodeticSurfaceNormal(kWgs84, corner) * (50.0 / kDt)));
  run(down, array, 30, [&](int, const CollisionState& state) {
    EXPECT_GE(state.clearanceMeters, 2.0 - 1e-9);
  });
  // Along the west edge (a meridian) southwards, proposed frame by frame at the camera's height
  // (angular moves, heightened): the longitude stays exactly on the edge; and along the north
  // edge (a parallel) by an angular velocity about the polar axis: the latitude stays on it to an
  // ulp (the ECEF round trip).
  CameraController meridian({corner, std::numbers::pi, 0.0, 0.0});
  FrameAudit edge;
  for (int frame = 1; frame <= 60; ++frame) {
    CameraPose next = meridian.pose();
    next.position.longitudeRadians = r.westRadians;
    next.position.latitudeRadians = r.northRadians - frame * 3e-6;
    ASSERT_TRUE(meridian.propose(next));
    const CollisionState& state = meridian.update(kDt, array, kWgs84);
    EXPECT_EQ(state.motion, MotionKind::Angular);
    EXPECT_EQ(meridian.pose().position.longitudeRadians, r.westRadians) << frame;
    EXPECT_EQ(meridian.pose().position.latitudeRadians, next.position.latitudeRadians) << frame;
    edge.check(meridian.pose(), meridian.settings().nearPlane, array);
  }
  EXPECT_EQ(edge.violations, 0);
  CameraController parallel({corner, std::numbers::pi / 2, 0.0, 0.0});
  ASSERT_TRUE(parallel.setAngularVelocity({0.0, 0.0, 3e-6 / kDt}));
  run(parallel, array, 60, [&](int frame, const CollisionState&) {
    EXPECT_NEAR(parallel.pose().position.latitudeRadians, r.northRadians, 1e-15) << frame;
  });
  // Jumps exactly onto the corner: 0.5 m above is refused, 2 m above accepted.
  CameraController jumper({testing::fujiSummit(6000.0), 0.0, -std::numbers::pi / 2, 0.0});
  geo::Cartographic low = corner;
  low.heightMeters -= 1.5;
  ASSERT_TRUE(jumper.setTargetPose({low, 0.0, 0.0, 0.0}));
  EXPECT_EQ(jumper.update(kDt, array, kWgs84).response, collision::Response::Stopped);
  ASSERT_TRUE(jumper.setTargetPose({corner, 0.0, 0.0, 0.0}));
  EXPECT_EQ(jumper.update(kDt, array, kWgs84).response, collision::Response::None);
  EXPECT_EQ(jumper.pose().position.heightMeters, corner.heightMeters);

  // Exact poles and +-180 deg tile corners of the global array, static and with a small move.
  const auto& globe = testing::globalArray();
  for (const geo::Cartographic at :
       {geo::Cartographic{0.0, std::numbers::pi / 2, 0.0},
        geo::Cartographic{std::numbers::pi, -std::numbers::pi / 2, 0.0},
        geo::Cartographic{-std::numbers::pi, geo::degreesToRadians(67.5), 0.0},
        geo::Cartographic{std::numbers::pi, geo::degreesToRadians(-45.0), 0.0}}) {
    geo::Cartographic c = at;
    c.heightMeters = testing::drawnHeight(globe, c.longitudeRadians, c.latitudeRadians) + 2.0;
    CameraController still({c, 0.0, -1.0, 0.0});
    run(still, globe, 5, [](int, const CollisionState&) {});
    ASSERT_TRUE(still.setVelocity({30.0, -30.0, -30.0}));
    run(still, globe, 30, [](int, const CollisionState&) {});
  }
}

}  // namespace
}  // namespace globe::camera
