// GeoJSON and GPX: Natural Earth's countries (Polygons with holes, MultiPolygons, Fiji across
// the antimeridian), a Garmin GPX 1.0 log with waypoints and tracks, and hand-made cases for the
// geometry types, simplestyle properties, GPX 1.1 and the errors.
#include <gtest/gtest.h>

#include <string>

#include "overlays/geojson_reader.hpp"
#include "overlays/overlay_file.hpp"
#include "tests/overlays/overlay_test_files.hpp"

namespace globe::overlays {
namespace {

TEST(GeoJsonFiles, NaturalEarthCountries) {
  auto document = readOverlayFile(kInterop / "overlays/ne_110m_admin_0_countries.geojson");
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "ne_110m_admin_0_countries.geojson");
  ASSERT_EQ(document->placemarks.size(), 177u);  // 148 Polygons, 29 MultiPolygons
  size_t polygons = 0;
  for (const Placemark& p : document->placemarks) {
    for (const Geometry& g : p.geometries) {
      EXPECT_EQ(g.kind, GeometryKind::Polygon);
      EXPECT_EQ(g.altitudeMode, AltitudeMode::ClampToGround);
      ++polygons;
    }
  }
  EXPECT_EQ(polygons, 288u);
  EXPECT_EQ(document->placemarks[0].name, "Afghanistan");  // from "NAME"

  // Lesotho is South Africa's hole.
  const Placemark* southAfrica = findPlacemark(*document, "South Africa");
  ASSERT_NE(southAfrica, nullptr);
  ASSERT_EQ(southAfrica->geometries.size(), 1u);
  ASSERT_EQ(southAfrica->geometries[0].rings.size(), 2u);
  EXPECT_EQ(southAfrica->geometries[0].rings[0].size(), 82u);
  EXPECT_EQ(southAfrica->geometries[0].rings[1].size(), 12u);
  EXPECT_DOUBLE_EQ(southAfrica->geometries[0].rings[0][0].longitudeDegrees, 19.895767856534434);
  EXPECT_DOUBLE_EQ(southAfrica->geometries[0].rings[0][0].latitudeDegrees, -24.76779021576059);

  const Placemark* canada = findPlacemark(*document, "Canada");
  ASSERT_NE(canada, nullptr);
  EXPECT_EQ(canada->geometries.size(), 30u);
  EXPECT_DOUBLE_EQ(canada->geometries[0].rings[0][0].longitudeDegrees, -63.6645);

  // Fiji's islands either side of the antimeridian touch ±180 exactly.
  const Placemark* fiji = findPlacemark(*document, "Fiji");
  ASSERT_NE(fiji, nullptr);
  EXPECT_EQ(fiji->geometries.size(), 3u);
  bool east = false;
  bool west = false;
  for (const Geometry& g : fiji->geometries) {
    for (const Position& p : g.rings[0]) {
      east = east || p.longitudeDegrees == 180.0;
      west = west || p.longitudeDegrees == -180.0;
    }
  }
  EXPECT_TRUE(east);
  EXPECT_TRUE(west);
}

TEST(GpxFiles, GarminLogWithWaypointsAndTracks) {
  auto document = readOverlayFile(kInterop / "overlays/cerknicko-jezero.gpx");
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "cerknicko-jezero.gpx");
  // 7 waypoints and 7 of the 8 tracks ("ACTIVE LOG" has an empty segment).
  ASSERT_EQ(document->placemarks.size(), 14u);
  const Placemark& first = document->placemarks[0];
  EXPECT_EQ(first.name, "001");
  EXPECT_EQ(first.description, "05-AUG-10 16:58:37");
  ASSERT_EQ(first.geometries.size(), 1u);
  EXPECT_EQ(first.geometries[0].kind, GeometryKind::Point);
  EXPECT_DOUBLE_EQ(first.geometries[0].rings[0][0].latitudeDegrees, 45.772163216);
  EXPECT_DOUBLE_EQ(first.geometries[0].rings[0][0].longitudeDegrees, 14.357652292);
  EXPECT_EQ(findPlacemark(*document, "ACTIVE LOG"), nullptr);
  const Placemark* log2 = findPlacemark(*document, "ACTIVE LOG #2");
  ASSERT_NE(log2, nullptr);
  ASSERT_EQ(log2->geometries.size(), 1u);
  EXPECT_EQ(log2->geometries[0].kind, GeometryKind::LineString);
  EXPECT_EQ(log2->geometries[0].altitudeMode, AltitudeMode::ClampToGround);
  ASSERT_EQ(log2->geometries[0].rings[0].size(), 173u);
  EXPECT_DOUBLE_EQ(log2->geometries[0].rings[0][0].latitudeDegrees, 45.772175035);
  EXPECT_DOUBLE_EQ(log2->geometries[0].rings[0][0].longitudeDegrees, 14.357659249);
  EXPECT_DOUBLE_EQ(log2->geometries[0].rings[0][0].heightMeters, 542.320923);
  EXPECT_EQ(findPlacemark(*document, "ACTIVE LOG #8")->geometries[0].rings[0].size(), 21u);
}

