// globe-tiler export --format heightmap and --webp on the bundled pyramid (Fuji's 3″ DEM over
// ETOPO20): the heightmap-1.0 tree decoded by the project's decoder and by an independent
// stdlib-Python decoder (tests/tools/heightmap_reference.py) and read back by globe's
// quantized-mesh: source, all against `globe query --mode exact` of the pyramid; its child and
// water masks and layer.json; WebP tiles the same pixels as the PNG export; bad arguments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "compression/gzip_bytes.hpp"
#include "formats/image_io.hpp"
#include "formats/quantized_mesh.hpp"
#include "formats/terrain_layer_json.hpp"
#include "geo/tile_id.hpp"
#include "services/terrain_services.hpp"
#include "terrain/height_block.hpp"
#include "tests/publish/query_points.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/shared_commands.hpp"
#include "tests/support/test_io_util.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "transport/atomic_file.hpp"

namespace globe::publish {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = GLOBE_SOURCE_DIR;

using Exit = globe::testing::CommandExit;
using globe::testing::runCommand;

using testing::heightsOf;
using testing::Point;
using testing::writePoints;

std::vector<double> queryHeights(const std::string& source, const fs::path& points) {
  const Exit r = runCommand(std::string(GLOBE_EXE) + " query --mode exact " + source + " < " +
                            points.string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return heightsOf(r.output);
}

std::vector<double> exactHeights(const fs::path& points) {
  return queryHeights(globe::testing::bundledPyramid().string(), points);
}

std::vector<double> sortedDifferences(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  std::vector<double> d;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) d.push_back(std::fabs(a[i] - b[i]));
  std::sort(d.begin(), d.end());
  return d;
}

// Fuji's DEM square, away from its edges (where the pyramid's finest level ends).
std::vector<Point> fujiPoints(size_t count, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> lon(138.15, 138.85), lat(35.15, 35.85);
  std::vector<Point> points;
  for (size_t i = 0; i < count; ++i) points.push_back({lon(random), lat(random)});
  return points;
}

std::string tiler() { return std::string(GLOBE_TILER_EXE) + " export "; }

fs::path tilePath(const fs::path& tree, const geo::TileId& tile) {
  const uint32_t tmsY = (1U << tile.level) - 1 - tile.y;
  return tree / std::to_string(tile.level) / std::to_string(tile.x) /
         (std::to_string(tmsY) + ".terrain");
}

formats::HeightmapTile readTile(const fs::path& path) {
  auto bytes = transport::readWholeFile(path, 1U << 20);
  EXPECT_TRUE(bytes) << bytes.error();
  if (!bytes) return {};
  EXPECT_TRUE(compression::isGzip(*bytes)) << path;
  auto inflated = compression::gunzipIfNeeded(*bytes, path.string(), 1U << 20);
  EXPECT_TRUE(inflated) << inflated.error();
  if (!inflated) return {};
  auto tile = formats::decodeHeightmapTile(*inflated, path.string());
  EXPECT_TRUE(tile) << tile.error();
  return tile ? *tile : formats::HeightmapTile{};
}

// The tile of `level` holding the point (rows from the north).
geo::TileId tileAt(uint32_t level, double lon, double lat) {
  const double size = 180.0 / std::ldexp(1.0, static_cast<int>(level));
  return {level, static_cast<uint32_t>((lon + 180) / size),
          static_cast<uint32_t>((90 - lat) / size)};
}

// One heightmap tree for the tests below, exported once per CTest run (sharedCommands): the
// world's coarse levels, then Fuji's square to its finest, in two runs (the second adds children
// to tiles the first wrote).
const std::string kFujiLevels = " --levels 3-12 --bounds 138,35,139,36 ";

class ExportTreesHeightmap : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string pyramid = globe::testing::bundledPyramid().string();
    run_ = globe::testing::sharedCommands(
        "export-heightmap", {tiler() + "--format heightmap -o {dir}/hm --levels 0-2 " + pyramid,
                             tiler() + "--format heightmap -o {dir}/hm" + kFujiLevels + pyramid});
    tree_ = run_.dir / "hm";
    scratch_ = globe::testing::freshTempDir("export-heightmap-scratch");
    ASSERT_EQ(run_.exits.size(), 2U);
    ASSERT_EQ(run_.exits[0].exitCode, 0) << run_.exits[0].output;
    ASSERT_EQ(run_.exits[1].exitCode, 0) << run_.exits[1].output;
  }
  globe::testing::SharedRun run_;
  fs::path tree_;     // shared: read only
  fs::path scratch_;  // this test's own
};

