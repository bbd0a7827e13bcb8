// Fly-mode maths (WASD in the ENU frame, speed from the clearance, look), the fly-to pick and
// animation, the path recorder and its JSON, and the HUD's text: all pure, no window.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "apps/globe/hud_text.hpp"
#include "formats/pyramid_manifest.hpp"
#include "apps/globe/path_recorder.hpp"
#include "camera/fly_controls.hpp"
#include "camera/fly_to.hpp"
#include "geo/ecef.hpp"
#include "render/hud_renderer.hpp"
#include "tests/support/test_constants.hpp"

namespace {

using globe::app::HudState;
using ViewMode = globe::camera::NavigationMode;
using globe::camera::CameraPose;
using globe::camera::FlyKeys;
using globe::camera::SpeedSteps;
using globe::geo::degreesToRadians;
using globe::geo::radiansToDegrees;

using globe::test::kWgs84;

FlyKeys keys(const std::string& held) {
  FlyKeys k;
  for (char c : held) {
    switch (c) {
      case 'w':
        k.forward = true;
        break;
      case 's':
        k.back = true;
        break;
      case 'a':
        k.left = true;
        break;
      case 'd':
        k.right = true;
        break;
      case 'q':
        k.down = true;
        break;
      case 'e':
        k.up = true;
        break;
      case 'S':
        k.fast = true;
        break;
      default:
        break;
    }
  }
  return k;
}

void expectNear(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(FlyControls, WasdMovesInTheEastNorthUpFrameOfTheHeading) {
  using globe::camera::flyDirectionEnu;
  // Heading 0 (north), level: W north, S south, D east, A west, E up, Q down.
  expectNear(flyDirectionEnu(keys("w"), 0, 0), {0, 1, 0});
  expectNear(flyDirectionEnu(keys("s"), 0, 0), {0, -1, 0});
  expectNear(flyDirectionEnu(keys("d"), 0, 0), {1, 0, 0});
  expectNear(flyDirectionEnu(keys("a"), 0, 0), {-1, 0, 0});
  expectNear(flyDirectionEnu(keys("e"), 0, 0), {0, 0, 1});
  expectNear(flyDirectionEnu(keys("q"), 0, 0), {0, 0, -1});
  // Heading east: W east, D south. Heading 225 (south-west): W south-west, D north-west.
  expectNear(flyDirectionEnu(keys("w"), std::numbers::pi / 2, 0), {1, 0, 0});
  expectNear(flyDirectionEnu(keys("d"), std::numbers::pi / 2, 0), {0, -1, 0});
  const double h = std::sqrt(0.5);
  expectNear(flyDirectionEnu(keys("w"), degreesToRadians(225), 0), {-h, -h, 0});
  expectNear(flyDirectionEnu(keys("d"), degreesToRadians(225), 0), {-h, h, 0});
  // Pitched down 30 deg: W follows the view down, A/D stay level, E/Q stay vertical.
  const double p = degreesToRadians(-30);
  expectNear(flyDirectionEnu(keys("w"), 0, p), {0, std::cos(p), std::sin(p)});
  expectNear(flyDirectionEnu(keys("d"), 0, p), {1, 0, 0});
  expectNear(flyDirectionEnu(keys("e"), 0, p), {0, 0, 1});
  // Straight down: W descends; combinations are normalised; opposite keys cancel.
  expectNear(flyDirectionEnu(keys("w"), 1.0, -std::numbers::pi / 2), {0, 0, -1});
  expectNear(flyDirectionEnu(keys("wd"), 0, 0), {h, h, 0});
  expectNear(flyDirectionEnu(keys("ws"), 0, 0), {0, 0, 0});
  EXPECT_FALSE(keys("ws").moving());
  EXPECT_FALSE(keys("S").moving());
  EXPECT_TRUE(keys("wq").moving());
}

// Across a cliff edge (the 32 m -> 1,845 m clearance in a few frames, and back), at
// 60 frames per second the speed changes by at most x2 per second up and /8 per second down:
// never by more than 2^(1/60) = 1.16 % up or 3.5 % down from one frame to the next.
TEST(FlyControls, SpeedNeverJumpsAcrossACliffEdge) {
  using globe::camera::SmoothedClearance;
  SmoothedClearance smoothed;
  const double dt = 1.0 / 60;
  double previous = smoothed.update(32, dt);
  EXPECT_EQ(previous, 32);
  double largestRise = 1, largestFall = 1;
  for (int frame = 1; frame < 600; ++frame) {
    const double measured = frame < 10 || frame > 400 ? 32.0 : 1845.0;
    const double now = smoothed.update(measured, dt);
    ASSERT_TRUE(std::isfinite(now));
    largestRise = std::max(largestRise, now / previous);
    largestFall = std::min(largestFall, now / previous);
    if (frame == 399) {
      EXPECT_NEAR(now, 1845, 1e-9);  // there after ~6 s
    }
    previous = now;
  }
  EXPECT_LE(largestRise, std::pow(2.0, dt) + 1e-12);
  EXPECT_GE(largestFall, std::pow(8.0, -dt) - 1e-12);
  EXPECT_NEAR(previous, 32, 1e-9);  // and back down within ~2 s
  EXPECT_EQ(smoothed.update(std::nan(""), dt), std::max(previous / std::pow(8.0, dt), 1.0));
}

// The HUD names the ground under the pointer, and no cursor line without it; the scale bar is
// the longest round length that fits.
TEST(FlyControls, HudShowsTheGroundUnderThePointerAndAScale) {
  HudState hud;
  auto lines = globe::app::hudStatusLines(hud, false);
  for (const std::string& line : lines) EXPECT_EQ(line.find("cursor"), std::string::npos) << line;
  hud.underCursor = globe::geo::Cartographic::fromDegrees(138.7275, 35.3606, 3731.2);
  lines = globe::app::hudStatusLines(hud, false);
  const std::string all = [&] {
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
  }();
  EXPECT_NE(all.find("cursor lon 138.72750  lat 35.36060  ground 3731.2 m"), std::string::npos)
      << all;
  using globe::app::scaleBarLength;
  const auto bar = scaleBarLength(23.5, 100);  // 2,350 m fit: 2 km
  ASSERT_TRUE(bar);
  EXPECT_EQ(bar->label, "2 km");
  EXPECT_NEAR(bar->pixels, 2000 / 23.5, 1e-9);
  EXPECT_EQ(scaleBarLength(0.5, 100)->label, "50 m");
  EXPECT_EQ(scaleBarLength(0.5, 100)->pixels, 100);  // exactly fits
  EXPECT_EQ(scaleBarLength(51, 200)->label, "10 km");
  EXPECT_EQ(scaleBarLength(1e5, 200)->label, "20000 km");
  EXPECT_EQ(scaleBarLength(0.004, 100)->label, "0.2 m");
  for (double metersPerPixel : {0.0031, 0.7, 3.3, 42.0, 999.0, 12345.0}) {
    const auto b = scaleBarLength(metersPerPixel, 150);
    ASSERT_TRUE(b);
    EXPECT_LE(b->pixels, 150 + 1e-9);
    EXPECT_GT(b->pixels, 150 / 2.5 - 1e-9);  // 1-2-5 steps: never less than 2/5 of the room
  }
  EXPECT_FALSE(scaleBarLength(std::nan(""), 100));
  EXPECT_FALSE(scaleBarLength(0, 100));
  EXPECT_FALSE(scaleBarLength(10, 0));
}

// The speed factor steps in powers of two, stops at x1/8 and x64, and comes back exactly to x1.
TEST(FlyControls, SpeedStepsAreCleanAndReturnExactlyToOne) {
  SpeedSteps speed;
  EXPECT_EQ(speed.factor(), 1.0);
  for (int i = 0; i < 20; ++i) speed.change(1);  // far past the top
  EXPECT_EQ(speed.factor(), 64.0);
  for (int i = 0; i < 6; ++i) speed.change(-1);
  EXPECT_EQ(speed.factor(), 1.0);
  speed.change(-100);
  EXPECT_EQ(speed.factor(), 0.125);
  speed.change(3);
  EXPECT_EQ(speed.factor(), 1.0);
  speed.change(0.4);  // a touchpad's part-notches add up to one step
  EXPECT_EQ(speed.factor(), 1.0);
  speed.change(0.6);
  EXPECT_EQ(speed.factor(), 2.0);
  speed.change(std::nan(""));
  EXPECT_EQ(speed.factor(), 2.0);
  HudState hud;
  hud.mode = ViewMode::Fly;
  hud.speedFactor = 0.125;
  EXPECT_NE(globe::app::hudStatusLines(hud, false)[0].find("(x1/8)"), std::string::npos);
  hud.speedFactor = 64;
  EXPECT_NE(globe::app::hudStatusLines(hud, false)[0].find("(x64)"), std::string::npos);
}

TEST(FlyControls, SpeedScalesWithTheClearanceWithAFloorAndShift) {
  using globe::camera::flySpeedMetersPerSecond;
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(0.5, false), 2.0);  // the 2 m/s floor
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(-10, false), 2.0);
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(2, false), 2.0);
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(150, false), 150.0);  // one clearance a second
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(150, true), 750.0);   // Shift x5
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(1, true), 10.0);
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(150, false, 0.5), 75.0);  // the scroll factor
  EXPECT_DOUBLE_EQ(flySpeedMetersPerSecond(std::nan(""), false), 2.0);
}