TEST(GeoJsonCases, EveryGeometryTypeAndSimplestyle) {
  ScratchFolder scratch;
  const auto file = scratch.write("shapes.geojson", R"({
    "type": "FeatureCollection", "name": "Shapes",
    "features": [
      {"type": "Feature", "properties": {"title": "T", "description": "<b>d</b>",
        "stroke": "#ff8000", "stroke-width": 3, "stroke-opacity": 0.5, "fill": "#0f0",
        "fill-opacity": 0.2, "marker-color": "#123456"},
       "geometry": {"type": "GeometryCollection", "geometries": [
         {"type": "Point", "coordinates": [180, -90, 12.5]},
         {"type": "MultiPoint", "coordinates": [[1, 2], [3, 4]]},
         {"type": "LineString", "coordinates": [[0, 0], [1, 1]]},
         {"type": "MultiLineString", "coordinates": [[[0, 0], [1, 1]], [[2, 2], [3, 3]]]},
         {"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4]],
                                             [[1, 1], [2, 1], [2, 2], [1, 1]]]},
         {"type": "GeometryCollection", "geometries": [
           {"type": "MultiPolygon", "coordinates": [[[[5, 5], [6, 5], [6, 6], [5, 5]]],
                                                    [[[7, 7], [8, 7], [8, 8], [7, 7]]]]}]}]}},
      {"type": "Feature", "properties": {"NAME": "upper", "name_en": "english"},
       "geometry": {"type": "Point", "coordinates": [-180, 90]}},
      {"type": "Feature", "properties": null, "geometry": null},
      {"type": "Feature", "properties": {"name": "empty point"},
       "geometry": {"type": "Point", "coordinates": []}}
    ]})");
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "Shapes");
  ASSERT_EQ(document->placemarks.size(), 2u);
  const Placemark& t = document->placemarks[0];
  EXPECT_EQ(t.name, "T");
  EXPECT_EQ(t.description, "<b>d</b>");
  ASSERT_EQ(t.geometries.size(), 9u);
  EXPECT_EQ(t.geometries[0].rings[0][0].heightMeters, 12.5);
  EXPECT_EQ(t.geometries[2].rings[0][0].latitudeDegrees, 4.0);
  EXPECT_EQ(t.geometries[3].rings[0][1].latitudeDegrees, 1.0);
  EXPECT_EQ(t.geometries[3].kind, GeometryKind::LineString);
  EXPECT_EQ(t.geometries[5].rings[0][0].longitudeDegrees, 2.0);
  const Geometry& polygon = t.geometries[6];
  EXPECT_EQ(polygon.kind, GeometryKind::Polygon);
  ASSERT_EQ(polygon.rings.size(), 2u);
  EXPECT_EQ(polygon.rings[0].size(), 5u);  // closed by the reader
  EXPECT_EQ(polygon.rings[1].size(), 4u);
  EXPECT_EQ(t.geometries[8].rings[0][0].longitudeDegrees, 7.0);
  EXPECT_EQ(t.style.lineColor, (Rgba{255, 128, 0, 128}));
  EXPECT_EQ(t.style.lineWidthPixels, 3.0);
  EXPECT_EQ(t.style.polygonColor, (Rgba{0, 255, 0, 51}));
  EXPECT_EQ(t.style.iconColor, (Rgba{0x12, 0x34, 0x56, 255}));
  EXPECT_EQ(document->placemarks[1].name, "upper");
  // No simplestyle: CesiumJS's defaults, a yellow line and a translucent yellow fill.
  EXPECT_EQ(document->placemarks[1].style.lineColor, (Rgba{255, 255, 0, 255}));
  EXPECT_EQ(document->placemarks[1].style.lineWidthPixels, 2.0);
  EXPECT_EQ(document->placemarks[1].style.polygonColor, (Rgba{255, 255, 0, 100}));

  auto bare = readOverlayFile(scratch.write(
      "bare.json", R"({"type": "LineString", "coordinates": [[10, 20, 30], [11, 21, 31]]})"));
  ASSERT_TRUE(bare) << bare.error();
  ASSERT_EQ(bare->placemarks.size(), 1u);
  EXPECT_EQ(bare->placemarks[0].geometries.at(0).rings.at(0).at(1).heightMeters, 31.0);
  auto feature = readOverlayFile(scratch.write(
      "feature.geojson",
      R"({"type": "Feature", "properties": {}, "geometry": {"type": "Point", "coordinates": [1, 2]}})"));
  ASSERT_TRUE(feature) << feature.error();
  EXPECT_EQ(feature->placemarks.size(), 1u);
}

