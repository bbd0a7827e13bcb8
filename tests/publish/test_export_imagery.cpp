// globe-tiler export-imagery on the bundled Zion Landsat layer: the XYZ tree's pixels against the
// layer's own samples (bilinear, computed here), the TMS tree as the XYZ one with its rows
// flipped (its tilemapresource.xml parsed by Python and opened by GDAL), the PMTiles archive
// decoded by an independent stdlib-Python reader (tests/tools/pmtiles_reference.py) into exactly
// the XYZ tree's bytes and read by the program's own PMTiles and TMS sources; directories with
// leaves, deduplication, resuming after a kill, bad arguments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/crc32.hpp"
#include "compression/gzip_bytes.hpp"
#include "formats/image_io.hpp"
#include "formats/pmtiles.hpp"
#include "geo/tiling_scheme.hpp"
#include "publish/imagery_export.hpp"
#include "publish/pmtiles_writer.hpp"
#include "services/imagery_services.hpp"
#include "streaming/imagery_store.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/shared_commands.hpp"
#include "tests/support/test_io_util.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::publish {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = GLOBE_SOURCE_DIR;

using Exit = globe::testing::CommandExit;
using globe::testing::runCommand;

std::string exportImagery(const std::string& arguments) {
  return std::string(GLOBE_TILER_EXE) + " export-imagery " + arguments;
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Every file below `dir` by its relative path, with its bytes.
std::map<std::string, std::string> filesOf(const fs::path& dir, const std::string& extension) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == extension) {
      files[fs::relative(entry.path(), dir).string()] = readFile(entry.path());
    }
  }
  return files;
}

// Zion's Landsat scene, zooms 9-12 (zoom 12 from the layer's level 11).
const std::string kZion = "--levels 9-12 --bounds -113.25,37.1,-112.8,37.55 ";

struct ZionExports {
  fs::path xyz, tms, pmtiles;
};

// Made once per CTest run (sharedCommands): four tests read them.
const ZionExports& zionExports() {
  static const ZionExports exports = [] {
    const std::string layer = globe::testing::zionLayer().string();
    std::vector<std::string> commands;
    for (const std::string out :
         {"xyz --format xyz", "tms --format tms", "zion.pmtiles --format pmtiles"}) {
      commands.push_back(exportImagery("-o {dir}/" + out + " " + kZion +
                                       "--attribution 'USGS Landsat 8' " + layer));
    }
    const globe::testing::SharedRun run =
        globe::testing::sharedCommands("export-imagery", commands);
    for (const Exit& r : run.exits) {
      EXPECT_EQ(r.exitCode, 0) << r.output;
      std::printf("%s", r.output.c_str());
    }
    return ZionExports{run.dir / "xyz", run.dir / "tms", run.dir / "zion.pmtiles"};
  }();
  return exports;
}

double toRadians(double degrees) { return degrees * std::numbers::pi / 180; }

