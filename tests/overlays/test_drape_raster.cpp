// The draped overlays drawn into imagery tiles: where lines and fills land, holes, the
// antimeridian, agreement along tile edges, ground overlays, and which tiles are touched.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <vector>

#include "geo/tiling_scheme.hpp"
#include "overlays/drape_raster.hpp"
#include "overlays/drape_set.hpp"
#include "overlays/overlay_file.hpp"
#include "overlays/overlay_imagery.hpp"
#include "tests/support/build_paths.hpp"

namespace globe::overlays {
namespace {

constexpr int kSize = 256;

Position drapeAt(double lon, double lat) { return {lon, lat, 0}; }

std::shared_ptr<const OverlayDocument> documentOf(std::vector<Placemark> placemarks,
                                                  std::vector<GroundOverlay> grounds = {}) {
  auto document = std::make_shared<OverlayDocument>();
  document->placemarks = std::move(placemarks);
  document->groundOverlays = std::move(grounds);
  return document;
}

Placemark line(std::vector<Position> points, Rgba colour, double widthPixels) {
  Placemark placemark;
  placemark.name = "line";
  placemark.style.lineColor = colour;
  placemark.style.lineWidthPixels = widthPixels;
  Geometry geometry;
  geometry.kind = GeometryKind::LineString;
  geometry.rings = {std::move(points)};
  placemark.geometries = {geometry};
  return placemark;
}

Placemark square(double west, double south, double east, double north, Rgba fill,
                 std::vector<std::vector<Position>> holes = {}) {
  Placemark placemark;
  placemark.name = "square";
  placemark.style.polygonColor = fill;
  placemark.style.outline = false;
  Geometry geometry;
  geometry.kind = GeometryKind::Polygon;
  geometry.rings = {{drapeAt(west, south), drapeAt(east, south), drapeAt(east, north),
                     drapeAt(west, north), drapeAt(west, south)}};
  for (auto& hole : holes) geometry.rings.push_back(std::move(hole));
  placemark.geometries = {geometry};
  return placemark;
}

const uint8_t* pixel(const formats::ImageRgba& image, int column, int row) {
  return &image.pixels[(static_cast<size_t>(row) * image.widthPixels + column) * 4];
}

// The pixel of a longitude/latitude in a tile (Edges grid: the corners are texel centres).
std::pair<int, int> pixelOf(const geo::TileId& tile, double lon, double lat) {
  const auto r = geo::GeographicTilingScheme::tileRectangle(tile);
  const double west = r.westRadians * 180 / M_PI, east = r.eastRadians * 180 / M_PI;
  const double south = r.southRadians * 180 / M_PI, north = r.northRadians * 180 / M_PI;
  return {static_cast<int>(std::lround((lon - west) / (east - west) * (kSize - 1))),
          static_cast<int>(std::lround((north - lat) / (north - south) * (kSize - 1)))};
}

TEST(DrapeRaster, AMeridianLineLandsOnItsColumnAndNowhereElse) {
  const auto document = documentOf({line({drapeAt(10, 10), drapeAt(10, 50)}, {255, 0, 0, 255}, 3)});
  const DrapeSet set = makeDrapeSet(std::span(&document, 1));
  const geo::TileId tile{1, 2, 0};  // 0..90 E, 0..90 N
  ASSERT_TRUE(touchesTile(set, tile, kSize));
  const formats::ImageRgba image = drawTile(set, tile, kSize);
  const auto [column, row] = pixelOf(tile, 10, 30);
  EXPECT_EQ(pixel(image, column, row)[0], 255);
  EXPECT_EQ(pixel(image, column, row)[3], 255);
  EXPECT_EQ(pixel(image, column + 4, row)[3], 0);
  EXPECT_EQ(pixel(image, column, pixelOf(tile, 10, 70).second)[3], 0);  // past the line's end
  size_t drawn = 0;
  for (size_t i = 3; i < image.pixels.size(); i += 4) drawn += image.pixels[i] > 0;
  // 40° of a 90° tile, 3 pixels wide plus antialiasing.
  EXPECT_GT(drawn, 3u * 100u);
  EXPECT_LT(drawn, 5u * 125u);
}

TEST(DrapeRaster, APolygonsHoleStaysClear) {
  const std::vector<Position> hole = {drapeAt(30, 30), drapeAt(60, 30), drapeAt(60, 60),
                                      drapeAt(30, 60), drapeAt(30, 30)};
  const auto document = documentOf({square(10, 10, 80, 80, {0, 0, 255, 128}, {hole})});
  const DrapeSet set = makeDrapeSet(std::span(&document, 1));
  const geo::TileId tile{1, 2, 0};
  const formats::ImageRgba image = drawTile(set, tile, kSize);
  const auto [fillColumn, fillRow] = pixelOf(tile, 20, 20);
  EXPECT_EQ(pixel(image, fillColumn, fillRow)[2], 255);
  EXPECT_NEAR(pixel(image, fillColumn, fillRow)[3], 128, 1);
  const auto [holeColumn, holeRow] = pixelOf(tile, 45, 45);
  EXPECT_EQ(pixel(image, holeColumn, holeRow)[3], 0);
  const auto [outColumn, outRow] = pixelOf(tile, 85, 85);
  EXPECT_EQ(pixel(image, outColumn, outRow)[3], 0);
}

TEST(DrapeRaster, ALineAcrossTheAntimeridianIsDrawnOnBothSides) {
  // 170 E to 170 W along 10 N: 20° long the short way, not 340° the long way.
  const auto document =
      documentOf({line({drapeAt(170, 10), drapeAt(-170, 10)}, {0, 255, 0, 255}, 2)});
  const DrapeSet set = makeDrapeSet(std::span(&document, 1));
  const geo::TileId east{2, 7, 1}, west{2, 0, 1};  // 135..180 E and 180..135 W, 0..45 N
  const geo::TileId middle{2, 3, 1};               // 45 W..0: nothing there
  ASSERT_TRUE(touchesTile(set, east, kSize));
  ASSERT_TRUE(touchesTile(set, west, kSize));
  EXPECT_FALSE(touchesTile(set, middle, kSize));
  const auto eastImage = drawTile(set, east, kSize), westImage = drawTile(set, west, kSize);
  const auto [eastColumn, eastRow] = pixelOf(east, 175, 10);
  const auto [westColumn, westRow] = pixelOf(west, -175, 10);
  EXPECT_EQ(pixel(eastImage, eastColumn, eastRow)[1], 255);
  EXPECT_EQ(pixel(westImage, westColumn, westRow)[1], 255);
  // Both tiles draw the line up to their shared edge (x = 180°), in the same rows.
  EXPECT_GT(pixel(eastImage, kSize - 1, eastRow)[3], 200);
  EXPECT_GT(pixel(westImage, 0, westRow)[3], 200);
}

TEST(DrapeRaster, NeighbouringTilesAgreeAlongTheirSharedEdge) {
  const auto document =
      documentOf({line({drapeAt(1, 1), drapeAt(89, 44), drapeAt(120, 80)}, {255, 255, 0, 255}, 4),
                  square(20, 20, 150, 70, {0, 128, 255, 200})});
  const DrapeSet set = makeDrapeSet(std::span(&document, 1));
  const geo::TileId left{1, 2, 0}, right{1, 3, 0};  // 0..90 E and 90..180 E
  const auto a = drawTile(set, left, kSize), b = drawTile(set, right, kSize);
  int differing = 0;
  for (int row = 0; row < kSize; ++row) {
    for (int c = 0; c < 4; ++c) {
      differing += std::abs(pixel(a, kSize - 1, row)[c] - pixel(b, 0, row)[c]) > 8;
    }
  }
  EXPECT_EQ(differing, 0);
}

TEST(DrapeRaster, AGroundOverlayCoversItsBoxAndTurnsWithItsRotation) {
  auto image = std::make_shared<formats::ImageRgba>();
  image->widthPixels = 2;
  image->heightPixels = 1;
  image->pixels = {255, 0, 0, 255, 0, 0, 255, 255};  // west half red, east half blue
  GroundOverlay ground;
  ground.image = image;
  ground.westDegrees = 20;
  ground.eastDegrees = 60;
  ground.southDegrees = 30;
  ground.northDegrees = 50;
  const geo::TileId tile{1, 2, 0};
  {
    const auto document = documentOf({}, {ground});
    const DrapeSet set = makeDrapeSet(std::span(&document, 1));
    const auto drawn = drawTile(set, tile, kSize);
    const auto [wc, wr] = pixelOf(tile, 25, 40);
    const auto [ec, er] = pixelOf(tile, 55, 40);
    EXPECT_GT(pixel(drawn, wc, wr)[0], 200);
    EXPECT_GT(pixel(drawn, ec, er)[2], 200);
    const auto [oc, orow] = pixelOf(tile, 65, 40);
    EXPECT_EQ(pixel(drawn, oc, orow)[3], 0);
  }
  {
    ground.rotationDegrees = 90;  // counter-clockwise: the west half turns south
    const auto document = documentOf({}, {ground});
    const DrapeSet set = makeDrapeSet(std::span(&document, 1));
    const auto drawn = drawTile(set, tile, kSize);
    const auto [sc, sr] = pixelOf(tile, 40, 25);
    const auto [nc, nr] = pixelOf(tile, 40, 55);
    EXPECT_GT(pixel(drawn, sc, sr)[0], 200);
    EXPECT_GT(pixel(drawn, nc, nr)[2], 200);
  }
}

TEST(OverlayImagery, OnlyTilesNearTheFeaturesArePresentAndPointsAloneMakeNoLayer) {
  Placemark point;
  point.geometries = {
      Geometry{GeometryKind::Point, AltitudeMode::ClampToGround, false, false, {{drapeAt(5, 5)}}}};
  const auto points = documentOf({point});
  EXPECT_TRUE(OverlayImagery::create(std::span(&points, 1), "points")->empty());

  Placemark atAltitude = line({drapeAt(0, 0), drapeAt(1, 1)}, {255, 255, 255, 255}, 1);
  atAltitude.geometries[0].altitudeMode = AltitudeMode::Absolute;  // drawn in 3D, not draped
  const auto flying = documentOf({atAltitude});
  const auto flyingLayer = OverlayImagery::create(std::span(&flying, 1), "flying");
  EXPECT_TRUE(flyingLayer->empty());
  EXPECT_EQ(flyingLayer->peekTile({0, 1, 0}), streaming::ImageryTiles::Peek::Absent);

  const auto document =
      documentOf({line({drapeAt(138.7, 35.3), drapeAt(138.8, 35.4)}, {255, 0, 0, 255}, 2)});
  const auto layer = OverlayImagery::create(std::span(&document, 1), "fuji");
  ASSERT_FALSE(layer->empty());
  const auto near =
      geo::GeographicTilingScheme::positionToTile(138.75 * M_PI / 180, 35.35 * M_PI / 180, 12);
  const auto far =
      geo::GeographicTilingScheme::positionToTile(-100 * M_PI / 180, 40 * M_PI / 180, 12);
  ASSERT_TRUE(near && far);
  EXPECT_EQ(layer->peekTile(*near), streaming::ImageryTiles::Peek::Present);
  EXPECT_EQ(layer->peekTile(*far), streaming::ImageryTiles::Peek::Absent);
  EXPECT_EQ(layer->peekTile({kOverlayMaxLevel + 1, 0, 0}), streaming::ImageryTiles::Peek::Absent);
  const auto loaded = layer->loadImage(*near);
  ASSERT_TRUE(loaded && loaded->has_value());
  EXPECT_EQ((*loaded)->widthPixels, 256);
  const auto absent = layer->loadImage(*far);
  ASSERT_TRUE(absent);
  EXPECT_FALSE(absent->has_value());
  EXPECT_EQ(layer->manifest().pixelGrid, formats::ImageryPixelGrid::Edges);
  EXPECT_NEAR(layer->manifest().bounds.west, 138.7, 1e-9);
}

}  // namespace
}  // namespace globe::overlays

