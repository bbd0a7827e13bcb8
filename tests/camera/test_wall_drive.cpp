// A camera driven at a real canyon wall (Zion Canyon's east wall below Observation Point, SRTM 3":
// ~270 m of rock in ~90 m, ~70 deg) from 16 directions at 1 m to 1 km a frame. Every frame the view
// between the eye and the near plane is checked with an oracle written apart from the collision
// code: rays from the eye to a 5 x 5 grid over the near-plane rectangle, each sampled at four
// points against the brute-force mesh ray cast (tests/collision/mesh_ray_cast). None may be
// below the drawn surface: the user never sees inside the terrain. The same drive without the
// lateral clearance (collision/lateral_clearance.hpp) is printed beside it: on these 3" walls
// (<= ~72 deg) the near plane's corners kept 0.5 m above the surface already keep it out; the
// ball matters on sharper relief (tests/collision/test_lateral_clearance.cpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "camera/camera_controller.hpp"
#include "collision/lateral_clearance.hpp"
#include "geo/ecef.hpp"
#include "geo/tiling_scheme.hpp"
#include "tests/camera/controller_test_support.hpp"
#include "tests/collision/collision_test_support.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using collision::testing::RealPyramid;
using globe::test::kDt;
constexpr int kFrames = 40;
using globe::test::kWgs84;

const terrain::RenderingTileArray& canyonArray() {
  static const terrain::RenderingTileArray array = [] {
    RealPyramid& pyramid = RealPyramid::zion();
    const uint32_t finest = pyramid.maxLevel();
    const auto tiles = collision::testing::quadtreeCut(pyramid, [&](const geo::TileId& id) {
      const geo::GlobeRectangle r = geo::GeographicTilingScheme::tileRectangle(id);
      const bool canyon = r.westRadians <= geo::degreesToRadians(-112.92) &&
                          r.eastRadians >= geo::degreesToRadians(-112.97) &&
                          r.southRadians <= geo::degreesToRadians(37.30) &&
                          r.northRadians >= geo::degreesToRadians(37.26);
      return id.level < 2 || (id.level < finest && canyon);
    });
    return pyramid.array(tiles);
  }();
  return array;
}

struct Totals {
  int frames = 0, inside = 0, pushed = 0;
  double deepestMeters = -INFINITY;
};

void driveAtTheWall(const ControllerSettings& settings, double bearing, double step,
                    Totals& totals) {
  const terrain::RenderingTileArray& array = canyonArray();
  // The target: half way up the wall.
  geo::Cartographic target = geo::Cartographic::fromDegrees(-112.9425, 37.2797, 0.0);
  target.heightMeters =
      testing::drawnHeight(array, target.longitudeRadians, target.latitudeRadians) + 1.0;
  const double distance = std::clamp(step * 15.0, 150.0, 3000.0);
  geo::Cartographic start = testing::offsetPosition(target, bearing, distance, 0.0);
  start.heightMeters =
      std::max(target.heightMeters,
               testing::drawnHeight(array, start.longitudeRadians, start.latitudeRadians) + 3.0);
  const glm::dvec3 from = geo::cartographicToEcef(kWgs84, start);
  const glm::dvec3 to = geo::cartographicToEcef(kWgs84, target);
  const glm::dvec3 way = glm::normalize(to - from);
  const EastNorthUp enu = eastNorthUp(kWgs84, start);
  const double heading = std::atan2(glm::dot(way, enu.east), glm::dot(way, enu.north));
  const double pitch = std::asin(std::clamp(glm::dot(way, enu.up), -1.0, 1.0));
  CameraController controller({start, heading, pitch, 0.0}, settings);
  ASSERT_TRUE(controller.setVelocity(way * (step / kDt)));
  for (int frame = 0; frame < kFrames; ++frame) {
    const CollisionState& state = controller.update(kDt, array, kWgs84);
    ASSERT_FALSE(state.inputRejected);
    const double deepest = testing::deepestInsideView(controller.pose(), settings.nearPlane, array);
    ++totals.frames;
    totals.inside += deepest > 0.0;
    totals.pushed += state.nearPlanePushed;
    totals.deepestMeters = std::max(totals.deepestMeters, deepest);
  }
}

Totals driveAll(const ControllerSettings& settings) {
  Totals totals;
  for (const double step : {1.0, 10.0, 100.0, 1000.0}) {
    for (int k = 0; k < 16; ++k) {
      driveAtTheWall(settings, 2 * std::numbers::pi * k / 16, step, totals);
      if (::testing::Test::HasFatalFailure()) return totals;
    }
  }
  return totals;
}

TEST(WallDrive, NoFrameSeesInsideTheTerrain) {
  const ControllerSettings settings;
  const Totals with = driveAll(settings);
  ControllerSettings without = settings;
  without.lateralCheck = false;
  const Totals control = driveAll(without);
  std::printf(
      "with the lateral clearance: %d frames, %d see inside (deepest %.3f m), %d pushed\n"
      "without it:                 %d frames, %d see inside (deepest %.3f m)\n",
      with.frames, with.inside, with.deepestMeters, with.pushed, control.frames, control.inside,
      control.deepestMeters);
  EXPECT_EQ(with.inside, 0);
  // The view comes within a metre of the rock (its near plane's corners kept 0.5 m above it).
  EXPECT_GT(with.deepestMeters, -1.0) << "the drive no longer comes near the wall";
}

}  // namespace
}  // namespace globe::camera

