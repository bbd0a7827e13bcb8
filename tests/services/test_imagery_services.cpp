// Imagery services read from a real nginx on 127.0.0.1 serving the real tile sets in
// tests/data/interop: each quadtree tile's edge samples against the source tiles' own pixels at
// the same longitude and latitude (the mapping written here again, from the specs), a PMTiles
// archive against the same tiles extracted to a z/x/y tree, WMTS by RESTful template and by KVP,
// and what cannot be read refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>

#include "formats/image_io.hpp"
#include "geo/tiling_scheme.hpp"
#include "services/imagery_services.hpp"
#include "tests/services/whitney_tiles.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/nginx_server.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/network_settings.hpp"

namespace {

namespace fs = std::filesystem;
using globe::formats::ImageRgba;
using globe::geo::TileId;
using globe::testing::NginxServer;

const fs::path kRepo = GLOBE_SOURCE_DIR;
const fs::path kTileSets = kRepo / "tests/data/interop";
constexpr double kPiImagery = 3.141592653589793;

std::shared_ptr<globe::transport::Network> noCacheNetwork() {
  globe::transport::NetworkSettings settings;
  settings.useCache = false;
  return std::make_shared<globe::transport::Network>(settings);
}

ImageRgba decodeFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
  std::vector<std::byte> bytes(chars.size());
  std::memcpy(bytes.data(), chars.data(), chars.size());
  auto image = globe::formats::decodeImageRgba(bytes, path.string());
  EXPECT_TRUE(image) << image.error();
  return image ? *image : ImageRgba{};
}

// A source tiling's pixel at longitude/latitude, read from its tile files: `tileOf(column, row)`
// gives the file of a tile (or "" beyond the grid), pixel (gx, gy) in the whole grid's pixels.
struct SourceGrid {
  std::function<fs::path(int64_t, int64_t)> fileOf;
  std::function<std::pair<double, double>(double, double)> pixelOf;  // lon, lat -> gx, gy
  int tileSize = 256;
  std::map<std::pair<int64_t, int64_t>, ImageRgba> tiles;

  // Bilinear between pixel centres, premultiplied by alpha; nullopt where no tile is.
  std::optional<std::array<double, 4>> at(double lon, double lat) {
    auto [gx, gy] = pixelOf(lon, lat);
    gx -= 0.5;
    gy -= 0.5;
    const double fx = std::floor(gx), fy = std::floor(gy);
    std::array<double, 4> sum{};
    double weights = 0;
    for (int dy = 0; dy < 2; ++dy) {
      for (int dx = 0; dx < 2; ++dx) {
        const double w = (dx ? gx - fx : 1 - (gx - fx)) * (dy ? gy - fy : 1 - (gy - fy));
        const auto px = static_cast<int64_t>(fx) + dx, py = static_cast<int64_t>(fy) + dy;
        const int64_t tx = px < 0 ? -1 : px / tileSize, ty = py < 0 ? -1 : py / tileSize;
        const fs::path file = fileOf(tx, ty);
        if (file.empty() || !fs::exists(file)) continue;
        auto [it, fresh] = tiles.try_emplace({tx, ty});
        if (fresh) it->second = decodeFile(file);
        const ImageRgba& t = it->second;
        const auto* p = &t.pixels[(static_cast<size_t>(py - ty * tileSize) * t.widthPixels +
                                   static_cast<size_t>(px - tx * tileSize)) *
                                  4];
        const double a = p[3] / 255.0 * w;
        for (int k = 0; k < 3; ++k) sum[k] += p[k] * a;
        sum[3] += a;
        weights += w;
      }
    }
    if (weights <= 0 || sum[3] <= 0) return std::nullopt;
    return std::array<double, 4>{sum[0] / sum[3], sum[1] / sum[3], sum[2] / sum[3], sum[3]};
  }
};

struct Agreement {
  double meanDifference = 0, maxDifference = 0;
  size_t compared = 0;
};

