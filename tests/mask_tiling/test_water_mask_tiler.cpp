// globe-tiler water-mask on polygon files made here: land, lakes and sea where they belong at
// every level, tiles split only along shorelines, the finest layer deciding where layers overlap,
// transparent outside the layers, and clear errors for bad inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "formats/image_io.hpp"
#include "formats/image_pack.hpp"
#include "formats/layer_manifest.hpp"
#include "geo/tile_id.hpp"
#include "imagery_tiling/imagery_reader.hpp"
#include "mask_tiling/ring_clip.hpp"
#include "mask_tiling/water_mask_tiler.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/atomic_file.hpp"

namespace globe::mask_tiling {
namespace {

namespace fs = std::filesystem;
using globe::testing::freshTempDir;

// A GeoJSON FeatureCollection of polygons, each a list of rings of (lon, lat).
std::string geoJson(
    const std::vector<std::vector<std::vector<std::pair<double, double>>>>& polygons) {
  std::ostringstream out;
  out.precision(17);
  out << R"({"type":"FeatureCollection","features":[)";
  for (size_t p = 0; p < polygons.size(); ++p) {
    out << (p ? "," : "")
        << R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[)";
    for (size_t r = 0; r < polygons[p].size(); ++r) {
      out << (r ? "," : "") << "[";
      const auto& ring = polygons[p][r];
      for (size_t i = 0; i <= ring.size(); ++i) {
        const auto& v = ring[i % ring.size()];
        out << (i ? "," : "") << "[" << v.first << "," << v.second << "]";
      }
      out << "]";
    }
    out << "]}}";
  }
  out << "]}";
  return out.str();
}

// A square ring with `perSide` vertices per side (more vertices: a finer shoreline).
std::vector<std::pair<double, double>> square(double west, double south, double east, double north,
                                              int perSide = 1) {
  std::vector<std::pair<double, double>> ring;
  auto side = [&](double x0, double y0, double x1, double y1) {
    for (int i = 0; i < perSide; ++i) {
      const double t = static_cast<double>(i) / perSide;
      ring.emplace_back(x0 + t * (x1 - x0), y0 + t * (y1 - y0));
    }
  };
  side(west, south, east, south);
  side(east, south, east, north);
  side(east, north, west, north);
  side(west, north, west, south);
  return ring;
}

fs::path writeFile(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path path = dir / name;
  std::ofstream(path) << text;
  return path;
}

// The layer's tiles, decoded (RGBA: grey in r, g, b).
struct MaskLayer {
  formats::LayerManifest manifest;
  std::map<geo::TileId, formats::ImageRgba> tiles;