TEST_F(ExportTreesHeightmap, LayerJsonListsEveryTileTheTreeHolds) {
  EXPECT_NE(run_.exits[1].output.find("heightmap tiles written"), std::string::npos)
      << run_.exits[1].output;
  std::ifstream in(tree_ / "layer.json");
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  auto layer = formats::parseTerrainLayerJson(text, "layer.json");
  ASSERT_TRUE(layer) << layer.error();
  EXPECT_EQ(layer->format, formats::TerrainLayerJson::Format::Heightmap);
  ASSERT_EQ(layer->tiles.size(), 1u);
  EXPECT_EQ(layer->tiles[0], "{z}/{x}/{y}.terrain?v={version}");
  EXPECT_EQ(layer->version.rfind("1.0.0-", 0), 0u) << layer->version;
  EXPECT_EQ(layer->maxZoom, 12u);
  ASSERT_EQ(layer->available.size(), 13u);
  EXPECT_NE(text.find("\"projection\": \"EPSG:4326\""), std::string::npos);
  EXPECT_NE(text.find("\"attribution\""), std::string::npos);
  // Every tile on disk is listed, and every listed tile is on disk.
  size_t onDisk = 0, listed = 0;
  for (const auto& entry : fs::recursive_directory_iterator(tree_)) {
    if (entry.path().extension() != ".terrain") continue;
    ++onDisk;
    const auto z = std::stoul(entry.path().parent_path().parent_path().filename());
    const auto x = std::stoul(entry.path().parent_path().filename());
    const auto y = std::stoul(entry.path().stem());
    ASSERT_LT(z, layer->available.size());
    const auto& ranges = layer->available[z];
    EXPECT_TRUE(std::any_of(ranges.begin(), ranges.end(), [&](const formats::TileRange& r) {
      return x >= r.startX && x <= r.endX && y >= r.startY && y <= r.endY;
    })) << entry.path();
  }
  for (size_t z = 0; z < layer->available.size(); ++z) {
    for (const formats::TileRange& r : layer->available[z]) {
      for (uint32_t x = r.startX; x <= r.endX; ++x) {
        for (uint32_t y = r.startY; y <= r.endY; ++y) {
          ++listed;
          EXPECT_TRUE(fs::exists(tree_ / std::to_string(z) / std::to_string(x) /
                                 (std::to_string(y) + ".terrain")))
              << z << "/" << x << "/" << y;
        }
      }
    }
  }
  EXPECT_EQ(listed, onDisk);
  EXPECT_EQ(layer->available[0].size(), 1u);  // both level-0 tiles, one rectangle
}

// Every tile's child mask names the children the tree holds: the second run's included, in the
// level-2 tile the first run wrote.
TEST_F(ExportTreesHeightmap, ChildMasksMatchTheTilesThatExist) {
  size_t tiles = 0, withChildren = 0;
  for (const auto& entry : fs::recursive_directory_iterator(tree_)) {
    if (entry.path().extension() != ".terrain") continue;
    const auto z =
        static_cast<uint32_t>(std::stoul(entry.path().parent_path().parent_path().filename()));
    const auto x = static_cast<uint32_t>(std::stoul(entry.path().parent_path().filename()));
    const auto tmsY = static_cast<uint32_t>(std::stoul(entry.path().stem()));
    const geo::TileId tile{z, x, (1U << z) - 1 - tmsY};
    const auto children = tile.children();  // NW, NE, SW, SE
    const uint8_t bits[4] = {4, 8, 1, 2};
    uint8_t expected = 0;
    for (size_t k = 0; k < 4; ++k) {
      if (fs::exists(tilePath(tree_, children[k]))) expected |= bits[k];
    }
    EXPECT_EQ(readTile(entry.path()).childMask, expected) << entry.path();
    ++tiles;
    withChildren += expected != 0 ? 1 : 0;
  }
  EXPECT_GT(tiles, 40u);
  EXPECT_GT(withChildren, 10u);
  EXPECT_NE(readTile(tilePath(tree_, tileAt(2, 138.5, 35.5))).childMask, 0);
}