TEST(FlyControls, VelocityIsEcefAlongTheViewAndAStepMovesThere) {
  const CameraPose pose = CameraPose::fromDegrees(138.7, 35.3, 5000, 0, 0);
  const glm::dvec3 v = globe::camera::flyVelocityEcef(kWgs84, pose, keys("w"), 1000);
  EXPECT_NEAR(glm::length(v), 1000, 1e-9);
  const auto enu = globe::camera::eastNorthUp(kWgs84, pose.position);
  EXPECT_NEAR(glm::dot(v, enu.north), 1000, 1e-9);
  // Half a second north at 1 km/s: 500 m, latitude up, longitude the same.
  const CameraPose next = globe::camera::flyStep(kWgs84, pose, v, 0.5);
  const double moved = glm::length(globe::geo::cartographicToEcef(kWgs84, next.position) -
                                   globe::geo::cartographicToEcef(kWgs84, pose.position));
  EXPECT_NEAR(moved, 500, 1e-6);
  EXPECT_GT(next.position.latitudeRadians, pose.position.latitudeRadians);
  EXPECT_NEAR(next.position.longitudeDegrees(), 138.7, 1e-9);
  EXPECT_DOUBLE_EQ(next.headingRadians, pose.headingRadians);
  EXPECT_EQ(globe::camera::flyStep(kWgs84, pose, glm::dvec3(0.0), 0.5).position.heightMeters, 5000);
}

