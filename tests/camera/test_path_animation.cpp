// Animation on camera paths: CSS easing per segment (inOut covers ~0 % of its way at 10 % of its
// time and half at half; a Bézier matches its own curve), targets held at the frame's centre on
// every sample, and KML LookAt keyframes; the JSON and KML readers of both.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <unistd.h>

#include <glm/geometric.hpp>

#include "camera/camera_path.hpp"
#include "camera/camera_path_file.hpp"
#include "camera/look_at.hpp"
#include "camera/path_easing.hpp"
#include "geo/ecef.hpp"
#include "tests/support/test_constants.hpp"

namespace globe::camera {
namespace {

using globe::test::kWgs84;
namespace fs = std::filesystem;

double bezier(double a, double b, double s) {
  return 3 * (1 - s) * (1 - s) * s * a + 3 * (1 - s) * s * s * b + s * s * s;
}

TEST(PathEasing, NamedCurvesAreCssAndABezierFollowsItsCurve) {
  EXPECT_LT(easeProgress(kEaseInOut, 0.1), 0.03) << "inOut: ~0 of its way at 10 % of its time";
  EXPECT_NEAR(easeProgress(kEaseInOut, 0.5), 0.5, 1e-9);
  EXPECT_NEAR(easeProgress(kEaseInOut, 0.9), 1.0 - easeProgress(kEaseInOut, 0.1), 1e-9);
  EXPECT_LT(easeProgress(kEaseIn, 0.5), 0.35);
  EXPECT_GT(easeProgress(kEaseOut, 0.5), 0.65);
  for (double x = 0; x <= 1.0; x += 0.05) EXPECT_NEAR(easeProgress(kEaseLinear, x), x, 1e-9);
  EXPECT_EQ(easeProgress(kEaseInOut, -1.0), 0.0);
  EXPECT_EQ(easeProgress(kEaseInOut, 2.0), 1.0);
  EXPECT_EQ(easeProgress(kEaseInOut, std::nan("")), 0.0);
  // Any curve: the point at parameter s lies on it.
  for (const CubicBezierEase ease : {CubicBezierEase{0.1, 0.7, 0.9, 0.2},
                                     CubicBezierEase{0.0, 1.5, 1.0, -0.5},
                                     CubicBezierEase{1.0, 0.0, 0.0, 1.0}}) {
    for (double s = 0.01; s < 1.0; s += 0.07) {
      EXPECT_NEAR(easeProgress(ease, bezier(ease.x1, ease.x2, s)), bezier(ease.y1, ease.y2, s),
                  1e-9)
          << ease.x1 << "," << ease.y1 << "," << ease.x2 << "," << ease.y2 << " at " << s;
    }
  }
  EXPECT_EQ(namedEase("inOut"), kEaseInOut);
  EXPECT_FALSE(namedEase("ease-in-out").has_value());
  EXPECT_EQ(easeName(kEaseOut), "out");
  EXPECT_EQ(easeName(CubicBezierEase{0.1, 0.2, 0.3, 0.4}), "");
}

// A linear path 10 s long along a meridian with the segment eased inOut: the camera's share of
// the way at 10 % and 50 % of the time.
TEST(PathEasing, AnEasedSegmentCoversItsWayByTheCurve) {
  CameraPath path;
  path.interpolation = PathInterpolation::Linear;
  path.keyframes.push_back({0.0, CameraPose::fromDegrees(10, 40, 2000, 0, -20, 0)});
  path.keyframes.push_back({10.0, CameraPose::fromDegrees(10, 41, 2000, 0, -20, 0)});
  path.keyframes.push_back({20.0, CameraPose::fromDegrees(10, 42, 2000, 0, -20, 0)});
  path.keyframes[0].ease = kEaseInOut;
  const auto share = [&](double t, double from) {
    return geo::radiansToDegrees(samplePath(path, t, kWgs84).position.latitudeRadians) - from;
  };
  EXPECT_LT(share(1.0, 40), 0.03);
  EXPECT_NEAR(share(5.0, 40), 0.5, 1e-6);
  EXPECT_NEAR(share(9.0, 40), 1.0 - share(1.0, 40), 1e-6);
  // The next segment has no ease: linear in time.
  EXPECT_NEAR(share(11.0, 41), 0.1, 1e-6);
  EXPECT_NEAR(share(10.0, 41), 0.0, 1e-9) << "keys are hit exactly";
}

// The angle (degrees) between the pose's view and the direction to a point.
double offCentreDegrees(const CameraPose& pose, const glm::dvec3& targetEcef) {
  const CameraFrame frame = cameraFrame(kWgs84, pose);
  const glm::dvec3 to = glm::normalize(targetEcef - frame.positionEcefMeters);
  return geo::radiansToDegrees(std::acos(std::clamp(glm::dot(frame.forward, to), -1.0, 1.0)));
}

TEST(PathTarget, TheTargetStaysAtTheFrameCentreAndTheRollIsKept) {
  const glm::dvec3 summit =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 3776));
  const glm::dvec3 lake =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.76, 35.49, 1000));
  for (const PathInterpolation interpolation :
       {PathInterpolation::Linear, PathInterpolation::Smooth}) {
    CameraPath path;
    path.interpolation = interpolation;
    const auto keyAt = [&](double t, CameraPose pose, const glm::dvec3& target) {
      CameraKeyframe key{t, lookingAt(kWgs84, pose, target)};
      key.targetEcefMeters = target;
      path.keyframes.push_back(key);
    };
    keyAt(0, CameraPose::fromDegrees(138.60, 35.20, 6000, 0, 0, 7), summit);
    keyAt(8, CameraPose::fromDegrees(138.90, 35.30, 4000, 0, 0, 7), summit);
    keyAt(16, CameraPose::fromDegrees(138.85, 35.60, 3000, 0, 0, -5), lake);
    path.keyframes[1].ease = kEaseInOut;
    double worst = 0;
    for (double t = 0; t <= 16.0; t += 0.1) {
      const CameraPose pose = samplePath(path, t, kWgs84);
      const double u = t <= 8 ? 0.0 : easeProgress(kEaseInOut, (t - 8) / 8);
      worst = std::max(worst, offCentreDegrees(pose, summit + u * (lake - summit)));
    }
    EXPECT_LT(worst, 1e-4) << toString(interpolation);
    // Roll: the keyframes' own, interpolated (7° to 7°, then 7° to −5° by the eased fraction).
    EXPECT_NEAR(geo::radiansToDegrees(samplePath(path, 4, kWgs84).rollRadians), 7, 1e-9);
    EXPECT_NEAR(geo::radiansToDegrees(samplePath(path, 12, kWgs84).rollRadians), 1, 1e-9);
  }
}

