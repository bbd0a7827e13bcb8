// 3D Tiles read for collision: real sample tilesets (CesiumGS's dragon, instanced trees), boxes
// made here at known places and heights, hostile files, and `globe query --tileset`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <sstream>

#include "geo/ecef.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tests/tiles3d/box_tileset.hpp"
#include "tiles3d/height_grid.hpp"
#include "tiles3d/tile_content.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_surface.hpp"
#include "transport/atomic_file.hpp"

namespace globe::tiles3d {
namespace {

namespace fs = std::filesystem;
using testing::boxGlb;
using testing::eastNorthUp;
using testing::transformJson;
using testing::writeFile;

const fs::path kSamples = fs::path(GLOBE_SOURCE_DIR) / "tests/data/interop/3dtiles";
const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();
constexpr double kDegree = std::numbers::pi / 180;

struct Extent {
  double west = 1e9, south = 1e9, east = -1e9, north = -1e9, low = 1e9, high = -1e9;
};

Extent extentOf(const TriangleMesh& mesh) {
  Extent e;
  for (const glm::dvec3& p : mesh.positions) {
    const auto c = geo::ecefToCartographic(kWgs84, p);
    EXPECT_TRUE(c.has_value());
    if (!c) continue;
    e.west = std::min(e.west, c->longitudeDegrees()),
    e.east = std::max(e.east, c->longitudeDegrees());
    e.south = std::min(e.south, c->latitudeDegrees()),
    e.north = std::max(e.north, c->latitudeDegrees());
    e.low = std::min(e.low, c->heightMeters), e.high = std::max(e.high, c->heightMeters);
  }
  return e;
}

Result<TriangleMesh> readContentFile(const fs::path& file, const glm::dmat4& transform) {
  auto bytes = transport::readWholeFile(file, 1u << 26);
  if (!bytes) return Error{bytes.error()};
  return readTileContent(*bytes, transform, kWgs84, file.string());
}

TEST(TileContent, TheDragonStandsInItsBoxWhereItsTransformPutsIt) {
  auto tileset = readTileset(kSamples / "TilesetWithDiscreteLOD");
  ASSERT_TRUE(tileset) << tileset.error();
  ASSERT_EQ(tileset->root.children.size(), 1u);
  const TileNode& medium = tileset->root.children[0];
  ASSERT_EQ(medium.contents.size(), 1u);
  auto mesh =
      readContentFile(kSamples / "TilesetWithDiscreteLOD" / medium.contents[0], medium.transform);
  ASSERT_TRUE(mesh) << mesh.error();
  EXPECT_GT(mesh->triangleCount(), 5000u);
  // The box: ±7.0955 × ±3.1405 × ±5.0375 local units, scaled 100×, centred 503.75 m up at
  // -75.6121, 40.0425 (its axes east, north and up there): the glTF's y-up turned z-up fits it.
  const Extent e = extentOf(*mesh);
  EXPECT_GT(e.low, -1.0);
  EXPECT_LT(e.high, 1008.0);
  EXPECT_GT(e.high, 950.0);  // the dragon fills its box's height, not its width
  EXPECT_NEAR((e.west + e.east) / 2, -75.6121, 0.002);
  EXPECT_NEAR((e.south + e.north) / 2, 40.0425, 0.002);
}

TEST(TileContent, InstancedTreesStandEastNorthUpInTheirRegion) {
  auto mesh = readContentFile(kSamples / "TilesetWithTreeBillboards/tree.i3dm", glm::dmat4(1.0));
  ASSERT_TRUE(mesh) << mesh.error();
  ASSERT_GT(mesh->triangleCount(), 0u);
  EXPECT_EQ(mesh->triangleCount() % 25, 0u);  // 25 instances of one model
  const Extent e = extentOf(*mesh);
  // The tileset's region: -1.3197004795898053..-1.3196595204101946 rad east, 0.6988582109..
  // 0.6988897891 north, 0..20 m: trees stand up in it (their crowns a little over its sides).
  EXPECT_GT(e.west, -1.3197004795898053 / kDegree - 0.0005);
  EXPECT_LT(e.east, -1.3196595204101946 / kDegree + 0.0005);
  EXPECT_GT(e.south, 0.6988582109 / kDegree - 0.0005);
  EXPECT_LT(e.north, 0.6988897891 / kDegree + 0.0005);
  EXPECT_GT(e.low, -2.0);
  EXPECT_LT(e.high, 25.0);
  EXPECT_GT(e.high, 5.0);
}

// What drawing needs comes along: the trees' leaf texture (512², its alpha: glTF's BLEND drawn
// as a 0.5 cut), their texture coordinates in [0, 1], the trunks' brown, the models' normals
// turned upright with each instance (unit length, pointing every way, not all up).
TEST(TileContent, TexturesNormalsAndAlphaComeAlongForDrawing) {
  auto mesh = readContentFile(kSamples / "TilesetWithTreeBillboards/tree.i3dm", glm::dmat4(1.0));
  ASSERT_TRUE(mesh) << mesh.error();
  ASSERT_EQ(mesh->normals.size(), mesh->positions.size());
  ASSERT_EQ(mesh->uvs.size(), mesh->positions.size());
  ASSERT_EQ(mesh->triangleParts.size(), mesh->triangleCount());
  ASSERT_EQ(mesh->parts.size(), 2u * 25);  // trunk and leaves, each instance
  const SurfacePart& trunk = mesh->parts[0];
  const SurfacePart& leaves = mesh->parts[1];
  EXPECT_FALSE(trunk.texture);
  EXPECT_NEAR(trunk.baseColor.r, 0.1223, 1e-3);
  EXPECT_EQ(trunk.alphaCutoff, 0.0f);
  ASSERT_TRUE(leaves.texture);
  EXPECT_EQ(leaves.texture->widthPixels, 512);
  EXPECT_EQ(leaves.texture->rgba.size(), 512u * 512 * 4);
  EXPECT_EQ(leaves.alphaCutoff, 0.5f);
  size_t textured = 0;
  glm::dvec3 sum(0.0);
  for (size_t k = 0; k < mesh->positions.size(); ++k) {
    EXPECT_NEAR(glm::length(mesh->normals[k]), 1.0, 1e-4);
    sum += glm::dvec3(mesh->normals[k]);
    if (mesh->parts[mesh->triangleParts[k / 3]].texture) {
      ++textured;
      EXPECT_GE(mesh->uvs[k].x, 0.0f);
      EXPECT_LE(mesh->uvs[k].y, 1.0f);
    }
  }
  EXPECT_GT(textured, 0u);
  EXPECT_LT(glm::length(sum) / static_cast<double>(mesh->positions.size()), 0.9);
}

TEST(TileContent, BadBytesAreClearErrorsNamingTheFile) {
  const auto bytes = [](const std::string& s) {
    std::vector<std::byte> b(s.size());
    std::memcpy(b.data(), s.data(), s.size());
    return b;
  };
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "not a 3D Tiles content"},
      {"b3dm\x01\x00\x00\x00", "shorter than its header"},
      {std::string("b3dm\x01\x00\x00\x00\xff\xff\x00\x00", 12) + std::string(16, '\0'),
       "reach past"},
      {"xyzw and more bytes here", "not a 3D Tiles content"},
      {std::string("cmpt\x01\x00\x00\x00\x20\x00\x00\x00\x01\x00\x00\x00", 16) +
           std::string("b3dm\x01\x00\x00\x00\xff\x00\x00\x00", 12),
       "of a wrong length"},
      {R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../../etc/passwd","byteLength":4}]})",
       "not a glTF"},
  };
  for (const auto& [content, problem] : cases) {
    auto mesh = readTileContent(bytes(content), glm::dmat4(1.0), kWgs84, "bad.b3dm");
    ASSERT_FALSE(mesh) << problem;
    EXPECT_NE(mesh.error().find("bad.b3dm"), std::string::npos) << mesh.error();
    EXPECT_NE(mesh.error().find(problem), std::string::npos) << mesh.error();
  }
}

