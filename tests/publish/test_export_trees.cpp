// globe-tiler export on the bundled pyramid (Fuji's 3″ DEM over ETOPO20): the quantized-mesh
// tree decoded by an independent stdlib-Python decoder and the Terrarium tiles by stb, both
// against `globe query --mode exact` of the pyramid itself; resuming; bad arguments.
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
#include <optional>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "compression/gzip_bytes.hpp"
#include "formats/image_io.hpp"
#include "formats/quantized_mesh.hpp"
#include "geo/tiling_scheme.hpp"
#include "publish/block_mesh.hpp"
#include "publish/terrarium_export.hpp"
#include "services/terrain_services.hpp"
#include "terrain/height_block.hpp"
#include "tests/publish/query_points.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/nginx_server.hpp"
#include "tests/support/test_io_util.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::publish {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = GLOBE_SOURCE_DIR;

using Exit = globe::testing::CommandExit;
using globe::testing::runCommand;

using testing::heightsOf;
using testing::Point;
using testing::writePoints;

std::vector<double> exactHeights(const fs::path& points, const std::string& level = "") {
  const Exit r = runCommand(std::string(GLOBE_EXE) + " query --mode exact " +
                            (level.empty() ? "" : "--level " + level + " ") +
                            globe::testing::bundledPyramid().string() + " < " + points.string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  return heightsOf(r.output);
}

std::vector<double> sortedDifferences(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  std::vector<double> d;
  for (size_t i = 0; i < std::min(a.size(), b.size()); ++i) d.push_back(std::fabs(a[i] - b[i]));
  std::sort(d.begin(), d.end());
  return d;
}

// Fuji's DEM square, away from its edges (where the pyramid's finest level ends).
std::vector<Point> fujiPoints(size_t count) {
  std::mt19937 random(31);
  std::uniform_real_distribution<double> lon(138.15, 138.85), lat(35.15, 35.85);
  std::vector<Point> points;
  for (size_t i = 0; i < count; ++i) points.push_back({lon(random), lat(random)});
  return points;
}

std::string tiler() { return std::string(GLOBE_TILER_EXE) + " export "; }

TEST(ExportTrees, QuantizedMeshHoldsThePyramidsSurface) {
  const fs::path out = globe::testing::freshTempDir("export-qm") / "qm";
  const std::string pyramid = globe::testing::bundledPyramid().string();
  // Two runs into one tree: the world's coarse levels, then Fuji's square to its finest.
  Exit a = runCommand(tiler() + "--format quantized-mesh -o " + out.string() + " --levels 0-3 " +
                      pyramid);
  ASSERT_EQ(a.exitCode, 0) << a.output;
  Exit b = runCommand(tiler() + "--format quantized-mesh -o " + out.string() +
                      " --levels 4-12 --bounds 138,35,139,36 " + pyramid);
  ASSERT_EQ(b.exitCode, 0) << b.output;
  EXPECT_NE(b.output.find("quantized-mesh tiles written"), std::string::npos) << b.output;
  // layer.json lists both runs' tiles: level 0's two, and level 12 over Fuji.
  std::ifstream layerFile(out / "layer.json");
  const std::string layer{std::istreambuf_iterator<char>(layerFile), {}};
  EXPECT_NE(layer.find("\"format\": \"quantized-mesh-1.0\""), std::string::npos) << layer;
  EXPECT_NE(layer.find("\"maxzoom\": 12"), std::string::npos) << layer;

  // An independent decoder of the tree (the finest tile its layer.json lists, the triangle's
  // plane) against the pyramid's exact surface: each level-12 tile's TIN lies within the tile's
  // geometric error (CesiumJS's 77,067 m / 2^12 = 18.8 m) plus the height quantization.
  const fs::path points = writePoints(out.parent_path() / "points.txt", fujiPoints(200));
  const auto decoded = [&](const fs::path& tree, const fs::path& at) {
    const Exit reference =
        runCommand("python3 " + (kSource / "tests/tools/quantized_mesh_reference.py").string() +
                   " " + tree.string() + " < " + at.string());
    EXPECT_EQ(reference.exitCode, 0) << reference.output;
    return heightsOf(reference.output);
  };
  const std::vector<double> d = sortedDifferences(decoded(out, points), exactHeights(points));
  ASSERT_EQ(d.size(), 200u);
  std::printf("[ quantized-mesh ] vs the pyramid: median %.3f m, 95th %.3f m, max %.3f m\n", d[100],
              d[190], d.back());
  const double levelTwelveErrorMeters = 6378137.0 * 2 * std::numbers::pi * 0.25 / 130 / 4096;
  EXPECT_LT(d.back(), levelTwelveErrorMeters + 0.15);
  EXPECT_LT(d[100], levelTwelveErrorMeters / 2);  // most points much nearer than the bound
  EXPECT_GT(d.back(), 0.15);                      // simplified: not the whole grid any more

  // --mesh-error 0 keeps every sample: the summit's tiles then equal the surface within the
  // quantization and the chord's sag over a level-12 cell (< 1 mm).
  const fs::path exact = out.parent_path() / "exact";
  Exit e = runCommand(tiler() + "--format quantized-mesh --mesh-error 0 -o " + exact.string() +
                      " --levels 12 --bounds 138.70,35.33,138.78,35.39 " + pyramid);
  ASSERT_EQ(e.exitCode, 0) << e.output;
  std::vector<Point> summit;
  for (const Point& p : fujiPoints(2000)) {
    if (p.lon > 138.705 && p.lon < 138.775 && p.lat > 35.335 && p.lat < 35.385) summit.push_back(p);
  }
  ASSERT_GT(summit.size(), 5u);
  const fs::path summitPoints = writePoints(out.parent_path() / "summit.txt", summit);
  const std::vector<double> de =
      sortedDifferences(decoded(exact, summitPoints), exactHeights(summitPoints));
  std::printf("[ quantized-mesh --mesh-error 0 ] %zu summit points: max %.3f m\n", de.size(),
              de.back());
  EXPECT_LT(de.back(), 0.15);

  // Resumed: nothing written again.
  Exit again = runCommand(tiler() + "--format quantized-mesh -o " + out.string() +
                          " --levels 4-12 --bounds 138,35,139,36 " + pyramid);
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_NE(again.output.find(": 0 quantized-mesh tiles written"), std::string::npos)
      << again.output;
}

// The simplified tiles as CesiumJS reads them: neighbours of one level have the same vertices
// on their shared side (no crack), every vertex has a unit normal facing up, the water mask is
// the sea classification (an ocean tile all water in one byte, a coast tile 256×256 with both),
// and the metadata lists the children the tree holds.
TEST(ExportTrees, QuantizedMeshNeighboursShareTheirSidesAndTilesCarryExtensions) {
  const fs::path out = globe::testing::freshTempDir("export-qm-sides") / "qm";
  const std::string pyramid = globe::testing::bundledPyramid().string();
  Exit a =
      runCommand(tiler() + "--format quantized-mesh -o " + out.string() + " --levels 3 " + pyramid);
  ASSERT_EQ(a.exitCode, 0) << a.output;
  Exit b = runCommand(tiler() + "--format quantized-mesh -o " + out.string() +
                      " --levels 9-10 --bounds 138.6,35.3,139.0,35.6 " + pyramid);
  ASSERT_EQ(b.exitCode, 0) << b.output;
  const auto tileAt = [&](uint32_t level, uint32_t x, uint32_t tmsY) {
    const fs::path path =
        out / std::to_string(level) / std::to_string(x) / (std::to_string(tmsY) + ".terrain");
    std::ifstream file(path, std::ios::binary);
    const std::vector<char> chars{std::istreambuf_iterator<char>(file), {}};
    EXPECT_FALSE(chars.empty()) << path;
    const std::vector<std::byte> stored(
        reinterpret_cast<const std::byte*>(chars.data()),
        reinterpret_cast<const std::byte*>(chars.data()) + chars.size());
    auto bytes = compression::gunzipIfNeeded(stored, path.string(), 64 << 20);
    EXPECT_TRUE(bytes) << path;
    auto mesh = formats::decodeQuantizedMesh(*bytes, path.string());
    EXPECT_TRUE(mesh) << mesh.error();
    return std::optional<formats::QuantizedMesh>(mesh ? std::optional(*mesh) : std::nullopt);
  };
  std::ifstream layerFile(out / "layer.json");
  const std::string layer{std::istreambuf_iterator<char>(layerFile), {}};
  EXPECT_NE(layer.find("\"octvertexnormals\""), std::string::npos) << layer;

  // Side by side over Fuji at level 10: u (or v) along the shared side and the heights there.
  const auto fuji = geo::GeographicTilingScheme::positionToTile(138.73 * std::numbers::pi / 180,
                                                                35.36 * std::numbers::pi / 180, 10);
  ASSERT_TRUE(fuji);
  const uint32_t tmsY = (1U << 10) - 1 - fuji->y;
  const auto west = tileAt(10, fuji->x, tmsY), east = tileAt(10, fuji->x + 1, tmsY);
  const auto north = tileAt(10, fuji->x, tmsY + 1);
  ASSERT_TRUE(west && east && north);
  EXPECT_LT(west->triangleCount(), 64u * 64u * 2u);  // simplified
  const auto side = [](const formats::QuantizedMesh& mesh, const std::vector<uint32_t>& edge,
                       bool alongV) {
    std::vector<std::pair<uint16_t, double>> along;
    for (uint32_t i : edge)
      along.emplace_back(alongV ? mesh.v[i] : mesh.u[i], mesh.heightMeters[i]);
    return along;
  };
  const auto expectSame = [](const auto& one, const auto& other, double stepMeters) {
    ASSERT_EQ(one.size(), other.size());
    ASSERT_GT(one.size(), 2u);  // Fuji's flanks: more than the corners
    for (size_t k = 0; k < one.size(); ++k) {
      EXPECT_EQ(one[k].first, other[k].first) << k;
      EXPECT_NEAR(one[k].second, other[k].second, stepMeters) << k;
    }
  };
  const auto step = [](const formats::QuantizedMesh& m) {
    return (m.maximumHeightMeters - m.minimumHeightMeters) / 32767.0 + 1e-6;
  };
  expectSame(side(*west, west->eastEdge, true), side(*east, east->westEdge, true),
             step(*west) + step(*east));
  expectSame(side(*west, west->northEdge, false), side(*north, north->southEdge, false),
             step(*west) + step(*north));

  // Normals: one per vertex, unit, up (the ellipsoid's normal within 60°: Fuji's steepest
  // flank is ~35°).
  ASSERT_EQ(west->normals.size(), west->vertexCount());
  const auto r = geo::GeographicTilingScheme::tileRectangle(*fuji);
  const double lat = (r.southRadians + r.northRadians) / 2,
               lon = (r.westRadians + r.eastRadians) / 2;
  const std::array<double, 3> up{std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                                 std::sin(lat)};
  for (const auto& n : west->normals) {
    EXPECT_NEAR(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 0.02);
    EXPECT_GT(n[0] * up[0] + n[1] * up[1] + n[2] * up[2], 0.5);
  }
  // Metadata: the level-10 tile lists its children (none exported: level 11 was not asked for).
  EXPECT_NE(west->metadataJson.find("\"available\""), std::string::npos) << west->metadataJson;
  const auto parent = tileAt(9, fuji->x / 2, tmsY / 2);
  ASSERT_TRUE(parent);
  EXPECT_NE(parent->metadataJson.find("\"startX\":" + std::to_string(fuji->x)), std::string::npos)
      << parent->metadataJson;

  // Water: the Pacific south-east of the Marquesas, all sea; the tile of the British Isles.
  const auto ocean = tileAt(3, 2, 3);  // −135..−112.5°, −22.5..0° (TMS row 3 of 4)
  ASSERT_TRUE(ocean);
  EXPECT_EQ(ocean->waterMask, std::vector<uint8_t>{255});
  const auto coast = tileAt(3, 7, 6);  // −22.5..0°, 45..67.5°
  ASSERT_TRUE(coast);
  ASSERT_EQ(coast->waterMask.size(), 256u * 256u);
  const auto wet = std::count(coast->waterMask.begin(), coast->waterMask.end(), 255);
  EXPECT_GT(wet, 256 * 256 / 2);  // mostly the Atlantic
  EXPECT_LT(wet, 256 * 256);      // and Ireland, Britain
  // Fuji is land.
  EXPECT_EQ(west->waterMask, std::vector<uint8_t>{0});
}

// Every tile of a tree decoded by @here/quantized-mesh-decoder (npm, tools/web) holds what
// globe's decoder reads from it: vertices, triangles, edge lists, normals, water mask, the
// heights' range, the metadata's children.
TEST(ExportTrees, QuantizedMeshTilesDecodeWithTheNpmDecoder) {
  if (!fs::exists(kSource / "tools/web/node_modules/@here/quantized-mesh-decoder/package.json")) {
    GTEST_SKIP() << "tools/web/install.sh has not installed the npm decoder";
  }
  const fs::path out = globe::testing::freshTempDir("export-qm-npm") / "qm";
  Exit e = runCommand(tiler() + "--format quantized-mesh -o " + out.string() +
                      " --levels 0-10 --bounds 138.4,35.1,139,35.6 " +
                      globe::testing::bundledPyramid().string());
  ASSERT_EQ(e.exitCode, 0) << e.output;
  const Exit decoded =
      runCommand("node " + (kSource / "tests/tools/quantized_mesh_node_check.mjs").string() + " " +
                 out.string());
  ASSERT_EQ(decoded.exitCode, 0) << decoded.output;
  std::istringstream lines(decoded.output);
  std::string line;
  size_t tiles = 0;
  while (std::getline(lines, line)) {
    const auto j = nlohmann::json::parse(line);
    const fs::path path = out / j["tile"].get<std::string>();
    std::ifstream file(path, std::ios::binary);
    const std::vector<char> chars{std::istreambuf_iterator<char>(file), {}};
    auto bytes = compression::gunzipIfNeeded(std::as_bytes(std::span(chars.data(), chars.size())),
                                         path.string(), 64 << 20);
    ASSERT_TRUE(bytes) << bytes.error();
    auto mesh = formats::decodeQuantizedMesh(*bytes, path.string());
    ASSERT_TRUE(mesh) << mesh.error();
    EXPECT_EQ(j["vertices"], mesh->vertexCount()) << path;
    EXPECT_EQ(j["triangles"], mesh->triangleCount()) << path;
    EXPECT_EQ(j["indicesOutOfRange"], 0) << path;
    EXPECT_EQ(j["edges"], nlohmann::json({mesh->westEdge.size(), mesh->southEdge.size(),
                                          mesh->eastEdge.size(), mesh->northEdge.size()}))
        << path;
    EXPECT_EQ(j["normals"], mesh->normals.size()) << path;
    EXPECT_EQ(j["waterMaskBytes"], mesh->waterMask.size()) << path;
    const double step = (mesh->maximumHeightMeters - mesh->minimumHeightMeters) / 32767.0 + 1e-3;
    EXPECT_NEAR(j["lowestMeters"].get<double>(),
                *std::min_element(mesh->heightMeters.begin(), mesh->heightMeters.end()), step);
    EXPECT_NEAR(j["highestMeters"].get<double>(),
                *std::max_element(mesh->heightMeters.begin(), mesh->heightMeters.end()), step);
    EXPECT_EQ(j["metadata"], nlohmann::json::parse(mesh->metadataJson)) << path;
    ++tiles;
  }
  EXPECT_GT(tiles, 20u);
}

// Tiles made by several threads are the tiles one thread makes, byte for byte.
TEST(ExportTrees, QuantizedMeshThreadsMakeTheSameTree) {
  const fs::path root = globe::testing::freshTempDir("export-qm-threads");
  const std::string pyramid = globe::testing::bundledPyramid().string();
  for (const char* threads : {"1", "3"}) {
    const fs::path out = root / threads / "qm";
    Exit e = runCommand(tiler() + "--format quantized-mesh -j " + threads + " -o " + out.string() +
                        " --levels 0-11 --bounds 138.5,35.2,139,35.6 " + pyramid);
    ASSERT_EQ(e.exitCode, 0) << e.output;
  }
  const auto one = globe::testing::checksums(root / "1" / "qm");
  EXPECT_GT(one.size(), 30u);
  EXPECT_EQ(one, globe::testing::checksums(root / "3" / "qm"));
}

// Served by nginx: `globe query` reads the tree, and again from its disk cache asks only for
// layer.json (the tiles' URLs carry the tree's version); without {version} in the template each
// tile is asked again (a conditional GET).
TEST(ExportTrees, AServedTreeIsKeptByItsVersion) {
  const fs::path site = globe::testing::freshTempDir("export-served");
  const fs::path tree = site / "www" / "qm";
  const Exit exported = runCommand(tiler() + "--format quantized-mesh -o " + tree.string() +
                                   " --levels 0-7 --bounds 138,35,139,36 " +
                                   globe::testing::bundledPyramid().string());
  ASSERT_EQ(exported.exitCode, 0) << exported.output;
  auto server = globe::testing::NginxServer::start({site / "www", ""});
  ASSERT_TRUE(server);
  const fs::path points = writePoints(site / "points.txt", fujiPoints(20));
  const auto query = [&] {
    const Exit r = runCommand(std::string(GLOBE_EXE) + " query --mode exact quantized-mesh:" +
                              server->url("/qm/layer.json") + " --cache-dir " +
                              (site / "cache").string() + " < " + points.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    return heightsOf(r.output);
  };
  const auto tileRequests = [&](size_t from) {
    const auto log = server->accessLog();
    return static_cast<size_t>(std::count_if(
        log.begin() + static_cast<ptrdiff_t>(from), log.end(),
        [](const std::string& line) { return line.find(".terrain") != std::string::npos; }));
  };
  const std::vector<double> cold = query();
  ASSERT_EQ(cold.size(), 20u);
  EXPECT_GT(tileRequests(0), 0u);
  size_t before = server->accessLog().size();
  EXPECT_EQ(query(), cold);
  EXPECT_EQ(tileRequests(before), 0u);
  EXPECT_EQ(server->accessLog().size(), before + 1) << "layer.json alone";

  // The same tree with an unversioned template: every tile revalidated.
  std::ifstream in(tree / "layer.json");
  std::string layer{std::istreambuf_iterator<char>(in), {}};
  const std::string versioned = "?v={version}";
  ASSERT_NE(layer.find(versioned), std::string::npos) << layer;
  layer.erase(layer.find(versioned), versioned.size());
  std::ofstream(tree / "layer.json") << layer;
  before = server->accessLog().size();
  EXPECT_EQ(query(), cold);
  const size_t unversioned = tileRequests(before);
  before = server->accessLog().size();
  EXPECT_EQ(query(), cold);
  EXPECT_EQ(tileRequests(before), unversioned);
  EXPECT_GT(unversioned, 0u);
}

TEST(ExportTrees, QuantizedMeshTilesAreWhatClientsCheck) {
  // A level-9 tile over Fuji: the header's centre on the tile, edge lists on their edges (the
  // decoder checks both), 64×64×2 triangles, heights within their quantization.
  const auto fuji = geo::GeographicTilingScheme::positionToTile(138.73 * std::numbers::pi / 180,
                                                                35.36 * std::numbers::pi / 180, 9);
  ASSERT_TRUE(fuji);
  std::vector<double> heights(65 * 65);
  for (size_t i = 0; i < heights.size(); ++i)
    heights[i] = 100.0 + 3776.0 * std::sin(static_cast<double>(i) * 0.01);
  const BlockMesh made = quantizedMeshOfGrid(*fuji, 65, heights, geo::Ellipsoid::wgs84());
  const std::vector<std::byte> bytes = formats::encodeQuantizedMesh(made.mesh, made.culling);
  auto mesh = formats::decodeQuantizedMesh(bytes, "fuji.terrain");
  ASSERT_TRUE(mesh) << mesh.error();
  EXPECT_EQ(mesh->vertexCount(), 65u * 65u);
  EXPECT_EQ(mesh->triangleCount(), 64u * 64u * 2u);
  EXPECT_EQ(mesh->westEdge.size(), 65u);
  EXPECT_EQ(mesh->northEdge.size(), 65u);
  const auto r = geo::GeographicTilingScheme::tileRectangle(*fuji);
  const double deg = 180 / std::numbers::pi;
  EXPECT_TRUE(formats::centreLiesOverTile(*mesh, r.westRadians * deg, r.southRadians * deg,
                                          r.eastRadians * deg, r.northRadians * deg));
  const double step = (mesh->maximumHeightMeters - mesh->minimumHeightMeters) / 32767.0;
  std::vector<double> sorted(mesh->heightMeters);
  std::vector<double> expected(heights);
  std::sort(sorted.begin(), sorted.end());
  std::sort(expected.begin(), expected.end());
  for (size_t i = 0; i < sorted.size(); ++i) ASSERT_NEAR(sorted[i], expected[i], step);
  // The horizon point lies outside the ellipsoid, on the centre's side.
  const auto& h = made.culling.horizonOcclusionPointScaled;
  EXPECT_GT(std::sqrt(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]), 1.0);
  EXPECT_GT(made.culling.boundingSphereRadiusMeters, 1000.0);
}

// A water mask (the extension ctb and Cesium ion serve) marks water in the blocks globe reads
// from the tiles: a level-0 tileset at 1000 m whose tiles' west halves are water.
TEST(ExportTrees, AWaterMaskMarksWaterInTheBlocksRead) {
  const fs::path dir = globe::testing::freshTempDir("export-watermask") / "tiles";
  const geo::Ellipsoid wgs84 = geo::Ellipsoid::wgs84();
  for (uint32_t x = 0; x < 2; ++x) {
    BlockMesh made =
        quantizedMeshOfGrid({0, x, 0}, 65, std::vector<double>(65 * 65, 1000.0), wgs84);
    made.mesh.waterMask.assign(256 * 256, 0);
    for (size_t row = 0; row < 256; ++row) std::fill_n(&made.mesh.waterMask[row * 256], 128, 255);
    fs::create_directories(dir / "0" / std::to_string(x));
    const auto bytes = formats::encodeQuantizedMesh(made.mesh, made.culling);
    std::ofstream(dir / "0" / std::to_string(x) / "0.terrain", std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()),
               static_cast<std::streamsize>(bytes.size()));
  }
  std::ofstream(dir / "layer.json")
      << R"({"tilejson":"2.1.0","format":"quantized-mesh-1.0","version":"1.0.0","scheme":"tms",)"
      << R"("tiles":["{z}/{x}/{y}.terrain"],"projection":"EPSG:4326","extensions":["watermask"],)"
      << R"("available":[[{"startX":0,"startY":0,"endX":1,"endY":0}]]})";
  auto source = services::openTerrainSource("quantized-mesh:" + dir.string(),
                                            terrain::SeaSurface::Water, nullptr);
  ASSERT_TRUE(source) << source.error();
  auto block = (*source)->loadBlock({0, 1, 0});
  ASSERT_TRUE(block) << block.error();
  const uint32_t n = block->verticesPerSide;
  size_t water = 0, land = 0;
  for (uint32_t row = 0; row < n; ++row) {
    for (uint32_t column = 0; column < n; ++column) {
      const int16_t code = block->at(row, column);
      // Inside each half (the middle column is where the mask's edge falls).
      if (column < n / 2 - 1) {
        EXPECT_TRUE(terrain::isWater(code)) << row << "," << column << ": " << code;
        water += terrain::isWater(code) ? 1 : 0;
      } else if (column > n / 2 + 1) {
        EXPECT_EQ(code, 1000) << row << "," << column;
        land += code == 1000 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(water, 0u);
  EXPECT_GT(land, 0u);
}

// The centre of pixel (column, row) of Web-Mercator tile (z, x, y), degrees.
Point pixelCentre(int z, int x, int y, int column, int row) {
  const double n = std::ldexp(1.0, z);
  const double lon = (x + (column + 0.5) / 256) / n * 360 - 180;
  const double mercator = std::numbers::pi * (1 - 2 * (y + (row + 0.5) / 256) / n);
  return {lon, std::atan(std::sinh(mercator)) * 180 / std::numbers::pi};
}

TEST(ExportTrees, TerrariumPixelsAreTheExactSurfaceAtTheirCentres) {
  const fs::path out = globe::testing::freshTempDir("export-terrarium") / "t";
  const Exit r = runCommand(tiler() + "--format terrarium -o " + out.string() +
                            " --levels 10 --bounds 138.7,35.3,138.8,35.4 " +
                            globe::testing::bundledPyramid().string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  // Zoom 10's pixel is 0.00137° wide: the pyramid's level 13 (0.00137°), as the exporter picks.
  const int z = 10;
  const int x = static_cast<int>((138.75 + 180) / 360 * 1024);
  const double latRadians = 35.35 * std::numbers::pi / 180;
  const int y = static_cast<int>(
      (1 - std::log(std::tan(latRadians) + 1 / std::cos(latRadians)) / std::numbers::pi) / 2 *
      1024);
  const fs::path tilePath =
      out / std::to_string(z) / std::to_string(x) / (std::to_string(y) + ".png");
  auto image = formats::loadImageRgba(tilePath);
  ASSERT_TRUE(image) << image.error();
  ASSERT_EQ(image->widthPixels, 256);
  std::vector<Point> points;
  std::vector<double> decoded;
  std::mt19937 random(5);
  std::uniform_int_distribution<int> pixel(0, 255);
  for (int i = 0; i < 100; ++i) {
    const int column = pixel(random), row = pixel(random);
    points.push_back(pixelCentre(z, x, y, column, row));
    const uint8_t* p = &image->pixels[(static_cast<size_t>(row) * 256 + column) * 4];
    decoded.push_back(p[0] * 256.0 + p[1] + p[2] / 256.0 - 32768.0);
  }
  const fs::path file = writePoints(out.parent_path() / "points.txt", points);
  const std::vector<double> d = sortedDifferences(decoded, exactHeights(file, "13"));
  ASSERT_EQ(d.size(), 100u);
  EXPECT_LT(d.back(), 0.01) << "median " << d[50];
  EXPECT_EQ(terrariumPixel(0.0), (std::array<uint8_t, 3>{128, 0, 0}));
  EXPECT_EQ(terrariumPixel(-11034.5), (std::array<uint8_t, 3>{84, 229, 128}));
  EXPECT_EQ(terrariumPixel(1e9), (std::array<uint8_t, 3>{255, 255, 255}));  // clamped
}

// The same tile as Terrain-RGB (Mapbox's encoding, 0.1 m steps): each pixel within 0.05 m of the
// exact surface at its centre, decoded here by the published formula.
TEST(ExportTrees, TerrainRgbPixelsAreTheExactSurfaceAtTheirCentres) {
  const fs::path out = globe::testing::freshTempDir("export-terrain-rgb") / "t";
  const Exit r = runCommand(tiler() + "--format terrain-rgb -o " + out.string() +
                            " --levels 10 --bounds 138.7,35.3,138.8,35.4 " +
                            globe::testing::bundledPyramid().string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("terrain-rgb tiles written"), std::string::npos) << r.output;
  const int z = 10;
  const int x = static_cast<int>((138.75 + 180) / 360 * 1024);
  const double latRadians = 35.35 * std::numbers::pi / 180;
  const int y = static_cast<int>(
      (1 - std::log(std::tan(latRadians) + 1 / std::cos(latRadians)) / std::numbers::pi) / 2 *
      1024);
  auto image = formats::loadImageRgba(out / std::to_string(z) / std::to_string(x) /
                                      (std::to_string(y) + ".png"));
  ASSERT_TRUE(image) << image.error();
  ASSERT_EQ(image->widthPixels, 256);
  std::vector<Point> points;
  std::vector<double> decoded;
  std::mt19937 random(7);
  std::uniform_int_distribution<int> pixel(0, 255);
  for (int i = 0; i < 100; ++i) {
    const int column = pixel(random), row = pixel(random);
    points.push_back(pixelCentre(z, x, y, column, row));
    const uint8_t* p = &image->pixels[(static_cast<size_t>(row) * 256 + column) * 4];
    decoded.push_back(-10000.0 + (p[0] * 65536.0 + p[1] * 256.0 + p[2]) * 0.1);
  }
  const fs::path file = writePoints(out.parent_path() / "points.txt", points);
  const std::vector<double> d = sortedDifferences(decoded, exactHeights(file, "13"));
  ASSERT_EQ(d.size(), 100u);
  EXPECT_LT(d.back(), 0.05 + 1e-6) << "median " << d[50];
  EXPECT_EQ(terrainRgbPixel(0.0), (std::array<uint8_t, 3>{1, 134, 160}));  // 100000
  EXPECT_EQ(terrainRgbPixel(-10000.0), (std::array<uint8_t, 3>{0, 0, 0}));
  EXPECT_EQ(terrainRgbPixel(-20000.0), (std::array<uint8_t, 3>{0, 0, 0}));   // clamped
  EXPECT_EQ(terrainRgbPixel(3776.04), (std::array<uint8_t, 3>{2, 26, 32}));  // 137760
}

// Every file under `dir` (relative path -> bytes).
std::map<std::string, std::string> treeFiles(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    files[fs::relative(entry.path(), dir).string()] = {std::istreambuf_iterator<char>(in), {}};
  }
  return files;
}

TEST(ExportTrees, AWholePyramidsElevationTreeStopsWithItsDataAndIsTheSameOnAnyThreadCount) {
  // No --levels, no --bounds: the world's zooms only as deep as the pyramid's data there (the
  // 20′ world to zoom 3, Fuji's and Britain's 3″ and 30″ deeper), the deepest the zoom of the
  // pyramid's finest level; it says what it will do.
  const fs::path dir = globe::testing::freshTempDir("export-whole");
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const Exit whole = runCommand(tiler() + "--format terrarium -j 2 -o " + (dir / "w").string() +
                                " " + pyramid);
  ASSERT_EQ(whole.exitCode, 0) << whole.output;
  EXPECT_NE(whole.output.find("terrarium tiles to make on 2 threads"), std::string::npos)
      << whole.output;
  const auto files = treeFiles(dir / "w");
  std::map<int, size_t> perZoom;
  for (const auto& [name, bytes] : files) ++perZoom[std::stoi(name.substr(0, name.find('/')))];
  ASSERT_FALSE(perZoom.empty());
  EXPECT_EQ(perZoom.begin()->first, 0);
  EXPECT_EQ(perZoom.rbegin()->first, 11);  // level 14 (Fuji's 3″) = zoom 11 with 17 vertices
  EXPECT_EQ(perZoom[0], 1U);
  EXPECT_EQ(perZoom[3], 64U);  // the whole world at level 6, the 20′ grid's finest
  EXPECT_LT(perZoom[4], 40U);  // then only where finer data lies
  EXPECT_LT(files.size(), 400U);

  // One thread and two write the same bytes (heightmap's child masks read the level below as
  // the workers write).
  const std::string region = " --bounds 138.7,35.3,138.8,35.4 ";
  for (const std::string format : {"terrarium", "heightmap"}) {
    for (const char* j : {"1", "2"}) {
      const Exit r = runCommand(tiler() + "--format " + format + " -q -j " + j + region + "-o " +
                                (dir / (format + j) / "t").string() + " " + pyramid);
      ASSERT_EQ(r.exitCode, 0) << r.output;
      EXPECT_EQ(r.output.find("to make"), std::string::npos) << "-q says nothing until the end";
    }
    const auto oneThread = treeFiles(dir / (format + "1") / "t");
    EXPECT_GT(oneThread.size(), 10U) << format;
    EXPECT_TRUE(oneThread == treeFiles(dir / (format + "2") / "t")) << format;
  }
}


TEST(ExportTrees, BadArgumentsAreClearErrors) {
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const fs::path out = globe::testing::freshTempDir("export-bad") / "x";
  const Exit levels =
      runCommand(tiler() + "--format terrarium -o " + out.string() + " --levels 9-3 " + pyramid);
  EXPECT_EQ(levels.exitCode, 2);
  EXPECT_NE(levels.output.find("--levels must be A-B"), std::string::npos) << levels.output;
  const Exit bounds = runCommand(tiler() + "--format terrarium -o " + out.string() +
                                 " --bounds 10,50,5,60 " + pyramid);
  EXPECT_EQ(bounds.exitCode, 2);
  EXPECT_NE(bounds.output.find("--bounds must be W,S,E,N"), std::string::npos) << bounds.output;
  const Exit missing =
      runCommand(tiler() + "--format quantized-mesh -o " + out.string() + " /nonexistent/pyramid");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("/nonexistent/pyramid"), std::string::npos) << missing.output;
  EXPECT_FALSE(fs::exists(out / "layer.json"));
  const Exit format = runCommand(tiler() + "--format mbtiles -o " + out.string() + " " + pyramid);
  EXPECT_NE(format.exitCode, 0);
}

}  // namespace
}  // namespace globe::publish