// A quadtree tile's edge samples (pixel (r, c) at west + c·w/255, north − r·h/255) against the
// source's pixels there.
Agreement compareTile(globe::streaming::ImageryTiles& layer, const TileId& tile, SourceGrid& grid) {
  auto image = layer.loadImage(tile);
  EXPECT_TRUE(image) << image.error();
  Agreement a;
  if (!image || !*image) return a;
  const auto r = globe::geo::GeographicTilingScheme::tileRectangle(tile);
  const double west = r.westRadians * 180 / kPiImagery, north = r.northRadians * 180 / kPiImagery;
  const double width = r.widthRadians() * 180 / kPiImagery,
               height = r.heightRadians() * 180 / kPiImagery;
  double total = 0;
  for (int row = 3; row < 256; row += 12) {
    for (int column = 5; column < 256; column += 12) {
      const auto expected = grid.at(west + width * column / 255, north - height * row / 255);
      const uint8_t* p = &(*image)->pixels[(static_cast<size_t>(row) * 256 + column) * 4];
      if (!expected) continue;
      if (p[3] == 0) {
        ADD_FAILURE() << "transparent where the source has imagery, " << globe::geo::tileName(tile);
        continue;
      }
      for (int k = 0; k < 3; ++k) {
        const double d = std::fabs(p[k] - (*expected)[k]);
        total += d;
        a.maxDifference = std::max(a.maxDifference, d);
      }
      ++a.compared;
    }
  }
  a.meanDifference = a.compared ? total / (3.0 * static_cast<double>(a.compared)) : 0;
  return a;
}

double mercatorY(double lat) {
  const double s = std::sin(lat * kPiImagery / 180);
  return 0.5 - std::log((1 + s) / (1 - s)) / (4 * kPiImagery);
}

class ImageryServices : public ::testing::Test {
 protected:
  void SetUp() override {
    server = NginxServer::start({kTileSets, ""});
    ASSERT_TRUE(server);
  }
  std::unique_ptr<NginxServer> server;
  std::shared_ptr<globe::transport::Network> network = noCacheNetwork();
};

TEST_F(ImageryServices, TmsNaturalEarthIIMatchesItsSourcePixels) {
  auto layer = globe::services::openImageryTiles(
      "tms:" + server->url("/raster-tiles/tms-geodetic-naturalearth2"), network);
  ASSERT_TRUE(layer) << layer.error();
  EXPECT_EQ((*layer)->manifest().sources.front().driver, "TMS");
  // Zoom 2: 8x4 tiles of 256 px over the world, rows from the bottom.
  SourceGrid grid;
  grid.fileOf = [](int64_t x, int64_t y) -> fs::path {
    if (x < 0 || y < 0 || x >= 8 || y >= 4) return {};
    return kTileSets / "raster-tiles/tms-geodetic-naturalearth2/2" / std::to_string(x) /
           (std::to_string(3 - y) + ".jpg");
  };
  grid.pixelOf = [](double lon, double lat) {
    return std::pair{(lon + 180) / 360 * 2048, (90 - lat) / 180 * 1024};
  };
  // Level 2's edge samples are as fine as zoom 2's pixels: the layer's finest level.
  EXPECT_EQ((*layer)->manifest().maxLevel(), 2u);
  for (const TileId tile : {TileId{2, 4, 1}, TileId{2, 0, 2}, TileId{2, 7, 3}, TileId{2, 3, 0}}) {
    SCOPED_TRACE(globe::geo::tileName(tile));
    const Agreement a = compareTile(**layer, tile, grid);
    EXPECT_GT(a.compared, 300u);
    EXPECT_LT(a.meanDifference, 0.5);
    EXPECT_LT(a.maxDifference, 2.0);
  }
}

TEST_F(ImageryServices, XyzWebMercatorDrapesWithoutDistortion) {
  auto layer = globe::services::openImageryTiles(
      "xyz:" + server->url("/raster-tiles/xyz-osm-carto-world-z0-3/{z}/{x}/{y}.png") + "?maxzoom=3",
      network);
  ASSERT_TRUE(layer) << layer.error();
  SourceGrid grid;  // zoom 3: 8x8 tiles of 256 px
  grid.fileOf = [](int64_t x, int64_t y) -> fs::path {
    if (x < 0 || y < 0 || x >= 8 || y >= 8) return {};
    return kTileSets / "raster-tiles/xyz-osm-carto-world-z0-3/3" / std::to_string(x) /
           (std::to_string(y) + ".png");
  };
  grid.pixelOf = [](double lon, double lat) {
    return std::pair{(lon + 180) / 360 * 2048, mercatorY(lat) * 2048};
  };
  // Europe, the equator and far south: the Mercator rows stretch, the samples follow them.
  for (const TileId tile : {TileId{2, 4, 0}, TileId{2, 4, 1}, TileId{2, 2, 1}, TileId{2, 1, 3}}) {
    SCOPED_TRACE(globe::geo::tileName(tile));
    const Agreement a = compareTile(**layer, tile, grid);
    EXPECT_GT(a.compared, 300u);
    EXPECT_LT(a.meanDifference, 0.5);
  }
  // Beyond Web Mercator's 85.05 degrees there is nothing: the pixels are transparent.
  auto polar = (*layer)->loadImage(TileId{2, 1, 0});
  ASSERT_TRUE(polar && *polar);
  EXPECT_EQ((*polar)->pixels[3], 0) << "the pole's row";
  EXPECT_EQ((*polar)->pixels[(255 * 256 + 10) * 4 + 3], 255) << "45 N";
}