// The highest of the triangles under a point (each interpolated linearly in longitude and
// latitude), by brute force.
std::optional<double> bruteForceHeight(const TriangleMesh& mesh, double lon, double lat) {
  std::optional<double> best;
  for (size_t t = 0; t < mesh.positions.size(); t += 3) {
    geo::Cartographic c[3];
    for (int k = 0; k < 3; ++k) c[k] = *geo::ecefToCartographic(kWgs84, mesh.positions[t + k]);
    const double det = (c[1].longitudeRadians - c[0].longitudeRadians) *
                           (c[2].latitudeRadians - c[0].latitudeRadians) -
                       (c[2].longitudeRadians - c[0].longitudeRadians) *
                           (c[1].latitudeRadians - c[0].latitudeRadians);
    if (std::fabs(det) < 1e-30) continue;
    const double u =
        ((lon - c[0].longitudeRadians) * (c[2].latitudeRadians - c[0].latitudeRadians) -
         (c[2].longitudeRadians - c[0].longitudeRadians) * (lat - c[0].latitudeRadians)) /
        det;
    const double v =
        ((c[1].longitudeRadians - c[0].longitudeRadians) * (lat - c[0].latitudeRadians) -
         (lon - c[0].longitudeRadians) * (c[1].latitudeRadians - c[0].latitudeRadians)) /
        det;
    if (u < 0 || v < 0 || u + v > 1) continue;
    const double h = c[0].heightMeters + u * (c[1].heightMeters - c[0].heightMeters) +
                     v * (c[2].heightMeters - c[0].heightMeters);
    if (!best || h > *best) best = h;
  }
  return best;
}