namespace globe::camera {
namespace {

// A needle: one vertex 1 km above its neighbours 76 m away (~86 deg faces, sharp edges between
// them). Eyes placed all around it, 2 m above the ground under them, looking at it: with the
// near plane's corners alone (kept 0.5 m above the surface under them) some views reach into
// the needle between the corners; with the lateral clearance none does.
TEST(WallDrive, BesideANeedleTheCornersAloneLetTheViewIntoIt) {
  using Scheme = geo::GeographicTilingScheme;
  constexpr uint32_t kLevel = 14;
  const geo::TileId centre =
      *Scheme::positionToTile(geo::degreesToRadians(10.0), geo::degreesToRadians(45.0), kLevel);
  std::vector<geo::TileId> tiles;
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      tiles.push_back({kLevel, static_cast<uint32_t>(static_cast<int>(centre.x) + dx),
                       static_cast<uint32_t>(static_cast<int>(centre.y) + dy)});
    }
  }
  const terrain::HeightBlock block = collision::testing::makeBlock(
      17, [](uint32_t i, uint32_t j) -> int16_t { return i == 8 && j == 8 ? 2000 : 1000; });
  const terrain::RenderingTileArray array = collision::testing::arrayOf(tiles, block);
  const geo::Cartographic apex{collision::testing::gridLongitude(centre, 17, 8),
                               collision::testing::gridLatitude(centre, 17, 8), 2000.0};
  ControllerSettings with;
  ControllerSettings without = with;
  without.lateralCheck = false;
  int views = 0, insideWith = 0, insideWithout = 0;
  double deepestWith = -INFINITY, deepestWithout = -INFINITY;
  for (double distance = 2.0; distance <= 60.0; distance += 2.0) {
    for (int k = 0; k < 24; ++k) {
      const double bearing = 2 * std::numbers::pi * k / 24;
      geo::Cartographic at = testing::offsetPosition(apex, bearing, distance, 0.0);
      at.heightMeters = testing::drawnHeight(array, at.longitudeRadians, at.latitudeRadians) + 2.0;
      for (const double pitchDegrees : {0.0, -20.0, 20.0}) {
        const CameraPose pose{at, bearing + std::numbers::pi, geo::degreesToRadians(pitchDegrees),
                              0.0};
        CameraController a(pose, with), b(pose, without);
        a.update(kDt, array, kWgs84);
        b.update(kDt, array, kWgs84);
        const double inA = testing::deepestInsideView(a.pose(), with.nearPlane, array);
        const double inB = testing::deepestInsideView(b.pose(), without.nearPlane, array);
        ++views;
        insideWith += inA > 0;
        insideWithout += inB > 0;
        deepestWith = std::max(deepestWith, inA);
        deepestWithout = std::max(deepestWithout, inB);
      }
    }
  }
  std::printf(
      "needle: %d views; inside with the lateral clearance %d (deepest %.3f m), "
      "without %d (deepest %.3f m)\n",
      views, insideWith, deepestWith, insideWithout, deepestWithout);
  EXPECT_EQ(insideWith, 0);
  EXPECT_GT(insideWithout, 0);
}

}  // namespace
}  // namespace globe::camera

namespace globe::camera {
namespace {

// Flight across Angels Landing (a fin ~140 m above the canyon floor on both sides), from the
// west and from the east, level and 20 deg down, from 20 m above the floor, at 1 m to 100 km a
// frame: the camera slides up and over and makes at least a tenth of its step along its heading
// every frame (the slide costs the part into the rock; a stall would be ~0).
TEST(RidgeSlide, KeepsMovingEveryFrameAtEverySpeed) {
  const terrain::RenderingTileArray& array = canyonArray();
  const geo::Cartographic ridge = geo::Cartographic::fromDegrees(-112.9485, 37.2692, 0.0);
  int frames = 0, slid = 0;
  double smallest = INFINITY;
  for (const double heading : {0.5 * std::numbers::pi, 1.5 * std::numbers::pi}) {
    for (const double pitch : {0.0, geo::degreesToRadians(-20.0)}) {
      for (const double step : {1.0, 10.0, 100.0, 1000.0, 10000.0, 100000.0}) {
        geo::Cartographic start = testing::offsetPosition(ridge, heading + std::numbers::pi,
                                                          std::clamp(3 * step, 150.0, 3000.0), 0.0);
        start.heightMeters =
            testing::drawnHeight(array, start.longitudeRadians, start.latitudeRadians) + 20.0;
        CameraController controller({start, heading, pitch, 0.0});
        ASSERT_TRUE(
            controller.setVelocity(testing::direction(start, heading, pitch) * (step / kDt)));
        for (int frame = 0; frame < 30; ++frame) {
          const glm::dvec3 before = geo::cartographicToEcef(kWgs84, controller.pose().position);
          const CollisionState& state = controller.update(kDt, array, kWgs84);
          const glm::dvec3 after = geo::cartographicToEcef(kWgs84, controller.pose().position);
          const EastNorthUp enu = eastNorthUp(kWgs84, controller.pose().position);
          const double along = glm::dot(
              after - before, std::sin(heading) * enu.east + std::cos(heading) * enu.north);
          EXPECT_GE(along, 0.1 * step) << "heading " << heading << " pitch " << pitch << " step "
                                       << step << " frame " << frame;
          smallest = std::min(smallest, along / step);
          ++frames;
          slid += state.response == collision::Response::Slid;
        }
      }
    }
  }
  std::printf("ridge slide: %d frames, %d slid, smallest move along the heading %.3f of the step\n",
              frames, slid, smallest);
  EXPECT_GT(slid, frames / 4);
}

}  // namespace
}  // namespace globe::camera

