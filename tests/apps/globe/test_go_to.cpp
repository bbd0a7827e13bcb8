// "Go to": coordinates and gazetteer names parsed, bad text refused with a message; the compass
// arrow points north; north-up turns about the centre's ground point.
#include "apps/globe/go_to.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "apps/globe/hud_text.hpp"
#include "camera/fly_to.hpp"
#include "camera/orbit_controls.hpp"
#include "formats/image_io.hpp"
#include "geo/ecef.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

TEST(GoTo, ParsesPositionsAndPlaceNames) {
  auto a = parseGoTo("35.36, 138.73");
  ASSERT_TRUE(a) << a.error();
  EXPECT_DOUBLE_EQ(a->latitudeDegrees, 35.36);
  EXPECT_DOUBLE_EQ(a->longitudeDegrees, 138.73);
  auto b = parseGoTo("  -33.9   18.4 ");
  ASSERT_TRUE(b) << b.error();
  EXPECT_DOUBLE_EQ(b->latitudeDegrees, -33.9);
  auto lonFirst = parseGoTo("138.73 35.36");  // the first cannot be a latitude
  ASSERT_TRUE(lonFirst) << lonFirst.error();
  EXPECT_DOUBLE_EQ(lonFirst->latitudeDegrees, 35.36);
  auto dms = parseGoTo("35°21'38\"N 138°43'39\"E");
  ASSERT_TRUE(dms) << dms.error();
  EXPECT_NEAR(dms->longitudeDegrees, 138.7275, 1e-4);
  auto fuji = parseGoTo("mount FUJI");
  ASSERT_TRUE(fuji) << fuji.error();
  EXPECT_EQ(fuji->name, "Mount Fuji, JP");
  EXPECT_NEAR(fuji->latitudeDegrees, 35.3606, 1e-4);
  auto zurich = parseGoTo("Zurich");
  ASSERT_TRUE(zurich) << zurich.error();
  EXPECT_EQ(zurich->name, "Zürich, CH");
  auto paris = parseGoTo("Paris, US");
  ASSERT_TRUE(paris) << paris.error();
  EXPECT_EQ(paris->name, "Paris, US");
  EXPECT_LT(paris->longitudeDegrees, -80);
}

TEST(GoTo, RefusesWhatItCannotPlace) {
  for (const char* text : {"", "   ", "91, 100", "10, 181", "Xqzzyx Atlantis"}) {
    const auto target = parseGoTo(text);
    ASSERT_FALSE(target) << text;
    EXPECT_EQ(target.error().rfind("go to:", 0), 0u) << target.error();
  }
  EXPECT_NE(parseGoTo("91, 100").error().find("-90..90"), std::string::npos);
  const auto lonFirst = parseGoTo("91, 10");  // 91 cannot be a latitude: longitude first
  ASSERT_TRUE(lonFirst) << lonFirst.error();
  EXPECT_DOUBLE_EQ(lonFirst->latitudeDegrees, 10);
}

TEST(GoTo, SuggestionsAreTheBestFewPlaces) {
  const auto suggestions = goToSuggestions("Spring", 5);
  ASSERT_EQ(suggestions.size(), 5u);
  EXPECT_TRUE(goToSuggestions("S", 5).empty());  // too short to suggest
  EXPECT_TRUE(goToSuggestions("35.3, 138.7", 5).empty());
  const auto lon = goToSuggestions("Londo", 3);
  ASSERT_FALSE(lon.empty());
  EXPECT_EQ(lon[0], "London, GB");
  // Mistyped: the box offers the place meant, spelt right.
  const auto zion = goToSuggestions("Zoin", 3);
  ASSERT_FALSE(zion.empty());
  EXPECT_EQ(zion[0], "Zion National Park, US");
  const auto fuji = parseGoTo("Mt Fuji");
  ASSERT_TRUE(fuji) << fuji.error();
  EXPECT_EQ(fuji->name, "Mount Fuji, JP");
}

