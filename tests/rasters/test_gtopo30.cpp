// readGtopo30/writeGtopo30 on the real GTOPO30 files, cross-checked sample by sample against GDAL.
#include "rasters/gtopo30.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "tests/support/test_io_util.hpp"
#include "transport/atomic_file.hpp"

namespace globe::rasters {
namespace {

using globe::testing::TempDir;

std::string slurp(const std::filesystem::path& path) {
  std::stringstream s;
  s << std::ifstream(path, std::ios::binary).rdbuf();
  return s.str();
}

TEST(Gtopo30, EveryRealFileMatchesGdalSampleForSampleAndInGeolocation) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  size_t compared = 0;
  for (const std::string& stem : globe::testing::gtopo30Stems()) {
    SCOPED_TRACE(stem);
    auto raster = readGtopo30(dir / (stem + ".DEM"));
    ASSERT_TRUE(raster.ok()) << raster.error();
    const globe::testing::GdalRaster gdal =
        globe::testing::readWithGdal(dir / (stem + ".DEM"), "EHdr");
    ASSERT_TRUE(gdal.ok);
    EXPECT_EQ(gdal.type, GDT_Int16);
    ASSERT_EQ(gdal.cols, raster->header.cols);
    ASSERT_EQ(gdal.rows, raster->header.rows);
    ASSERT_EQ(gdal.heights.size(), raster->heights.size());
    EXPECT_TRUE(gdal.heights == raster->heights)
        << std::count_if(
               gdal.heights.begin(), gdal.heights.end(),
               [&, i = size_t{0}](int16_t v) mutable { return v != raster->heights[i++]; })
        << " samples differ";
    compared += gdal.heights.size();
    const Gtopo30Header& h = raster->header;
    EXPECT_NEAR(gdal.geoTransform[0], h.ulxMapDegrees - h.xDimDegrees / 2, 1e-9);
    EXPECT_NEAR(gdal.geoTransform[3], h.ulyMapDegrees + h.yDimDegrees / 2, 1e-9);
    EXPECT_NEAR(gdal.geoTransform[1], h.xDimDegrees, 1e-12);
    EXPECT_NEAR(gdal.geoTransform[5], -h.yDimDegrees, 1e-12);
    EXPECT_EQ(gdal.geoTransform[2], 0.0);
    EXPECT_EQ(gdal.geoTransform[4], 0.0);
  }
  // 240² + 1080·540 + 4 · 1201²
  EXPECT_EQ(compared, 57600u + 583200u + 4u * 1442401u);
}

TEST(Gtopo30, W002N52KnownValues) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  auto raster = readGtopo30(dir / "W002N52");  // the stem
  ASSERT_TRUE(raster.ok()) << raster.error();
  EXPECT_EQ(raster->header.rows, 240);
  EXPECT_EQ(raster->header.cols, 240);
  ASSERT_EQ(raster->heights.size(), 240u * 240u);
  int16_t lowest = INT16_MAX, highest = INT16_MIN;
  size_t noData = 0;
  for (int16_t v : raster->heights) {
    if (v == kNoDataHeight) {
      ++noData;
    } else {
      lowest = std::min(lowest, v);
      highest = std::max(highest, v);
    }
  }
  EXPECT_EQ(lowest, 1);
  EXPECT_EQ(highest, 613);
  EXPECT_EQ(noData, 821u);
  // The North Sea is in the north-east corner, land in the south-west.
  EXPECT_EQ(raster->at(0, 239), kNoDataHeight);
  EXPECT_NE(raster->at(239, 0), kNoDataHeight);
  EXPECT_EQ(raster->at(-1, 0), kNoDataHeight);
  EXPECT_EQ(raster->at(0, 240), kNoDataHeight);
}

TEST(Gtopo30, StxStatisticsOfRealTilesMatchTheirStx) {
  GLOBE_REQUIRE_DEM_DIR(dir, "gtopo30");
  TempDir tmp;
  for (const char* name : {"ETOPO20", "E138N35_FUJI", "N50E008", "N57E011"}) {
    const std::string stem = name;
    auto raster = readGtopo30(dir / (stem + ".HDR"));  // the header names it too
    ASSERT_TRUE(raster.ok()) << raster.error();
    ASSERT_TRUE(writeGtopo30(tmp / stem, *raster).ok());
    for (const char* ext : {".STX", ".PRJ", ".DEM"}) {
      EXPECT_EQ(slurp(tmp / (stem + ext)), slurp(dir / (stem + ext))) << stem << ext;
    }
  }
}

Gtopo30Raster smallRaster() {
  Gtopo30Raster r;
  r.header.rows = 3;
  r.header.cols = 4;
  r.header.ulxMapDegrees = -179.75;
  r.header.ulyMapDegrees = -10.25;
  r.header.xDimDegrees = 0.5;
  r.header.yDimDegrees = 0.5;
  r.heights = {-9999, -9999, 0, 1, -32768, 32767, -100, -1, 255, 256, 8848, -10994};
  return r;
}