TEST(GeoJsonCases, ErrorsNameTheFileAndTheFeature) {
  ScratchFolder scratch;
  const struct {
    const char* json;
    const char* message;
  } cases[] = {
      {R"({"type": "FeatureCollection", "features": [{"type": "Feature", "properties":
          {"name": "Nowhere"}, "geometry": {"type": "Point", "coordinates": [10, 91]}}]})",
       R"(: feature 1 "Nowhere": position [10,91]: latitude 91 is outside -90..90)"},
      {R"({"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": null},
          {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[0, 0], ["a", 1]]}}]})",
       R"(: feature 2: a position ["a",1] is not [longitude, latitude(, height)])"},
      {R"({"type": "Feature", "geometry": {"type": "Circle", "coordinates": [0, 0]}})",
       R"(: feature 1: unknown geometry type "Circle")"},
      {R"({"type": "FeatureCollection", "features": 3})",
       ": a FeatureCollection without a \"features\" array"},
      {R"([1, 2, 3])", R"(: not GeoJSON (no "type" member in a top-level object))"},
      {R"({"type": "FeatureCollection", "features": [)", ": not JSON ("},
  };
  for (const auto& c : cases) {
    const auto file = scratch.write("bad.geojson", c.json);
    auto document = readOverlayFile(file);
    ASSERT_FALSE(document) << c.json;
    EXPECT_NE(document.error().find(file.string() + c.message), std::string::npos)
        << document.error();
  }
  std::string deep = R"({"type": "GeometryCollection", "geometries": [)";
  for (int i = 0; i < 70; ++i) deep += R"({"type": "GeometryCollection", "geometries": [)";
  for (int i = 0; i < 71; ++i) deep += "]}";
  auto document = readOverlayFile(scratch.write("deep.geojson", deep));
  ASSERT_FALSE(document);
  EXPECT_NE(document.error().find("GeometryCollections nested deeper than 64 levels"),
            std::string::npos)
      << document.error();
  document = readOverlayFile(scratch.write("brackets.json", std::string(100000, '[')));
  ASSERT_FALSE(document);
  EXPECT_NE(document.error().find("JSON nested deeper than 256 levels"), std::string::npos)
      << document.error();
}

// One bad feature among good ones is left out with a warning naming it, as GDAL reads the other
// 26 of such a file; many are listed five at a time.
TEST(GeoJsonCases, ABadFeatureIsLeftOutAndTheOthersRead) {
  ScratchFolder scratch;
  auto point = [](int k, const std::string& coordinates) {
    return R"({"type": "Feature", "properties": {"name": "P)" + std::to_string(k) +
           R"("}, "geometry": {"type": "Point", "coordinates": )" + coordinates + "}}";
  };
  std::string json = R"({"type": "FeatureCollection", "features": [)";
  for (int k = 1; k <= 27; ++k) {
    json += (k > 1 ? "," : "") + point(k, k == 14 ? "[139.7, 135.7]" : "[139.7, 35.7]");
  }
  const auto file = scratch.write("one-bad.geojson", json + "]}");
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->placemarks.size(), 26u);
  ASSERT_EQ(document->warnings.size(), 1u);
  EXPECT_EQ(document->warnings[0], file.string() +
                                       R"(: feature 14 "P14": position [139.7,135.7]: latitude )"
                                       R"(135.7 is outside -90..90; feature left out)");
  json = R"({"type": "FeatureCollection", "features": [)" + point(1, "[1, 2]");
  for (int k = 2; k <= 9; ++k) json += "," + point(k, R"(["x", 2])");
  document = readOverlayFile(scratch.write("many-bad.geojson", json + "]}"));
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->placemarks.size(), 1u);
  ASSERT_EQ(document->warnings.size(), 6u);
  EXPECT_NE(document->warnings[5].find(": 3 more features left out"), std::string::npos)
      << document->warnings[5];
}

