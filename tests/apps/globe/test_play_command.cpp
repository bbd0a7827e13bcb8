// `globe play`: the real program plays a hostile path (a dive into Mount Fuji, a skim 1 m above
// its summit ridge, across the antimeridian and over the south pole at low height) and never logs
// a camera below the drawn surface; runs are byte-identical; bad input leaves nothing behind.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "surface/pyramid_surface.hpp"
#include "camera/camera_path_file.hpp"
#include "geo/cartographic.hpp"
#include "streaming/tile_store.hpp"
#include "tests/apps/globe/play_log_rows.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using globe::testing::bundledPyramid;
using globe::testing::freshTempDir;
using test::number;
using test::readLog;

struct PlayRun {
  int exitCode = -1;
  std::string output;  // stdout and stderr
};

PlayRun runGlobe(const std::string& arguments, const std::string& environment = "") {
  static int counter = 0;
  const fs::path log = freshTempDir("play-output") / ("run" + std::to_string(++counter) + ".txt");
  const std::string command =
      environment + " " + GLOBE_EXE + " play " + arguments + " > " + log.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::stringstream text;
  text << std::ifstream(log).rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The hostile path, with the heights "above the terrain" resolved from the finest pyramid tiles.
fs::path writeHostilePath(const fs::path& dir) {
  auto store = streaming::TileStore::open(bundledPyramid());
  EXPECT_TRUE(store) << store.error();
  surface::PyramidSurface surface(**store, geo::Ellipsoid::wgs84());
  auto above = [&](double lon, double lat, double meters) {
    auto ground = surface.heightMeters(geo::degreesToRadians(lon), geo::degreesToRadians(lat));
    EXPECT_TRUE(ground) << ground.error();
    return *ground + meters;
  };
  camera::CameraPathFile path;
  path.interpolation = "smooth";
  path.keyframes = {
      {0.0, 138.700, 35.300, 4500, 20, -20, 0},
      {1.5, 138.727, 35.345, 2500, 20, -15, 0},  // ~500 m inside Fuji's south-east flank
      {2.5, 138.730, 35.362, above(138.730, 35.362, 1), 60, -20, 0},  // 1 m above the summit
      {3.0, 138.733, 35.364, above(138.733, 35.364, 1), 60, -20, 0},  // ridge
      {4.0, 150.0, -30.0, 2.0e6, 180, -90, 0},
      {5.0, 179.0, -84.0, above(179.0, -84.0, 50), 90, -30, 0},    // the Ross Ice Shelf
      {6.0, -179.0, -84.0, above(-179.0, -84.0, 50), 90, -30, 0},  // across 180°
      {7.0, -179.0, -87.0, 50000, 180, -30, 0},  // over the Transantarctic Mountains
      {8.0, -179.0, -89.8, above(-179.0, -89.8, 30), 180, -30, 0},
      {9.0, 1.0, -89.8, above(1.0, -89.8, 30), 0, -30, 0},  // over the south pole
  };
  const fs::path file = dir / "hostile.json";
  auto written = camera::writeCameraPathJson(file, path);
  EXPECT_TRUE(written) << written.error();
  return file;
}

// Plays of the hostile path into dir/NAME, each run once per test process (ctest runs every
// test in its own): "a" and "b" with frames, "c" without.
class GlobePlay : public ::testing::Test {
 protected:
  static const fs::path& dir() {
    static const fs::path path = [] {
      const fs::path made = freshTempDir("play");
      writeHostilePath(made);
      return made;
    }();
    return path;
  }
  static const PlayRun& play(const std::string& name, const std::string& options = "") {
    static std::map<std::string, PlayRun> runs;
    if (auto it = runs.find(name); it != runs.end()) return it->second;
    return runs[name] =
               runGlobe(bundledPyramid().string() + " " + (dir() / "hostile.json").string() +
                        " --fps 10 --size 160x90 --out " + (dir() / name).string() + " " + options);
  }
};

TEST_F(GlobePlay, HostilePathNeverLogsACameraBelowTheDrawnSurface) {
  ASSERT_EQ(play("a").exitCode, 0) << play("a").output;
  const auto rows = readLog(dir() / "a" / "log.csv");
  ASSERT_EQ(rows.size(), 91u);  // 9 s at 10 fps, both ends
  double lowestDrawn = 1e9, lowestOverall = 1e9;
  int collisions = 0, lifted = 0, drawnRows = 0;
  bool west = false, east = false, overPole = false, skimmed = false;
  for (const auto& row : rows) {
    const double clearance = number(row, "clearance_m");
    const double height = number(row, "height_m"), terrain = number(row, "terrain_height_m");
    EXPECT_NEAR(clearance, height - terrain, 0.0011) << row.at("frame");
    EXPECT_GE(clearance, 0.0) << "frame " << row.at("frame");
    lowestOverall = std::min(lowestOverall, clearance);
    if (row.at("terrain_source") != "finest") {
      // The controller's floor (the 2 m eye clearance) holds against the surface it knows: the
      // drawn tiles (and the tile under the camera when the scene adds it for collision only).
      EXPECT_GE(clearance, 2.0 - 1e-6) << "frame " << row.at("frame");
      lowestDrawn = std::min(lowestDrawn, clearance);
      ++drawnRows;
    }
    collisions += row.at("collided") == "1";
    lifted += number(row, "lift_m") > 0.01;
    const double lon = number(row, "lon_deg"), lat = number(row, "lat_deg");
    west = west || (lat < -80 && lon > 179.0);
    east = east || (lat < -80 && lon < -179.0);
    overPole = overPole || (lat < -89.95 && clearance < 200);
    // The script itself passes within 3 m of the summit ridge (the camera is lifted off it).
    skimmed = skimmed ||
              (lat > 35.36 && lat < 35.365 && number(row, "scripted_height_m") - terrain < 3.0);
  }
  EXPECT_GT(lifted, 5);  // the dive and the ridge: the controller lifts the camera off the path
  EXPECT_GT(drawnRows, 60);
  EXPECT_TRUE(west && east) << "the path crosses the antimeridian at 84°S";
  EXPECT_TRUE(overPole) << "the path passes over the south pole low";
  EXPECT_TRUE(skimmed) << "the path skims the summit ridge within 3 m";
  std::printf(
      "lowest clearance: %.3f m over the drawn surface, %.3f m overall; %d frames lifted, %d "
      "collision frames\n",
      lowestDrawn, lowestOverall, lifted, collisions);
  const std::string summary = readFile(dir() / "a" / "summary.txt");
  EXPECT_NE(summary.find("frames: 91"), std::string::npos) << summary;
  EXPECT_NE(summary.find("min clearance:"), std::string::npos) << summary;
  EXPECT_NE(play("a").output.find("time per frame: median"), std::string::npos) << play("a").output;
  EXPECT_EQ(readLog(dir() / "a" / "timing.csv").size(), 91u);
}

TEST_F(GlobePlay, TwoRunsGiveIdenticalLogsAndImages) {
  ASSERT_EQ(play("a").exitCode, 0) << play("a").output;
  ASSERT_EQ(play("b").exitCode, 0) << play("b").output;
  const std::string log = readFile(dir() / "a" / "log.csv");
  ASSERT_GT(log.size(), 1000u);
  EXPECT_EQ(log, readFile(dir() / "b" / "log.csv"));
  int compared = 0;
  for (int i = 0; i < 91; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "%05d.png", i);
    const std::string a = readFile(dir() / "a" / "frames" / name);
    ASSERT_GT(a.size(), 100u) << name;
    EXPECT_TRUE(a == readFile(dir() / "b" / "frames" / name)) << name << " differs";
    ++compared;
  }
  EXPECT_EQ(compared, 91);
  EXPECT_FALSE(fs::exists(dir() / "a" / "frames" / "00091.png"));
  for (const auto& entry : fs::directory_iterator(dir() / "a")) {  // no temporaries left
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
    EXPECT_EQ(entry.path().filename().string().find("partial"), std::string::npos);
  }
}

