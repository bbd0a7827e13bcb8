// An overlay file is bounded by its work, not its bytes: the readers count placemarks and
// vertices and stop with an error naming the file and the limit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "overlays/overlay_budget.hpp"
#include "overlays/overlay_file.hpp"
#include "tests/overlays/overlay_test_files.hpp"

namespace globe::overlays {
namespace {

Placemark pointAt(double lon, double lat) {
  Placemark p;
  p.geometries.push_back(Geometry{GeometryKind::Point, AltitudeMode::ClampToGround, false, false,
                                  {{Position{lon, lat, 0}}}});
  return p;
}

TEST(OverlayBudget, StopsPastThePlacemarkLimitNamingTheFile) {
  OverlayBudget budget("bomb.kml");
  OverlayDocument document;
  const Placemark p = pointAt(1, 2);
  for (size_t i = 0; i < kMaxOverlayPlacemarks; ++i) {
    ASSERT_TRUE(budget.append(p, document));
    document.placemarks.clear();  // the budget counts what the file held, kept or not
  }
  const auto past = budget.append(p, document);
  ASSERT_FALSE(past);
  EXPECT_NE(past.error().find("bomb.kml: more than 500000 placemarks"), std::string::npos)
      << past.error();
}

TEST(OverlayBudget, StopsPastTheVertexLimit) {
  OverlayBudget budget("long.geojson");
  OverlayDocument document;
  Placemark line;
  line.geometries.push_back(Geometry{GeometryKind::LineString, AltitudeMode::ClampToGround, false,
                                     false, {std::vector<Position>(kMaxOverlayVertices / 4)}});
  for (int i = 0; i < 4; ++i) {
    ASSERT_TRUE(budget.append(line, document));
    document.placemarks.clear();
  }
  const auto past = budget.append(pointAt(0, 0), document);
  ASSERT_FALSE(past);
  EXPECT_NE(past.error().find("long.geojson: more than 10000000 vertices"), std::string::npos)
      << past.error();
}

// Through a reader: a GPX file of 500,001 waypoints (14 MB) is refused as it is read.
TEST(OverlayBudget, AReaderRefusesAFilePastTheLimit) {
  const ScratchFolder dir;
  const auto gpx = dir.path() / "route.gpx";
  {
    std::ofstream out(gpx);
    out << "<?xml version=\"1.0\"?>\n<gpx version=\"1.1\" creator=\"t\">";
    for (size_t i = 0; i <= kMaxOverlayPlacemarks; ++i) out << "<wpt lat=\"1\" lon=\"2\"/>";
    out << "</gpx>\n";
  }
  const auto read = readOverlayFile(gpx);
  ASSERT_FALSE(read);
  EXPECT_NE(read.error().find(gpx.string() + ": more than 500000 placemarks"), std::string::npos)
      << read.error();
}

}  // namespace
}  // namespace globe::overlays
