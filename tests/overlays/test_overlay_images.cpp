// GroundOverlay images as map exporters write them: GeoTIFFs (RGB and paletted) read through
// GDAL, on disk beside a KML and inside a KMZ; and an image that is missing or cannot be decoded
// is named in the document's warnings, never dropped without a word.
#include <gdal.h>
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "overlays/overlay_file.hpp"
#include "tests/overlays/overlay_test_files.hpp"

namespace globe::overlays {
namespace {

namespace fs = std::filesystem;

std::string groundOverlay(const std::string& name, const std::string& href) {
  return "<GroundOverlay><name>" + name + "</name><Icon><href>" + href +
         "</href></Icon><LatLonBox><north>36</north><south>35</south><east>139</east>"
         "<west>138</west></LatLonBox></GroundOverlay>";
}

// The colour of pixel (x, y) in the test images: a gradient no two neighbours share.
std::array<uint8_t, 3> colourAt(int x, int y) {
  return {static_cast<uint8_t>(20 * x), static_cast<uint8_t>(30 * y),
          static_cast<uint8_t>(100 + x + y)};
}

// An 8x4 GeoTIFF: three RGB bands, or one band of palette indexes into the same colours.
void writeGeoTiff(const fs::path& file, bool paletted) {
  GDALAllRegister();
  constexpr int kWidth = 8, kHeight = 4;
  GDALDatasetH d = GDALCreate(GDALGetDriverByName("GTiff"), file.c_str(), kWidth, kHeight,
                              paletted ? 1 : 3, GDT_Byte, nullptr);
  ASSERT_NE(d, nullptr);
  double transform[6] = {138, 1.0 / kWidth, 0, 36, 0, -1.0 / kHeight};
  GDALSetGeoTransform(d, transform);
  std::array<std::vector<uint8_t>, 3> bands;
  GDALColorTableH table = GDALCreateColorTable(GPI_RGB);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const auto c = colourAt(x, y);
      for (int b = 0; b < 3; ++b) bands[b].push_back(c[b]);
      const GDALColorEntry entry{c[0], c[1], c[2], 255};
      GDALSetColorEntry(table, y * kWidth + x, &entry);
    }
  }
  if (paletted) {
    std::vector<uint8_t> indexes(kWidth * kHeight);
    for (size_t k = 0; k < indexes.size(); ++k) indexes[k] = static_cast<uint8_t>(k);
    GDALSetRasterColorTable(GDALGetRasterBand(d, 1), table);
    ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(d, 1), GF_Write, 0, 0, kWidth, kHeight, indexes.data(),
                           kWidth, kHeight, GDT_Byte, 0, 0),
              CE_None);
  } else {
    for (int b = 0; b < 3; ++b) {
      ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(d, b + 1), GF_Write, 0, 0, kWidth, kHeight,
                             bands[b].data(), kWidth, kHeight, GDT_Byte, 0, 0),
                CE_None);
    }
  }
  GDALDestroyColorTable(table);
  GDALClose(d);
}

void expectTestImage(const GroundOverlay& overlay) {
  SCOPED_TRACE(overlay.name);
  ASSERT_NE(overlay.image, nullptr) << overlay.imageHref;
  ASSERT_EQ(overlay.image->widthPixels, 8);
  ASSERT_EQ(overlay.image->heightPixels, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      const uint8_t* p = &overlay.image->pixels[static_cast<size_t>(4 * (y * 8 + x))];
      const auto c = colourAt(x, y);
      EXPECT_EQ((std::array<uint8_t, 4>{p[0], p[1], p[2], p[3]}),
                (std::array<uint8_t, 4>{c[0], c[1], c[2], 255}))
          << x << "," << y;
    }
  }
}

std::string fileBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

TEST(OverlayImages, GeoTiffGroundOverlaysAreReadThroughGdal) {
  ScratchFolder scratch;
  writeGeoTiff(scratch.path() / "rgb.tif", false);
  writeGeoTiff(scratch.path() / "paletted.tif", true);
  const std::string features =
      groundOverlay("rgb", "rgb.tif") + groundOverlay("paletted", "paletted.tif");
  auto onDisk = readOverlayFile(scratch.write("maps.kml", kml(features)));
  ASSERT_TRUE(onDisk) << onDisk.error();
  EXPECT_TRUE(onDisk->warnings.empty()) << onDisk->warnings.front();
  ASSERT_EQ(onDisk->groundOverlays.size(), 2u);
  for (const GroundOverlay& overlay : onDisk->groundOverlays) expectTestImage(overlay);

  const fs::path kmz = scratch.path() / "maps.kmz";
  writeZip(kmz, {{"doc.kml", kml(features)},
                 {"rgb.tif", fileBytes(scratch.path() / "rgb.tif")},
                 {"paletted.tif", fileBytes(scratch.path() / "paletted.tif")}});
  fs::remove(scratch.path() / "rgb.tif");
  fs::remove(scratch.path() / "paletted.tif");
  auto inArchive = readOverlayFile(kmz);
  ASSERT_TRUE(inArchive) << inArchive.error();
  ASSERT_EQ(inArchive->groundOverlays.size(), 2u);
  for (const GroundOverlay& overlay : inArchive->groundOverlays) expectTestImage(overlay);
}

TEST(OverlayImages, MissingAndUndecodableImagesAreNamed) {
  ScratchFolder scratch;
  scratch.write("broken.png", "\x89PNG\r\n\x1a\n not really");
  auto document =
      readOverlayFile(scratch.write("maps.kml", kml(groundOverlay("missing", "gone.png") +
                                                    groundOverlay("broken", "broken.png"))));
  ASSERT_TRUE(document) << document.error();
  ASSERT_EQ(document->groundOverlays.size(), 2u);
  for (const GroundOverlay& overlay : document->groundOverlays) EXPECT_EQ(overlay.image, nullptr);
  ASSERT_EQ(document->warnings.size(), 2u);
  EXPECT_NE(document->warnings[0].find("image href \"gone.png\": "), std::string::npos)
      << document->warnings[0];
  EXPECT_NE(document->warnings[1].find("image href \"broken.png\": "), std::string::npos)
      << document->warnings[1];
  for (const std::string& warning : document->warnings)
    EXPECT_NE(warning.find("; not drawn"), std::string::npos) << warning;
}

}  // namespace
}  // namespace globe::overlays