// `globe search` as a user runs it: CSV best first, a position read back, a miss an error.
TEST(GlobeSearch, PrintsPlacesBestFirstAsCsv) {
  const auto fuji = test::runGlobe("search Fuji --limit 3");
  ASSERT_EQ(fuji.exitCode, 0) << fuji.output;
  EXPECT_EQ(fuji.output.rfind(
                "name,lon,lat,kind,population\n\"Mount Fuji, JP\",138.72740,35.36060,peak,0\n", 0),
            0u)
      << fuji.output;
  const auto sao = test::runGlobe("search 'sao paulo' --limit 1");
  ASSERT_EQ(sao.exitCode, 0) << sao.output;
  EXPECT_NE(sao.output.find("\"São Paulo, BR\",-46.63611,-23.54750,city,10021295"),
            std::string::npos)
      << sao.output;
  const auto position = test::runGlobe("search '35 21 38 N 138 43 39 E'");
  ASSERT_EQ(position.exitCode, 0) << position.output;
  EXPECT_NE(position.output.find(",138.727500,35.360556,position,0"), std::string::npos)
      << position.output;
  const auto none = test::runGlobe("search Xqzzyx");
  EXPECT_EQ(none.exitCode, 1);
  EXPECT_NE(none.output.find("no place named \"Xqzzyx\""), std::string::npos) << none.output;
  const auto badFile = test::runGlobe("search Paris --places /nonexistent/places.tsv");
  EXPECT_EQ(badFile.exitCode, 1);
  EXPECT_NE(badFile.output.find("/nonexistent/places.tsv"), std::string::npos) << badFile.output;
}

// `--go-to` on snapshot: a name lands where its position does (Mount Fuji's gazetteer position
// is 35.3606, 138.7274), and the mountain is in the middle of the picture, above the horizon.
TEST(GlobeSearch, SnapshotGoToANameIsGoingToItsPosition) {
  const auto dir = globe::testing::freshTempDir("go-to-snapshot");
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const auto byName =
      test::runGlobe("snapshot " + pyramid + " --go-to 'mount fuji' --size 320x180 -o " +
                     (dir / "name.png").string());
  ASSERT_EQ(byName.exitCode, 0) << byName.output;
  const auto byPosition =
      test::runGlobe("snapshot " + pyramid + " --go-to '35.3606, 138.7274' --size 320x180 -o " +
                     (dir / "position.png").string());
  ASSERT_EQ(byPosition.exitCode, 0) << byPosition.output;
  auto a = globe::formats::loadImageRgba(dir / "name.png");
  auto b = globe::formats::loadImageRgba(dir / "position.png");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->pixels, b->pixels);
  // The summit's snow (grey-white, brighter than the brown slopes) near the middle.
  size_t bright = 0;
  for (int y = 40; y < 110; ++y) {
    for (int x = 110; x < 210; ++x) {
      const uint8_t* p = &a->pixels[static_cast<size_t>(y * 320 + x) * 4];
      if (p[0] > 150 && p[1] > 150 && p[2] > 150) ++bright;
    }
  }
  EXPECT_GT(bright, 20u);  // 41 at 320x180
  const auto both = test::runGlobe("snapshot " + pyramid + " --go-to Fuji --camera 0,0,1e7 -o " +
                                   (dir / "x.png").string());
  EXPECT_EQ(both.exitCode, 2);
  EXPECT_NE(both.output.find("--camera, --go-to or --view (one of them)"), std::string::npos)
      << both.output;
  const auto unknown = test::runGlobe("view " + pyramid + " --go-to Xqzzyx --frames 1");
  EXPECT_EQ(unknown.exitCode, 2);
  EXPECT_NE(unknown.output.find("no place named \"Xqzzyx\""), std::string::npos) << unknown.output;
}

TEST(Compass, NorthUpTurnsAboutTheCentreGroundPoint) {
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  camera::OrbitControls controls(
      wgs84, camera::CameraPose::fromDegrees(138.6, 35.2, 15000, 130, -40, 0), 0.8);
  const auto frame = camera::cameraFrame(wgs84, controls.pose());
  const auto pivot = camera::intersectTerrain(wgs84, frame.positionEcefMeters, frame.forward,
                                              [](double, double) { return 1000.0; });
  ASSERT_TRUE(pivot);
  controls.northUp(pivot);
  EXPECT_NEAR(std::remainder(controls.pose().headingRadians, 2 * 3.141592653589793), 0, 1e-3);
  const auto after = camera::cameraFrame(wgs84, controls.pose());
  const glm::dvec3 toPivot = glm::normalize(*pivot - after.positionEcefMeters);
  EXPECT_GT(glm::dot(toPivot, after.forward), std::cos(1e-4));  // still at the centre
  controls.northUp(std::nullopt);                               // no ground at the centre: in place
  EXPECT_EQ(controls.pose().headingRadians, 0);
}

}  // namespace
}  // namespace globe::app
