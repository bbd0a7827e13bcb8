// Real KML and KMZ files: Google's KML Samples (styles, StyleMap, folders, polygons with holes,
// altitude modes, a GroundOverlay), USGS GNIS placemarks styled by StyleMaps with inline pairs,
// TfGM's Metrolink lines (MultiGeometry), and two KMZs from Google's kml-samples (an embedded
// ground overlay image, an embedded icon). Expected values were read from the files themselves.
#include <gtest/gtest.h>

#include "overlays/overlay_file.hpp"
#include "tests/overlays/overlay_test_files.hpp"

namespace globe::overlays {
namespace {

TEST(KmlFiles, GoogleKmlSamplesDocumentFoldersAndCounts) {
  auto document = readOverlayFile(kInterop / "kml/kmlsamples.kml");
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "KML Samples");
  // 20 Placemarks, one of them ("Descriptive HTML") without a geometry.
  EXPECT_EQ(document->placemarks.size(), 19u);
  EXPECT_EQ(findPlacemark(*document, "Descriptive HTML"), nullptr);
  ASSERT_EQ(document->groundOverlays.size(), 1u);  // ScreenOverlays are ignored

  const Placemark* simple = findPlacemark(*document, "Simple placemark");
  ASSERT_NE(simple, nullptr);
  EXPECT_EQ(simple->folderPath, "Placemarks");
  EXPECT_TRUE(simple->visible);
  EXPECT_NE(simple->description.find("Attached to the ground."), std::string::npos);
  ASSERT_EQ(simple->geometries.size(), 1u);
  const Geometry& point = simple->geometries[0];
  EXPECT_EQ(point.kind, GeometryKind::Point);
  EXPECT_EQ(point.altitudeMode, AltitudeMode::ClampToGround);
  ASSERT_EQ(point.rings.size(), 1u);
  ASSERT_EQ(point.rings[0].size(), 1u);
  EXPECT_DOUBLE_EQ(point.rings[0][0].longitudeDegrees, -122.082203542568);
  EXPECT_DOUBLE_EQ(point.rings[0][0].latitudeDegrees, 37.4222899014025);
  EXPECT_EQ(simple->style.lineColor, (Rgba{255, 255, 255, 255}));  // Google Earth's defaults
  EXPECT_EQ(simple->style.lineWidthPixels, 1.0);
  EXPECT_TRUE(simple->style.fill);
  EXPECT_TRUE(simple->style.outline);
  EXPECT_EQ(simple->style.labelScale, 1.0);
  EXPECT_TRUE(simple->style.iconHref.empty());

