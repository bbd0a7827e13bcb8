// `globe-tiler buildings` on the bundled pyramid (Fuji's 3″ DEM) with the synthetic footprints of
// tests/data/buildings, read back by the project's own 3D Tiles reader: every roof at the lowest
// ground under its footprint (the pyramid's surface at its vertices and centre) plus the height
// its attributes give, nothing beside it; the footprints without a height counted; bad inputs
// named; a second run writing the same bytes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "buildings/footprint_reader.hpp"
#include "geo/cartographic.hpp"
#include "streaming/tile_store.hpp"
#include "surface/pyramid_surface.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/command_run.hpp"
#include "tests/support/test_io_util.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tiles3d/tileset.hpp"
#include "tiles3d/tileset_surface.hpp"

namespace globe::buildings {
namespace {

namespace fs = std::filesystem;
using globe::testing::runCommand;

fs::path footprintFile() {
  return fs::path(GLOBE_SOURCE_DIR) / "tests/data/buildings/fuji_footprints.geojson";
}

std::string buildingsCommand(const fs::path& out, const std::string& inputs,
                             const std::string& extra = "") {
  return std::string(GLOBE_TILER_EXE) + " buildings -o " + out.string() + " " + inputs +
         " --pyramid " + globe::testing::bundledPyramid().string() + " " + extra;
}

// The heights the test data's attributes give, by feature id (make_footprints.py): `height`,
// else building:levels × 3 m; feature 4 has none.
const std::map<int, double> kHeightMeters{{0, 12}, {1, 25.5}, {2, 9}, {3, 12},  {5, 18},  {6, 10},
                                          {7, 6},  {8, 40},   {9, 7}, {10, 15}, {11, 20}, {12, 8}};

int featureId(const Footprint& f) { return std::stoi(f.name.substr(f.name.rfind(' ') + 1)); }

bool insideRings(const Footprint& f, double lon, double lat) {
  bool inside = false;
  for (const RingDegrees& ring : f.rings) {
    for (size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      if ((ring[i].y > lat) != (ring[j].y > lat) &&
          lon < (ring[j].x - ring[i].x) * (lat - ring[i].y) / (ring[j].y - ring[i].y) + ring[i].x) {
        inside = !inside;
      }
    }
  }
  return inside;
}

// The oracle: the lowest ground of the pyramid at the outer ring's vertices and centre.
double lowestGround(const Footprint& f, surface::PyramidSurface& surface, double* highest) {
  std::vector<glm::dvec2> probes = f.rings.front();
  glm::dvec2 sum(0.0);
  for (const glm::dvec2& p : f.rings.front()) sum += p;
  probes.push_back(sum / static_cast<double>(f.rings.front().size()));
  double low = 1e300, high = -1e300;
  for (const glm::dvec2& p : probes) {
    auto h = surface.heightMeters(geo::degreesToRadians(p.x), geo::degreesToRadians(p.y));
    EXPECT_TRUE(h.ok()) << h.error();
    low = std::min(low, h.ok() ? *h : 0.0);
    high = std::max(high, h.ok() ? *h : 0.0);
  }
  *highest = high;
  return low;
}

std::optional<double> tilesetHeight(const tiles3d::TilesetSurface& s, double lon, double lat) {
  return s.heightAt(geo::degreesToRadians(lon), geo::degreesToRadians(lat));
}

TEST(BuildingsExport, RoofsReadBackAtTheLowestGroundPlusTheirHeight) {
  const fs::path out = globe::testing::freshTempDir("buildings") / "tiles";
  const auto run =
      runCommand(buildingsCommand(out, footprintFile().string(), "--tile-buildings 3"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("13 buildings"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("1 without a height, 0 refused"), std::string::npos) << run.output;

  auto tileset = tiles3d::readTileset(out);
  ASSERT_TRUE(tileset.ok()) << tileset.error();
  EXPECT_GT(tileset->tileCount, 1u);
  auto read = tiles3d::TilesetSurface::load(*tileset, geo::Ellipsoid::wgs84());
  ASSERT_TRUE(read.ok()) << read.error();
  EXPECT_TRUE(read->warnings().empty()) << read->warnings().front();

  FootprintSet set;
  ASSERT_TRUE(readFootprints(footprintFile().string(), {}, set).ok());
  ASSERT_EQ(set.footprints.size(), 13u);
  auto store = streaming::TileStore::open(globe::testing::bundledPyramid().string());
  ASSERT_TRUE(store.ok()) << store.error();
  surface::PyramidSurface ground(**store, geo::Ellipsoid::wgs84());
  double steepest = 0;
  for (const Footprint& f : set.footprints) {
    const int id = featureId(f);
    ASSERT_TRUE(kHeightMeters.count(id)) << f.name;
    EXPECT_DOUBLE_EQ(f.heightMeters, kHeightMeters.at(id)) << f.name;
    double highest = 0;
    const double base = lowestGround(f, ground, &highest);
    steepest = std::max(steepest, highest - base);
    const double roof = base + kHeightMeters.at(id);
    const ExtentDegrees e = extentOf(f);
    size_t probes = 0;
    double worst = 0;
    for (int i = 1; i < 10; ++i) {
      for (int j = 1; j < 10; ++j) {
        const double lon = e.west + (e.east - e.west) * i / 10,
                     lat = e.south + (e.north - e.south) * j / 10;
        if (!insideRings(f, lon, lat)) continue;
        ++probes;
        const auto h = tilesetHeight(*read, lon, lat);
        ASSERT_TRUE(h) << f.name << " at " << lon << "," << lat;
        EXPECT_GE(*h, roof - 1e-3) << f.name;
        EXPECT_LE(*h, roof + 1.0) << f.name;
        worst = std::max(worst, std::abs(*h - roof));
      }
    }
    EXPECT_GE(probes, 20u) << f.name;
    std::printf(
        "[ roof ] feature %2d: ground %.2f-%.2f m, roof expected %.2f m, read back within %.3f m "
        "over %zu points\n",
        id, base, highest, roof, worst, probes);
    // 20 m beside each side: nothing, or (a neighbour) nothing as high.
    const double dLon = 20 / (111320 * std::cos(geo::degreesToRadians(e.south))),
                 dLat = 20 / 110574.0;
    const double midLon = (e.west + e.east) / 2, midLat = (e.south + e.north) / 2;
    for (const auto& [lon, lat] :
         std::vector<std::pair<double, double>>{{e.west - dLon, midLat},
                                                {e.east + dLon, midLat},
                                                {midLon, e.south - dLat},
                                                {midLon, e.north + dLat}}) {
      const auto h = tilesetHeight(*read, lon, lat);
      if (id == 12) continue;  // the two parts stand 15 m apart
      EXPECT_FALSE(h) << f.name << " beside, at " << lon << "," << lat << ": " << h.value_or(0);
    }
  }
  // The courtyard's middle (feature 2's hole) is open.
  EXPECT_FALSE(tilesetHeight(*read, 138.8050, 35.4790));
  // The slope feature 6 stands on: the rule that takes the lowest ground is exercised.
  EXPECT_GT(steepest, 5.0);
}

TEST(BuildingsExport, TheNamedHeightAttributeComesFirst) {
  const fs::path out = globe::testing::freshTempDir("buildings-attr") / "tiles";
  const auto run = runCommand(buildingsCommand(
      out, footprintFile().string(), "--height-attribute roof_m --level-height-meters 4"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto tileset = tiles3d::readTileset(out);
  ASSERT_TRUE(tileset.ok()) << tileset.error();
  auto read = tiles3d::TilesetSurface::load(*tileset, geo::Ellipsoid::wgs84());
  ASSERT_TRUE(read.ok()) << read.error();
  FootprintSet set;
  FootprintOptions options;
  options.heightAttribute = "roof_m";
  options.levelHeightMeters = 4;
  ASSERT_TRUE(readFootprints(footprintFile().string(), options, set).ok());
  auto store = streaming::TileStore::open(globe::testing::bundledPyramid().string());
  ASSERT_TRUE(store.ok()) << store.error();
  surface::PyramidSurface ground(**store, geo::Ellipsoid::wgs84());
  const std::map<int, double> changed{{0, 31}, {10, 33}, {3, 16}};  // roof_m; 4 levels × 4 m
  for (const Footprint& f : set.footprints) {
    if (!changed.count(featureId(f))) continue;
    double highest = 0;
    const double roof = lowestGround(f, ground, &highest) + changed.at(featureId(f));
    const ExtentDegrees e = extentOf(f);
    const auto h = tilesetHeight(*read, (e.west + e.east) / 2, (e.south + e.north) / 2);
    ASSERT_TRUE(h) << f.name;
    EXPECT_GE(*h, roof - 1e-3) << f.name;
    EXPECT_LE(*h, roof + 1.0) << f.name;
  }
}

TEST(BuildingsExport, TilesetJsonIs3DTiles11WithGlbContents) {
  const fs::path out = globe::testing::freshTempDir("buildings-json") / "tiles";
  const auto run =
      runCommand(buildingsCommand(out, footprintFile().string(), "--tile-buildings 3"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  std::ifstream in(out / "tileset.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["asset"]["version"], "1.1");
  EXPECT_GT(j["geometricError"].get<double>(), 0);
  EXPECT_EQ(j["root"]["refine"], "ADD");
  ASSERT_EQ(j["root"]["boundingVolume"]["region"].size(), 6u);
  size_t contents = 0;
  std::vector<const nlohmann::json*> stack{&j["root"]};
  while (!stack.empty()) {
    const nlohmann::json& tile = *stack.back();
    stack.pop_back();
    const auto& region = tile["boundingVolume"]["region"];
    EXPECT_LT(region[0].get<double>(), region[2].get<double>());
    EXPECT_LT(region[4].get<double>(), region[5].get<double>());
    if (tile.contains("content")) {
      ++contents;
      std::ifstream glb(out / tile["content"]["uri"].get<std::string>(), std::ios::binary);
      char magic[4] = {};
      glb.read(magic, 4);
      EXPECT_EQ(std::string(magic, 4), "glTF");
    }
    if (tile.contains("children")) {
      EXPECT_GT(tile["geometricError"].get<double>(), 0);
      for (const auto& child : tile["children"]) stack.push_back(&child);
    }
  }
  EXPECT_GE(contents, 3u);
}

TEST(BuildingsExport, ASecondRunWritesTheSameBytes) {
  const fs::path dir = globe::testing::freshTempDir("buildings-again");
  const std::string command =
      buildingsCommand(dir / "tiles", footprintFile().string(), "--tile-buildings 3");
  ASSERT_EQ(runCommand(command).exitCode, 0);
  const auto first = globe::testing::checksums(dir / "tiles");
  ASSERT_EQ(runCommand(command).exitCode, 0);
  EXPECT_EQ(globe::testing::checksums(dir / "tiles"), first);
  const auto other =
      runCommand(buildingsCommand(dir / "other", footprintFile().string(), "--tile-buildings 3"));
  ASSERT_EQ(other.exitCode, 0) << other.output;
  EXPECT_EQ(globe::testing::checksums(dir / "other"), first);
  EXPECT_GE(first.size(), 4u);
}

TEST(BuildingsExport, BadInputsAreNamedNeverCrash) {
  const fs::path dir = globe::testing::freshTempDir("buildings-bad");
  const auto expectError = [&](const std::string& inputs, const std::string& words) {
    const auto r = runCommand(buildingsCommand(dir / "out", inputs));
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find(words), std::string::npos) << r.output;
  };
  expectError((dir / "missing.geojson").string(),
              "missing.geojson: not a vector file OGR can open");
  globe::testing::writeText(
      dir / "points.geojson",
      R"({"type":"FeatureCollection","features":[{"type":"Feature",)"
      R"("properties":{"height":5},"geometry":{"type":"Point","coordinates":[138.8,35.48]}}]})");
  expectError((dir / "points.geojson").string(), "points.geojson: holds no polygon features");
  globe::testing::writeText(dir / "text.geojson", "this is not GeoJSON {");
  expectError((dir / "text.geojson").string(), "text.geojson: not a vector file OGR can open");

  // NaN vertices and absurd heights: skipped with a warning naming the feature, the rest built.
  const std::string square = "[[138.8,35.48],[138.8002,35.48],[138.8002,35.4802],[138.8,35.48]]";
  const std::string nanSquare = "[[138.8,35.48],[NaN,35.48],[138.8002,35.4802],[138.8,35.48]]";
  const auto feature = [](const std::string& props, const std::string& ring) {
    return R"({"type":"Feature","properties":{)" + props +
           R"(},"geometry":{"type":"Polygon","coordinates":[)" + ring + "]}}";
  };
  globe::testing::writeText(
      dir / "mixed.geojson",
      R"({"type":"FeatureCollection","features":[)" + feature(R"("height":"10")", square) + "," +
          feature(R"("height":"10")", nanSquare) + "," + feature(R"("height":"1e9")", square) +
          "," + feature(R"("height":"-5")", square) + "," + feature(R"("name":"x")", square) +
          "]}");
  const auto r = runCommand(buildingsCommand(dir / "mixed", (dir / "mixed.geojson").string()));
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("1 buildings"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 without a height, 3 refused"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(
                "mixed.geojson: layer mixed: feature 1: a vertex that is not a longitude/latitude"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("feature 2: height 1e9 gives"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("feature 3: height -5 gives"), std::string::npos) << r.output;

  // Only unusable footprints: an error, and no tileset.
  globe::testing::writeText(dir / "none.geojson", R"({"type":"FeatureCollection","features":[)" +
                                                      feature(R"("height":"1e9")", square) + "]}");
  expectError((dir / "none.geojson").string(), "no footprint with a height");
  EXPECT_FALSE(fs::exists(dir / "out" / "tileset.json"));
  // A pyramid that is not one.
  const auto noPyramid =
      runCommand(std::string(GLOBE_TILER_EXE) + " buildings -o " + (dir / "p").string() + " " +
                 footprintFile().string() + " --pyramid " + (dir / "nowhere").string());
  EXPECT_EQ(noPyramid.exitCode, 1) << noPyramid.output;
  EXPECT_NE(noPyramid.output.find("nowhere"), std::string::npos) << noPyramid.output;
}

TEST(BuildingsExport, TooManyFootprintsIsAnErrorBeforeAnyAllocation) {
  FootprintSet set;
  FootprintOptions options;
  options.limits.maxFootprints = 5;
  const auto r = readFootprints(footprintFile().string(), options, set);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().find("fuji_footprints.geojson: more than 5 footprints"), std::string::npos)
      << r.error();
}

}  // namespace
}  // namespace globe::buildings