TEST(ExportImagery, XyzPixelsAreTheLayersColourAtTheirCentres) {
  const fs::path xyz = zionExports().xyz;
  auto layer = streaming::ImageryStore::open(globe::testing::zionLayer().string());
  ASSERT_TRUE(layer) << layer.error();
  ASSERT_EQ((*layer)->manifest().pixelGrid, formats::ImageryPixelGrid::Edges);
  const int zoom = 12;
  const uint32_t level = layerLevelForZoom(zoom, 256);
  EXPECT_EQ(level, 11u);  // 180° / 2^11 / 256 = 360° / 2^12 / 256
  std::mt19937 random(11);
  std::uniform_real_distribution<double> lon(-113.15, -112.95), lat(37.2, 37.45);
  int compared = 0;
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    // The pixel of zoom 12 under a random point, and its centre.
    const double n = std::ldexp(1.0, zoom);
    const double column = (lon(random) + 180) / 360 * n;
    const double latRadians = toRadians(lat(random));
    const double row =
        (1 - std::log(std::tan(latRadians) + 1 / std::cos(latRadians)) / std::numbers::pi) / 2 * n;
    const int x = static_cast<int>(column), y = static_cast<int>(row);
    const int c = static_cast<int>((column - x) * 256), r = static_cast<int>((row - y) * 256);
    const double centreLon = (x + (c + 0.5) / 256) / n * 360 - 180;
    const double centreLat =
        std::atan(std::sinh(std::numbers::pi * (1 - 2 * (y + (r + 0.5) / 256) / n))) * 180 /
        std::numbers::pi;
    auto tile = formats::loadImageRgba(xyz / std::to_string(zoom) / std::to_string(x) /
                                       (std::to_string(y) + ".png"));
    ASSERT_TRUE(tile) << tile.error();
    const uint8_t* got = &tile->pixels[(static_cast<size_t>(r) * 256 + c) * 4];

    // The layer's level-11 edge samples around the centre (sample (i, j) at west + i·w/255,
    // north − j·h/255), bilinear.
    const auto t = geo::GeographicTilingScheme::positionToTile(toRadians(centreLon),
                                                               toRadians(centreLat), level);
    ASSERT_TRUE(t);
    const auto rect = geo::GeographicTilingScheme::tileRectangle(*t);
    const double u =
        (toRadians(centreLon) - rect.westRadians) / (rect.eastRadians - rect.westRadians) * 255;
    const double v =
        (rect.northRadians - toRadians(centreLat)) / (rect.northRadians - rect.southRadians) * 255;
    auto image = (*layer)->loadImage(*t);
    ASSERT_TRUE(image) << image.error();
    ASSERT_TRUE(image->has_value());
    const int i0 = std::min(static_cast<int>(u), 254), j0 = std::min(static_cast<int>(v), 254);
    const double fu = u - i0, fv = v - j0;
    const auto at = [&](int si, int sj, int channel) {
      return (**image).pixels[(static_cast<size_t>(sj) * 256 + si) * 4 + channel];
    };
    if (at(i0, j0, 3) < 255 || at(i0 + 1, j0, 3) < 255 || at(i0, j0 + 1, 3) < 255 ||
        at(i0 + 1, j0 + 1, 3) < 255) {
      continue;  // the scene's no-data corners
    }
    for (int channel = 0; channel < 4; ++channel) {
      const double expected =
          (1 - fv) * ((1 - fu) * at(i0, j0, channel) + fu * at(i0 + 1, j0, channel)) +
          fv * ((1 - fu) * at(i0, j0 + 1, channel) + fu * at(i0 + 1, j0 + 1, channel));
      worst = std::max(worst, std::fabs(got[channel] - expected));
    }
    ++compared;
  }
  std::printf("[ xyz ] %d pixels against the layer's samples: worst %.2f\n", compared, worst);
  EXPECT_GT(compared, 150);
  EXPECT_LE(worst, 1.0);  // rounding only

  // tilejson.json: TileJSON 3.0 with the run's zooms, bounds and attribution.
  const auto j = nlohmann::json::parse(readFile(xyz / "tilejson.json"));
  EXPECT_EQ(j["tilejson"], "3.0.0");
  EXPECT_EQ(j["tiles"][0], "{z}/{x}/{y}.png");
  EXPECT_EQ(j["minzoom"], 9);
  EXPECT_EQ(j["maxzoom"], 12);
  EXPECT_EQ(j["attribution"], "USGS Landsat 8");
  EXPECT_NEAR(j["bounds"][0].get<double>(), -113.2414, 1e-3);  // the scene's, within --bounds
  EXPECT_NEAR(j["bounds"][3].get<double>(), 37.5191, 1e-3);
}