  // Water fraction (0..255) and alpha of the sample nearest a point in a tile.
  std::pair<int, int> sample(const geo::TileId& tile, double lon, double lat) const {
    const auto& image = tiles.at(tile);
    const imagery_tiling::TileFrameDegrees f = imagery_tiling::tileFrameDegrees(tile);
    const double step = f.size / 255;
    const auto c = static_cast<size_t>(std::lround((lon - f.west) / step));
    const auto r = static_cast<size_t>(std::lround((f.north - lat) / step));
    const size_t i = 4 * (r * 256 + c);
    return {image.pixels[i], image.pixels[i + 3]};
  }
  // The deepest tile holding the point.
  geo::TileId deepestAt(double lon, double lat) const {
    geo::TileId best{0, lon < 0 ? 0u : 1u, 0};
    for (const auto& [tile, image] : tiles) {
      const imagery_tiling::TileFrameDegrees f = imagery_tiling::tileFrameDegrees(tile);
      if (lon >= f.west && lon <= f.west + f.size && lat <= f.north && lat >= f.north - f.size &&
          tile.level > best.level) {
        best = tile;
      }
    }
    return best;
  }
};

MaskLayer readMask(const fs::path& dir) {
  MaskLayer out;
  auto manifest = formats::readLayerManifest(dir);
  EXPECT_TRUE(manifest) << manifest.error();
  if (!manifest) return out;
  out.manifest = *manifest;
  for (const formats::ImageryLevelInfo& level : manifest->levels) {
    for (const formats::PackId& id : level.packs) {
      const fs::path path = formats::packPath(dir, id);
      auto bytes = transport::readWholeFile(path, 1u << 30);
      EXPECT_TRUE(bytes) << bytes.error();
      auto pack = formats::decodeImagePack(*bytes, path);
      EXPECT_TRUE(pack) << pack.error();
      for (size_t slot = 0; slot < pack->payloads.size(); ++slot) {
        if (pack->payloads[slot].empty()) continue;
        auto image = formats::decodeImageRgba(pack->payloads[slot], path.string());
        EXPECT_TRUE(image) << image.error();
        out.tiles.emplace(formats::tileOfSlot(id, slot, manifest->packTilesPerSide),
                          std::move(*image));
      }
    }
  }
  return out;
}

Result<WaterMaskTilerReport> tile(const std::vector<fs::path>& inputs, const fs::path& out,
                                  std::optional<uint32_t> maxLevel) {
  WaterMaskTilerOptions options;
  for (const fs::path& input : inputs) options.inputs.push_back(input.string());
  options.outputDir = out;
  options.maxLevel = maxLevel;
  options.threads = 2;
  return runWaterMaskTiler(options);
}

TEST(WaterMaskTiler, LandLakesAndSeaAtEveryLevel) {
  const fs::path dir = freshTempDir("water-mask-island");
  // An island from 10 to 20 degrees with a lake from 14 to 16 and an islet in the lake.
  const fs::path input = writeFile(dir, "island.geojson",
                                   geoJson({{square(10, 10, 20, 20), square(14, 14, 16, 16)},
                                            {square(14.8, 14.8, 15.2, 15.2)}}));
  auto report = tile({input}, dir / "mask", 6);
  ASSERT_TRUE(report) << report.error();
  const MaskLayer mask = readMask(dir / "mask");
  EXPECT_EQ(mask.manifest.kind, formats::LayerKind::WaterMask);
  EXPECT_EQ(mask.manifest.maxLevel(), 6u);
  for (uint32_t level = 0; level <= 6; ++level) {
    // Each level's deepest tile at the point says the same.
    auto at = [&](double lon, double lat) {
      geo::TileId t = mask.deepestAt(lon, lat);
      while (t.level > level) t = t.parent();
      return mask.sample(t, lon, lat);
    };
    EXPECT_EQ(at(12, 12), std::make_pair(0, 255)) << "land, level " << level;
    if (level >= 3) {  // finer than the lake's 2 degrees: a sample wholly in the lake
      EXPECT_EQ(at(14.4, 14.4), std::make_pair(255, 255)) << "lake, level " << level;
    }
    if (level >= 6) {
      EXPECT_EQ(at(15, 15).first, 0) << "islet, level " << level;
    }
  }
  // Outside the polygons' extent nothing is decided: alpha 0.
  EXPECT_EQ(mask.sample({0, 1, 0}, 100, 40).second, 0);
  // Tiles deeper than level 0 only where a shoreline runs through their parent.
  for (const auto& [t, image] : mask.tiles) {
    if (t.level == 0) continue;
    const imagery_tiling::TileFrameDegrees f = imagery_tiling::tileFrameDegrees(t.parent());
    const RectangleDegrees parent{f.west, f.north - f.size, f.west + f.size, f.north};
    EXPECT_TRUE(parent.intersects({10, 10, 20, 20})) << t.level << "/" << t.x << "/" << t.y;
  }
  // Level 6 tiles (2.8 degrees) wholly inside the land away from the lake are not split to.
  size_t level6 = 0;
  for (const auto& [t, image] : mask.tiles) level6 += t.level == 6 ? 1 : 0;
  EXPECT_GT(level6, 0u);
  EXPECT_LT(level6, 40u);  // the shorelines' tiles and their siblings, not the 16 x 16 over the box
  EXPECT_GT(report->coastTiles, 0u);
}

TEST(WaterMaskTiler, TheFinestShorelineDecidesWhereLayersOverlap) {
  const fs::path dir = freshTempDir("water-mask-overlap");
  // A coarse layer says land from 0 to 40; a fine one (many vertices) has a bay at 10..11.
  const fs::path coarse = writeFile(dir, "coarse.geojson", geoJson({{square(0, 0, 40, 40)}}));
  const fs::path fine =
      writeFile(dir, "fine.geojson",
                geoJson({{square(9.5, 9.5, 11.5, 11.5, 200), square(10, 10, 11, 11, 100)}}));
  auto report = tile({coarse, fine}, dir / "mask", std::nullopt);
  ASSERT_TRUE(report) << report.error();
  const MaskLayer mask = readMask(dir / "mask");
  const geo::TileId deepest = mask.deepestAt(10.5, 10.5);
  EXPECT_GE(deepest.level, 5u);
  EXPECT_EQ(mask.sample(deepest, 10.5, 10.5), std::make_pair(255, 255));           // the fine bay
  EXPECT_EQ(mask.sample(mask.deepestAt(30, 30), 30, 30), std::make_pair(0, 255));  // coarse land
  // The coarse layer's automatic depth stops well above the fine one's.
  ASSERT_EQ(mask.manifest.sources.size(), 2u);
  EXPECT_LT(mask.manifest.sources[1].finestLevel, mask.manifest.sources[0].finestLevel);
}

TEST(WaterMaskTiler, NearAFineLayersSideTheCoastMovesToTheCoarseOnesInsteadOfJumping) {
  const fs::path dir = freshTempDir("water-mask-blend");
  // Coarse: land from 0 to 40. Fine (many vertices): a rim of land from 10 to 20 around water.
  // Inside the fine extent near its west side, the coarse layer's land blends into the fine
  // layer's water over an eighth of the extent (1.25 degrees, capped there).
  const fs::path coarse = writeFile(dir, "coarse.geojson", geoJson({{square(0, 0, 40, 40)}}));
  const fs::path fine =
      writeFile(dir, "fine.geojson",
                geoJson({{square(10, 10, 20, 20, 400), square(10.3, 10.3, 19.7, 19.7, 400)}}));
  auto report = tile({coarse, fine}, dir / "mask", 6);
  ASSERT_TRUE(report) << report.error();
  const MaskLayer mask = readMask(dir / "mask");
  auto waterAt = [&](double lon) { return mask.sample(mask.deepestAt(lon, 15), lon, 15).first; };
  EXPECT_LT(waterAt(10.4), 128) << "near the side, mostly the coarse layer's land";
  EXPECT_LT(waterAt(10.4), waterAt(10.8));
  EXPECT_LT(waterAt(10.8), waterAt(11.1));
  EXPECT_EQ(waterAt(15.0), 255) << "farther in, the fine layer alone";
  EXPECT_EQ(waterAt(5.0), 0) << "outside the fine extent, the coarse layer alone";
}

TEST(WaterMaskTiler, BadInputsAreRefusedNamingThem) {
  const fs::path dir = freshTempDir("water-mask-bad");
  const fs::path points =
      writeFile(dir, "points.geojson",
                R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},)"
                R"("geometry":{"type":"Point","coordinates":[1,2]}}]})");
  auto noPolygons = tile({points}, dir / "a", 3);
  ASSERT_FALSE(noPolygons);
  EXPECT_NE(noPolygons.error().find("points.geojson"), std::string::npos) << noPolygons.error();
  EXPECT_NE(noPolygons.error().find("no polygons"), std::string::npos) << noPolygons.error();