// The project's decoder at the tiles' posts, the independent decoder anywhere (the cell's
// triangle), globe's quantized-mesh: source reading the tree: each within the encoding's 0.2 m
// step of the pyramid's exact surface.
TEST_F(ExportTreesHeightmap, TilesHoldThePyramidsSurface) {
  // Posts of level-12 tiles (the pyramid's level-14 vertices) near random points.
  std::vector<Point> posts;
  std::vector<double> decoded;
  for (const Point& p : fujiPoints(60, 11)) {
    const geo::TileId tile = tileAt(12, p.lon, p.lat);
    const formats::HeightmapTile hm = readTile(tilePath(tree_, tile));
    ASSERT_EQ(hm.heightMeters.size(), 65u * 65u);
    const double size = 180.0 / 4096, west = tile.x * size - 180, north = 90 - tile.y * size;
    const auto column = static_cast<uint32_t>(std::lround((p.lon - west) / size * 64));
    const auto row = static_cast<uint32_t>(std::lround((north - p.lat) / size * 64));
    posts.push_back({west + column * size / 64, north - row * size / 64});
    decoded.push_back(hm.heightMeters[row * 65 + column]);
  }
  const fs::path postFile = writePoints(scratch_ / "posts.txt", posts);
  std::vector<double> d = sortedDifferences(decoded, exactHeights(postFile));
  ASSERT_EQ(d.size(), 60u);
  std::printf("[ heightmap posts ] vs the pyramid: median %.3f m, max %.3f m\n", d[30], d.back());
  EXPECT_LE(d.back(), 0.1 + 1e-6);  // rounded to the 0.2 m step

  const fs::path points = writePoints(scratch_ / "points.txt", fujiPoints(200, 31));
  const std::vector<double> exact = exactHeights(points);
  const Exit reference =
      runCommand("python3 " + (kSource / "tests/tools/heightmap_reference.py").string() + " " +
                 tree_.string() + " < " + points.string());
  ASSERT_EQ(reference.exitCode, 0) << reference.output;
  d = sortedDifferences(heightsOf(reference.output), exact);
  ASSERT_EQ(d.size(), 200u);
  std::printf("[ heightmap python ] vs the pyramid: median %.3f m, 95th %.3f m, max %.3f m\n",
              d[100], d[190], d.back());
  EXPECT_LT(d.back(), 0.2);

  d = sortedDifferences(queryHeights("quantized-mesh:" + tree_.string(), points), exact);
  ASSERT_EQ(d.size(), 200u);
  std::printf("[ heightmap globe ] vs the pyramid: median %.3f m, 95th %.3f m, max %.3f m\n",
              d[100], d[190], d.back());
  EXPECT_LT(d.back(), 0.2);
}