TEST(ExportImagery, TmsIsTheXyzTreeWithRowsFromTheSouth) {
  const ZionExports& e = zionExports();
  const auto xyz = filesOf(e.xyz, ".png");
  const auto tms = filesOf(e.tms, ".png");
  ASSERT_GT(xyz.size(), 50u);
  EXPECT_EQ(tms.size(), xyz.size());
  for (const auto& [path, bytes] : xyz) {
    int z = 0, x = 0, y = 0;
    ASSERT_EQ(std::sscanf(path.c_str(), "%d/%d/%d.png", &z, &x, &y), 3) << path;
    const std::string flipped = std::to_string(z) + "/" + std::to_string(x) + "/" +
                                std::to_string((1 << z) - 1 - y) + ".png";
    auto it = tms.find(flipped);
    ASSERT_NE(it, tms.end()) << flipped;
    EXPECT_EQ(it->second, bytes) << path << " vs " << flipped;
  }
  // tilemapresource.xml: XML with a global-mercator TileSet per zoom (metres per pixel halving).
  const fs::path resource = e.tms / "tilemapresource.xml";
  const Exit parsed = runCommand(
      "python3 -c \"import sys, xml.etree.ElementTree as E; r = E.parse(sys.argv[1]).getroot(); "
      "s = r.find('TileSets'); print(r.find('SRS').text, s.get('profile'), "
      "[(t.get('href'), round(float(t.get('units-per-pixel')), 4)) for t in s])\" " +
      resource.string());
  ASSERT_EQ(parsed.exitCode, 0) << parsed.output;
  EXPECT_NE(parsed.output.find("EPSG:3857 global-mercator [('9', 305.7481), ('10', 152.8741), "
                               "('11', 76.437), ('12', 38.2185)]"),
            std::string::npos)
      << parsed.output;
  // GDAL's WMS driver reads a TileMap document whose tile sets start at zoom 0: a Web-Mercator
  // raster of the deepest zoom's pixels.
  const fs::path fromZero = globe::testing::freshTempDir("export-imagery-tms0") / "tms-from-0";
  const Exit exported =
      runCommand(exportImagery("--format tms --levels 0-10 -o " + fromZero.string() + " " +
                               globe::testing::zionLayer().string()));
  ASSERT_EQ(exported.exitCode, 0) << exported.output;
  const Exit gdal = runCommand("gdalinfo " + (fromZero / "tilemapresource.xml").string());
  if (gdal.output.find("not found") != std::string::npos) GTEST_SKIP() << "no gdalinfo";
  EXPECT_EQ(gdal.exitCode, 0) << gdal.output;
  EXPECT_NE(gdal.output.find("Pseudo-Mercator"), std::string::npos) << gdal.output;
  EXPECT_NE(gdal.output.find("Pixel Size = (152."), std::string::npos) << gdal.output;
}

TEST(ExportImagery, PmtilesHoldsExactlyTheXyzTreesTiles) {
  const ZionExports& e = zionExports();
  const fs::path dump = globe::testing::freshTempDir("export-imagery-dump") / "pmtiles-dump";
  const Exit reference =
      runCommand("python3 " + (kSource / "tests/tools/pmtiles_reference.py").string() + " " +
                 e.pmtiles.string() + " " + dump.string());
  ASSERT_EQ(reference.exitCode, 0) << reference.output;
  const auto summary = nlohmann::json::parse(reference.output);
  const auto& h = summary["header"];
  EXPECT_EQ(h["clustered"], 1);
  EXPECT_EQ(h["internal_compression"], 2);  // gzip
  EXPECT_EQ(h["tile_compression"], 1);      // none
  EXPECT_EQ(h["tile_type"], 2);             // PNG
  EXPECT_EQ(h["min_zoom"], 9);
  EXPECT_EQ(h["max_zoom"], 12);
  EXPECT_EQ(h["root_offset"], 127);
  EXPECT_NEAR(h["bounds"][0].get<double>(), -113.2414, 1e-3);
  EXPECT_EQ(summary["metadata"]["name"], "zion");
  EXPECT_EQ(summary["metadata"]["attribution"], "USGS Landsat 8");
  EXPECT_EQ(summary["metadata"]["bounds"].size(), 4u);
  // Exactly the tree's tiles, byte for byte.
  const auto xyz = filesOf(e.xyz, ".png");
  EXPECT_EQ(filesOf(dump, ".png"), xyz);
  EXPECT_EQ(summary["tiles"], xyz.size());
  uint64_t treeBytes = 0;
  for (const auto& [path, bytes] : xyz) treeBytes += bytes.size();
  std::printf("[ pmtiles ] %zu tiles: archive %llu bytes, tree %llu bytes of tiles\n", xyz.size(),
              static_cast<unsigned long long>(fs::file_size(e.pmtiles)),
              static_cast<unsigned long long>(treeBytes));

  // The program's own readers: the archive and the TMS tree as layers give the same quadtree
  // tiles (the same Web-Mercator tiles under them), close to the layer's own.
  auto pmtiles = services::openImageryTiles("pmtiles:" + e.pmtiles.string(), nullptr);
  ASSERT_TRUE(pmtiles) << pmtiles.error();
  EXPECT_EQ((*pmtiles)->attribution(), "USGS Landsat 8");
  auto tms = services::openImageryTiles("tms:" + (e.tms / "tilemapresource.xml").string(), nullptr);
  ASSERT_TRUE(tms) << tms.error();
  auto layer = streaming::ImageryStore::open(globe::testing::zionLayer().string());
  ASSERT_TRUE(layer) << layer.error();
  const auto tile =
      geo::GeographicTilingScheme::positionToTile(toRadians(-113.05), toRadians(37.3), 10);
  ASSERT_TRUE(tile);
  auto fromArchive = (*pmtiles)->loadImage(*tile);
  auto fromTms = (*tms)->loadImage(*tile);
  auto fromLayer = (*layer)->loadImage(*tile);
  ASSERT_TRUE(fromArchive && fromTms && fromLayer);
  ASSERT_TRUE(fromArchive->has_value() && fromTms->has_value() && fromLayer->has_value());
  EXPECT_EQ((*fromArchive)->pixels, (*fromTms)->pixels);
  double sum = 0;
  double count = 0;
  for (size_t i = 0; i < (*fromLayer)->pixels.size(); i += 4) {
    if ((*fromLayer)->pixels[i + 3] < 255 || (*fromArchive)->pixels[i + 3] < 255) continue;
    for (size_t k = 0; k < 3; ++k) {
      sum += std::abs((*fromLayer)->pixels[i + k] - (*fromArchive)->pixels[i + k]);
      ++count;
    }
  }
  ASSERT_GT(count, 10000);
  std::printf("[ pmtiles ] read back onto the quadtree: mean difference %.2f\n", sum / count);
  EXPECT_LT(sum / count, 6.0);  // resampled twice, never shifted
}

