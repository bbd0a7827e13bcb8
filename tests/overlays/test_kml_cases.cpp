// Hand-made KML for what the real files do not cover: hidden folders, the StyleMap and inline
// style cascade, gx:Track, ring closing, the antimeridian, local icons, what is ignored, and the
// errors (bad coordinates, not XML, hostile nesting).
#include <gtest/gtest.h>

#include <string>

#include "formats/image_io.hpp"
#include "overlays/kml_reader.hpp"
#include "overlays/overlay_file.hpp"
#include "tests/overlays/overlay_test_files.hpp"

namespace globe::overlays {
namespace {

std::string placemark(const std::string& name, const std::string& inner) {
  return "<Placemark><name>" + name + "</name>" + inner + "</Placemark>";
}

std::string point(const std::string& coordinates) {
  return "<Point><coordinates>" + coordinates + "</coordinates></Point>";
}

TEST(KmlCases, AHiddenFolderHidesEverythingInsideIt) {
  ScratchFolder scratch;
  const auto file = scratch.write(
      "folders.kml",
      kml("<name>Trip</name>"
          "<Folder><name>Days</name><visibility>0</visibility>"
          "  <Folder><name>Monday</name><visibility>1</visibility>" +
          placemark("Inn", point("7.5,46.1")) + "</Folder>" + placemark("Bridge", point("7,46")) +
          "</Folder>"
          "<Folder><name>Shown</name>" +
          placemark("Peak", point("7.6,46.2")) +
          placemark("Hut", "<visibility>0</visibility>" + point("7.7,46.3")) + "</Folder>" +
          placemark("Top", point("8,47"))));
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "Trip");
  ASSERT_EQ(document->placemarks.size(), 5u);
  const Placemark* inn = findPlacemark(*document, "Inn");
  ASSERT_NE(inn, nullptr);
  EXPECT_EQ(inn->folderPath, "Days/Monday");
  EXPECT_FALSE(inn->visible);  // its own folder says 1, its parent 0
  EXPECT_FALSE(findPlacemark(*document, "Bridge", "Days")->visible);
  EXPECT_TRUE(findPlacemark(*document, "Peak", "Shown")->visible);
  EXPECT_FALSE(findPlacemark(*document, "Hut", "Shown")->visible);
  EXPECT_TRUE(findPlacemark(*document, "Top", "")->visible);
}

TEST(KmlCases, StyleMapsResolveToTheirNormalPair) {
  ScratchFolder scratch;
  const auto file = scratch.write(
      "stylemap.kml",
      kml("<Style id=\"thin\"><LineStyle><color>ff0000ff</color><width>2</width></LineStyle>"
          "</Style>"
          "<Style id=\"hot\"><LineStyle><color>ff00ff00</color><width>9</width></LineStyle>"
          "</Style>"
          "<StyleMap id=\"byUrl\"><Pair><key>highlight</key><styleUrl>#hot</styleUrl></Pair>"
          "<Pair><key>normal</key><styleUrl>#thin</styleUrl></Pair></StyleMap>"
          "<StyleMap id=\"inlinePair\"><Pair><key>normal</key><Style><PolyStyle>"
          "<color>80ff0000</color><fill>0</fill></PolyStyle></Style></Pair>"
          "<Pair><key>highlight</key><styleUrl>#hot</styleUrl></Pair></StyleMap>"
          "<StyleMap id=\"loop\"><Pair><key>normal</key><styleUrl>#loop</styleUrl></Pair>"
          "</StyleMap>"
          "<Folder><name>F</name>"
          "<Style id=\"inFolder\"><LabelStyle><color>ff00ffff</color><scale>2</scale>"
          "</LabelStyle></Style></Folder>" +
          placemark("a", "<styleUrl>#byUrl</styleUrl>" + point("1,2")) +
          placemark("b", "<styleUrl>#inlinePair</styleUrl>" + point("1,2")) +
          placemark("c", "<styleUrl>#loop</styleUrl>" + point("1,2")) +
          placemark("d", "<styleUrl>#inFolder</styleUrl>" + point("1,2")) +
          placemark("e", "<styleUrl>#nowhere</styleUrl>" + point("1,2")) +
          placemark("f", "<styleUrl>other.kml#thin</styleUrl>" + point("1,2"))));
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  const Style& a = findPlacemark(*document, "a")->style;
  EXPECT_EQ(a.lineColor, (Rgba{255, 0, 0, 255}));
  EXPECT_EQ(a.lineWidthPixels, 2.0);
  const Style& b = findPlacemark(*document, "b")->style;
  EXPECT_EQ(b.polygonColor, (Rgba{0, 0, 255, 128}));
  EXPECT_FALSE(b.fill);
  EXPECT_TRUE(b.outline);
  EXPECT_EQ(b.lineWidthPixels, 1.0);
  EXPECT_EQ(findPlacemark(*document, "c")->style.lineWidthPixels, 1.0);  // a cycle: defaults
  const Style& d = findPlacemark(*document, "d")->style;
  EXPECT_EQ(d.labelColor, (Rgba{255, 255, 0, 255}));
  EXPECT_EQ(d.labelScale, 2.0);
  EXPECT_EQ(findPlacemark(*document, "e")->style.lineColor, (Rgba{255, 255, 255, 255}));
  EXPECT_EQ(findPlacemark(*document, "f")->style.lineWidthPixels, 1.0);
}

TEST(KmlCases, AnInlineStyleMergesOverTheSharedOne) {
  ScratchFolder scratch;
  const auto file = scratch.write(
      "inline.kml",
      kml("<Style id=\"shared\"><LineStyle><color>ff0000ff</color><width>3</width></LineStyle>"
          "<PolyStyle><color>7f00ff00</color><outline>0</outline></PolyStyle>"
          "<IconStyle><scale>1.5</scale><Icon><href>https://example.com/a.png</href></Icon>"
          "</IconStyle></Style>" +
          placemark("p", std::string(
                             "<styleUrl>#shared</styleUrl><Style><LineStyle><color>ffff0000</color>"
                             "</LineStyle><PolyStyle><fill>false</fill></PolyStyle></Style>") +
                             "<LineString><coordinates>0,0 1,1</coordinates></LineString>")));
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  const Style& style = document->placemarks.at(0).style;
  EXPECT_EQ(style.lineColor, (Rgba{0, 0, 255, 255}));  // the inline colour
  EXPECT_EQ(style.lineWidthPixels, 3.0);               // the shared width
  EXPECT_EQ(style.polygonColor, (Rgba{0, 255, 0, 127}));
  EXPECT_FALSE(style.fill);
  EXPECT_FALSE(style.outline);
  EXPECT_EQ(style.iconScale, 1.5);
  EXPECT_EQ(style.iconHref, "https://example.com/a.png");
}

TEST(KmlCases, GeometriesTracksAndAltitudeModes) {
  ScratchFolder scratch;
  const auto file = scratch.write(
      "geometries.kml",
      kml(placemark(
              "multi",
              "<MultiGeometry><Point><coordinates>1,2,3</coordinates></Point>"
              "<MultiGeometry><LinearRing><coordinates>0,0 1,0 1,1</coordinates></LinearRing>"
              "<Polygon><gx:altitudeMode>relativeToSeaFloor</gx:altitudeMode><outerBoundaryIs>"
              "<LinearRing><coordinates>0,0 4,0 4,4 0,4</coordinates></LinearRing>"
              "</outerBoundaryIs><innerBoundaryIs><LinearRing><coordinates>1,1 2,1 2,2"
              "</coordinates></LinearRing></innerBoundaryIs><innerBoundaryIs><LinearRing>"
              "<coordinates>3,3 3.5,3 3.5,3.5 3,3</coordinates></LinearRing></innerBoundaryIs>"
              "</Polygon></MultiGeometry></MultiGeometry>") +
          placemark("track",
                    "<gx:Track><gx:altitudeMode>clampToSeaFloor</gx:altitudeMode>"
                    "<when>2020-01-01T00:00:00Z</when><when>2020-01-01T00:01:00Z</when>"
                    "<gx:coord>7.1 46.1 1000</gx:coord><gx:coord>7.2 46.2 1100</gx:coord>"
                    "</gx:Track>") +
          placemark("tracks",
                    "<gx:MultiTrack><altitudeMode>absolute</altitudeMode><gx:Track>"
                    "<gx:coord>1 1 5</gx:coord><gx:coord>2 2 6</gx:coord></gx:Track><gx:Track>"
                    "<gx:altitudeMode>relativeToGround</gx:altitudeMode><gx:coord>3 3 0"
                    "</gx:coord><gx:coord>4 4 0</gx:coord></gx:Track></gx:MultiTrack>") +
          placemark("lonely line", "<LineString><coordinates>1,1</coordinates></LineString>") +
          placemark("model only", "<Model><Link><href>house.dae</href></Link></Model>") +
          "<NetworkLink><Link><href>http://example.com/a.kml</href></Link></NetworkLink>"
          "<ScreenOverlay><Icon><href>logo.png</href></Icon></ScreenOverlay>"
          "<PhotoOverlay><Icon><href>photo.jpg</href></Icon></PhotoOverlay>"
          "<gx:Tour><name>tour</name></gx:Tour>"));
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  ASSERT_EQ(document->placemarks.size(), 3u);  // the lonely line and the model draw nothing
  const Placemark* multi = findPlacemark(*document, "multi");
  ASSERT_EQ(multi->geometries.size(), 3u);
  EXPECT_EQ(multi->geometries[0].kind, GeometryKind::Point);
  EXPECT_EQ(multi->geometries[0].rings[0][0].heightMeters, 3.0);
  const Geometry& ring = multi->geometries[1];
  EXPECT_EQ(ring.kind, GeometryKind::LineString);
  ASSERT_EQ(ring.rings[0].size(), 4u);  // closed by the reader
  EXPECT_EQ(ring.rings[0][3].longitudeDegrees, 0.0);
  const Geometry& polygon = multi->geometries[2];
  EXPECT_EQ(polygon.kind, GeometryKind::Polygon);
  EXPECT_EQ(polygon.altitudeMode, AltitudeMode::RelativeToGround);
  ASSERT_EQ(polygon.rings.size(), 3u);
  EXPECT_EQ(polygon.rings[0].size(), 5u);
  EXPECT_EQ(polygon.rings[1].size(), 4u);
  EXPECT_EQ(polygon.rings[2].size(), 4u);  // already closed: unchanged
  EXPECT_EQ(polygon.rings[1].back().longitudeDegrees, 1.0);

  const Placemark* track = findPlacemark(*document, "track");
  ASSERT_EQ(track->geometries.size(), 1u);
  EXPECT_EQ(track->geometries[0].kind, GeometryKind::LineString);
  EXPECT_EQ(track->geometries[0].altitudeMode, AltitudeMode::ClampToGround);
  ASSERT_EQ(track->geometries[0].rings[0].size(), 2u);
  EXPECT_EQ(track->geometries[0].rings[0][1].latitudeDegrees, 46.2);
  EXPECT_EQ(track->geometries[0].rings[0][1].heightMeters, 1100.0);
  const Placemark* tracks = findPlacemark(*document, "tracks");
  ASSERT_EQ(tracks->geometries.size(), 2u);
  EXPECT_EQ(tracks->geometries[0].altitudeMode, AltitudeMode::Absolute);  // the MultiTrack's
  EXPECT_EQ(tracks->geometries[1].altitudeMode, AltitudeMode::RelativeToGround);
}

// MultiPolygon, MultiLineString and MultiPoint, which are not KML but which tools write and GDAL
// reads (GDAL's non_conformant_multi.kml, issue 4031): read as MultiGeometry.
TEST(KmlCases, NonConformantMultiElementsAreReadAsGdalReadsThem) {
  ScratchFolder scratch;
  const auto file = scratch.write("multi.kml", kml(R"(
    <Placemark><name>area</name><MultiPolygon><Polygon><outerBoundaryIs><LinearRing>
      <coordinates>0,0 0,1 1,1 1,0 0,0</coordinates></LinearRing></outerBoundaryIs></Polygon>
    </MultiPolygon></Placemark>
    <Placemark><name>line</name><MultiLineString><LineString><coordinates>0,0 1,1</coordinates>
    </LineString></MultiLineString></Placemark>
    <Placemark><name>point</name><MultiPoint><Point><coordinates>0,0</coordinates></Point>
    </MultiPoint></Placemark>)"));
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  ASSERT_EQ(document->placemarks.size(), 3u);
  const GeometryKind kinds[] = {GeometryKind::Polygon, GeometryKind::LineString,
                                GeometryKind::Point};
  for (size_t k = 0; k < 3; ++k) {
    ASSERT_EQ(document->placemarks[k].geometries.size(), 1u) << document->placemarks[k].name;
    EXPECT_EQ(document->placemarks[k].geometries[0].kind, kinds[k]) << document->placemarks[k].name;
  }
}

TEST(KmlCases, CoordinatesToleratedWhitespaceAndTheAntimeridian) {
  ScratchFolder scratch;
  const auto file = scratch.write(
      "antimeridian.kml",
      kml(placemark("dateline",
                    "<LineString><coordinates>\n\t 179.5,-16.8,0\n"
                    "180,-16.9\t-180,-17.0 \r\n  -179.5 , -17.1 , 12\n"
                    "</coordinates></LineString>") +
          placemark("pole", point(" +0,90 ")) + placemark("other pole", point("0,-90,-5"))));
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  const auto& line = findPlacemark(*document, "dateline")->geometries.at(0).rings.at(0);
  ASSERT_EQ(line.size(), 4u);
  EXPECT_EQ(line[1].longitudeDegrees, 180.0);
  EXPECT_EQ(line[2].longitudeDegrees, -180.0);
  EXPECT_EQ(line[3].longitudeDegrees, -179.5);
  EXPECT_EQ(line[3].latitudeDegrees, -17.1);
  EXPECT_EQ(line[3].heightMeters, 12.0);
  EXPECT_EQ(findPlacemark(*document, "pole")->geometries[0].rings[0][0].latitudeDegrees, 90.0);
  EXPECT_EQ(findPlacemark(*document, "other pole")->geometries[0].rings[0][0].heightMeters, -5.0);
}

TEST(KmlCases, BadCoordinatesNameTheFileAndThePlacemark) {
  ScratchFolder scratch;
  const struct {
    const char* coordinates;
    const char* problem;
  } cases[] = {{"10,95", "latitude 95 is outside -90..90"},
               {"180.0001,0", "longitude 180.0001 is outside -180..180"},
               {"nan,0", "longitude nan is outside -180..180"},
               {"0,inf", "latitude inf is outside -90..90"},
               {"0,0 1", "coordinate 2 \"1\" has no latitude"},
               {"0,0,0,0", "is not lon,lat[,alt]"},
               {"0,0 x,1", "coordinate 2 \"x,1\" is not lon,lat[,alt]"},
               {"0,0,inf", "height inf is not a finite number"},
               {"0,1e999", "coordinate 1 \"0,1e999\" is not lon,lat[,alt]"}};
  for (const auto& c : cases) {
    const auto file = scratch.write(
        "bad.kml", kml("<Folder>\n" + placemark("Summit", point(c.coordinates)) + "\n</Folder>"));
    auto document = readOverlayFile(file);
    ASSERT_FALSE(document) << c.coordinates;
    EXPECT_NE(document.error().find(file.string() + ": placemark \"Summit\" (line 5)"),
              std::string::npos)
        << document.error();
    EXPECT_NE(document.error().find(c.problem), std::string::npos) << document.error();
  }
  const auto track = scratch.write(
      "track.kml", kml(placemark("T",
                                 "<gx:Track><gx:coord>1 2 3</gx:coord><gx:coord>1 91 3"
                                 "</gx:coord></gx:Track>")));
  auto document = readOverlayFile(track);
  ASSERT_FALSE(document);
  EXPECT_NE(document.error().find("placemark \"T\""), std::string::npos) << document.error();
  EXPECT_NE(document.error().find("latitude 91"), std::string::npos) << document.error();
}

TEST(KmlCases, NotXmlNotKmlAndEmptyFilesAreClearErrors) {
  ScratchFolder scratch;
  const auto text = scratch.write("notes.kml", "just some notes\n");
  auto document = readOverlayFile(text);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(), text.string() +
                                  ": neither KML, KMZ, GeoJSON nor GPX (the file starts with "
                                  "neither '<' nor '{')");
  const auto broken = scratch.write("broken.kml", "<kml><Document><Placemark></Document></kml>");
  document = readOverlayFile(broken);
  ASSERT_FALSE(document);
  EXPECT_TRUE(document.error().starts_with(broken.string() + ": not XML (")) << document.error();
  const auto html = scratch.write("page.kml", "<!DOCTYPE html><html><body/></html>");
  document = readOverlayFile(html);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(), html.string() + ": not KML (the root element is <html>, not <kml>)");
  const auto empty = scratch.write("empty.kml", " \n");
  document = readOverlayFile(empty);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(), empty.string() + ": an empty file");
  document = readOverlayFile(scratch.path() / "missing.kml");
  ASSERT_FALSE(document);
  EXPECT_NE(document.error().find("missing.kml"), std::string::npos);
}