TEST(HeightGrid, NeverBelowTheDragonAndCloseAboveIt) {
  auto tileset = readTileset(kSamples / "TilesetWithDiscreteLOD");
  ASSERT_TRUE(tileset) << tileset.error();
  auto mesh = readContentFile(kSamples / "TilesetWithDiscreteLOD" / tileset->root.contents[0],
                              tileset->root.transform);  // low LOD
  ASSERT_TRUE(mesh) << mesh.error();
  const HeightGrid grid = HeightGrid::rasterize(*mesh, kWgs84, 0.5, 512);
  ASSERT_FALSE(grid.empty());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const geo::GlobeRectangle& r = grid.rectangle();
  std::vector<double> above;
  for (int k = 0; k < 400; ++k) {
    const double lon = r.westRadians + unit(random) * r.widthRadians();
    const double lat = r.southRadians + unit(random) * r.heightRadians();
    const auto truth = bruteForceHeight(*mesh, lon, lat);
    if (!truth) continue;
    const auto h = grid.heightAt(lon, lat);
    ASSERT_TRUE(h.has_value()) << lon << "," << lat;
    EXPECT_GE(*h, *truth - 1e-6) << lon << "," << lat;
    above.push_back(*h - *truth);
  }
  ASSERT_GT(above.size(), 50u);
  std::sort(above.begin(), above.end());
  EXPECT_LT(above[above.size() / 2], 10.0);  // cells ~2.8 m on a 1.4 km dragon's slopes
  std::printf(
      "[ dragon grid %ux%u ] above the triangles: median %.2f m, 95th %.2f m over %zu points\n",
      grid.columns(), grid.rows(), above[above.size() / 2], above[above.size() * 95 / 100],
      above.size());
}

// A tileset of boxes made here: `json` is its root tile.
fs::path writeTileset(const fs::path& dir, const std::string& root) {
  writeFile(dir / "tileset.json",
            R"({"asset":{"version":"1.1"},"geometricError":100,"root":)" + root + "}");
  return dir;
}