TEST(FlyControls, LookTurnsAndClampsThePitch) {
  const CameraPose pose = CameraPose::fromDegrees(0, 0, 100, 350, 0);
  const CameraPose right = globe::camera::lookByPixels(pose, 100, 0);  // drag right: turn right
  EXPECT_NEAR(radiansToDegrees(right.headingRadians), 350 + radiansToDegrees(0.3) - 360, 1e-9);
  const CameraPose up = globe::camera::lookByPixels(pose, 0, -100);  // drag up: look up
  EXPECT_NEAR(up.pitchRadians, 0.3, 1e-12);
  EXPECT_NEAR(radiansToDegrees(globe::camera::lookByPixels(pose, 0, 1e6).pitchRadians), -89, 1e-9);
  EXPECT_NEAR(radiansToDegrees(globe::camera::lookByRadians(pose, 0, 10).pitchRadians), 89, 1e-9);
}

TEST(FlyTo, ThePixelRayHitsTheTerrainUnderIt) {
  // 10 km above a flat plateau 1,000 m high, looking straight down: the centre pixel hits
  // the plateau right below, 9,000 m away.
  const CameraPose pose = CameraPose::fromDegrees(10, 45, 10000, 0, -90);
  const auto frame = globe::camera::cameraFrame(kWgs84, pose);
  const glm::dvec3 ray =
      globe::camera::pixelRayEcef(frame, 320, 180, 640, 360, std::numbers::pi / 4);
  expectNear(ray, frame.forward, 1e-12);
  const auto plateau = [](double, double) -> std::optional<double> { return 1000.0; };
  const auto hit = globe::camera::intersectTerrain(kWgs84, frame.positionEcefMeters, ray, plateau);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(glm::length(*hit - frame.positionEcefMeters), 9000, 0.05);
  const auto point = globe::geo::ecefToCartographic(kWgs84, *hit);
  EXPECT_NEAR(point->heightMeters, 1000, 0.05);
  // The top edge's centre pixel looks 22.5 deg forward (north) of straight down.
  const glm::dvec3 top = globe::camera::pixelRayEcef(frame, 320, 0, 640, 360, std::numbers::pi / 4);
  EXPECT_NEAR(std::acos(glm::dot(top, frame.forward)), std::numbers::pi / 8, 1e-9);
  const auto north =
      globe::camera::intersectTerrain(kWgs84, frame.positionEcefMeters, top, plateau);
  ASSERT_TRUE(north);
  EXPECT_GT(globe::geo::ecefToCartographic(kWgs84, *north)->latitudeDegrees(), 45);
  // Looking up at the sky misses.
  const CameraPose sky = CameraPose::fromDegrees(10, 45, 10000, 0, 30);
  const auto skyFrame = globe::camera::cameraFrame(kWgs84, sky);
  EXPECT_FALSE(globe::camera::intersectTerrain(kWgs84, skyFrame.positionEcefMeters,
                                               skyFrame.forward, plateau));
}