TEST(GpxCases, Gpx11RoutesSegmentsAndErrors) {
  ScratchFolder scratch;
  const auto file = scratch.write("walk.gpx", R"(<?xml version="1.0"?>
<gpx version="1.1" creator="hand" xmlns="http://www.topografix.com/GPX/1/1">
  <metadata><name>Walk</name></metadata>
  <wpt lat="46.5" lon="7.5"><ele>1200</ele><name>Start</name><desc>car park</desc></wpt>
  <rte><name>Route</name><rtept lat="46.5" lon="7.5"/><rtept lat="46.6" lon="7.6"/>
    <rtept lat="46.7" lon="7.7"><ele>1500</ele></rtept></rte>
  <trk><name>Track</name>
    <trkseg><trkpt lat="1" lon="2"/><trkpt lat="3" lon="4"/></trkseg>
    <trkseg><trkpt lat="5" lon="6"/></trkseg>
    <trkseg><trkpt lat="7" lon="8"/><trkpt lat="9" lon="10"/></trkseg>
    <extensions><x/></extensions>
  </trk>
</gpx>)");
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "Walk");
  ASSERT_EQ(document->placemarks.size(), 3u);
  const Placemark& start = document->placemarks[0];
  EXPECT_EQ(start.name, "Start");
  EXPECT_EQ(start.description, "car park");
  EXPECT_EQ(start.geometries.at(0).rings.at(0).at(0).heightMeters, 1200.0);
  const Placemark& route = document->placemarks[1];
  EXPECT_EQ(route.name, "Route");
  ASSERT_EQ(route.geometries.size(), 1u);
  ASSERT_EQ(route.geometries[0].rings[0].size(), 3u);
  EXPECT_EQ(route.geometries[0].rings[0][2].heightMeters, 1500.0);
  const Placemark& track = document->placemarks[2];
  EXPECT_EQ(track.name, "Track");
  ASSERT_EQ(track.geometries.size(), 2u);  // the one-point segment draws nothing
  EXPECT_EQ(track.geometries[1].rings[0][1].longitudeDegrees, 10.0);

  const auto bad = scratch.write("bad.gpx",
                                 "<gpx version=\"1.0\">\n<trk><trkseg>\n<trkpt lat=\"95\" "
                                 "lon=\"1\"/>\n</trkseg></trk></gpx>");
  document = readOverlayFile(bad);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(),
            bad.string() + ": line 3: a <trkpt>'s latitude 95 is outside -90..90");
  // 1e308 and NaN where a device had no elevation: read as not given, with one warning.
  const auto ele = scratch.write("ele.gpx",
                                 "<gpx><trk><trkseg><trkpt lat=\"1\" lon=\"2\"><ele>1e308</ele>"
                                 "</trkpt><trkpt lat=\"1.1\" lon=\"2\"><ele>NaN</ele></trkpt>"
                                 "</trkseg></trk></gpx>");
  document = readOverlayFile(ele);
  ASSERT_TRUE(document) << document.error();
  ASSERT_EQ(document->placemarks.size(), 1u);
  EXPECT_EQ(document->placemarks[0].geometries.at(0).rings.at(0).at(0).heightMeters, 0.0);
  ASSERT_EQ(document->warnings.size(), 1u);
  EXPECT_EQ(document->warnings[0], ele.string() +
                                       ": 2 elevations outside -12000..100000 m or "
                                       "not numbers, read as not given");
  const auto noLat = scratch.write("nolat.gpx", "<gpx><wpt lon=\"1\"/></gpx>");
  document = readOverlayFile(noLat);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(), noLat.string() + ": line 1: a <wpt> without numeric lat and lon");
}

}  // namespace
}  // namespace globe::overlays
