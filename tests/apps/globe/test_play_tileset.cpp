// The camera kept out of 3D Tiles as out of the terrain: a block of box buildings of known
// heights made here on the water of Suruga Bay (the bundled pyramid's sea, 0 m); a flight
// through the block is lifted over every roof (on every frame over a footprint at least the
// 2 m floor above that roof), and a dive onto a roof stops on it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "tests/apps/globe/play_log_rows.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/tiler_test_fixture.hpp"
#include "tests/tiles3d/box_tileset.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::number;

constexpr double kWestDeg = 138.6, kLatDeg = 34.9;
constexpr double kMetersPerDegLon = 91343.0;  // at 34.9°
constexpr double kMetersPerDegLat = 110951.0;
constexpr double kHalfMeters = 15.0;  // each box 30 m x 30 m

struct Box {
  double eastMeters, northMeters, heightMeters;
};
// A 3 x 2 block, 60 m apart, 25 to 70 m tall.
const std::vector<Box> kBlock = {{0, 0, 40},  {60, 0, 70},  {120, 0, 25},
                                 {0, 60, 55}, {60, 60, 30}, {120, 60, 65}};

fs::path writeBlock() {
  const fs::path dir = globe::testing::freshTempDir("play-tileset-block");
  std::string children;
  for (size_t k = 0; k < kBlock.size(); ++k) {
    const Box& b = kBlock[k];
    const std::string name = "box" + std::to_string(k) + ".glb";
    tiles3d::testing::writeFile(dir / name,
                                tiles3d::testing::boxGlb(kHalfMeters, kHalfMeters, b.heightMeters));
    children += std::string(k ? "," : "") +
                R"({"geometricError":0,"transform":[1,0,0,0,0,1,0,0,0,0,1,0,)" +
                std::to_string(b.eastMeters) + "," + std::to_string(b.northMeters) +
                R"(,0,1],"content":{"uri":")" + name + R"("}})";
  }
  tiles3d::testing::writeFile(
      dir / "tileset.json",
      R"({"asset":{"version":"1.1"},"geometricError":50,"root":{"geometricError":10,"refine":"ADD","transform":)" +
          tiles3d::testing::transformJson(tiles3d::testing::eastNorthUp(kWestDeg, kLatDeg, 0)) +
          R"(,"children":[)" + children + "]}}");
  return dir;
}

// The roof under a logged position (0: the sea between the boxes).
double roofAt(double lonDeg, double latDeg) {
  const double east = (lonDeg - kWestDeg) * kMetersPerDegLon;
  const double north = (latDeg - kLatDeg) * kMetersPerDegLat;
  double roof = 0;
  for (const Box& b : kBlock) {
    // A metre in from each wall: the grid's cells at the walls stand on both sides.
    if (std::fabs(east - b.eastMeters) < kHalfMeters - 1 &&
        std::fabs(north - b.northMeters) < kHalfMeters - 1) {
      roof = std::max(roof, b.heightMeters);
    }
  }
  return roof;
}

std::vector<test::LogRow> play(const fs::path& tileset, const std::string& name,
                               const std::vector<camera::PathKeyframe>& keys,
                               const std::string& options = "") {
  const fs::path dir = globe::testing::freshTempDir("play-tileset-" + name);
  camera::CameraPathFile path;
  path.interpolation = "linear";
  path.keyframes = keys;
  EXPECT_TRUE(camera::writeCameraPathJson(dir / "path.json", path));
  const auto run =
      test::runGlobe("play " + globe::testing::bundledPyramid().string() + " " +
                     (dir / "path.json").string() + " --tileset " + tileset.string() +
                     " --size 320x180 --no-frames " + options + " --out " + (dir / "out").string());
  EXPECT_EQ(run.exitCode, 0) << run.output;
  return test::readLog(dir / "out" / "log.csv");
}

TEST(PlayTileset, AFlightThroughABlockIsLiftedOverEveryRoof) {
  const fs::path block = writeBlock();
  // East at 30 m/s, 20 m above the sea (below every roof), along each row of the block.
  for (const double north : {0.0, 60.0}) {
    const double lat = kLatDeg + north / kMetersPerDegLat;
    const auto rows = play(block, "row" + std::to_string(static_cast<int>(north)),
                           {{0, kWestDeg - 60 / kMetersPerDegLon, lat, 20, 90, -10, 0},
                            {8, kWestDeg + 180 / kMetersPerDegLon, lat, 20, 90, -10, 0}});
    ASSERT_GT(rows.size(), 200u);
    int overRoofs = 0;
    double lowest = 1e9;
    for (const auto& row : rows) {
      // The log's ground is the highest drawn surface, roofs included: never under the floor.
      EXPECT_GE(number(row, "clearance_m"), 2.0 - 0.02) << row.at("time_s");
      const double roof = roofAt(number(row, "lon_deg"), number(row, "lat_deg"));
      if (roof <= 0) continue;
      ++overRoofs;
      lowest = std::min(lowest, number(row, "height_m") - roof);
    }
    std::printf("[ row %g m ] %d frames over roofs, lowest %.3f m above the roof\n", north,
                overRoofs, lowest);
    EXPECT_GT(overRoofs, 60);
    EXPECT_GE(lowest, 2.0 - 0.02);  // the floor, less the contact skin
  }
}

// With the glide (the default) and with the paper's response alone.
TEST(PlayTileset, ADiveOntoARoofStopsOnIt) {
  const fs::path block = writeBlock();
  const double lon = kWestDeg + 60 / kMetersPerDegLon;  // the 70 m box
  for (const std::string options : {"", "--no-glide"}) {
    // Down at ~100 m/s to 10 m (through the roof), then held there.
    const auto rows = play(block, "dive" + std::to_string(options.size()),
                           {{0, lon, kLatDeg, 400, 0, -60, 0},
                            {4, lon, kLatDeg, 10, 0, -60, 0},
                            {8, lon, kLatDeg, 10, 0, -60, 0}},
                           options);
    ASSERT_FALSE(rows.empty());
    double lowest = 1e9;
    for (const auto& row : rows) lowest = std::min(lowest, number(row, "clearance_m"));
    const double last = number(rows.back(), "height_m");
    std::printf("[ dive %s ] held at %.3f m over the 70 m roof, lowest clearance %.3f m\n",
                options.c_str(), last, lowest);
    EXPECT_GE(lowest, 2.0 - 0.02);
    EXPECT_GE(last, 70 + 2.0 - 0.02);
    EXPECT_LT(last, 70 + 6.0);  // on the roof (the glide's margin 3 m), not hovering above it
  }
}

}  // namespace
}  // namespace globe::app