// A synthetic archive through the writer: repeated tiles stored once (a run where they follow
// each other), and enough distinct tiles that the root points at leaf directories; the Python
// reader and the program's decoder find every tile.
TEST(ExportImagery, PmtilesWriterDeduplicatesAndSpillsIntoLeaves) {
  const fs::path archive = globe::testing::freshTempDir("pmtiles-writer") / "t.pmtiles";
  auto writer = PmtilesWriter::create(archive);
  ASSERT_TRUE(writer) << writer.error();
  struct Tile {
    uint64_t id;
    uint32_t z, x, y;
    std::string bytes;
  };
  std::vector<Tile> tiles;
  std::mt19937 random(3);
  const uint32_t zoom = 7;
  for (uint32_t y = 0; y < 128; ++y) {
    for (uint32_t x = 0; x < 128; ++x) {
      // A quarter of them one "sea" tile; the rest distinct, of lengths that gzip cannot
      // predict (so that the directory outgrows the root's 16 KiB).
      std::string bytes = random() % 4 == 0 ? std::string("sea")
                                            : std::to_string(x) + "/" + std::to_string(y) +
                                                  std::string(random() % 600, 'x');
      tiles.push_back({formats::pmtilesTileId(zoom, x, y), zoom, x, y, bytes});
    }
  }
  // And the whole of zoom 2 the same tile: one entry, a run of 16.
  for (uint32_t y = 0; y < 4; ++y) {
    for (uint32_t x = 0; x < 4; ++x)
      tiles.push_back({formats::pmtilesTileId(2, x, y), 2, x, y, "sea"});
  }
  std::sort(tiles.begin(), tiles.end(), [](const Tile& a, const Tile& b) { return a.id < b.id; });
  for (const Tile& t : tiles) {
    auto added = (*writer)->add(t.z, t.x, t.y, std::as_bytes(std::span(t.bytes)));
    ASSERT_TRUE(added) << added.error();
  }
  // Out of order: refused.
  EXPECT_FALSE((*writer)->add(0, 0, 0, std::as_bytes(std::span(std::string_view("a")))));
  formats::PmtilesHeader header;
  header.tileType = formats::PmtilesTileType::Png;
  header.minZoom = 2;
  header.maxZoom = 7;
  auto summary = (*writer)->finish(header, R"({"name":"t"})");
  ASSERT_TRUE(summary) << summary.error();
  EXPECT_EQ(summary->addressedTiles, tiles.size());
  EXPECT_LT(summary->tileContents, tiles.size() * 4 / 5);
  EXPECT_GT(summary->leafDirectories, 0u);
  EXPECT_FALSE(fs::exists(archive.string() + ".tmp"));
  EXPECT_FALSE(fs::exists(archive.string() + ".tmp-tiles"));

  const Exit reference =
      runCommand("python3 " + (kSource / "tests/tools/pmtiles_reference.py").string() + " " +
                 archive.string() + " -");
  ASSERT_EQ(reference.exitCode, 0) << reference.output;
  const auto j = nlohmann::json::parse(reference.output);
  EXPECT_EQ(j["tiles"], tiles.size());
  EXPECT_EQ(j["leaf_directories"], summary->leafDirectories);
  EXPECT_LE(j["header"]["root_length"].get<uint64_t>() + 127, 16384u);
  const auto& crcs = j["crc32"];
  for (const Tile& t : tiles) {
    const std::string name =
        std::to_string(t.z) + "/" + std::to_string(t.x) + "/" + std::to_string(t.y);
    ASSERT_TRUE(crcs.contains(name)) << name;
    EXPECT_EQ(crcs[name].get<uint32_t>(), core::crc32(std::as_bytes(std::span(t.bytes)))) << name;
  }
  // The program's decoder: zoom 2 is one entry with a run of 16.
  const std::string bytes = readFile(archive);
  const auto span = std::as_bytes(std::span(bytes));
  auto h = formats::decodePmtilesHeader(span, bytes.size(), archive.string());
  ASSERT_TRUE(h) << h.error();
  EXPECT_EQ(h->tileEntries, summary->tileEntries);
  EXPECT_TRUE(h->clustered);
  const auto directory = [&](uint64_t offset, uint64_t length) {
    auto inflated = compression::gunzipIfNeeded(span.subspan(offset, length), "directory", 1 << 24);
    EXPECT_TRUE(inflated) << inflated.error();
    auto entries = formats::decodePmtilesDirectory(*inflated, "directory");
    EXPECT_TRUE(entries) << entries.error();
    return *entries;
  };
  const auto root = directory(h->rootOffset, h->rootLength);
  ASSERT_FALSE(root.empty());
  EXPECT_EQ(root[0].runLength, 0u);  // a leaf
  const auto leaf = directory(h->leavesOffset + root[0].offset, root[0].length);
  ASSERT_FALSE(leaf.empty());
  EXPECT_EQ(leaf[0].tileId, formats::pmtilesTileId(2, 0, 0));
  EXPECT_EQ(leaf[0].runLength, 16u);
}

