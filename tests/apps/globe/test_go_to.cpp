// "Go to": coordinates and gazetteer names parsed, bad text refused with a message; the compass
// arrow points north; north-up turns about the centre's ground point.
#include "apps/globe/go_to.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include <glm/geometric.hpp>

#include "apps/globe/hud_text.hpp"
#include "camera/fly_to.hpp"
#include "camera/orbit_controls.hpp"
#include "geo/ecef.hpp"

namespace globe::app {
namespace {

TEST(GoTo, ParsesLatLonAndPlaceNames) {
  auto a = parseGoTo("35.36, 138.73");
  ASSERT_TRUE(a) << a.error();
  EXPECT_DOUBLE_EQ(a->latitudeDegrees, 35.36);
  EXPECT_DOUBLE_EQ(a->longitudeDegrees, 138.73);
  auto b = parseGoTo("  -33.9   18.4 ");
  ASSERT_TRUE(b) << b.error();
  EXPECT_DOUBLE_EQ(b->latitudeDegrees, -33.9);
  auto fuji = parseGoTo("mount FUJI");
  ASSERT_TRUE(fuji) << fuji.error();
  EXPECT_EQ(fuji->name, "Mount Fuji");
  EXPECT_NEAR(fuji->latitudeDegrees, 35.3606, 1e-9);
  auto angels = parseGoTo("angels");  // a unique prefix
  ASSERT_TRUE(angels) << angels.error();
  EXPECT_EQ(angels->name, "Angels Landing");
}

TEST(GoTo, RefusesWhatItCannotPlace) {
  for (const char* text : {"", "   ", "91, 10", "10, 181", "nan, 3", "Atlantis", "Mount"}) {
    const auto target = parseGoTo(text);
    ASSERT_FALSE(target) << text;
    EXPECT_NE(target.error().find("go to:"), std::string::npos) << target.error();
  }
  EXPECT_NE(parseGoTo("Atlantis").error().find("Mount Fuji"), std::string::npos);  // suggestions
  EXPECT_NE(parseGoTo("Mount").error().find("more than one"), std::string::npos);
}

TEST(GoTo, GazetteerNamesAreUniqueAndOnTheGlobe) {
  std::set<std::string> names;
  for (const Place& place : gazetteer()) {
    EXPECT_TRUE(names.insert(place.name).second) << place.name;
    EXPECT_LE(std::abs(place.latitudeDegrees), 90.0) << place.name;
    EXPECT_LE(std::abs(place.longitudeDegrees), 180.0) << place.name;
    const auto found = parseGoTo(place.name);  // every name finds itself
    ASSERT_TRUE(found) << found.error();
    EXPECT_EQ(found->name, place.name);
  }
  EXPECT_GE(names.size(), 10u);
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
