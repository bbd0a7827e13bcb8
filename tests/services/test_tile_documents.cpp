// Tile documents written the way real producers write them: tilemapresource.xml as gdal2tiles 1.x
// wrote it (the box and origin in degrees, latitude first, whatever the SRS), read as CesiumJS
// reads it with flipXY; and WMTS CRS84 sets with latitude-first corners, read as OpenLayers and
// GDAL read them. Each gives the grid of the same document written right.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "services/imagery_services.hpp"
#include "services/tms_tilemap.hpp"
#include "services/wmts_capabilities.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::services {
namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

void expectSameGrid(const TmsTileMap& a, const TmsTileMap& b) {
  ASSERT_EQ(a.tiling.matrices.size(), b.tiling.matrices.size());
  EXPECT_EQ(a.tiling.crs, b.tiling.crs);
  for (size_t k = 0; k < a.tiling.matrices.size(); ++k) {
    SCOPED_TRACE(k);
    const TileMatrix &m = a.tiling.matrices[k], &n = b.tiling.matrices[k];
    EXPECT_EQ(m.columns, n.columns);
    EXPECT_EQ(m.rows, n.rows);
    EXPECT_NEAR(m.originX, n.originX, 1e-6);
    EXPECT_NEAR(m.originY, n.originY, 1e-6);
  }
  EXPECT_NEAR(a.bounds.west, b.bounds.west, 1e-9);
  EXPECT_NEAR(a.bounds.south, b.bounds.south, 1e-9);
  EXPECT_NEAR(a.bounds.east, b.bounds.east, 1e-9);
  EXPECT_NEAR(a.bounds.north, b.bounds.north, 1e-9);
}

TEST(TmsTileMap, AGeodeticBoxWrittenLatitudeFirstIsTheSameGrid) {
  const std::string xml = readText(std::string(GLOBE_SOURCE_DIR) +
                                   "/tests/data/interop/raster-tiles/tms-geodetic-naturalearth2/"
                                   "tilemapresource.xml");
  auto right = parseTmsTileMap(xml, "right.xml");
  ASSERT_TRUE(right) << right.error();
  EXPECT_EQ(right->tiling.matrices.at(0).columns, 2u);
  EXPECT_EQ(right->tiling.matrices.at(0).rows, 1u);
  // gdal2tiles 1.x: minx = south, miny = west, and the origin likewise.
  std::string flipped = replaced(
      xml,
      R"(miny="-90.00000000000000" minx="-180.00000000000000" maxy="90.00000000000000" maxx="180.00000000000000")",
      R"(minx="-90.00000000000000" miny="-180.00000000000000" maxx="90.00000000000000" maxy="180.00000000000000")");
  flipped = replaced(flipped, R"(<Origin y="-90.00000000000000" x="-180.00000000000000"/>)",
                     R"(<Origin x="-90.00000000000000" y="-180.00000000000000"/>)");
  auto read = parseTmsTileMap(flipped, "flipped.xml");
  ASSERT_TRUE(read) << read.error();
  expectSameGrid(*read, *right);
}

std::string mercatorTileMap(const std::string& box, const std::string& origin) {
  return R"(<?xml version="1.0"?><TileMap version="1.0.0"><Title>t</Title><SRS>EPSG:900913</SRS>)" +
         box + origin +
         R"(<TileFormat width="256" height="256" mime-type="image/png" extension="png"/>
  <TileSets profile="mercator">
    <TileSet href="0" units-per-pixel="156543.03390000000945" order="0"/>
    <TileSet href="1" units-per-pixel="78271.51695000000473" order="1"/>
    <TileSet href="2" units-per-pixel="39135.75847500000236" order="2"/>
  </TileSets></TileMap>)";
}