TEST_F(ImageryServices, PmtilesArchiveEqualsTheSameTilesAsAZxyTree) {
  auto archive = globe::services::openImageryTiles(
      "pmtiles:" + server->url("/pmtiles/usgs-mt-whitney-8-15-webp-512.pmtiles"), network);
  ASSERT_TRUE(archive) << archive.error();
  auto tree = globe::services::openImageryTiles(
      "xyz:" + server->url("/raster-tiles/xyz-usgs-topo-mt-whitney-webp512/{z}/{x}/{y}.webp") +
          "?minzoom=8&maxzoom=15&tilesize=512",
      network);
  ASSERT_TRUE(tree) << tree.error();
  const size_t compared = globe::services::testing::compareTilesAtWhitney(**archive, **tree);
  EXPECT_GE(compared, 6u);
  // Stamen Toner: PNG tiles, run-length and deduplicated entries, the whole world at zoom 0-3.
  auto toner = globe::services::openImageryTiles(
      "pmtiles:" + server->url("/pmtiles/stamen_toner(raster)CC-BY+ODbL_z3.pmtiles"), network);
  ASSERT_TRUE(toner) << toner.error();
  for (const TileId tile : {TileId{0, 0, 0}, TileId{1, 2, 0}, TileId{2, 4, 1}}) {
    auto image = (*toner)->loadImage(tile);
    ASSERT_TRUE(image && *image) << globe::geo::tileName(tile);
    size_t black = 0, white = 0;
    for (size_t p = 0; p < (*image)->pixels.size(); p += 4) {
      black += (*image)->pixels[p] < 60 && (*image)->pixels[p + 3] == 255;
      white += (*image)->pixels[p] > 200 && (*image)->pixels[p + 3] == 255;
    }
    EXPECT_GT(black, 1000u) << globe::geo::tileName(tile);  // the sea
    EXPECT_GT(white, 1000u) << globe::geo::tileName(tile);  // the land
  }
}