TEST(KmlCases, NestingBeyondTheLimitIsAnErrorNotACrash) {
  ScratchFolder scratch;
  const auto nested = [](const std::string& open, const std::string& close, int depth,
                         const std::string& inner) {
    std::string text;
    for (int i = 0; i < depth; ++i) text += open;
    text += inner;
    for (int i = 0; i < depth; ++i) text += close;
    return text;
  };
  // The top Document is level 1: 63 Folders inside it read, 64 do not.
  auto shallow = readOverlayFile(
      scratch.write("ok.kml", kml(nested("<Folder><name>f</name>", "</Folder>", kMaxKmlNesting - 1,
                                         placemark("deep", point("1,1"))))));
  ASSERT_TRUE(shallow) << shallow.error();
  EXPECT_EQ(shallow->placemarks.at(0).folderPath.size(), size_t{2 * (kMaxKmlNesting - 1) - 1});
  const auto deep = scratch.write("folders.kml", kml(nested("<Folder>", "</Folder>", kMaxKmlNesting,
                                                            placemark("deep", point("1,1")))));
  auto document = readOverlayFile(deep);
  ASSERT_FALSE(document);
  EXPECT_NE(
      document.error().find(deep.string() + ": Folders and Documents nested deeper than 64 levels"),
      std::string::npos)
      << document.error();
  const auto multi = scratch.write(
      "multi.kml",
      kml(placemark("m", nested("<MultiGeometry>", "</MultiGeometry>", 70, point("1,1")))));
  document = readOverlayFile(multi);
  ASSERT_FALSE(document);
  EXPECT_NE(document.error().find("MultiGeometry elements nested deeper than 64 levels"),
            std::string::npos)
      << document.error();
  // Deeper than the XML parser itself allows.
  const auto xml = scratch.write("xml.kml", kml(nested("<a>", "</a>", 5000, "")));
  document = readOverlayFile(xml);
  ASSERT_FALSE(document);
  EXPECT_TRUE(document.error().starts_with(xml.string() + ": not XML")) << document.error();
}