  // <visibility>0</visibility> on the placemark itself; an http icon stays a URL.
  const Placemark* floating = findPlacemark(*document, "Floating placemark");
  ASSERT_NE(floating, nullptr);
  EXPECT_FALSE(floating->visible);
  EXPECT_EQ(floating->geometries[0].altitudeMode, AltitudeMode::RelativeToGround);
  EXPECT_EQ(floating->style.iconHref, "http://maps.google.com/mapfiles/kml/pal4/icon28.png");
  EXPECT_EQ(floating->style.iconImage, nullptr);
  const Placemark* extruded = findPlacemark(*document, "Extruded placemark");
  ASSERT_NE(extruded, nullptr);
  EXPECT_TRUE(extruded->geometries[0].extrude);
  EXPECT_EQ(extruded->style.lineWidthPixels, 2.0);  // globeIcon's LineStyle
}

TEST(KmlFiles, GoogleKmlSamplesStyleMapNestedDocumentAndHiddenFolders) {
  auto document = readOverlayFile(kInterop / "kml/kmlsamples.kml");
  ASSERT_TRUE(document) << document.error();
  // A Document inside a Folder is a folder level; its StyleMap's "normal" pair is used.
  const Placemark* rollover =
      findPlacemark(*document, "Roll over this icon", "Styles and Markup/Highlighted Icon");
  ASSERT_NE(rollover, nullptr);
  EXPECT_FALSE(rollover->visible);
  EXPECT_EQ(rollover->style.iconHref, "http://maps.google.com/mapfiles/kml/paddle/wht-blank.png");

  // The Pentagon has no <visibility> of its own but sits in the hidden "Polygons" folder.
  const Placemark* pentagon = findPlacemark(*document, "The Pentagon");
  ASSERT_NE(pentagon, nullptr);
  EXPECT_EQ(pentagon->folderPath, "Polygons/Extruded Polygon");
  EXPECT_FALSE(pentagon->visible);
  ASSERT_EQ(pentagon->geometries.size(), 1u);
  const Geometry& polygon = pentagon->geometries[0];
  EXPECT_EQ(polygon.kind, GeometryKind::Polygon);
  EXPECT_TRUE(polygon.extrude);
  EXPECT_EQ(polygon.altitudeMode, AltitudeMode::RelativeToGround);
  ASSERT_EQ(polygon.rings.size(), 2u);  // the outer boundary and the courtyard
  ASSERT_EQ(polygon.rings[0].size(), 6u);
  EXPECT_DOUBLE_EQ(polygon.rings[0][0].longitudeDegrees, -77.0578845766097);
  EXPECT_DOUBLE_EQ(polygon.rings[0][0].latitudeDegrees, 38.8725325989282);
  EXPECT_DOUBLE_EQ(polygon.rings[0][0].heightMeters, 100);
  EXPECT_DOUBLE_EQ(polygon.rings[1][0].longitudeDegrees, -77.0566805501913);
  EXPECT_EQ(polygon.rings[1].front().latitudeDegrees, polygon.rings[1].back().latitudeDegrees);
}

TEST(KmlFiles, GoogleKmlSamplesSharedStylesAndAltitudeModes) {
  auto document = readOverlayFile(kInterop / "kml/kmlsamples.kml");
  ASSERT_TRUE(document) << document.error();
  // transPurpleLineGreenPoly: LineStyle 7fff00ff width 4, PolyStyle 7f00ff00.
  const Placemark* purple = findPlacemark(*document, "Absolute", "Paths");
  ASSERT_NE(purple, nullptr);
  EXPECT_EQ(purple->style.lineColor, (Rgba{255, 0, 255, 127}));
  EXPECT_EQ(purple->style.lineWidthPixels, 4.0);
  EXPECT_EQ(purple->style.polygonColor, (Rgba{0, 255, 0, 127}));
  EXPECT_EQ(purple->geometries[0].kind, GeometryKind::LineString);
  EXPECT_EQ(purple->geometries[0].altitudeMode, AltitudeMode::Absolute);

  const Placemark* tessellated = findPlacemark(*document, "Tessellated", "Paths");
  ASSERT_NE(tessellated, nullptr);
  EXPECT_TRUE(tessellated->geometries[0].tessellate);
  ASSERT_EQ(tessellated->geometries[0].rings[0].size(), 2u);
  EXPECT_DOUBLE_EQ(tessellated->geometries[0].rings[0][1].latitudeDegrees, 36.0905099328766);
  EXPECT_FALSE(findPlacemark(*document, "Untessellated", "Paths")->geometries[0].tessellate);

  // transRedPoly: LineStyle width 1.5, PolyStyle 7d0000ff.
  const Placemark* b40 = findPlacemark(*document, "Building 40", "Polygons/Google Campus");
  ASSERT_NE(b40, nullptr);
  EXPECT_EQ(b40->style.lineWidthPixels, 1.5);
  EXPECT_EQ(b40->style.polygonColor, (Rgba{255, 0, 0, 125}));
  EXPECT_EQ(b40->style.lineColor, (Rgba{255, 255, 255, 255}));

  const Placemark* absolute =
      findPlacemark(*document, "Absolute", "Polygons/Absolute and Relative");
  ASSERT_NE(absolute, nullptr);
  EXPECT_EQ(absolute->geometries[0].altitudeMode, AltitudeMode::Absolute);
  EXPECT_EQ(absolute->style.polygonColor, (Rgba{0, 0, 255, 125}));  // transBluePoly 7dff0000
  EXPECT_DOUBLE_EQ(absolute->geometries[0].rings[0][0].heightMeters, 1784);
}

TEST(KmlFiles, GoogleKmlSamplesGroundOverlayWithARemoteImage) {
  auto document = readOverlayFile(kInterop / "kml/kmlsamples.kml");
  ASSERT_TRUE(document) << document.error();
  const GroundOverlay& etna = document->groundOverlays.at(0);
  EXPECT_EQ(etna.name, "Large-scale overlay on terrain");
  EXPECT_FALSE(etna.visible);
  EXPECT_EQ(etna.imageHref, "http://code.google.com/apis/kml/documentation/etna.jpg");
  EXPECT_EQ(etna.image, nullptr);  // never fetched by the reader
  EXPECT_DOUBLE_EQ(etna.northDegrees, 37.9190419268166);
  EXPECT_DOUBLE_EQ(etna.southDegrees, 37.4654338859814);
  EXPECT_DOUBLE_EQ(etna.eastDegrees, 15.3583265374221);
  EXPECT_DOUBLE_EQ(etna.westDegrees, 14.601283697467);
  EXPECT_DOUBLE_EQ(etna.rotationDegrees, -0.155664079949624);
}

TEST(KmlFiles, GnisPlacemarksStyledByStyleMapsWithInlinePairs) {
  auto document = readOverlayFile(kInterop / "overlays/gnis-ak-first-101.kml");
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "gnis-ak-first-101.kml");  // its Document has no <name>
  ASSERT_EQ(document->placemarks.size(), 101u);
  const Placemark& pacific = document->placemarks[0];
  EXPECT_EQ(pacific.name, "Pacific Ocean");
  EXPECT_EQ(pacific.folderPath, "");
  EXPECT_DOUBLE_EQ(pacific.geometries.at(0).rings.at(0).at(0).longitudeDegrees, -123.8447222);
  EXPECT_DOUBLE_EQ(pacific.geometries[0].rings[0][0].latitudeDegrees, 39.3102778);
  // style-Sea's normal pair: IconStyle ff8f007f scale 0.8, LabelStyle scale 0.
  EXPECT_EQ(pacific.style.iconColor, (Rgba{0x7f, 0x00, 0x8f, 0xff}));
  EXPECT_DOUBLE_EQ(pacific.style.iconScale, 0.8);
  EXPECT_DOUBLE_EQ(pacific.style.labelScale, 0.0);
  EXPECT_EQ(pacific.style.iconHref,
            "http://maps.google.com/mapfiles/kml/shapes/placemark_circle.png");
  for (const Placemark& p : document->placemarks) {
    EXPECT_EQ(p.geometries.size(), 1u);
    EXPECT_EQ(p.geometries[0].kind, GeometryKind::Point);
    EXPECT_TRUE(p.visible);
  }
}

