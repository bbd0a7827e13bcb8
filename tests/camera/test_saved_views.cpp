// Saved views: the views file round trip, names replaced, KML out and back (Camera), Google's
// KML samples read (LookAt: the camera is where the point is seen from), bad files named.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "camera/saved_views.hpp"
#include "geo/ecef.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::camera {
namespace {

namespace fs = std::filesystem;
constexpr double kDeg = 3.14159265358979323846 / 180;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("globe-views-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void expectSamePose(const CameraPose& a, const CameraPose& b) {
  EXPECT_NEAR(a.position.longitudeRadians, b.position.longitudeRadians, 1e-9);
  EXPECT_NEAR(a.position.latitudeRadians, b.position.latitudeRadians, 1e-9);
  EXPECT_NEAR(a.position.heightMeters, b.position.heightMeters, 1e-3);
  EXPECT_NEAR(a.headingRadians, b.headingRadians, 1e-6);
  EXPECT_NEAR(a.pitchRadians, b.pitchRadians, 1e-6);
  EXPECT_NEAR(a.rollRadians, b.rollRadians, 1e-6);
}

TEST(SavedViews, FileRoundTripAndNamesReplaced) {
  const fs::path dir = scratch("file");
  std::vector<SavedView> views;
  putSavedView(views,
               {"Fuji from the south", CameraPose::fromDegrees(138.73, 35.2, 9000, 0, -35, 0)});
  putSavedView(views, {"Zion <canyon> & \"narrows\"",
                       CameraPose::fromDegrees(-112.95, 37.3, 3000, 200, -20, 1), true});
  putSavedView(views,
               {"fuji FROM the south", CameraPose::fromDegrees(138.7, 35.1, 8000, 10, -30, 0)});
  ASSERT_EQ(views.size(), 2u);  // the third replaced the first (case ignored)
  ASSERT_TRUE(writeSavedViews(dir / "sub/views.json", views));
  auto back = readSavedViews(dir / "sub/views.json");
  ASSERT_TRUE(back) << back.error();
  ASSERT_EQ(back->size(), 2u);
  EXPECT_EQ((*back)[0].name, "fuji FROM the south");
  expectSamePose((*back)[0].pose, views[0].pose);
  EXPECT_TRUE((*back)[1].heightAboveTerrain);
  ASSERT_NE(findSavedView(*back, "ZION <CANYON> & \"NARROWS\""), nullptr);
  EXPECT_EQ(findSavedView(*back, "nowhere"), nullptr);
  auto none = readSavedViews(dir / "missing.json");
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());
  std::ofstream(dir / "bad.json") << R"({"views":[{"name":"x","camera":[1,2]}]})";
  auto bad = readSavedViews(dir / "bad.json");
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("bad.json"), std::string::npos) << bad.error();

  // Out as KML Cameras and back: the same poses, names escaped and restored.
  std::ofstream(dir / "views.kml") << savedViewsToKml(views);
  auto kml = savedViewsFromKml(dir / "views.kml", geo::Ellipsoid::wgs84());
  ASSERT_TRUE(kml) << kml.error();
  ASSERT_EQ(kml->size(), 2u);
  EXPECT_EQ((*kml)[1].name, views[1].name);
  for (size_t i = 0; i < 2; ++i) expectSamePose((*kml)[i].pose, views[i].pose);
  EXPECT_TRUE((*kml)[1].heightAboveTerrain);
  fs::remove_all(dir);
}

TEST(SavedViews, ALookAtPutsTheCameraWhereThePointIsSeenFrom) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  // Straight down from 10 km: right above the point.
  const CameraPose down = lookAtPose(138.73, 35.36, 0, 0, 0, 10000, wgs84);
  EXPECT_NEAR(down.position.longitudeRadians, 138.73 * kDeg, 1e-9);
  EXPECT_NEAR(down.position.latitudeRadians, 35.36 * kDeg, 1e-9);
  EXPECT_NEAR(down.position.heightMeters, 10000, 1e-3);
  EXPECT_NEAR(down.pitchRadians, -90 * kDeg, 1e-6);
  // Tilted 60 degrees, heading 30: the camera's view ray meets the point, heading kept.
  const CameraPose tilted = lookAtPose(138.73, 35.36, 1000, 30, 60, 20000, wgs84);
  const CameraFrame frame = cameraFrame(wgs84, tilted);
  const glm::dvec3 point = geo::cartographicToEcef(wgs84, {138.73 * kDeg, 35.36 * kDeg, 1000});
  const glm::dvec3 toPoint = point - frame.positionEcefMeters;
  EXPECT_NEAR(glm::length(toPoint), 20000, 1e-3);
  EXPECT_NEAR(glm::dot(glm::normalize(toPoint), frame.forward), 1.0, 1e-9);
  EXPECT_NEAR(tilted.headingRadians, 30 * kDeg, 0.01);
  EXPECT_NEAR(tilted.pitchRadians, -30 * kDeg, 0.01);
}

TEST(SavedViews, GooglesKmlSamplesReadAsViews) {
  const fs::path samples = fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/kml/kmlsamples.kml";
  auto views = savedViewsFromKml(samples, geo::Ellipsoid::wgs84());
  ASSERT_TRUE(views) << views.error();
  EXPECT_EQ(views->size(), 17u);  // its 17 LookAts
  bool simple = false;
  for (const SavedView& v : *views) {
    EXPECT_TRUE(v.pose.isFinite()) << v.name;
    EXPECT_GT(v.pose.position.heightMeters, 0) << v.name;
    if (v.name == "Placemarks") simple = true;  // the folder that holds the LookAt
  }
  EXPECT_TRUE(simple);
  const fs::path dir = scratch("kml");
  std::ofstream(dir / "bad.kml") << "<kml><Placemark><name>x</name>\n<Camera><longitude>abc"
                                    "</longitude><latitude>1</latitude></Camera></Placemark></kml>";
  auto bad = savedViewsFromKml(dir / "bad.kml", geo::Ellipsoid::wgs84());
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("bad.kml:2"), std::string::npos) << bad.error();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace globe::camera