// The water mask: the nearest pyramid vertex's water flag; a level-0 tile holds the Pacific and
// the Americas (256×256), and globe's reader takes the sea there as water.
TEST_F(ExportTreesHeightmap, WaterMasksMarkTheSea) {
  const formats::HeightmapTile west = readTile(tilePath(tree_, {0, 0, 0}));
  ASSERT_EQ(west.waterMask.size(), 256u * 256u);
  const auto pixel = [&](double lon, double lat) {
    const auto column = static_cast<size_t>((lon + 180) / 180 * 256);
    const auto row = static_cast<size_t>((90 - lat) / 180 * 256);
    return west.waterMask[row * 256 + column];
  };
  EXPECT_EQ(pixel(-150, 0), 255);  // the Pacific
  EXPECT_EQ(pixel(-100, 40), 0);   // Kansas
  EXPECT_EQ(pixel(-60, -10), 0);   // Amazonia
  EXPECT_EQ(pixel(-30, 30), 255);  // the Atlantic
  // Fuji's summit tile: all land, one byte.
  EXPECT_EQ(readTile(tilePath(tree_, tileAt(12, 138.7274, 35.3606))).waterMask,
            std::vector<uint8_t>{0});
  // The sea read back: its 0 m surface, as the pyramid's exact surface of the level the tile
  // samples (2 deeper) has it between its vertices (the chords of a coarse level dip below 0).
  const fs::path sea = writePoints(scratch_ / "sea.txt", {{-150, 0}, {-30, 30}});
  const std::vector<double> d = sortedDifferences(
      queryHeights("quantized-mesh:" + tree_.string(), sea),
      queryHeights("--level 4 " + globe::testing::bundledPyramid().string(), sea));
  ASSERT_EQ(d.size(), 2u);
  EXPECT_LT(d.back(), 0.2);
  // globe's reader marks the masked vertices water: the block of the level-0 tile.
  auto source = services::openTerrainSource("quantized-mesh:" + tree_.string(),
                                            terrain::SeaSurface::Water, nullptr);
  ASSERT_TRUE(source) << source.error();
  auto block = (*source)->loadBlock({0, 0, 0});
  ASSERT_TRUE(block) << block.error();
  ASSERT_EQ(block->verticesPerSide, 65u);
  const auto vertex = [&](double lon, double lat) {
    const auto column = static_cast<size_t>(std::lround((lon + 180) / 180 * 64));
    const auto row = static_cast<size_t>(std::lround((90 - lat) / 180 * 64));
    return block->heights[row * 65 + column];
  };
  EXPECT_TRUE(terrain::isWater(vertex(-150, 0)));
  EXPECT_TRUE(terrain::isWater(vertex(-30, 30)));
  EXPECT_FALSE(terrain::isWater(vertex(-100, 40)));
  EXPECT_FALSE(terrain::isWater(vertex(-60, -10)));
}

TEST_F(ExportTreesHeightmap, ARunAgainWritesNothing) {
  // On a copy: the shared tree stays as every other test reads it.
  const fs::path copy = scratch_ / "hm";
  fs::copy(tree_, copy, fs::copy_options::recursive);
  const Exit again = runCommand(tiler() + "--format heightmap -o " + copy.string() + kFujiLevels +
                                globe::testing::bundledPyramid().string());
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NE(again.output.find(": 0 heightmap tiles written"), std::string::npos) << again.output;
}

TEST(ExportTrees, HeightmapTilesEncodeInTheFormatsSteps) {
  formats::HeightmapTile tile;
  tile.heightMeters.assign(65 * 65, 0.0);
  tile.heightMeters[0] = -1000.0;  // raw 0
  tile.heightMeters[1] = 3776.33;  // raw 23882 (3776.4 m)
  tile.heightMeters[2] = -5000.0;  // clamped to -1000 m
  tile.heightMeters[3] = 20000.0;  // clamped to 65535 / 5 - 1000 m
  tile.childMask = 0b1010;
  for (const std::vector<uint8_t>& water :
       {std::vector<uint8_t>{}, std::vector<uint8_t>{255}, std::vector<uint8_t>(256 * 256, 7)}) {
    tile.waterMask = water;
    const std::vector<std::byte> bytes = formats::encodeHeightmapTile(tile);
    ASSERT_EQ(bytes.size(), 65u * 65u * 2u + 1u + water.size());
    EXPECT_EQ(static_cast<int>(bytes[2]), 23882 & 0xFF);  // little-endian
    EXPECT_EQ(static_cast<int>(bytes[3]), 23882 >> 8);
    auto decoded = formats::decodeHeightmapTile(bytes, "tile");
    ASSERT_TRUE(decoded) << decoded.error();
    EXPECT_DOUBLE_EQ(decoded->heightMeters[0], -1000.0);
    EXPECT_NEAR(decoded->heightMeters[1], 3776.4, 1e-9);
    EXPECT_DOUBLE_EQ(decoded->heightMeters[2], -1000.0);
    EXPECT_DOUBLE_EQ(decoded->heightMeters[3], 65535 / 5.0 - 1000.0);
    EXPECT_DOUBLE_EQ(decoded->heightMeters[4], 0.0);
    EXPECT_EQ(decoded->childMask, 0b1010);
    EXPECT_EQ(decoded->waterMask, water);
  }
}

