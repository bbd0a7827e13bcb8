// Fly mode over a real cliff: the navigator and the collision controller, frame by frame as
// `globe view` runs them, flying level off the east rim of Zion Canyon (SRTM 3", a ~650 m drop
// within ~500 m below Observation Point), then on into the far wall. The clearance under the
// camera leaps (~50 m -> ~650 m in 3 s), the speed does not: it changes by at most x2 per second
// up and /8 per second down, and no frame moves the camera farther than that speed allows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

#include "camera/camera_controller.hpp"
#include "camera/navigator.hpp"
#include "collision/collision_response.hpp"
#include "collision/exact_surface.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/collision/collision_test_support.hpp"

namespace globe::camera {
namespace {

using collision::testing::RealPyramid;

const geo::Ellipsoid& wgs84() {
  static const geo::Ellipsoid ellipsoid = geo::Ellipsoid::wgs84();
  return ellipsoid;
}

bool intersectsCanyon(const geo::TileId& id) {
  const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(id);
  return r.westRadians <= geo::degreesToRadians(-112.90) &&
         r.eastRadians >= geo::degreesToRadians(-112.99) &&
         r.southRadians <= geo::degreesToRadians(37.30) &&
         r.northRadians >= geo::degreesToRadians(37.26);
}

TEST(CliffFlight, SpeedNeverJumpsFlyingOffZionCanyonsRim) {
  RealPyramid& pyramid = RealPyramid::zion();
  const uint32_t finest = pyramid.maxLevel();
  const auto tiles = collision::testing::quadtreeCut(pyramid, [&](const geo::TileId& id) {
    return id.level < 2 || (id.level < finest && intersectsCanyon(id));
  });
  const terrain::RenderingTileArray array = pyramid.array(tiles);
  const auto terrain = [&](double lon, double lat) -> std::optional<double> {
    return testing::drawnHeight(array, lon, lat);
  };

  // Level, heading west, 2,020 m above the ellipsoid: a few tens of metres over the rim.
  const CameraPose start = CameraPose::fromDegrees(-112.936, 37.2797, 2020, 270, 0);
  Navigator navigator(wgs84(), start, 0.785, terrain);
  navigator.setViewport(1280, 720);
  CameraController controller(start);
  navigator.toggleMode();
  navigator.adopt(controller.pose(), controller.update(0, array, wgs84()));  // the first frame
  FlyKeys keys;
  keys.forward = true;
  navigator.setFlyKeys(keys);

  const double dt = 1.0 / 60;
  std::vector<double> clearances, speeds, steps;
  glm::dvec3 previous = cameraFrame(wgs84(), controller.pose()).positionEcefMeters;
  int belowGround = 0;
  for (int frame = 0; frame < 60 * 25; ++frame) {
    if (const auto proposal = navigator.update(dt)) {
      controller.propose(proposal->pose, proposal->kind);
    }
    const CollisionState& state = controller.update(dt, array, wgs84());
    navigator.adopt(controller.pose(), state);
    const glm::dvec3 now = cameraFrame(wgs84(), controller.pose()).positionEcefMeters;
    clearances.push_back(state.clearanceMeters);
    speeds.push_back(navigator.flySpeedMetersPerSecond());
    steps.push_back(glm::distance(now, previous));
    previous = now;
    const geo::Cartographic& p = controller.pose().position;
    if (p.heightMeters < terrain(p.longitudeRadians, p.latitudeRadians).value_or(0)) ++belowGround;
  }
  EXPECT_EQ(belowGround, 0);

  // The flight crossed the cliff: the clearance rose more than tenfold within 3 s.
  double leap = 0;
  for (size_t i = 0; i + 180 < clearances.size(); ++i) {
    leap = std::max(leap, clearances[i + 180] / std::max(clearances[i], 1.0));
  }
  EXPECT_GT(leap, 10.0) << "the path no longer crosses a cliff";
  EXPECT_LT(controller.pose().position.longitudeDegrees(), -112.946);  // over the canyon floor

  // The speed did not: bounded factors per frame, and each step within the speed flown.
  double largestRise = 1, largestFall = 1;
  for (size_t i = 1; i < speeds.size(); ++i) {
    largestRise = std::max(largestRise, speeds[i] / speeds[i - 1]);
    largestFall = std::min(largestFall, speeds[i] / speeds[i - 1]);
    // (Sliding along the far wall adds the contact skin's re-raise, up to a centimetre.)
    EXPECT_LE(steps[i], speeds[i] * dt * 1.001 + 2 * collision::kContactSkinMeters)
        << "frame " << i;
  }
  EXPECT_LE(largestRise, std::pow(2.0, dt) + 1e-9);
  EXPECT_GE(largestFall, std::pow(8.0, -dt) - 1e-9);
  RecordProperty("clearance_leap", std::to_string(leap));
}

}  // namespace
}  // namespace globe::camera