namespace globe::camera {
namespace {

// A script flown level into the canyon's east wall from 40 m above the floor, as globe play flies
// it (an absolute pose a frame, the next 3 s of the script as the look-ahead). The paper's
// response alone slides up the rock a hand's width from it (the screen one colour); the glide
// reads the wall ahead and rises over the rim first, without falling behind the script.
struct WallFlight {
  double nearestMeters = INFINITY;  // the eye's nearest approach to any drawn triangle
  double lowestEyeMeters = INFINITY;
  double largestLagMeters = 0.0;  // horizontal distance from the script's position
};

geo::Cartographic scripted(const geo::Cartographic& start, double speed, double seconds) {
  return testing::offsetPosition(start, 0.5 * std::numbers::pi, speed * seconds,
                                 start.heightMeters);
}

WallFlight flyIntoTheWall(bool glide, double speed) {
  const terrain::RenderingTileArray& array = canyonArray();
  const geo::Cartographic wall = geo::Cartographic::fromDegrees(-112.9425, 37.2797, 0.0);
  geo::Cartographic start = testing::offsetPosition(wall, 1.5 * std::numbers::pi, 500.0, 0.0);
  start.heightMeters =
      testing::drawnHeight(array, start.longitudeRadians, start.latitudeRadians) + 40.0;
  ControllerSettings settings;
  settings.glide.enabled = glide;
  CameraController controller({start, 0.5 * std::numbers::pi, 0.0, 0.0}, settings);
  WallFlight flight;
  const int frames = static_cast<int>(2000.0 / speed / kDt);
  for (int frame = 1; frame <= frames; ++frame) {
    const double t = frame * kDt;
    std::vector<GlidePoint> ahead;
    for (int k = 1; k <= 24; ++k)
      ahead.push_back({scripted(start, speed, t + k * 0.125), k * 0.125});
    const CameraPose pose{scripted(start, speed, t), 0.5 * std::numbers::pi, 0.0, 0.0};
    EXPECT_TRUE(controller.propose(pose, MotionKind::Linear, ahead));
    const CollisionState& state = controller.update(kDt, array, kWgs84);
    const glm::dvec3 eye = geo::cartographicToEcef(kWgs84, controller.pose().position);
    const auto nearest = collision::nearestDrawnTriangle(array, kWgs84, eye, 300.0);
    flight.nearestMeters =
        std::min(flight.nearestMeters, nearest ? nearest->distanceMeters : 300.0);
    flight.lowestEyeMeters = std::min(flight.lowestEyeMeters, state.clearanceMeters);
    geo::Cartographic level = controller.pose().position;
    level.heightMeters = pose.position.heightMeters;
    flight.largestLagMeters = std::max(flight.largestLagMeters,
                                       glm::length(geo::cartographicToEcef(kWgs84, level) -
                                                   geo::cartographicToEcef(kWgs84, pose.position)));
  }
  return flight;
}

TEST(WallGlide, AScriptIntoTheCanyonWallRisesOverTheRimInsteadOfHuggingIt) {
  for (const double speed : {30.0, 100.0, 250.0}) {
    const WallFlight alone = flyIntoTheWall(false, speed);
    const WallFlight glide = flyIntoTheWall(true, speed);
    std::printf(
        "wall at %.0f m/s: nearest approach %.2f m alone, %.2f m gliding; lowest eye %.2f / "
        "%.2f m; largest lag behind the script %.1f / %.1f m\n",
        speed, alone.nearestMeters, glide.nearestMeters, alone.lowestEyeMeters,
        glide.lowestEyeMeters, alone.largestLagMeters, glide.largestLagMeters);
    EXPECT_LT(alone.nearestMeters, 2.0) << speed;  // the failure: scraping the rock
    EXPECT_GT(glide.nearestMeters, 10.0) << speed;
    EXPECT_GE(glide.lowestEyeMeters, 2.0) << speed;
    EXPECT_LT(glide.largestLagMeters, 1.0) << speed;  // over the rim with the script, not stuck
  }
}

}  // namespace
}  // namespace globe::camera