TEST(TilesetSurface, AddKeepsEveryLevelReplaceOnlyTheChildren) {
  const fs::path dir = globe::testing::freshTempDir("tiles3d-refine");
  writeFile(dir / "wide.glb", boxGlb(40, 40, 10));    // around P
  writeFile(dir / "sub/tall.glb", boxGlb(5, 5, 30));  // at Q, 30 m east of P
  const std::string p = transformJson(eastNorthUp(138.6, 35.0, 0));
  // The external tileset's root transform is relative to its parent tile's (the chain): 30 m
  // east in P's east-north-up frame.
  const std::string q = "[1,0,0,0,0,1,0,0,0,0,1,0,30,0,0,1]";
  writeFile(dir / "sub/tileset.json", R"({"asset":{"version":"1.1"},"root":{"transform":)" + q +
                                          R"(,"geometricError":0,"content":{"uri":"tall.glb"}}})");
  const auto at = [](double eastMeters) { return (138.6 + eastMeters / 91190.0) * kDegree; };
  for (const std::string refine : {"ADD", "REPLACE"}) {
    writeTileset(dir, R"({"transform":)" + p + R"(,"geometricError":10,"refine":")" + refine +
                          R"(","content":{"uri":"wide.glb"},"children":[{"geometricError":1,)"
                          R"("content":{"uri":"sub/tileset.json"}}]})");
    auto tileset = readTileset(dir);
    ASSERT_TRUE(tileset) << tileset.error();
    auto surface = TilesetSurface::load(*tileset, kWgs84);
    ASSERT_TRUE(surface) << surface.error();
    EXPECT_TRUE(surface->warnings().empty()) << surface->warnings()[0];
    EXPECT_EQ(surface->contentsRead(), 2u);
    const auto tall = surface->heightAt(at(30), 35.0 * kDegree);
    const auto wide = surface->heightAt(at(-20), 35.0 * kDegree);
    const auto none = surface->heightAt(at(200), 35.0 * kDegree);
    EXPECT_FALSE(none.has_value());
    if (refine == "ADD") {
      ASSERT_TRUE(tall && wide);
      EXPECT_NEAR(*tall, 30.0, 0.05);
      EXPECT_NEAR(*wide, 10.0, 0.05);
    } else {
      EXPECT_FALSE(wide.has_value());  // replaced by the child, which is not there
    }
  }
}

TEST(TilesetSurface, AMissingContentLeavesItsParentStanding) {
  auto tileset = readTileset(kSamples / "TilesetWithDiscreteLOD");
  ASSERT_TRUE(tileset) << tileset.error();
  EXPECT_EQ(tileset->tileCount, 3u);
  auto surface = TilesetSurface::load(*tileset, kWgs84);
  ASSERT_TRUE(surface) << surface.error();
  ASSERT_EQ(surface->warnings().size(), 1u);
  EXPECT_NE(surface->warnings()[0].find("dragon_high.b3dm"), std::string::npos);
  EXPECT_NE(surface->warnings()[0].find("its parent's content stands in"), std::string::npos);
  EXPECT_EQ(surface->contentsRead(), 2u);
  // The medium dragon answers where the high one would have.
  const auto h = surface->heightAt(-75.6121 * kDegree, 40.0427 * kDegree);
  ASSERT_TRUE(h.has_value());
  EXPECT_GT(*h, 300.0);
}