namespace globe::overlays {
namespace {

// The real KMZ's ground overlay (hidden in its file, shown when asked) lands on Etna's tile.
TEST(DrapeRaster, TheEtnaKmzGroundOverlayIsDrawnWhenShown) {
  auto read = readOverlayFile(std::filesystem::path(GLOBE_SOURCE_DIR) /
                              "tests/data/interop/overlays/etna.kmz");
  ASSERT_TRUE(read) << read.error();
  {
    const std::shared_ptr<const OverlayDocument> hidden = std::make_shared<OverlayDocument>(*read);
    EXPECT_TRUE(makeDrapeSet(std::span(&hidden, 1)).empty()) << "visibility 0 in the file";
  }
  showEverything(*read);
  const std::shared_ptr<const OverlayDocument> document = std::make_shared<OverlayDocument>(*read);
  const DrapeSet set = makeDrapeSet(std::span(&document, 1));
  ASSERT_EQ(set.images.size(), 1u);
  const auto tile =
      geo::GeographicTilingScheme::positionToTile(15.0 * M_PI / 180, 37.7 * M_PI / 180, 8);
  ASSERT_TRUE(tile);
  ASSERT_TRUE(touchesTile(set, *tile, kSize));
  const formats::ImageRgba image = drawTile(set, *tile, kSize);
  size_t opaque = 0;
  for (size_t i = 3; i < image.pixels.size(); i += 4) opaque += image.pixels[i] == 255;
  EXPECT_GT(opaque, image.pixels.size() / 4 / 2);
}

}  // namespace
}  // namespace globe::overlays