TEST(Gtopo30, WriteThenReadRoundTripsAndGdalAgrees) {
  TempDir tmp;
  const Gtopo30Raster raster = smallRaster();
  ASSERT_TRUE(writeGtopo30(tmp / "T", raster).ok());
  for (const char* ext : {".DEM", ".HDR", ".PRJ", ".STX"}) {
    EXPECT_TRUE(std::filesystem::exists(tmp / (std::string("T") + ext))) << ext;
  }
  EXPECT_EQ(std::filesystem::file_size(tmp / "T.DEM"), 24u);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(tmp.path()),
                          std::filesystem::directory_iterator()),
            4);

  auto back = readGtopo30(tmp / "T.DEM");
  ASSERT_TRUE(back.ok()) << back.error();
  EXPECT_EQ(back->heights, raster.heights);
  EXPECT_EQ(back->header.ulxMapDegrees, -179.75);
  EXPECT_EQ(back->header.ulyMapDegrees, -10.25);
  EXPECT_EQ(back->header.byteOrder, 'M');
  EXPECT_EQ(back->at(1, 0), -32768);
  EXPECT_EQ(back->at(2, 3), -10994);

  // Big-endian on disk, whatever the host.
  const std::string dem = slurp(tmp / "T.DEM");
  EXPECT_EQ(static_cast<unsigned char>(dem[4]), 0x00);  // 0
  EXPECT_EQ(static_cast<unsigned char>(dem[6]), 0x00);  // 1 = 00 01
  EXPECT_EQ(static_cast<unsigned char>(dem[7]), 0x01);
  EXPECT_EQ(slurp(tmp / "T.STX"), "1 -32768 32767 -173.6 15318.0\n");

  const globe::testing::GdalRaster gdal = globe::testing::readWithGdal(tmp / "T.DEM", "EHdr");
  ASSERT_TRUE(gdal.ok);
  EXPECT_EQ(gdal.type, GDT_Int16);
  EXPECT_EQ(gdal.heights, raster.heights);
  EXPECT_TRUE(gdal.hasNoData);
  EXPECT_EQ(gdal.noData, -9999);
  EXPECT_NEAR(gdal.geoTransform[0], -180.0, 1e-12);
  EXPECT_NEAR(gdal.geoTransform[3], -10.0, 1e-12);
  EXPECT_NEAR(gdal.geoTransform[1], 0.5, 1e-15);
  EXPECT_NEAR(gdal.geoTransform[5], -0.5, 1e-15);
}

TEST(Gtopo30, ReadsLittleEndianAndPaddedRows) {
  TempDir tmp;
  // 2 x 3 samples, Intel order, rows padded to 8 bytes (the last row's padding absent).
  const int16_t values[] = {-9999, -5, 300, 7, 32767, -32768};
  std::string dem;
  for (int row = 0; row < 2; ++row) {
    for (int col = 0; col < 3; ++col) {
      const auto v = static_cast<uint16_t>(values[row * 3 + col]);
      dem += static_cast<char>(v & 0xff);
      dem += static_cast<char>(v >> 8);
    }
    if (row == 0) dem += std::string("\xAA\xBB", 2);
  }
  globe::testing::writeText(tmp / "le.dem", dem);
  globe::testing::writeText(
      tmp / "le.hdr",
      "BYTEORDER I\nLAYOUT BIL\nNROWS 2\nNCOLS 3\nNBANDS 1\nNBITS 16\n"
      "BANDROWBYTES 6\nTOTALROWBYTES 8\nULXMAP 1\nULYMAP 2\nXDIM 1\nYDIM 1\n");
  auto r = readGtopo30(tmp / "le.dem");
  ASSERT_TRUE(r.ok()) << r.error();
  EXPECT_EQ(r->heights, std::vector<int16_t>(std::begin(values), std::end(values)));
  // Written back it becomes plain big-endian GTOPO30.
  ASSERT_TRUE(writeGtopo30(tmp / "be", *r).ok());
  auto be = readGtopo30(tmp / "be.HDR");
  ASSERT_TRUE(be.ok()) << be.error();
  EXPECT_EQ(be->heights, r->heights);
  EXPECT_EQ(be->header.totalRowBytes, 6);
  EXPECT_EQ(be->header.byteOrder, 'M');
}

TEST(Gtopo30, FindsFilesWhateverTheExtensionCase) {
  TempDir tmp;
  const Gtopo30Raster raster = smallRaster();
  ASSERT_TRUE(writeGtopo30(tmp / "Up", raster).ok());
  std::filesystem::rename(tmp / "Up.DEM", tmp / "lower.dem");
  std::filesystem::rename(tmp / "Up.HDR", tmp / "lower.Hdr");
  for (const char* name : {"lower.dem", "lower.Hdr", "lower"}) {
    auto r = readGtopo30(tmp / name);
    ASSERT_TRUE(r.ok()) << name << ": " << r.error();
    EXPECT_EQ(r->heights, raster.heights);
  }
  auto files = findGtopo30Files(tmp / "lower");
  ASSERT_TRUE(files.ok()) << files.error();
  EXPECT_EQ(files->data.filename(), "lower.dem");
  EXPECT_EQ(files->header.filename(), "lower.Hdr");
}

TEST(Gtopo30, WriteDropsGivenExtensionAndRejectsInconsistentRasters) {
  TempDir tmp;
  Gtopo30Raster raster = smallRaster();
  ASSERT_TRUE(writeGtopo30(tmp / "x.DEM", raster).ok());
  EXPECT_TRUE(std::filesystem::exists(tmp / "x.HDR"));

  raster.heights.pop_back();
  auto r = writeGtopo30(tmp / "bad", raster);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("bad: raster has 11 heights but its header says 3 x 4"),
            std::string::npos)
      << r.error();
  EXPECT_FALSE(std::filesystem::exists(tmp / "bad.DEM"));

  raster = smallRaster();
  raster.header.xDimDegrees = 0;
  EXPECT_FALSE(writeGtopo30(tmp / "bad", raster).ok());
  auto missingDir = writeGtopo30(tmp / "no/dir/t", smallRaster());
  ASSERT_FALSE(missingDir.ok());
  EXPECT_NE(missingDir.error().find("no/dir/t.DEM"), std::string::npos) << missingDir.error();
}

}  // namespace
}  // namespace globe::rasters