TEST(FlyTo, EndsLookingAtTheTargetAndAnimatesSmoothly) {
  const CameraPose from = CameraPose::fromDegrees(138.0, 35.0, 50000, 30, -60);
  const glm::dvec3 target = globe::geo::cartographicToEcef(
      kWgs84, globe::geo::Cartographic::fromDegrees(138.5, 35.5, 800));
  const CameraPose end = globe::camera::flyToEndPose(kWgs84, from, target);
  const auto frame = globe::camera::cameraFrame(kWgs84, end);
  const glm::dvec3 toTarget = target - frame.positionEcefMeters;
  // The target is at the centre of the view, 0.3 of the way's length away.
  EXPECT_NEAR(glm::dot(glm::normalize(toTarget), frame.forward), 1.0, 1e-12);
  const double way = glm::length(target - globe::geo::cartographicToEcef(kWgs84, from.position));
  EXPECT_NEAR(glm::length(toTarget), 0.3 * way, 1e-3);
  EXPECT_NEAR(radiansToDegrees(end.pitchRadians), -60, 0.5);
  globe::camera::FlyToAnimation animation(kWgs84, from, end, 1.0);
  const CameraPose begin = animation.poseAt(0), middle = animation.poseAt(0.5);
  EXPECT_DOUBLE_EQ(begin.position.heightMeters, from.position.heightMeters);
  EXPECT_GT(middle.position.longitudeDegrees(), 138.0);
  EXPECT_LT(middle.position.longitudeDegrees(), end.position.longitudeDegrees());
  EXPECT_TRUE(animation.finishedAt(1.0));
  EXPECT_FALSE(animation.finishedAt(0.99));
  EXPECT_DOUBLE_EQ(animation.poseAt(1.0).position.heightMeters, end.position.heightMeters);
  // Looking straight down the fly ends straight above the target, the heading kept.
  const CameraPose down = CameraPose::fromDegrees(138.0, 35.0, 50000, 30, -90);
  const CameraPose above = globe::camera::flyToEndPose(kWgs84, down, target);
  EXPECT_NEAR(radiansToDegrees(above.headingRadians), 30, 1e-6);
  EXPECT_NEAR(radiansToDegrees(above.pitchRadians), -90, 1e-6);
  EXPECT_NEAR(above.position.longitudeDegrees(), 138.5, 1e-9);
  EXPECT_NEAR(above.position.latitudeDegrees(), 35.5, 1e-9);
  // Across the antimeridian the short way round.
  const CameraPose west = CameraPose::fromDegrees(179.5, 0, 1e5),
                   east = CameraPose::fromDegrees(-179.5, 0, 1e5);
  const double lon = globe::camera::FlyToAnimation(kWgs84, west, east, 1.0)
                         .poseAt(0.5)
                         .position.longitudeDegrees();
  EXPECT_NEAR(std::abs(lon), 180, 1e-6);
}