// A fresh directory for this process and name (removed first).
fs::path freshTempDir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("globe_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

fs::path writeFile(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

// A dive from 20,000 km to 1 km in 10 s, 50 frames: with logarithmic altitude the height falls
// by the same ratio every frame, and the ground passes by the same share of the height (it moves
// evenly on screen); linear altitude spends most of the frames in space.
TEST(PathAltitude, ALogarithmicDiveKeepsItsRatioAndItsScreenSpeed) {
  for (const PathInterpolation interpolation :
       {PathInterpolation::Linear, PathInterpolation::Smooth}) {
    CameraPath path;
    path.interpolation = interpolation;
    path.logarithmicAltitude = true;
    path.keyframes.push_back({0.0, CameraPose::fromDegrees(120, 10, 2e7, 0, -90, 0)});
    path.keyframes.push_back({10.0, CameraPose::fromDegrees(139, 35, 1000, 0, -90, 0)});
    const double expectedRatio = std::pow(1000.0 / 2e7, 1.0 / 50);
    double firstShare = 0;
    for (int i = 0; i < 50; ++i) {
      const CameraPose a = samplePath(path, i * 0.2, kWgs84);
      const CameraPose b = samplePath(path, (i + 1) * 0.2, kWgs84);
      EXPECT_NEAR(b.position.heightMeters / a.position.heightMeters, expectedRatio, 1e-9)
          << toString(interpolation) << " frame " << i;
      // The ground passed over the height's change: the same every frame.
      const auto ground = [](const CameraPose& pose) {
        geo::Cartographic surface = pose.position;
        surface.heightMeters = 0;
        return geo::cartographicToEcef(kWgs84, surface);
      };
      const double share = glm::length(ground(b) - ground(a)) /
                           (a.position.heightMeters - b.position.heightMeters);
      if (i == 0) firstShare = share;
      if (interpolation == PathInterpolation::Linear) {
        EXPECT_NEAR(share / firstShare, 1.0, 0.02) << "frame " << i;
      }
    }
  }
  // Heights at or below 0 m: the segment as it is (linear).
  CameraPath sea;
  sea.interpolation = PathInterpolation::Linear;
  sea.logarithmicAltitude = true;
  sea.keyframes.push_back({0.0, CameraPose::fromDegrees(0, 0, 0, 0, -90, 0)});
  sea.keyframes.push_back({10.0, CameraPose::fromDegrees(0, 1, 1000, 0, -90, 0)});
  EXPECT_NEAR(samplePath(sea, 5, kWgs84).position.heightMeters, 500, 1e-9);
}

TEST(PathFov, TheFieldOfViewIsInterpolatedBetweenTheKeyframesThatHaveOne) {
  CameraPath path;
  path.interpolation = PathInterpolation::Linear;
  for (const double t : {0.0, 4.0, 8.0, 12.0}) {
    path.keyframes.push_back({t, CameraPose::fromDegrees(10, 40 + t / 10, 2000, 0, -20, 0)});
  }
  EXPECT_FALSE(sampleFovY(path, 3).has_value()) << "none anywhere: the program's";
  path.keyframes[1].fovYRadians = 1.0;
  path.keyframes[3].fovYRadians = 0.5;
  path.keyframes[1].ease = kEaseInOut;
  EXPECT_EQ(sampleFovY(path, 0), 1.0) << "the first one's before it";
  EXPECT_EQ(sampleFovY(path, 4), 1.0);
  EXPECT_NEAR(*sampleFovY(path, 6), 0.875, 1e-12) << "half of the eased first half";
  EXPECT_NEAR(*sampleFovY(path, 5), 1.0 - 0.25 * easeProgress(kEaseInOut, 0.25), 1e-12);
  EXPECT_NEAR(*sampleFovY(path, 10), 0.625, 1e-12);
  EXPECT_EQ(sampleFovY(path, 20), 0.5);
}

TEST(PathTarget, JsonReadsEaseAndTargetsWritesThemBackAndNamesMistakes) {
  const fs::path dir = freshTempDir("path-animation-json");
  const fs::path good = writeFile(dir, "good.json", R"({"interpolation": "linear",
    "altitude": "logarithmic", "keyframes": [
    {"t": 0, "lon": 138.6, "lat": 35.2, "height": 6000, "ease": "inOut",
     "target": {"lon": 138.7274, "lat": 35.3606, "height": 0, "aboveTerrain": true}},
    {"t": 5, "lon": 138.9, "lat": 35.3, "height": 4000, "ease": [0.1, 0.7, 0.9, 0.2]},
    {"t": 9, "lon": 138.8, "lat": 35.5, "height": 3000, "fov": 30}]})");
  auto file = readCameraPath(good);
  ASSERT_TRUE(file) << file.error();
  EXPECT_EQ(file->keyframes[0].ease, kEaseInOut);
  EXPECT_EQ(file->keyframes[1].ease, (CubicBezierEase{0.1, 0.7, 0.9, 0.2}));
  EXPECT_FALSE(file->keyframes[2].ease.has_value());
  EXPECT_EQ(file->keyframes[2].fovDegrees, 30.0);
  EXPECT_FALSE(file->keyframes[0].fovDegrees.has_value());
  EXPECT_TRUE(file->logarithmicAltitude);
  ASSERT_TRUE(file->keyframes[0].target.has_value());
  EXPECT_EQ(file->keyframes[0].target->longitudeDegrees, 138.7274);
  EXPECT_TRUE(file->keyframes[0].target->heightAboveTerrain);
  const fs::path copy = dir / "copy.json";
  ASSERT_TRUE(writeCameraPathJson(copy, *file));
  auto again = readCameraPath(copy);
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(again->keyframes[1].ease, file->keyframes[1].ease);
  EXPECT_EQ(again->keyframes[0].target->latitudeDegrees, 35.3606);
  EXPECT_TRUE(again->keyframes[0].target->heightAboveTerrain);
  EXPECT_EQ(again->keyframes[2].fovDegrees, 30.0);
  EXPECT_TRUE(again->logarithmicAltitude);

  const std::pair<const char*, const char*> mistakes[] = {
      {R"("ease": "bounce")", "keyframes[0].ease: 'bounce' is not linear, in, out, inOut"},
      {R"("ease": [1.5, 0, 0.5, 1])", "keyframes[0].ease[0]: 1.5 is outside 0..1"},
      {R"("ease": [0.1, 0.2])", "keyframes[0].ease: expected linear, in, out, inOut or"},
      {R"("target": {"lon": 138, "height": 0})", "keyframes[0].target: missing field 'lat'"},
      {R"("target": {"lon": 138, "lat": 95, "height": 0})", "keyframes[0].target.lat: 95 is outside"},
      {R"("target": {"lon": 1, "lat": 2, "height": 0, "alt": 3})", "keyframes[0].target.alt: unknown field"},
      {R"("fov": 0)", "keyframes[0].fov: 0 is outside 1..170"},
      {R"("fov": "wide")", "keyframes[0].fov: expected a number (degrees), got a string"},
  };
  for (const auto& [field, expected] : mistakes) {
    const fs::path bad = writeFile(dir, "bad.json",
                                   std::string(R"({"keyframes": [{"t": 0, "lon": 1, "lat": 2, )"
                                               R"("height": 3, )") + field + "}]}");
    auto read = readCameraPath(bad);
    ASSERT_FALSE(read) << field;
    EXPECT_NE(read.error().find(expected), std::string::npos) << read.error();
  }
}

TEST(PathTarget, KmlLookAtsBecomeCamerasLookingAtTheirPoints) {
  const fs::path dir = freshTempDir("path-animation-kml");
  const fs::path tour = writeFile(dir, "tour.kml", R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2" xmlns:gx="http://www.google.com/kml/ext/2.2">
<gx:Tour><gx:Playlist>
  <gx:FlyTo><gx:duration>1</gx:duration><gx:flyToMode>smooth</gx:flyToMode>
    <LookAt><longitude>138.7274</longitude><latitude>35.3606</latitude><altitude>3776</altitude>
      <heading>30</heading><tilt>60</tilt><range>12000</range>
      <altitudeMode>absolute</altitudeMode></LookAt></gx:FlyTo>
  <gx:FlyTo><gx:duration>6</gx:duration><gx:flyToMode>smooth</gx:flyToMode>
    <LookAt><longitude>138.7274</longitude><latitude>35.3606</latitude><altitude>3776</altitude>
      <heading>120</heading><tilt>70</tilt><range>9000</range>
      <altitudeMode>absolute</altitudeMode></LookAt></gx:FlyTo>
  <gx:FlyTo><gx:duration>4</gx:duration>
    <LookAt><longitude>138.75</longitude><latitude>35.40</latitude>
      <heading>0</heading><tilt>0</tilt><range>5000</range></LookAt></gx:FlyTo>
</gx:Playlist></gx:Tour></kml>)");
  auto file = readCameraPath(tour);
  ASSERT_TRUE(file) << file.error();
  ASSERT_EQ(file->keyframes.size(), 3u);
  const glm::dvec3 summit =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 3776));
  for (size_t k = 0; k < 2; ++k) {
    const PathKeyframe& key = file->keyframes[k];
    ASSERT_TRUE(key.target.has_value());
    const CameraPose pose =
        CameraPose::fromDegrees(key.longitudeDegrees, key.latitudeDegrees, key.heightMeters,
                                key.headingDegrees, key.pitchDegrees, key.rollDegrees);
    EXPECT_NEAR(glm::length(geo::cartographicToEcef(kWgs84, pose.position) - summit),
                k == 0 ? 12000 : 9000, 1e-3)
        << "range";
    EXPECT_LT(offCentreDegrees(pose, summit), 1e-4);
    // The LookAt's heading and tilt are the point's; the camera's own horizon, 9..12 km away,
    // is tilted from it by the Earth's curvature (~0.1°).
    EXPECT_NEAR(key.headingDegrees, k == 0 ? 30 : 120, 0.1);
    EXPECT_NEAR(key.pitchDegrees, k == 0 ? -30 : -20, 0.15);
  }
  // Straight down from 5 km over a point on the ground (clampToGround: above the terrain).
  const PathKeyframe& last = file->keyframes.back();
  EXPECT_NEAR(last.latitudeDegrees, 35.40, 1e-9);
  EXPECT_NEAR(last.heightMeters, 5000, 1e-3);
  EXPECT_TRUE(last.heightAboveTerrain);
  EXPECT_NEAR(last.pitchDegrees, -90, 1e-6);
  EXPECT_EQ(file->keyframes[1].timeSeconds, 6);
  // The last FlyTo bounces (KML's default): it stops there, easing in and out (no arc between
  // a camera above the ellipsoid and one above the terrain).
  EXPECT_EQ(file->interpolation, "smooth");
  ASSERT_EQ(file->keyframes.size(), 3u);
  EXPECT_FALSE(file->keyframes[0].ease.has_value()) << "the smooth FlyTos run through";
  EXPECT_EQ(file->keyframes[1].ease, kEaseInOut);
}