TEST(Tileset, FilesOutsideItsFolderAreNeverRead) {
  const fs::path root = globe::testing::freshTempDir("tiles3d-outside");
  writeFile(root / "secret.glb", boxGlb(5, 5, 99));
  const fs::path dir = root / "set";
  writeTileset(dir, R"({"geometricError":1,"contents":[{"uri":"../secret.glb"},{"uri":")" +
                        (root / "secret.glb").string() +
                        R"("},{"uri":"https://example.com/a.glb"},{"uri":"data:x"}]})");
  auto tileset = readTileset(dir / "tileset.json");
  ASSERT_TRUE(tileset) << tileset.error();
  EXPECT_TRUE(tileset->root.contents.empty());
  ASSERT_EQ(tileset->warnings.size(), 4u);
  EXPECT_NE(tileset->warnings[0].find("outside the tileset's folder"), std::string::npos);
  EXPECT_NE(tileset->warnings[1].find("an absolute path"), std::string::npos);
  // A tileset that is not one is a clear error.
  writeFile(dir / "tileset.json", "{\"asset\":{}}");
  auto bad = readTileset(dir);
  ASSERT_FALSE(bad);
  EXPECT_NE(bad.error().find("not a 3D Tiles tileset"), std::string::npos) << bad.error();
  // Fields of the wrong type, in the tileset or an implicit tile: clear errors, never a throw.
  for (
      const std::string& wrongRoot :
      {std::string(R"({"geometricError":"far","content":{"uri":"a.glb"}})"),
       std::string(R"({"geometricError":1,"refine":7})"),
       std::string(
           R"({"geometricError":1,"implicitTiling":{"subdivisionScheme":4,"subtreeLevels":"x"}})")}) {
    writeTileset(dir, wrongRoot);
    auto wrong = readTileset(dir);
    ASSERT_FALSE(wrong) << wrongRoot;
    EXPECT_NE(wrong.error().find("tileset.json"), std::string::npos) << wrong.error();
  }
  writeTileset(dir, R"({"geometricError":1,"content":{"uri":"tileset.json"}})");
  // A tileset naming itself: read to the depth bound, then read past with a warning.
  auto loop = readTileset(dir);
  ASSERT_TRUE(loop) << loop.error();
  ASSERT_EQ(loop->warnings.size(), 1u);
  EXPECT_NE(loop->warnings[0].find("deeper than"), std::string::npos) << loop->warnings[0];
}

// `globe query --tileset`: the higher of the terrain and the tileset's roof. A 30 m box on the
// water of Suruga Bay (the bundled pyramid's sea there, 0 m).
TEST(QueryTileset, ARoofReadsItsHeightAndBesideItTheTerrain) {
  const fs::path dir = globe::testing::freshTempDir("tiles3d-query");
  writeFile(dir / "box.glb", boxGlb(20, 20, 30));
  writeTileset(dir, R"({"transform":)" + transformJson(eastNorthUp(138.6, 34.9, 0)) +
                        R"(,"geometricError":0,"content":{"uri":"box.glb"}})");
  writeFile(dir / "points.txt", "138.6,34.9\n138.6001,34.9001\n138.61,34.9\n");
  const std::string pyramid = globe::testing::bundledPyramid().string();
  const auto run = [&](const std::string& extra) {
    return globe::testing::runCommand(std::string(GLOBE_EXE) + " query " + pyramid + extra + " < " +
                                      (dir / "points.txt").string());
  };
  const auto terrain = run("");
  ASSERT_EQ(terrain.exitCode, 0) << terrain.output;
  EXPECT_NE(terrain.output.find("138.6,34.9,"), std::string::npos) << terrain.output;
  const auto withBox = run(" --tileset " + dir.string());
  ASSERT_EQ(withBox.exitCode, 0) << withBox.output;
  std::istringstream lines(withBox.output), plain(terrain.output);
  std::vector<double> heights, terrainHeights;
  for (std::string line; std::getline(lines, line);)
    heights.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  for (std::string line; std::getline(plain, line);)
    terrainHeights.push_back(std::stod(line.substr(line.rfind(',') + 1)));
  ASSERT_EQ(heights.size(), 3u) << withBox.output;
  ASSERT_EQ(terrainHeights.size(), 3u) << terrain.output;
  EXPECT_NEAR(terrainHeights[0], 0.0, 0.01);  // the bay
  EXPECT_NEAR(heights[0], 30.0, 0.01);        // the roof
  EXPECT_NEAR(heights[1], 30.0, 0.01);        // its corner, 11 m east and north
  EXPECT_EQ(heights[2], terrainHeights[2]);   // 900 m away: the terrain
}

}  // namespace
}  // namespace globe::tiles3d