TEST(PathRecorder, KeyframesEveryHalfSecondOfMotionAtStopsAndAtTheEnd) {
  globe::app::PathRecorder recorder;
  CameraPose pose = CameraPose::fromDegrees(138, 35, 3000, 0, -10);
  recorder.start(100.0, pose);
  EXPECT_TRUE(recorder.recording());
  // Moving north for 1.2 s at 50 frames a second, then standing still.
  double t = 100.0;
  for (int frame = 1; frame <= 60; ++frame) {
    t = 100.0 + frame * 0.02;
    pose.position.latitudeRadians += 1e-6;
    recorder.sample(t, pose);
  }
  recorder.sample(t + 0.02, pose);  // a stop
  const auto keyframes = recorder.stop(105.0, pose);
  EXPECT_FALSE(recorder.recording());
  // 0, 0.5, 1.0, the stop at 1.22, the end at 5.0.
  ASSERT_EQ(keyframes.size(), 5u);
  EXPECT_DOUBLE_EQ(keyframes[0].tSeconds, 0.0);
  EXPECT_NEAR(keyframes[1].tSeconds, 0.5, 1e-9);
  EXPECT_NEAR(keyframes[2].tSeconds, 1.0, 1e-9);
  EXPECT_NEAR(keyframes[3].tSeconds, 1.22, 1e-9);
  EXPECT_NEAR(keyframes[4].tSeconds, 5.0, 1e-9);
  for (size_t k = 1; k < keyframes.size(); ++k)
    EXPECT_GT(keyframes[k].tSeconds, keyframes[k - 1].tSeconds);

  // Written as `globe view` writes it: io::writeCameraPathJson of the recorded path.
  const auto file = std::filesystem::temp_directory_path() / "globe-recorded-path.json";
  ASSERT_TRUE(
      globe::camera::writeCameraPathJson(file, globe::app::recordedPathFile(keyframes)).ok());
  const auto json = nlohmann::json::parse(std::ifstream(file));
  std::filesystem::remove(file);
  EXPECT_EQ(json.at("interpolation"), "smooth");
  ASSERT_EQ(json.at("keyframes").size(), 5u);
  const auto& first = json.at("keyframes")[0];
  EXPECT_DOUBLE_EQ(first.at("t").get<double>(), 0.0);
  EXPECT_NEAR(first.at("lon").get<double>(), 138, 1e-8);
  EXPECT_NEAR(first.at("lat").get<double>(), 35, 1e-8);
  EXPECT_NEAR(first.at("height").get<double>(), 3000, 1e-3);
  EXPECT_NEAR(first.at("heading").get<double>(), 0, 1e-4);
  EXPECT_NEAR(first.at("pitch").get<double>(), -10, 1e-4);
  EXPECT_NEAR(first.at("roll").get<double>(), 0, 1e-4);
}

TEST(PathRecorder, APauseIsKeptWhenTheMotionResumes) {
  globe::app::PathRecorder recorder;
  CameraPose pose = CameraPose::fromDegrees(0, 0, 100);
  recorder.start(0.0, pose);
  pose.headingRadians = 0.1;
  recorder.sample(0.05, pose);  // a drag's last event; the loop then idles (no stop seen)
  pose.headingRadians = 0.2;
  recorder.sample(3.0, pose);  // the next drag, 3 s later
  const auto keyframes = recorder.stop(3.05, pose);
  // 0, the pose at 0.05 held until 2.9, then moving again.
  ASSERT_GE(keyframes.size(), 4u);
  EXPECT_NEAR(keyframes[1].tSeconds, 0.05, 1e-9);
  EXPECT_NEAR(keyframes[2].tSeconds, 2.9, 1e-9);
  EXPECT_DOUBLE_EQ(keyframes[2].pose.headingRadians, 0.1);
}