// KML's bounce fly-to from Fuji to Rainier (7,700 km) arcs up to the fly-to's hop at the middle
// and starts and stops at rest; the same tour flown smooth goes straight through.
TEST(PathShots, ABounceFlyToArcsOverALongWayAndSmoothDoesNot) {
  const fs::path dir = freshTempDir("path-bounce");
  const auto tour = [&](const char* mode) {
    std::string text = R"(<kml xmlns:gx="http://www.google.com/kml/ext/2.2"><gx:Tour><gx:Playlist>
      <gx:FlyTo><Camera><longitude>138.73</longitude><latitude>35.36</latitude>
        <altitude>20000</altitude><altitudeMode>absolute</altitudeMode></Camera></gx:FlyTo>
      <gx:FlyTo><gx:duration>30</gx:duration><gx:flyToMode>)";
    text += mode;
    text += R"(</gx:flyToMode><Camera><longitude>-121.76</longitude><latitude>46.85</latitude>
        <altitude>15000</altitude><altitudeMode>absolute</altitudeMode></Camera></gx:FlyTo>
      </gx:Playlist></gx:Tour></kml>)";
    return readCameraPath(writeFile(dir, std::string(mode) + ".kml", text));
  };
  auto bounce = tour("bounce");
  ASSERT_TRUE(bounce) << bounce.error();
  ASSERT_EQ(bounce->keyframes.size(), 3u);
  EXPECT_EQ(bounce->keyframes[1].timeSeconds, 15);
  EXPECT_GT(bounce->keyframes[1].heightMeters, 3e6) << "half the way's length up";
  EXPECT_EQ(bounce->keyframes[0].ease, kEaseIn);
  EXPECT_EQ(bounce->keyframes[1].ease, kEaseOut);
  auto smooth = tour("smooth");
  ASSERT_TRUE(smooth) << smooth.error();
  ASSERT_EQ(smooth->keyframes.size(), 2u);
  EXPECT_FALSE(smooth->keyframes[0].ease.has_value());
}