TEST_F(ImageryServices, WmtsRestfulTemplateReadsTheSameTilesAsXyz) {
  // The Taiwan capabilities document, its template pointed at this server's copy of the tiles.
  const fs::path dir = globe::testing::freshTempDir("wmts-caps");
  std::ifstream in(kTileSets / "wmts/osmhacktw-terrain-rgb-wmts.xml");
  std::string xml{std::istreambuf_iterator<char>(in), {}};
  const std::string live = "https://osmhacktw.github.io/terrain-rgb/tiles/";
  ASSERT_NE(xml.find(live), std::string::npos);
  xml.replace(xml.find(live), live.size(), server->url("/terrain-rgb/taiwan-moi-dem20m/"));
  std::ofstream(dir / "caps.xml") << xml;
  auto wmts = globe::services::openImageryTiles(
      "wmts:" + (dir / "caps.xml").string() + "?layer=terrain-rgb", network);
  ASSERT_TRUE(wmts) << wmts.error();
  auto xyz = globe::services::openImageryTiles(
      "xyz:" + server->url("/terrain-rgb/taiwan-moi-dem20m/{z}/{x}/{y}.png") +
          "?minzoom=6&maxzoom=12",
      network);
  ASSERT_TRUE(xyz) << xyz.error();
  size_t compared = 0;
  for (uint32_t level = 5; level <= 11; ++level) {
    const auto tile = globe::geo::GeographicTilingScheme::positionToTile(
        120.9572 * kPiImagery / 180, 23.47 * kPiImagery / 180, level);
    auto a = (*wmts)->loadImage(*tile);
    auto b = (*xyz)->loadImage(*tile);
    ASSERT_TRUE(a && b);
    ASSERT_EQ(a->has_value(), b->has_value()) << level;  // zoom 6 is not served: neither has it
    if (!*a) continue;
    // The capabilities' scale denominators are rounded: the same pixels to a unit or two where
    // transparent sea meets land.
    size_t differing = 0;
    for (size_t k = 0; k < (*a)->pixels.size(); ++k)
      differing += std::abs((*a)->pixels[k] - (*b)->pixels[k]) > 2;
    EXPECT_LT(differing, (*a)->pixels.size() / 1000) << "level " << level;
    ++compared;
  }
  EXPECT_GE(compared, 5u);
  // The same document as MapServer writes an 8-bit PNG's format ("image/png; mode=8bit", both in
  // <Format> and in the template's format): the same tiles.
  std::string eightBit = xml;
  for (size_t at = 0; (at = eightBit.find("image/png", at)) != std::string::npos; at += 20)
    eightBit.replace(at, 9, "image/png; mode=8bit");
  std::ofstream(dir / "caps-8bit.xml") << eightBit;
  auto paletted = globe::services::openImageryTiles(
      "wmts:" + (dir / "caps-8bit.xml").string() + "?layer=terrain-rgb", network);
  ASSERT_TRUE(paletted) << paletted.error();
  const auto summit = globe::geo::GeographicTilingScheme::positionToTile(
      120.9572 * kPiImagery / 180, 23.47 * kPiImagery / 180, 9);
  auto viaPaletted = (*paletted)->loadImage(*summit);
  auto viaPlain = (*wmts)->loadImage(*summit);
  ASSERT_TRUE(viaPaletted && viaPlain && *viaPaletted && *viaPlain);
  EXPECT_EQ((*viaPaletted)->pixels, (*viaPlain)->pixels);
  auto unnamed = globe::services::openImageryTiles("wmts:" + (dir / "caps.xml").string(), network);
  ASSERT_FALSE(unnamed);
  EXPECT_NE(unnamed.error().find("name a layer with ?layer=NAME; it has terrain-rgb"),
            std::string::npos)
      << unnamed.error();
}