TEST(PathRecorder, FileNamesCarryTheTimeAndNeverOverwrite) {
  const auto dir = std::filesystem::temp_directory_path() / "globe-path-names";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto first = globe::app::timestampedPath(dir, "globe-path", ".json");
  EXPECT_EQ(first.parent_path(), dir);
  const std::string name = first.filename().string();
  ASSERT_EQ(name.size(), std::string("globe-path-YYYYMMDD-HHMMSS.json").size()) << name;
  EXPECT_EQ(name.substr(0, 11), "globe-path-");
  std::ofstream(first) << "{}";
  const auto second = globe::app::timestampedPath(dir, "globe-path", ".json");
  EXPECT_NE(second, first);
  std::filesystem::remove_all(dir);
}

// Where only the 20' base exists the HUD says so, and says what finer data is where it is.
TEST(HudText, TheTerrainsDataAndItsSpacingAreSaid) {
  EXPECT_EQ(globe::app::spacingText(1.0 / 3), "20' (~37 km)");
  EXPECT_EQ(globe::app::spacingText(3.0 / 3600), "3\" (~93 m)");
  EXPECT_EQ(globe::app::spacingText(0.5), "30' (~56 km)");
  EXPECT_EQ(globe::app::spacingText(2.0), "2 deg (~222 km)");
  EXPECT_EQ(globe::app::spacingText(1.0 / 120), "30\" (~927 m)");
  globe::formats::PyramidManifest manifest;
  manifest.sources.push_back({"data/dem/ETOPO20.DEM", "GTOPO30", 1080, 540, 1.0 / 3,
                              {-180, -90, 180, 90}, 6, {}, std::nullopt});
  manifest.sources.push_back({"data/dem/E138N35_FUJI.DEM", "GTOPO30", 1201, 1201, 3.0 / 3600,
                              {138.0, 35.0, 139.0, 36.0}, 13, {}, std::nullopt});
  const auto* fuji = globe::formats::finestSourceAt(manifest, 138.73, 35.36);
  ASSERT_NE(fuji, nullptr);
  EXPECT_EQ(fuji->path, "data/dem/E138N35_FUJI.DEM");
  EXPECT_EQ(globe::formats::finestSourceAt(manifest, 2.35, 48.85)->path, "data/dem/ETOPO20.DEM")
      << "Paris: the base alone";
  EXPECT_EQ(globe::formats::finestSourceAt(manifest, 138.73 - 360, 35.36), fuji) << "a turn west";
  manifest.sources.erase(manifest.sources.begin());
  EXPECT_EQ(globe::formats::finestSourceAt(manifest, 2.35, 48.85), nullptr);
  globe::app::HudState state;
  state.terrainData = "ETOPO20.DEM, " + globe::app::spacingText(1.0 / 3);
  bool said = false;
  for (const std::string& line : globe::app::hudStatusLines(state)) {
    said = said || line == "terrain data: ETOPO20.DEM, 20' (~37 km)";
  }
  EXPECT_TRUE(said);
}