TEST(TmsTileMap, AMercatorBoxWrittenInDegreesIsTheGlobalGrid) {
  // The world's Web Mercator square in metres, as the spec has it.
  const std::string half = "20037508.342789244";
  auto right =
      parseTmsTileMap(mercatorTileMap(R"(<BoundingBox minx="-)" + half + R"(" miny="-)" + half +
                                          R"(" maxx=")" + half + R"(" maxy=")" + half + R"("/>)",
                                      R"(<Origin x="-)" + half + R"(" y="-)" + half + R"("/>)"),
                      "right.xml");
  ASSERT_TRUE(right) << right.error();
  EXPECT_EQ(right->tiling.matrices.at(2).columns, 4u);
  // gdal2tiles 1.x over the same world: south, west, north, east in degrees.
  auto degrees =
      parseTmsTileMap(mercatorTileMap(R"(<BoundingBox minx="-85.05112877980659" miny="-180.0" )"
                                      R"(maxx="85.05112877980659" maxy="180.0"/>)",
                                      R"(<Origin x="-85.05112877980659" y="-180.0"/>)"),
                      "degrees.xml");
  ASSERT_TRUE(degrees) << degrees.error();
  expectSameGrid(*degrees, *right);
  // A part of it: the same global grid, the box where the tiles are.
  auto part = parseTmsTileMap(
      mercatorTileMap(R"(<BoundingBox minx="35.0" miny="138.0" maxx="36.0" maxy="139.0"/>)",
                      R"(<Origin x="35.0" y="138.0"/>)"),
      "part.xml");
  ASSERT_TRUE(part) << part.error();
  EXPECT_EQ(part->tiling.matrices.at(2).columns, 4u);
  EXPECT_NEAR(part->tiling.matrices.at(2).originX, -20037508.342789244, 1e-3);
  EXPECT_DOUBLE_EQ(part->bounds.west, 138.0);
  EXPECT_DOUBLE_EQ(part->bounds.north, 36.0);
}

TEST(WmtsCapabilities, Crs84CornersWrittenLatitudeFirstAreTheSameGrid) {
  const std::string xml = readText(std::string(GLOBE_SOURCE_DIR) +
                                   "/tests/data/interop/wmts/nasa-gibs-eosdis-wmts-cap.xml");
  std::string flipped = xml;
  size_t corners = 0;
  const std::string right = "<TopLeftCorner>-180 90</TopLeftCorner>";
  for (size_t at = 0; (at = flipped.find(right, at)) != std::string::npos; ++corners)
    flipped.replace(at, right.size(), "<TopLeftCorner>90 -180</TopLeftCorner>");
  ASSERT_GT(corners, 5u);
  auto a = parseWmtsCapabilities(xml, "right.xml");
  auto b = parseWmtsCapabilities(flipped, "flipped.xml");
  ASSERT_TRUE(a && b);
  ASSERT_EQ(a->tileMatrixSets.size(), b->tileMatrixSets.size());
  size_t compared = 0;
  for (const auto& [id, set] : a->tileMatrixSets) {
    const TileMatrixSet& other = b->tileMatrixSets.at(id);
    ASSERT_EQ(set.matrices.size(), other.matrices.size()) << id;
    for (size_t k = 0; k < set.matrices.size(); ++k, ++compared) {
      EXPECT_EQ(set.matrices[k].originX, other.matrices[k].originX) << id;
      EXPECT_EQ(set.matrices[k].originY, other.matrices[k].originY) << id;
    }
  }
  EXPECT_GT(compared, 5u);
  EXPECT_EQ(a->tileMatrixSets.begin()->second.matrices.at(0).originX, -180.0);
}

// A PMTiles archive of vector tiles (or of a type PMTiles does not define) is refused saying
// which; AVIF archives are read (test_avif_tiles.cpp).
TEST(PmtilesImagery, TileTypesThatAreNotReadAreNamed) {
  const std::string real = std::string(GLOBE_SOURCE_DIR) +
                           "/tests/data/interop/pmtiles/usgs-mt-whitney-8-15-webp-512.pmtiles";
  std::ifstream in(real, std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), {}};
  ASSERT_GT(bytes.size(), 127u);
  ASSERT_EQ(bytes[99], 4) << "the archive's tile type byte (WebP)";
  const std::filesystem::path dir = globe::testing::freshTempDir("pmtiles-types");
  const struct {
    char type;
    const char* says;
  } cases[] = {{1, "its tiles are Mapbox vector tiles, not imagery"},
               {9, "its tiles are of unknown type 9"}};
  for (const auto& c : cases) {
    bytes[99] = c.type;
    const std::filesystem::path file = dir / ("type" + std::to_string(int{c.type}) + ".pmtiles");
    std::ofstream(file, std::ios::binary) << bytes;
    transport::NetworkSettings settings;
    settings.useCache = false;
    auto layer = openImageryTiles("pmtiles:" + file.string(),
                                  std::make_shared<transport::Network>(settings));
    ASSERT_FALSE(layer) << c.says;
    EXPECT_NE(layer.error().find(c.says), std::string::npos) << layer.error();
  }
}

}  // namespace
}  // namespace globe::services