TEST(ExportImagery, WebpAndJpegTilesAreReadBack) {
  const fs::path dir = globe::testing::freshTempDir("export-imagery-webp");
  const std::string layer = globe::testing::zionLayer().string();
  const Exit webp =
      runCommand(exportImagery("--format pmtiles --tile-format webp -o " +
                               (dir / "z.pmtiles").string() + " --levels 10 " + layer));
  ASSERT_EQ(webp.exitCode, 0) << webp.output;
  auto archive = services::openImageryTiles("pmtiles:" + (dir / "z.pmtiles").string(), nullptr);
  ASSERT_TRUE(archive) << archive.error();
  const auto tile =
      geo::GeographicTilingScheme::positionToTile(toRadians(-113.05), toRadians(37.3), 9);
  auto image = (*archive)->loadImage(*tile);
  ASSERT_TRUE(image) << image.error();
  EXPECT_TRUE(image->has_value());
  const Exit jpeg = runCommand(exportImagery("--format xyz --tile-format jpeg -o " +
                                             (dir / "jpeg").string() + " --levels 10 " + layer));
  ASSERT_EQ(jpeg.exitCode, 0) << jpeg.output;
  const auto tiles = filesOf(dir / "jpeg", ".jpg");
  ASSERT_FALSE(tiles.empty());
  for (const auto& [path, bytes] : tiles) {
    auto decoded = formats::decodeImageRgba(std::as_bytes(std::span(bytes)), path);
    EXPECT_TRUE(decoded) << decoded.error();
  }
  EXPECT_EQ(nlohmann::json::parse(readFile(dir / "jpeg" / "tilejson.json"))["tiles"][0],
            "{z}/{x}/{y}.jpg");
}

