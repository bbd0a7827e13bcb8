// Hand-made KMZs (written with GDAL's zip writer): a KML not called doc.kml, an icon in a
// subfolder of the archive, a missing overlay image; and what is not a KMZ.
#include <cpl_conv.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "formats/image_io.hpp"
#include "overlays/overlay_file.hpp"
#include "tests/overlays/overlay_test_files.hpp"

namespace globe::overlays {
namespace {

std::string pngBytes(int width, int height) {
  const formats::ImageRgba image{width, height,
                                 std::vector<uint8_t>(static_cast<size_t>(width * height * 4), 90)};
  auto png = formats::encodePng(image);
  EXPECT_TRUE(png) << png.error();
  return png ? std::string(reinterpret_cast<const char*>(png->data()), png->size()) : "";
}

TEST(KmzCases, TheFirstKmlAtTheRootAndImagesInsideTheArchive) {
  ScratchFolder scratch;
  const auto file = scratch.path() / "trip.kmz";
  writeZip(file, {{"files/pin.png", pngBytes(4, 5)},
                  {"files/nested.kml", kml("<name>nested</name>")},
                  {"overview.kml",
                   kml("<name>Overview</name><Placemark><name>camp</name><Style><IconStyle><Icon>"
                       "<href>files/pin.png</href></Icon></IconStyle></Style><Point><coordinates>"
                       "6.9,45.9</coordinates></Point></Placemark>"
                       "<GroundOverlay><name>map</name><Icon><href>files/map.jpg</href></Icon>"
                       "<LatLonBox><north>46</north><south>45</south><east>7</east><west>6</west>"
                       "</LatLonBox></GroundOverlay>")},
                  {"second.kml", kml("<name>second</name>")}});
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  EXPECT_EQ(document->name, "Overview");
  ASSERT_EQ(document->placemarks.size(), 1u);
  const Style& style = document->placemarks[0].style;
  EXPECT_EQ(style.iconHref, "/vsizip/" + file.string() + "/files/pin.png");
  ASSERT_NE(style.iconImage, nullptr);
  EXPECT_EQ(style.iconImage->widthPixels, 4);
  EXPECT_EQ(style.iconImage->heightPixels, 5);
  ASSERT_EQ(document->groundOverlays.size(), 1u);
  EXPECT_EQ(document->groundOverlays[0].image, nullptr);  // not in the archive nor beside it
  EXPECT_EQ(document->groundOverlays[0].northDegrees, 46.0);
}

TEST(KmzCases, ImagesBesideTheArchiveWhenNotInIt) {
  ScratchFolder scratch;
  scratch.write("beside.png", pngBytes(3, 3));
  const auto file = scratch.path() / "doc.kmz";
  writeZip(file, {{"doc.kml", kml("<GroundOverlay><Icon><href>beside.png</href></Icon>"
                                  "<LatLonBox><north>1</north><south>0</south><east>1</east>"
                                  "<west>0</west></LatLonBox></GroundOverlay>")}});
  auto document = readOverlayFile(file);
  ASSERT_TRUE(document) << document.error();
  ASSERT_EQ(document->groundOverlays.size(), 1u);
  ASSERT_NE(document->groundOverlays[0].image, nullptr);
  EXPECT_EQ(document->groundOverlays[0].imageHref, (scratch.path() / "beside.png").string());
}

TEST(KmzCases, NotAZipOrNoKmlAreClearErrors) {
  ScratchFolder scratch;
  const auto text = scratch.write("fake.kmz", kml(""));
  auto document = readOverlayFile(text);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(), text.string() + ": not a KMZ (the file is not a zip archive)");

  const auto noKml = scratch.path() / "images.kmz";
  writeZip(noKml, {{"readme.txt", "hello"}, {"sub/doc.kml", kml("")}});
  document = readOverlayFile(noKml);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(),
            noKml.string() + ": a zip archive with no .kml file at its root, not a KMZ");

  // A zip's signature followed by garbage, whatever its extension.
  const auto truncated = scratch.write("cut.kml", std::string("PK\3\4", 4) + "garbage");
  document = readOverlayFile(truncated);
  ASSERT_FALSE(document);
  EXPECT_EQ(document.error(), truncated.string() + ": not a KMZ (the file is not a zip archive)");

  const auto badKml = scratch.path() / "bad.kmz";
  writeZip(badKml, {{"doc.kml", kml("<Placemark><name>P</name><Point><coordinates>0,99"
                                    "</coordinates></Point></Placemark>")}});
  document = readOverlayFile(badKml);
  ASSERT_FALSE(document);
  EXPECT_NE(document.error().find(badKml.string() + ": placemark \"P\""), std::string::npos)
      << document.error();
}

}  // namespace
}  // namespace globe::overlays