TEST_F(GlobePlay, NoFramesWritesTheSameLogAndNoFrames) {
  ASSERT_EQ(play("a").exitCode, 0) << play("a").output;
  ASSERT_EQ(play("c", "--no-frames").exitCode, 0) << play("c").output;
  EXPECT_FALSE(fs::exists(dir() / "c" / "frames"));
  EXPECT_EQ(readFile(dir() / "c" / "log.csv"), readFile(dir() / "a" / "log.csv"));
  EXPECT_TRUE(fs::exists(dir() / "c" / "summary.txt"));
}

TEST_F(GlobePlay, AWindowPlaysTheSameLoopAndLog) {
  if (std::system("command -v xvfb-run > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "xvfb-run is not installed";
  }
  ASSERT_EQ(play("a").exitCode, 0) << play("a").output;
  const fs::path path = dir() / "hostile.json";
  const PlayRun run =
      runGlobe(bundledPyramid().string() + " " + path.string() +
                   " --fps 10 --size 160x90 --window --no-frames --out " + (dir() / "w").string(),
               "xvfb-run -a -s '-screen 0 640x480x24'");
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_EQ(readFile(dir() / "w" / "log.csv"), readFile(dir() / "a" / "log.csv"));
}

TEST(GlobePlayErrors, ABadPathFileExitsWithItsLineAndWritesNothing) {
  const fs::path dir = freshTempDir("play-bad");
  std::ofstream(dir / "bad.json") << "{\"keyframes\": [\n"
                                     "  {\"t\": 0, \"lon\": 10, \"lat\": 20, \"height\": 1000},\n"
                                     "  {\"t\": 1, \"lon\": 10, \"lat\": 95, \"height\": 1000}\n"
                                     "]}\n";
  const PlayRun run = runGlobe(bundledPyramid().string() + " " + (dir / "bad.json").string() +
                               " --out " + (dir / "out").string());
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("bad.json:3: keyframes[1].lat: 95 is outside -90..90"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(fs::exists(dir / "out"));  // refused before anything was written
  const PlayRun missing = runGlobe(bundledPyramid().string() + " " + (dir / "none.kml").string() +
                                   " --out " + (dir / "out").string());
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(missing.output.find("none.kml: cannot open"), std::string::npos) << missing.output;
}

TEST(GlobePlayErrors, AnUnwritableOutputOrMissingFfmpegIsRefusedBeforeRendering) {
  const fs::path dir = freshTempDir("play-out");
  const std::string path = std::string(GLOBE_SOURCE_DIR) + "/data/paths/fuji-demo.json";
  std::ofstream(dir / "file") << "not a directory";
  const PlayRun blocked =
      runGlobe(bundledPyramid().string() + " " + path + " --fps 1 --size 32x18 " + "--out " +
               (dir / "file" / "out").string());
  EXPECT_EQ(blocked.exitCode, 1);
  EXPECT_NE(blocked.output.find("cannot create the output directory"), std::string::npos)
      << blocked.output;
  const PlayRun noFfmpeg =
      runGlobe(bundledPyramid().string() + " " + path + " --fps 1 --size 32x18 --out " +
                   (dir / "v").string() + " --video " + (dir / "v.mp4").string(),
               "PATH=/nonexistent");
  EXPECT_EQ(noFfmpeg.exitCode, 1);
  EXPECT_NE(noFfmpeg.output.find("--video needs the ffmpeg program on PATH"), std::string::npos)
      << noFfmpeg.output;
  EXPECT_FALSE(fs::exists(dir / "v"));
  const PlayRun badFps =
      runGlobe(bundledPyramid().string() + " " + path + " --fps 0 --out " + (dir / "f").string());
  EXPECT_EQ(badFps.exitCode, 2);  // a bad argument
  EXPECT_NE(badFps.output.find("--fps '0': must be in (0, 1000]"), std::string::npos)
      << badFps.output;
}

TEST(GlobePlayFormats, TheBundledKmlTourPlaysAndAVideoIsEncoded) {
  const fs::path dir = freshTempDir("play-tour");
  const std::string tour = std::string(GLOBE_SOURCE_DIR) + "/data/paths/fuji-tour.kml";
  const bool ffmpeg = std::system("command -v ffmpeg > /dev/null 2>&1") == 0;
  const PlayRun run =
      runGlobe(bundledPyramid().string() + " " + tour + " --fps 1 --size 96x54 --out " +
               (dir / "out").string() + (ffmpeg ? " --video " + (dir / "tour.mp4").string() : ""));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto rows = readLog(dir / "out" / "log.csv");
  ASSERT_GT(rows.size(), 10u);
  for (const auto& row : rows) EXPECT_GE(number(row, "clearance_m"), 0.0) << row.at("frame");
  if (!ffmpeg) GTEST_SKIP() << "ffmpeg is not installed: the video was not tested";
  EXPECT_GT(fs::file_size(dir / "tour.mp4"), 1000u);
  EXPECT_EQ(readFile(dir / "tour.mp4").substr(4, 4), "ftyp");  // an MP4 container
}

}  // namespace
}  // namespace globe::app