// Killed mid-way (SIGKILL), each export run again completes: the tree into the same tiles as
// an uninterrupted run, the archive (absent until whole) into the same bytes.
TEST(ExportImagery, AKilledRunRunAgainCompletes) {
  const ZionExports& e = zionExports();
  const fs::path dir = globe::testing::freshTempDir("export-imagery-killed");
  const std::string layer = globe::testing::zionLayer().string();
  const std::string tree = exportImagery("--format xyz -o " + (dir / "xyz").string() + " " + kZion +
                                         "--attribution 'USGS Landsat 8' " + layer);
  const std::string archive =
      exportImagery("--format pmtiles -o " + (dir / "zion.pmtiles").string() + " " + kZion +
                    "--attribution 'USGS Landsat 8' " + layer);
  runCommand("timeout -s KILL 0.5 " + tree);
  // Killed (137) before it finished: no archive, not a half one.
  if (runCommand("timeout -s KILL 0.5 " + archive).exitCode == 137) {
    EXPECT_FALSE(fs::exists(dir / "zion.pmtiles"));
  }
  const Exit again = runCommand(tree);
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(filesOf(dir / "xyz", ".png"), filesOf(e.xyz, ".png"));
  EXPECT_EQ(readFile(dir / "xyz" / "tilejson.json"), readFile(e.xyz / "tilejson.json"));
  const Exit archiveAgain = runCommand(archive);
  ASSERT_EQ(archiveAgain.exitCode, 0) << archiveAgain.output;
  EXPECT_EQ(readFile(dir / "zion.pmtiles"), readFile(e.pmtiles));
  EXPECT_FALSE(fs::exists(dir / "zion.pmtiles.tmp"));
  EXPECT_FALSE(fs::exists(dir / "zion.pmtiles.tmp-tiles"));
  // Run a third time: every tile kept.
  const Exit third = runCommand(tree);
  ASSERT_EQ(third.exitCode, 0) << third.output;
  EXPECT_NE(third.output.find(": 0 png tiles written"), std::string::npos) << third.output;
}

TEST(ExportImagery, BadArgumentsAreClearErrors) {
  const std::string layer = globe::testing::zionLayer().string();
  const fs::path dir = globe::testing::freshTempDir("export-imagery-bad");
  const std::string out = (dir / "x").string();
  const auto expectError = [](const Exit& r, int code, const std::string& text) {
    EXPECT_EQ(r.exitCode, code) << r.output;
    EXPECT_NE(r.output.find(text), std::string::npos) << r.output;
  };
  expectError(runCommand(exportImagery("--format xyz -o " + out + " /nonexistent/layer")), 1,
              "/nonexistent/layer");
  expectError(runCommand(exportImagery("--format xyz -o " + out + " --levels 9-3 " + layer)), 2,
              "--levels must be A-B");
  expectError(runCommand(exportImagery("--format xyz -o " + out + " --levels 20 " + layer)), 1,
              "finest is zoom 13");
  expectError(runCommand(exportImagery("--format xyz -o " + out + " --bounds 10,50,5,60 " + layer)),
              2, "--bounds must be W,S,E,N");
  expectError(runCommand(exportImagery("--format xyz -o " + out + " --bounds 0,0,10,10 " + layer)),
              1, "do not meet");
  // Unwritable: a directory under a regular file; an archive where a directory is.
  globe::testing::writeText(dir / "file", "x");
  expectError(runCommand(exportImagery("--format xyz --levels 9 -o " +
                                       (dir / "file" / "t").string() + " " + layer)),
              1, (dir / "file").string());
  fs::create_directories(dir / "d.pmtiles");
  expectError(runCommand(exportImagery("--format pmtiles --levels 9 -o " +
                                       (dir / "d.pmtiles").string() + " " + layer)),
              1, "is a directory");
  // A tree of other tiles in the directory.
  ASSERT_EQ(runCommand(exportImagery("--format xyz --levels 9 -o " + out + " " + layer)).exitCode,
            0);
  expectError(runCommand(exportImagery("--format tms --levels 9 -o " + out + " " + layer)), 1,
              "an earlier export of other tiles");
  EXPECT_NE(runCommand(exportImagery("--format mbtiles -o " + out + " " + layer)).exitCode, 0);
  EXPECT_NE(
      runCommand(exportImagery("--format xyz --tile-format gif -o " + out + " " + layer)).exitCode,
      0);
  EXPECT_NE(runCommand(exportImagery("-o " + out + " " + layer)).exitCode, 0);  // --format required
}

}  // namespace
}  // namespace globe::publish
