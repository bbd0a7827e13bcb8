// The window's ruler without a window: points added and undone, a ring closed by a click near its
// first point, lengths and areas against GeographicLib's (known values), the text's units, and
// the overlay document that draws it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/globe/hud_text.hpp"
#include "apps/globe/profile_panel.hpp"
#include "apps/globe/ruler.hpp"
#include "apps/globe/ruler_overlay.hpp"
#include "measure/geodesic_path.hpp"

namespace globe::app {
namespace {

// A 0.01-degree square near Fuji, clicked at these window pixels.
const RulerPoint kSouthWest{138.70, 35.35, 1500}, kSouthEast{138.71, 35.35, 1500},
    kNorthEast{138.71, 35.36, 1500}, kNorthWest{138.70, 35.36, 1500};

TEST(Ruler, PointsAddUpToTheGeodesicLengthAndBackspaceUndoes) {
  Ruler ruler;
  EXPECT_FALSE(ruler.active());
  ruler.setActive(true);
  EXPECT_EQ(ruler.lengthMeters(), 0);
  ruler.click(kSouthWest, {100, 300}, std::nullopt);
  ruler.click(kSouthEast, {300, 300}, glm::dvec2(100, 300));
  ASSERT_EQ(ruler.points().size(), 2u);
  const double east = measure::geodesicLengthMeters({{138.70, 35.35}, {138.71, 35.35}});
  EXPECT_NEAR(east, 909.0, 0.5);  // 0.01 degree of longitude at 35.35 N
  EXPECT_DOUBLE_EQ(ruler.lengthMeters(), east);
  EXPECT_FALSE(ruler.areaSquareMeters());
  const uint64_t revision = ruler.revision();
  EXPECT_TRUE(ruler.undo());
  EXPECT_GT(ruler.revision(), revision);
  EXPECT_EQ(ruler.points().size(), 1u);
  EXPECT_TRUE(ruler.undo());
  EXPECT_FALSE(ruler.undo()) << "nothing left to undo";
}

TEST(Ruler, AClickNearTheFirstPointClosesTheRing) {
  Ruler ruler;
  ruler.setActive(true);
  const glm::dvec2 first(100, 300);
  ruler.click(kSouthWest, first, std::nullopt);
  ruler.click(kSouthEast, {300, 300}, first);
  // Two points: a click on the first one adds a point, a line back (no ring of two).
  ruler.click(kNorthEast, {300, 100}, first);
  ruler.click(kNorthWest, {100, 100}, first);
  ASSERT_EQ(ruler.points().size(), 4u);
  ruler.click(kSouthWest, first + glm::dvec2(12, 0), first);  // too far: a fifth point
  EXPECT_EQ(ruler.points().size(), 5u);
  EXPECT_FALSE(ruler.closed());
  ruler.undo();
  ruler.click(kSouthWest, first + glm::dvec2(6, 7), first);  // 9.2 px: closes
  EXPECT_TRUE(ruler.closed());
  EXPECT_EQ(ruler.points().size(), 4u);
  EXPECT_EQ(ruler.path().size(), 5u);
  const double perimeter = measure::geodesicLengthMeters(ruler.path());
  EXPECT_DOUBLE_EQ(ruler.lengthMeters(), perimeter);
  ASSERT_TRUE(ruler.areaSquareMeters());
  const double area = *ruler.areaSquareMeters();
  EXPECT_NEAR(area, 908.9 * 1109.5, 908.9 * 1109.5 * 0.002);  // east by north, metres
  EXPECT_NE(rulerLogLine(ruler).find("ruler: 4 points, "), std::string::npos);
  EXPECT_NE(rulerLogLine(ruler).find(", area "), std::string::npos) << rulerLogLine(ruler);
  // Backspace reopens the ring; a click after a closed ring starts a new path.
  ruler.undo();
  EXPECT_FALSE(ruler.closed());
  EXPECT_EQ(ruler.points().size(), 4u);
  ruler.click(kSouthWest, first, first);
  ASSERT_TRUE(ruler.closed());
  ruler.click(kNorthEast, {300, 100}, first);
  EXPECT_FALSE(ruler.closed());
  EXPECT_EQ(ruler.points().size(), 1u);
  // Off clears it.
  ruler.setActive(false);
  EXPECT_TRUE(ruler.points().empty());
  EXPECT_EQ(rulerLogLine(ruler), "ruler: 0 points, 0.00 m");
}

TEST(Ruler, LengthsAndAreasInSensibleUnits) {
  EXPECT_EQ(formatLength(8.254), "8.25 m");
  EXPECT_EQ(formatLength(812.4), "812 m");
  EXPECT_EQ(formatLength(9345.2), "9345 m");
  EXPECT_EQ(formatLength(12'430), "12.4 km");
  EXPECT_EQ(formatLength(345'600), "346 km");
  EXPECT_EQ(formatArea(950), "950 m2");
  EXPECT_EQ(formatArea(42.26), "42.3 m2");
  EXPECT_EQ(formatArea(125'000), "12.5 ha");
  EXPECT_EQ(formatArea(31.8e6), "31.8 km2");
  EXPECT_EQ(formatArea(4.56e9), "4560 km2");
  Ruler ruler;
  ruler.setActive(true);
  EXPECT_NE(rulerHudLine(ruler).find("click the ground"), std::string::npos);
  ruler.click(kSouthWest, {0, 0}, std::nullopt);
  ruler.click(kNorthEast, {0, 0}, std::nullopt);
  EXPECT_NE(rulerHudLine(ruler).find("2 points  1434 m"), std::string::npos) << rulerHudLine(ruler);
}

TEST(Ruler, DrawnAsALineAndSmallIconsWithoutText) {
  Ruler ruler;
  ruler.setActive(true);
  EXPECT_EQ(rulerDocument(ruler), nullptr);
  EXPECT_EQ(withRuler({}, nullptr).size(), 0u);
  ruler.click(kSouthWest, {0, 0}, std::nullopt);
  ruler.click(kSouthEast, {200, 0}, std::nullopt);
  ruler.click(kNorthEast, {200, 200}, std::nullopt);
  auto document = rulerDocument(ruler);
  ASSERT_TRUE(document);
  ASSERT_EQ(document->placemarks.size(), 4u);  // the path, then a point each
  const overlays::Placemark& path = document->placemarks[0];
  ASSERT_EQ(path.geometries.size(), 1u);
  EXPECT_EQ(path.geometries[0].kind, overlays::GeometryKind::LineString);
  EXPECT_EQ(path.geometries[0].altitudeMode, overlays::AltitudeMode::ClampToGround);
  EXPECT_EQ(path.geometries[0].rings[0].size(), 3u);
  EXPECT_EQ(path.style.lineWidthPixels, 3);
  for (size_t i = 1; i < 4; ++i) {
    EXPECT_EQ(document->placemarks[i].geometries[0].kind, overlays::GeometryKind::Point);
    EXPECT_EQ(document->placemarks[i].style.labelScale, 0);
    EXPECT_LT(document->placemarks[i].style.iconScale, 1);
  }
  // Closed: filled, the line back to the first point.
  ruler.click(kSouthWest, {1, 1}, glm::dvec2(0, 0));
  document = rulerDocument(ruler);
  ASSERT_EQ(document->placemarks[0].geometries.size(), 2u);
  EXPECT_EQ(document->placemarks[0].geometries[0].kind, overlays::GeometryKind::Polygon);
  EXPECT_EQ(document->placemarks[0].geometries[1].rings[0].size(), 4u);
  // Shown after the user's documents.
  auto user = std::make_shared<const overlays::OverlayDocument>();
  const auto shown = withRuler({user}, document);
  ASSERT_EQ(shown.size(), 2u);
  EXPECT_EQ(shown[0], user);
  EXPECT_EQ(shown[1], document);
}

TEST(Ruler, AProfileTakesAPlacemarksFirstLineAndFitsTheWindow) {
  overlays::Placemark placemark;
  EXPECT_FALSE(placemarkLine(placemark));
  placemark.geometries.push_back({});  // a point
  placemark.geometries.push_back({overlays::GeometryKind::LineString,
                                  overlays::AltitudeMode::Absolute,
                                  false,
                                  false,
                                  {{{138.7, 35.3, 2000}, {138.8, 35.4, 2500}}}});
  const auto line = placemarkLine(placemark);
  ASSERT_TRUE(line);
  ASSERT_EQ(line->size(), 2u);
  EXPECT_EQ((*line)[1].longitudeDegrees, 138.8);
  EXPECT_TRUE(std::isnan((*line)[1].elevationMeters));
  EXPECT_EQ(profileChartSizePixels(640, 360), glm::ivec2(320, 150));
  EXPECT_EQ(profileChartSizePixels(1280, 720), glm::ivec2(640, 288));
  EXPECT_EQ(profileChartSizePixels(4000, 2000), glm::ivec2(900, 360));
}

}  // namespace
}  // namespace globe::app