namespace globe::app {
namespace {

// A path that dives into two of the Fuji SRTM tile's former voids (the summit crater's rim, 45
// samples; the largest, 314 samples in the Southern Alps) and skims the filled surface 1 m up:
// the camera never goes below the drawn surface, nor more than 3 m below the filled one (the
// finest tiles), where it used to follow a void's pit down to sea level.
// The log's heading is a compass heading, as the path and --camera give it: 330, not -30.
TEST(GlobePlayLog, HeadingsAreCompassHeadingsAsTheCameraTakesThem) {
  const fs::path dir = freshTempDir("play-heading");
  camera::CameraPathFile path;
  path.keyframes = {{0.0, 138.70, 35.33, 9000, 330, -30, 0},
                    {0.5, 138.71, 35.34, 9000, 330, -30, 0}};
  ASSERT_TRUE(camera::writeCameraPathJson(dir / "north-west.json", path));
  const PlayRun run = runGlobe(bundledPyramid().string() + " " +
                               (dir / "north-west.json").string() + " --fps 10 --no-frames --out " +
                               (dir / "out").string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto rows = readLog(dir / "out" / "log.csv");
  ASSERT_FALSE(rows.empty());
  for (const auto& row : rows) EXPECT_EQ(row.at("heading_deg"), "330.000") << row.at("frame");
}

TEST(GlobePlayVoids, ADiveIntoFormerVoidsStaysOnTheFilledSurface) {
  const fs::path dir = freshTempDir("play-voids");
  auto store = streaming::TileStore::open(bundledPyramid());
  ASSERT_TRUE(store) << store.error();
  surface::PyramidSurface surface(**store, geo::Ellipsoid::wgs84());
  auto ground = [&](double lon, double lat) {
    auto h = surface.heightMeters(geo::degreesToRadians(lon), geo::degreesToRadians(lat));
    EXPECT_TRUE(h) << h.error();
    return h ? *h : 0.0;
  };
  camera::CameraPathFile path;
  path.interpolation = "smooth";
  path.keyframes = {
      {0.0, 138.700, 35.330, 5000, 20, -30, 0},
      {1.5, 138.7156, 35.3614, ground(138.7156, 35.3614) - 200, 60, -20, 0},  // into the void
      {2.5, 138.7200, 35.3625, ground(138.7200, 35.3625) + 1, 90, -20, 0},
      {3.5, 138.7300, 35.3606, ground(138.7300, 35.3606) + 1, 90, -20, 0},     // the filled summit
      {5.5, 138.2112, 35.7666, ground(138.2112, 35.7666) - 100, 300, -20, 0},  // the largest void
      {6.5, 138.2446, 35.7545, ground(138.2446, 35.7545) + 1, 110, -20, 0},
  };
  ASSERT_TRUE(camera::writeCameraPathJson(dir / "voids.json", path));
  const PlayRun run = runGlobe(bundledPyramid().string() + " " + (dir / "voids.json").string() +
                               " --fps 10 --no-frames --out " + (dir / "out").string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto rows = readLog(dir / "out" / "log.csv");
  ASSERT_EQ(rows.size(), 66u);
  double lowestClearance = 1e9, lowestBelowFilled = 1e9;
  int overSummitVoid = 0, overAlpsVoid = 0;
  for (const auto& row : rows) {
    const double lon = number(row, "lon_deg"), lat = number(row, "lat_deg");
    const double clearance = number(row, "clearance_m");
    const double aboveFilled = number(row, "height_m") - ground(lon, lat);
    EXPECT_GE(clearance, 0.0) << "frame " << row.at("frame");
    EXPECT_GE(aboveFilled, -3.0) << "frame " << row.at("frame") << " at " << lon << "," << lat;
    lowestClearance = std::min(lowestClearance, clearance);
    lowestBelowFilled = std::min(lowestBelowFilled, aboveFilled);
    const bool overSummit = std::abs(lon - 138.7156) < 0.003 && std::abs(lat - 35.3614) < 0.003;
    const bool overAlps = std::abs(lon - 138.2112) < 0.01 && std::abs(lat - 35.7666) < 0.01;
    overSummitVoid += overSummit;
    overAlpsVoid += overAlps;
    // Over the former voids the ground is the mountain (their borders: 2,338-3,582 m and
    // 1,580-2,643 m), not the sea-level pit the voids used to be drawn as.
    if (overSummit) {
      EXPECT_GT(number(row, "terrain_height_m"), 2000.0) << "frame " << row.at("frame");
    }
    if (overAlps) {
      EXPECT_GT(number(row, "terrain_height_m"), 1200.0) << "frame " << row.at("frame");
    }
  }
  EXPECT_GT(overSummitVoid, 0) << "the path passes over the summit's former void";
  EXPECT_GT(overAlpsVoid, 0) << "the path passes over the Southern Alps' former void";
  std::printf(
      "voids: lowest clearance %.3f m over the drawn surface, lowest %.3f m above the "
      "filled surface\n",
      lowestClearance, lowestBelowFilled);
}

}  // namespace
}  // namespace globe::app

namespace globe::app {
namespace {

// Real data: a dive to 500 m below sea level over the Suruga trough, south of the Fuji tile
// (ETOPO20 measures the floor there at about -790 m). By default the camera stops on the water
// surface; with --sea-floor it goes under water, above the floor.
TEST(GlobePlaySea, TheCameraStopsAtTheWaterSurfaceUnlessTheSeaFloorIsShown) {
  const fs::path dir = freshTempDir("play-sea");
  camera::CameraPathFile path;
  path.interpolation = "linear";
  path.keyframes = {{0.0, 138.55, 34.60, 2000, 0, -30, 0}, {2.0, 138.55, 34.60, -500, 0, -30, 0}};
  ASSERT_TRUE(camera::writeCameraPathJson(dir / "dive.json", path));
  auto lowest = [&](const std::string& name, const std::string& options) {
    const PlayRun run =
        runGlobe(bundledPyramid().string() + " " + (dir / "dive.json").string() +
                 " --fps 10 --no-frames --out " + (dir / name).string() + " " + options);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    double low = 1e9;
    for (const auto& row : readLog(dir / name / "log.csv")) {
      EXPECT_GE(number(row, "clearance_m"), 0.0) << name << " frame " << row.at("frame");
      low = std::min(low, number(row, "height_m"));
    }
    return low;
  };
  const double water = lowest("water", "");
  const double floor = lowest("floor", "--sea-floor");
  std::printf("lowest camera: %.2f m on the water, %.2f m with the sea floor\n", water, floor);
  // The 2 m floor above the water at 0 m, plus what the glide keeps at the dive's 1250 m/s
  // (camera/terrain_glide.hpp: 3 m + 0.02 s x speed, and the spring's lag), never under it.
  EXPECT_GE(water, 2.0 - 1e-6);
  EXPECT_LE(water, 60.0);
  EXPECT_LT(floor, -450.0);  // under water, as the path asks
}

}  // namespace
}  // namespace globe::app

namespace globe::app {
namespace {

// Playback draws overlays too: the bundled Fuji tour's frames with data/overlays/fuji-demo.kml
// differ from the same frames without it, the collision log does not (overlays never move the
// camera).
TEST(GlobePlayFormats, OverlaysAreDrawnInPlayback) {
  const fs::path dir = freshTempDir("play-overlays");
  const std::string common = bundledPyramid().string() + " " + std::string(GLOBE_SOURCE_DIR) +
                             "/data/paths/fuji-tour.kml --fps 0.5 --size 160x90 --out ";
  const PlayRun plain = runGlobe(common + (dir / "plain").string());
  ASSERT_EQ(plain.exitCode, 0) << plain.output;
  const PlayRun overlaid = runGlobe(common + (dir / "overlaid").string() + " --overlay " +
                                    std::string(GLOBE_SOURCE_DIR) + "/data/overlays/fuji-demo.kml");
  ASSERT_EQ(overlaid.exitCode, 0) << overlaid.output;
  size_t frames = 0, differing = 0;
  for (const auto& entry : fs::directory_iterator(dir / "plain" / "frames")) {
    const fs::path other = dir / "overlaid" / "frames" / entry.path().filename();
    ASSERT_TRUE(fs::exists(other)) << other;
    ++frames;
    differing += readFile(entry.path()) != readFile(other);
  }
  EXPECT_GT(frames, 5u);
  EXPECT_GT(differing, frames / 2) << "the trail, the zone, the wall and the labels show";
  const auto plainRows = readLog(dir / "plain" / "log.csv");
  const auto overlaidRows = readLog(dir / "overlaid" / "log.csv");
  ASSERT_EQ(plainRows.size(), overlaidRows.size());
  for (size_t i = 0; i < plainRows.size(); ++i) {
    EXPECT_EQ(plainRows[i].at("clearance_m"), overlaidRows[i].at("clearance_m")) << i;
  }
}

}  // namespace
}  // namespace globe::app

namespace globe::app {
namespace {

// --real-time: the frames are paced on the clock and draw what has arrived (no waiting for
// complete views), finer tiles near the camera morphing in; a descent onto Fuji's flank from a
// view whose tiles are all coarse. The log has new_ground_lift_m, the summary its largest value;
// the camera is never under the drawn surface.
TEST(GlobePlayRealTime, ADescentDrawsWhatArrivedAndNeverGoesUnderTheGround) {
  const fs::path dir = freshTempDir("play-real-time");
  camera::CameraPathFile path;
  path.interpolation = "linear";
  path.keyframes = {
      {0.0, 138.745, 35.345, 40000, 0, -60, 0},
      {1.0, 138.745, 35.345, 0, 0, -60, 0},  // into the flank (~2,900 m) at 40 km/s
      {1.5, 138.750, 35.350, 0, 0, -60, 0},
  };
  ASSERT_TRUE(camera::writeCameraPathJson(dir / "descent.json", path));
  const PlayRun run = runGlobe(bundledPyramid().string() + " " + (dir / "descent.json").string() +
                               " --fps 20 --size 320x180 --no-frames --real-time --no-glide --out " +
                               (dir / "out").string());
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("largest lift by new ground in one frame"), std::string::npos)
      << run.output;
  const auto rows = readLog(dir / "out" / "log.csv");
  ASSERT_EQ(rows.size(), 31u);
  double largestLift = 0;
  for (const auto& row : rows) {
    ASSERT_TRUE(row.contains("new_ground_lift_m"));
    largestLift = std::max(largestLift, number(row, "new_ground_lift_m"));
    EXPECT_GE(number(row, "clearance_m"), 2.0 - 1e-3) << "frame " << row.at("frame");
  }
  EXPECT_GT(number(rows.back(), "terrain_height_m"), 2000.0) << "it landed on the mountain";
  char line[64];
  std::snprintf(line, sizeof line, "largest lift by new ground in one frame %.3f m", largestLift);
  EXPECT_NE(run.output.find(line), std::string::npos) << run.output;
}

}  // namespace
}  // namespace globe::app