// --webp: lossless WebP tiles ({z}/{x}/{y}.webp) with the very pixels of the PNG export, for
// both encodings, and globe's terrarium: source reads them as it reads the PNGs.
TEST(ExportTrees, WebpTilesAreThePngTilesExactly) {
  const fs::path dir = globe::testing::freshTempDir("export-webp");
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const std::string region = " --levels 9-10 --bounds 138.7,35.3,138.8,35.4 ";
  for (const std::string format : {"terrarium", "terrain-rgb"}) {
    const fs::path png = dir / (format + "-png"), webp = dir / (format + "-webp");
    const Exit a =
        runCommand(tiler() + "--format " + format + " -o " + png.string() + region + pyramid);
    ASSERT_EQ(a.exitCode, 0) << a.output;
    const Exit b = runCommand(tiler() + "--format " + format + " --webp -o " + webp.string() +
                              region + pyramid);
    ASSERT_EQ(b.exitCode, 0) << b.output;
    size_t compared = 0;
    for (const auto& entry : fs::recursive_directory_iterator(png)) {
      if (entry.path().extension() != ".png") continue;
      fs::path twin = webp / fs::relative(entry.path(), png);
      twin.replace_extension(".webp");
      auto bytes = transport::readWholeFile(twin, 1U << 24);
      ASSERT_TRUE(bytes) << bytes.error();
      ASSERT_GT(bytes->size(), 20u);
      // RIFF....WEBPVP8L: the lossless bitstream.
      EXPECT_EQ(std::memcmp(bytes->data() + 8, "WEBPVP8L", 8), 0) << twin;
      auto decoded = formats::decodeImageRgba(*bytes, twin.string());  // libwebp
      ASSERT_TRUE(decoded) << decoded.error();
      auto reference = formats::loadImageRgba(entry.path());
      ASSERT_TRUE(reference) << reference.error();
      ASSERT_EQ(decoded->widthPixels, 256);
      ASSERT_EQ(decoded->heightPixels, 256);
      EXPECT_EQ(decoded->pixels, reference->pixels) << twin;
      ++compared;
    }
    EXPECT_GE(compared, 2u) << format;
    // Resumed: the .webp tiles are the ones kept.
    const Exit c = runCommand(tiler() + "--format " + format + " --webp -o " + webp.string() +
                              region + pyramid);
    EXPECT_NE(c.output.find(": 0 " + format + " tiles written"), std::string::npos) << c.output;
  }
  // globe reads the WebP tree as the PNG one.
  const fs::path points = writePoints(dir / "points.txt", fujiPoints(30, 5));
  const auto read = [&](const std::string& extension) {
    return queryHeights("'terrarium:" + (dir / "terrarium-").string() + extension +
                            "/{z}/{x}/{y}." + extension + "?maxzoom=10'",
                        points);
  };
  const std::vector<double> fromPng = read("png");
  ASSERT_EQ(fromPng.size(), 30u);
  EXPECT_EQ(read("webp"), fromPng);
}

TEST(ExportTrees, WebpIsOnlyForElevationImages) {
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const fs::path out = globe::testing::freshTempDir("export-bad-webp") / "x";
  for (const std::string format : {"quantized-mesh", "heightmap"}) {
    const Exit r =
        runCommand(tiler() + "--format " + format + " --webp -o " + out.string() + " " + pyramid);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("--webp is for --format terrarium or terrain-rgb"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(format), std::string::npos) << r.output;
  }
  const Exit block = runCommand(tiler() + "--webp " + pyramid + " 0 0 0 " + out.string());
  EXPECT_EQ(block.exitCode, 2) << block.output;
  EXPECT_NE(block.output.find("--webp needs --format"), std::string::npos) << block.output;
  EXPECT_FALSE(fs::exists(out));
  const Exit help = runCommand(tiler() + "--help");
  EXPECT_NE(help.output.find("heightmap"), std::string::npos) << help.output;
  EXPECT_NE(help.output.find("lossless"), std::string::npos) << help.output;
}

}  // namespace
}  // namespace globe::publish