TEST(KmlFiles, MetrolinkLinesWithMultiGeometry) {
  auto document = readOverlayFile(kInterop / "overlays/tfgm-Metrolink_Lines_Functional.kml");
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "Metrolink_Lines_Functional");
  ASSERT_EQ(document->placemarks.size(), 20u);
  size_t lines = 0;
  for (const Placemark& p : document->placemarks) lines += p.geometries.size();
  EXPECT_EQ(lines, 24u);
  const Placemark* mediaCity = findPlacemark(*document, "MediaCity Spur", "RailwayLink");
  ASSERT_NE(mediaCity, nullptr);
  ASSERT_EQ(mediaCity->geometries.size(), 3u);  // the MultiGeometry, flattened
  EXPECT_EQ(mediaCity->geometries[0].rings[0].size(), 21u);
  EXPECT_EQ(mediaCity->geometries[1].rings[0].size(), 10u);
  EXPECT_EQ(mediaCity->geometries[2].rings[0].size(), 5u);
  EXPECT_TRUE(mediaCity->geometries[0].tessellate);
  EXPECT_DOUBLE_EQ(mediaCity->geometries[0].rings[0][0].longitudeDegrees, -2.29433475487594);
  EXPECT_DOUBLE_EQ(mediaCity->geometries[0].rings[0][0].latitudeDegrees, 53.4734013192895);
  EXPECT_EQ(mediaCity->style.lineColor, (Rgba{0xf0, 0xb4, 0x00, 0xff}));  // inline ff00b4f0
}

TEST(KmzFiles, EtnaGroundOverlayImageInsideTheArchive) {
  const auto file = kInterop / "overlays/etna.kmz";
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  EXPECT_TRUE(document->placemarks.empty());
  ASSERT_EQ(document->groundOverlays.size(), 1u);
  const GroundOverlay& etna = document->groundOverlays[0];
  EXPECT_EQ(etna.name, "Large-scale overlay on terrain");
  EXPECT_EQ(etna.description, "Overlay shows Mount Etna erupting on July 13th, 2001.");
  EXPECT_FALSE(etna.visible);
  EXPECT_DOUBLE_EQ(etna.westDegrees, 14.60128369746704);
  EXPECT_DOUBLE_EQ(etna.rotationDegrees, -0.1556640799496235);
  ASSERT_NE(etna.image, nullptr) << etna.imageHref;
  // etna.jpg is 558x418 (its JPEG header).
  EXPECT_EQ(etna.image->widthPixels, 558);
  EXPECT_EQ(etna.image->heightPixels, 418);
  EXPECT_EQ(etna.image->pixels.size(), size_t{558} * 418 * 4);
  EXPECT_EQ(etna.imageHref, "/vsizip/" + std::filesystem::absolute(file).string() + "/etna.jpg");
}

TEST(KmzFiles, StyledPlacemarkIconInsideTheArchive) {
  auto document = readOverlayFile(kInterop / "overlays/styled_placemark.kmz");
  ASSERT_TRUE(document) << document.error();
  ASSERT_EQ(document->placemarks.size(), 1u);
  const Placemark& placemark = document->placemarks[0];
  EXPECT_EQ(placemark.name, "styled placemark");
  EXPECT_EQ(placemark.description,
            "<img src=\"http://upload.wikimedia.org/wikipedia/commons/9/95/Usaf.u2.750pix.jpg\">");
  EXPECT_DOUBLE_EQ(placemark.style.iconScale, 1.1);
  EXPECT_EQ(placemark.style.labelColor, (Rgba{0, 0, 255, 255}));  // ffff0000: blue
  ASSERT_NE(placemark.style.iconImage, nullptr);
  EXPECT_EQ(placemark.style.iconImage->widthPixels, 80);
  EXPECT_EQ(placemark.style.iconImage->heightPixels, 80);
  EXPECT_TRUE(placemark.style.iconHref.ends_with("styled_placemark.kmz/icon.png"));
  EXPECT_DOUBLE_EQ(placemark.geometries.at(0).rings.at(0).at(0).longitudeDegrees,
                   48.11078528860224);
}

}  // namespace
}  // namespace globe::overlays