  auto missing = tile({dir / "absent.gpkg"}, dir / "b", 3);
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("absent.gpkg"), std::string::npos) << missing.error();

  const fs::path garbage = writeFile(dir, "garbage.geojson", "{\"type\": \"Featu");
  auto broken = tile({garbage}, dir / "c", 3);
  ASSERT_FALSE(broken);
  EXPECT_NE(broken.error().find("garbage.geojson"), std::string::npos) << broken.error();

  const fs::path outside = writeFile(dir, "outside.geojson", geoJson({{square(170, 10, 190, 20)}}));
  auto beyond = tile({outside}, dir / "d", 3);
  ASSERT_FALSE(beyond);
  EXPECT_NE(beyond.error().find("outside longitude"), std::string::npos) << beyond.error();

  // An imagery layer's directory is not overwritten.
  const fs::path island = writeFile(dir, "island.geojson", geoJson({{square(1, 1, 2, 2)}}));
  formats::LayerManifest imagery;
  imagery.levels.push_back({});
  fs::create_directories(dir / "imagery");
  ASSERT_TRUE(formats::writeLayerManifest(dir / "imagery", imagery));
  auto over = tile({island}, dir / "imagery", 3);
  ASSERT_FALSE(over);
  EXPECT_NE(over.error().find("imagery layer"), std::string::npos) << over.error();
}

TEST(WaterMaskTiler, AutomaticDepthFollowsTheShorelinesDetail) {
  EXPECT_EQ(waterMaskLevelFor(10.0), 0u);  // a texel of 0.7 degrees is fine enough
  // Half a 100 m edge (~0.0009 degrees) needs texels of 0.00045 degrees: level 11.
  EXPECT_EQ(waterMaskLevelFor(0.0009), 11u);
  EXPECT_EQ(waterMaskLevelFor(0.0), kWaterMaskMaxAutoLevel);
}

}  // namespace
}  // namespace globe::mask_tiling