TEST(KmlCases, LocalIconsAndOverlayImagesBesideTheFile) {
  ScratchFolder scratch;
  std::filesystem::create_directories(scratch.path() / "icons");
  const formats::ImageRgba pin{2, 3, std::vector<uint8_t>(2 * 3 * 4, 200)};
  auto png = formats::encodePng(pin);
  ASSERT_TRUE(png) << png.error();
  scratch.write("icons/pin.png",
                std::string_view(reinterpret_cast<const char*>(png->data()), png->size()));
  const auto file = scratch.write(
      "local.kml",
      kml("<Style id=\"s\"><IconStyle><Icon><href>icons/pin.png</href></Icon></IconStyle>"
          "</Style>" +
          placemark("one", "<styleUrl>#s</styleUrl>" + point("1,1")) +
          placemark("two", "<styleUrl>#s</styleUrl>" + point("2,2")) +
          "<GroundOverlay><name>gone</name><color>80ffffff</color><drawOrder>3</drawOrder>"
          "<Icon><href>missing.jpg</href></Icon><LatLonBox><north>10</north><south>-10</south>"
          "<east>180</east><west>170</west></LatLonBox></GroundOverlay>"
          "<GroundOverlay><name>no box</name><Icon><href>a.png</href></Icon></GroundOverlay>"));
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  const Style& one = findPlacemark(*document, "one")->style;
  EXPECT_EQ(one.iconHref, (scratch.path() / "icons/pin.png").string());
  ASSERT_NE(one.iconImage, nullptr);
  EXPECT_EQ(one.iconImage->widthPixels, 2);
  EXPECT_EQ(one.iconImage->heightPixels, 3);
  EXPECT_EQ(findPlacemark(*document, "two")->style.iconImage, one.iconImage);  // decoded once
  ASSERT_EQ(document->groundOverlays.size(), 1u);  // without a LatLonBox: not placed
  const GroundOverlay& gone = document->groundOverlays[0];
  EXPECT_EQ(gone.image, nullptr);  // kept: the caller warns
  EXPECT_EQ(gone.imageHref, (scratch.path() / "missing.jpg").string());
  EXPECT_EQ(gone.color, (Rgba{255, 255, 255, 128}));
  EXPECT_EQ(gone.drawOrder, 3);
  EXPECT_EQ(gone.eastDegrees, 180.0);

  const auto bad = scratch.write(
      "badbox.kml", kml("<GroundOverlay><name>Bad box</name><LatLonBox><north>91</north>"
                        "</LatLonBox></GroundOverlay>"));
  document = readOverlayFile(bad);
  ASSERT_FALSE(document);
  EXPECT_NE(document.error().find("GroundOverlay \"Bad box\" (line 4): LatLonBox north \"91\""),
            std::string::npos)
      << document.error();
}

}  // namespace
}  // namespace globe::overlays