// The shots: an orbit is a keyframe per 10° on its circle, each looking at the centre; a flyTo
// is Google Earth's arc from one pose to the other, rising over a long way.
TEST(PathShots, AnOrbitCirclesItsPointAndAFlyToArcsBetweenItsPoses) {
  const fs::path dir = freshTempDir("path-shots");
  auto orbit = readCameraPath(writeFile(dir, "orbit.json", R"({"orbit": {
    "lon": 138.7274, "lat": 35.3606, "height": 3776, "radius": 8000, "altitude": 1500,
    "degrees": -270, "duration": 27, "startBearing": 90, "fov": 40}})"));
  ASSERT_TRUE(orbit) << orbit.error();
  ASSERT_EQ(orbit->keyframes.size(), 28u);
  EXPECT_EQ(orbit->interpolation, "smooth");
  const glm::dvec3 summit =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 3776));
  const glm::dvec3 up = geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 0));
  for (size_t k = 0; k < orbit->keyframes.size(); ++k) {
    const PathKeyframe& key = orbit->keyframes[k];
    EXPECT_NEAR(key.timeSeconds, static_cast<double>(k), 1e-9);
    EXPECT_EQ(key.heightMeters, 3776 + 1500);
    ASSERT_TRUE(key.target.has_value());
    EXPECT_EQ(key.target->latitudeDegrees, 35.3606);
    EXPECT_EQ(key.fovDegrees, 40.0);
    const glm::dvec3 at = geo::cartographicToEcef(
        kWgs84, geo::Cartographic::fromDegrees(key.longitudeDegrees, key.latitudeDegrees, 3776));
    const glm::dvec3 off = at - summit;
    EXPECT_NEAR(glm::length(off - up * glm::dot(off, up)), 8000, 5) << k;
  }
  // Starting east of the point (bearing 90) and turning anticlockwise: north of it after 90°.
  EXPECT_GT(orbit->keyframes.front().longitudeDegrees, 138.7274 + 0.05);
  EXPECT_GT(orbit->keyframes[9].latitudeDegrees, 35.3606 + 0.05);

  auto flight = readCameraPath(writeFile(dir, "fly.json", R"({"flyTo": {
    "from": {"lon": 138.73, "lat": 35.36, "height": 9000, "heading": 0, "pitch": -30},
    "to": {"lon": -112.95, "lat": 37.25, "height": 4000, "heading": 90, "pitch": -20},
    "duration": 20}})"));
  ASSERT_TRUE(flight) << flight.error();
  ASSERT_EQ(flight->keyframes.size(), 81u);
  EXPECT_NEAR(flight->keyframes.front().longitudeDegrees, 138.73, 1e-9);
  EXPECT_NEAR(flight->keyframes.back().longitudeDegrees, -112.95, 1e-9);
  EXPECT_NEAR(flight->keyframes.back().headingDegrees, 90, 1e-9);
  double highest = 0;
  for (const PathKeyframe& key : flight->keyframes) highest = std::max(highest, key.heightMeters);
  EXPECT_GT(highest, 1e6) << "a hop over the Pacific";

  const std::pair<const char*, const char*> mistakes[] = {
      {R"({"orbit": {"lon": 1, "lat": 2, "altitude": 3, "duration": 4}})",
       "orbit: missing field 'radius'"},
      {R"({"orbit": {"lon": 1, "lat": 2, "radius": 0, "altitude": 3, "duration": 4}})",
       "orbit.radius: 0 is outside 1..10000000"},
      {R"({"flyTo": {"from": {"lon": 1, "lat": 2, "height": 3}, "duration": 4}})",
       "flyTo: missing field 'to'"},
      {R"({"flyTo": {"duration": 4}, "orbit": {}})", "give one of keyframes, orbit or flyTo"},
  };
  for (const auto& [text, expected] : mistakes) {
    auto read = readCameraPath(writeFile(dir, "bad.json", text));
    ASSERT_FALSE(read) << text;
    EXPECT_NE(read.error().find(expected), std::string::npos) << read.error();
  }
}

}  // namespace
}  // namespace globe::camera