TEST(HudText, StatusShowsPositionTerrainCollisionTilesAndMode) {
  globe::app::HudState state;
  state.mode = globe::camera::NavigationMode::Fly;
  state.pose = CameraPose::fromDegrees(138.72751, 35.36063, 3800.5, 90, -12.25);
  state.collision.terrainFound = true;
  state.collision.terrainHeightMeters = 3731.24;
  state.collision.clearanceMeters = 69.26;
  state.collision.collided = true;
  state.collision.response = globe::collision::Response::Slid;
  state.tilesDrawn = 123;
  state.tilesLoading = 4;
  state.frameMilliseconds = 20;
  state.flySpeedMetersPerSecond = 69.26;
  state.recording = true;
  state.keyframes = 7;
  const auto lines = globe::app::hudStatusLines(state);
  const std::string slid =
      "COLLISION " + std::string(globe::collision::toString(globe::collision::Response::Slid));
  std::string text;
  for (const auto& line : lines) text += line + "\n";
  for (const char* expected :
       {"FLY", "speed 69.3 m/s", "lon 138.72751", "lat 35.36063", "height 3800.5 m",
        "terrain 3731.2 m", "clearance 69.26 m", "heading 90.0", "pitch -12.2", slid.c_str(),
        "tiles 123 drawn, 4 loading", "frame 20.0 ms (50 fps)", "REC  7 keyframes", "H: help"}) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected << " not in\n" << text;
  }
  // Without the frame time (what decides a redraw) the rest is the same.
  const auto key = globe::app::hudStatusLines(state, false);
  state.frameMilliseconds = 35;
  EXPECT_EQ(globe::app::hudStatusLines(state, false), key);
  EXPECT_NE(globe::app::hudStatusLines(state), lines);
  // Tiles the view wanted that failed (a damaged pack, an undecodable tile) are said, not hidden.
  EXPECT_EQ(text.find("FAILED"), std::string::npos) << text;
  state.tilesMissing = 3;
  std::string failed;
  for (const auto& line : globe::app::hudStatusLines(state)) failed += line + "\n";
  EXPECT_NE(failed.find("tiles 123 drawn, 4 loading, 3 FAILED (drawn coarser)"), std::string::npos)
      << failed;
  // Orbit mode, no collision, nothing loading, no terrain under the camera.
  globe::app::HudState orbit;
  orbit.pose = CameraPose::fromDegrees(0, 20, 2e7);
  orbit.collision.clearanceMeters = 2e7;
  std::string orbitText;
  for (const auto& line : globe::app::hudStatusLines(orbit)) orbitText += line + "\n";
  for (const char* expected : {"ORBIT", "height 20000000 m", "no terrain under the camera",
                               "collision none", "tiles 0 drawn, 0 loading"}) {
    EXPECT_NE(orbitText.find(expected), std::string::npos) << expected << " not in\n" << orbitText;
  }
  EXPECT_EQ(orbitText.find("speed"), std::string::npos);
  EXPECT_EQ(orbitText.find("REC"), std::string::npos);
}

// With layers the HUD says the lighting and each layer's state; without, nothing about them.
TEST(HudText, ImageryStatusShowsLightingAndLayers) {
  globe::app::HudState state;
  EXPECT_EQ(globe::app::imageryStatus(state), "");
  state.lighting = globe::terrain::ImageryLighting::Off;
  state.layers = {{true, 1.0f}, {false, 0.4f}};
  state.selectedLayer = 1;
  EXPECT_EQ(globe::app::imageryStatus(state), "lighting off  layers 1 on 100%  >2 off 40%");
  std::string text;
  for (const auto& line : globe::app::hudStatusLines(state)) text += line + "\n";
  EXPECT_NE(text.find("lighting off"), std::string::npos) << text;
}

TEST(HudText, GlyphQuadsStayInsideTheirBox) {
  globe::render::HudTextBlock block;
  block.lines = {"lon 138.72751", "H: help"};
  block.topLeftPixels = {10, 20};
  block.scale = 2;
  const glm::vec2 size = globe::render::hudBlockSizePixels(block);
  EXPECT_GT(size.x, 13 * 5 * 2);
  EXPECT_GT(size.y, 2 * 12);
  const auto triangles = globe::render::buildHudTriangles(std::span(&block, 1));
  ASSERT_GT(triangles.size(), 6u * 20);
  EXPECT_EQ(triangles.size() % 6, 0u);
  for (size_t k = 6; k < triangles.size(); ++k) {
    EXPECT_GE(triangles[k].positionPixels.x, 10);
    EXPECT_GE(triangles[k].positionPixels.y, 20);
    EXPECT_LE(triangles[k].positionPixels.x, 10 + size.x);
    EXPECT_LE(triangles[k].positionPixels.y, 20 + size.y);
    EXPECT_EQ(triangles[k].rgba, block.textRgba);
  }
  EXPECT_EQ(triangles[0].rgba, block.backgroundRgba);
}

}  // namespace