TEST_F(ImageryServices, WmtsKvpGetTileOfNasaGibs) {
  // GIBS's capabilities (KVP only, CRS84, 512-pixel tiles whose grid overhangs the world), its
  // endpoint pointed at this server, where nginx answers GetTile from a tree made here from the
  // bundled Blue Marble, as GIBS cuts its EPSG4326_2km tiles.
  const fs::path dir = globe::testing::freshTempDir("gibs");
  const ImageRgba world =
      globe::formats::loadImageRgba(kRepo / "data/imagery/world.topo.bathy.200412.3x5400x2700.jpg")
          .value();
  const double degreesPerPixel[] = {0.5625, 0.28125, 0.140625};
  auto worldPixel = [&](double lon, double lat) -> const uint8_t* {
    if (lon < -180 || lon >= 180 || lat <= -90 || lat > 90) return nullptr;
    const auto x = std::min<int>(static_cast<int>((lon + 180) / 360 * world.widthPixels),
                                 world.widthPixels - 1);
    const auto y = std::min<int>(static_cast<int>((90 - lat) / 180 * world.heightPixels),
                                 world.heightPixels - 1);
    return &world.pixels[(static_cast<size_t>(y) * world.widthPixels + x) * 4];
  };
  for (int m = 0; m < 3; ++m) {
    const double res = degreesPerPixel[m];
    for (int row = 0; row * 512 * res < 180; ++row) {
      for (int col = 0; col * 512 * res < 360; ++col) {
        ImageRgba tile{512, 512, std::vector<uint8_t>(512 * 512 * 4, 0)};
        for (int i = 0; i < 512; ++i) {
          for (int j = 0; j < 512; ++j) {
            const uint8_t* p =
                worldPixel(-180 + (col * 512 + j + 0.5) * res, 90 - (row * 512 + i + 0.5) * res);
            if (p) std::memcpy(&tile.pixels[(static_cast<size_t>(i) * 512 + j) * 4], p, 4);
          }
        }
        const fs::path file = dir / "tiles" / std::to_string(m) / std::to_string(row) /
                              (std::to_string(col) + ".png");
        fs::create_directories(file.parent_path());
        auto png = globe::formats::encodePng(tile);
        ASSERT_TRUE(png);
        std::ofstream(file, std::ios::binary)
            .write(reinterpret_cast<const char*>(png->data()),
                   static_cast<std::streamsize>(png->size()));
      }
    }
  }
  std::ifstream in(kTileSets / "wmts/nasa-gibs-eosdis-wmts-cap.xml");
  std::string xml{std::istreambuf_iterator<char>(in), {}};
  const std::string live = "http://map1b.vis.earthdata.nasa.gov/wmts-geo/wmts.cgi?";
  ASSERT_NE(xml.find(live), std::string::npos);
  fs::create_directories(dir / "www");
  auto gibs = NginxServer::start(
      {dir / "www", "location = /wmts.cgi { root " + dir.string() +
                        "; if ($arg_REQUEST != GetTile) { return 400; } "
                        "try_files /tiles/$arg_TILEMATRIX/$arg_TILEROW/$arg_TILECOL.png =404; }"});
  ASSERT_TRUE(gibs);
  // Every endpoint (GetCapabilities and GetTile): nothing may reach the real service.
  for (size_t at = xml.find(live); at != std::string::npos; at = xml.find(live))
    xml.replace(at, live.size(), gibs->url("/wmts.cgi?"));
  ASSERT_EQ(xml.find("map1b.vis"), std::string::npos);
  std::ofstream(dir / "www/caps.xml") << xml;
  auto layer = globe::services::openImageryTiles(
      "wmts:" + gibs->url("/caps.xml") + "?layer=AIRS_CO_Total_Column_Day", network);
  ASSERT_TRUE(layer) << layer.error();
  SourceGrid grid;  // matrix 2: 0.140625 degrees a pixel
  grid.tileSize = 512;
  grid.fileOf = [&](int64_t x, int64_t y) -> fs::path {
    if (x < 0 || y < 0) return {};
    return dir / "tiles/2" / std::to_string(y) / (std::to_string(x) + ".png");
  };
  grid.pixelOf = [](double lon, double lat) {
    return std::pair{(lon + 180) / 0.140625, (90 - lat) / 0.140625};
  };
  for (const TileId tile : {TileId{2, 4, 1}, TileId{2, 0, 2}, TileId{2, 7, 3}}) {
    SCOPED_TRACE(globe::geo::tileName(tile));
    const Agreement a = compareTile(**layer, tile, grid);
    EXPECT_GT(a.compared, 300u);
    EXPECT_LT(a.meanDifference, 0.5);
  }
  // Every tile asked for by KVP, with this server's answer.
  size_t getTiles = 0;
  for (const std::string& line : gibs->accessLog()) {
    if (line.find("REQUEST=GetTile") != std::string::npos &&
        line.find("LAYER=AIRS_CO_Total_Column_Day") != std::string::npos &&
        line.find("TILEMATRIXSET=EPSG4326_2km") != std::string::npos) {
      ++getTiles;
    }
  }
  EXPECT_GT(getTiles, 0u);
}

TEST_F(ImageryServices, WhatCannotBeReadIsRefusedByName) {
  auto none = globe::services::openImageryTiles("tms:" + server->url("/nothing-here"), network);
  ASSERT_FALSE(none);
  EXPECT_NE(none.error().find(server->url("/nothing-here/tilemapresource.xml") + ": not found"),
            std::string::npos)
      << none.error();
  auto notPmtiles = globe::services::openImageryTiles(
      "pmtiles:" + server->url("/wmts/nasa-gibs-eosdis-wmts-cap.xml"), network);
  ASSERT_FALSE(notPmtiles);
  EXPECT_NE(notPmtiles.error().find("nasa-gibs-eosdis-wmts-cap.xml: not a PMTiles archive"),
            std::string::npos)
      << notPmtiles.error();
  auto noTemplate =
      globe::services::openImageryTiles("xyz:" + server->url("/a/{z}/{x}.png"), network);
  ASSERT_FALSE(noTemplate);
  EXPECT_NE(noTemplate.error().find("needs {z}, {x} and {y}"), std::string::npos);
  auto wrongLayer = globe::services::openImageryTiles(
      "wmts:" + server->url("/wmts/nasa-gibs-eosdis-wmts-cap.xml") + "?layer=Nope", network);
  ASSERT_FALSE(wrongLayer);
  EXPECT_NE(wrongLayer.error().find("no layer Nope; it has AIRS_CO_Total_Column_Day"),
            std::string::npos)
      << wrongLayer.error();
}

}  // namespace
