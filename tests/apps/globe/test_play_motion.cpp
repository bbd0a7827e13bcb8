// How the camera moves when a scripted flight runs into real terrain the demo does not use (the
// Taunus SRTM3 tiles over ETOPO20): into a mountain flank at 250 m/s, across ridges and the
// concave notches between them, a dive at 1 km/s. With the glide the height follows a smooth
// envelope of the ground ahead: no shudder, no bounce, no stall, never under the 2 m floor.
// The paper's response alone (--no-glide) is played too: it shows the roughness these measures
// catch, so they can fail.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "tests/apps/globe/play_log_rows.hpp"
#include "tests/apps/globe/run_globe.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::LogRow;
using test::number;

const fs::path& taunusPyramid() {
  static const fs::path pyramid = [] {
    const std::string dem = std::string(GLOBE_SOURCE_DIR) + "/tests/data/dem/gtopo30/";
    return globe::testing::sharedPyramid(
        "taunus", {dem + "ETOPO20.DEM", dem + "N50E008.DEM", dem + "N50E009.DEM"});
  }();
  return pyramid;
}

// Plays the keyframes (linear) at 30 fps, no frames; the log's rows.
std::vector<LogRow> play(const std::string& name, const std::vector<camera::PathKeyframe>& keys,
                         const std::string& options = "") {
  const fs::path dir = globe::testing::freshTempDir("play-motion-" + name);
  camera::CameraPathFile path;
  path.interpolation = "linear";
  path.keyframes = keys;
  EXPECT_TRUE(camera::writeCameraPathJson(dir / "path.json", path));
  const auto run =
      test::runGlobe("play " + taunusPyramid().string() + " " + (dir / "path.json").string() +
                     " --size 320x180 --no-frames " + options + " --out " + (dir / "out").string());
  EXPECT_EQ(run.exitCode, 0) << run.output;
  std::printf("[ %s %s ] %s", name.c_str(), options.c_str(), run.output.c_str());
  return test::readLog(dir / "out" / "log.csv");
}

double p95(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[static_cast<size_t>(std::ceil(0.95 * static_cast<double>(values.size()))) - 1];
}

struct Motion {
  double p95Jolt = 0, p95Ground = 0, p95Free = 0;  // m per frame², as the summary's motion line
  double lowestEye = 1e9, lowestNear = 1e9;        // over rows on the controller's surface
  int flips = 0;   // consecutive frames whose jolts are both > 1 m/frame² with opposite signs
  int stalls = 0;  // frames the camera did not advance horizontally (these scripts always do)
  int acting = 0;  // frames the controller moved the camera off the script (and neighbours)
  double largestStepMeters = 0;  // the largest frame-to-frame height change beyond the script's
};

Motion measure(const std::vector<LogRow>& rows) {
  Motion m;
  const size_t n = rows.size();
  std::vector<bool> acting(n, false);
  for (size_t i = 0; i < n; ++i) {
    if (number(rows[i], "lift_m") <= 0.01 && rows[i].at("collided") == "0") continue;
    for (size_t k = i > 0 ? i - 1 : 0; k <= std::min(i + 1, n - 1); ++k) acting[k] = true;
  }
  std::vector<double> jolt, ground, free;
  auto height = [&](size_t i) { return number(rows[i], "height_m"); };
  auto terrain = [&](size_t i) { return number(rows[i], "terrain_height_m"); };
  for (size_t i = 0; i < n; ++i) {
    if (rows[i].at("terrain_source") != "finest") {
      m.lowestEye = std::min(m.lowestEye, number(rows[i], "clearance_m"));
      m.lowestNear = std::min(m.lowestNear, number(rows[i], "near_clearance_m"));
    }
    if (i > 0) {
      const double scriptStep =
          number(rows[i], "scripted_height_m") - number(rows[i - 1], "scripted_height_m");
      m.largestStepMeters =
          std::max(m.largestStepMeters, std::abs(height(i) - height(i - 1) - scriptStep));
      const double moved = std::hypot(number(rows[i], "lon_deg") - number(rows[i - 1], "lon_deg"),
                                      number(rows[i], "lat_deg") - number(rows[i - 1], "lat_deg"));
      if (moved * 111e3 * 0.64 < 0.25 && number(rows[i], "time_s") > 0) {
        // 0.64: cos(50°), a lower bound on a degree of longitude's length here.
        m.stalls += 1;
      }
    }
    if (i == 0 || i + 1 == n) continue;
    const double j = height(i + 1) - 2 * height(i) + height(i - 1);
    (acting[i] ? jolt : free).push_back(std::abs(j));
    if (acting[i]) {
      ground.push_back(std::abs(terrain(i + 1) - 2 * terrain(i) + terrain(i - 1)));
      ++m.acting;
    }
    if (i + 2 < n) {
      const double next = height(i + 2) - 2 * height(i + 1) + height(i);
      if (std::abs(j) > 1 && std::abs(next) > 1 && j * next < 0) ++m.flips;
    }
  }
  m.p95Jolt = p95(jolt);
  m.p95Ground = p95(ground);
  m.p95Free = p95(free);
  return m;
}

void print(const char* name, const Motion& m) {
  std::printf(
      "%s: p95 jolt %.3f (ground %.3f, free %.3f) m/frame², %d acting, lowest eye %.3f m, near "
      "%.3f m, %d flips, %d stalls, largest step %.2f m\n",
      name, m.p95Jolt, m.p95Ground, m.p95Free, m.acting, m.lowestEye, m.lowestNear, m.flips,
      m.stalls, m.largestStepMeters);
}

// The bar: p95 jolt at most a quarter of the ground's along the track, or 3x free
// flight's, whichever is larger; the floor (2 m eye, 0.5 m near plane); no flips, no stalls.
void expectGlide(const Motion& m) {
  EXPECT_GT(m.acting, 0);
  EXPECT_LE(m.p95Jolt, std::max(0.25 * m.p95Ground, 3 * m.p95Free));
  EXPECT_GE(m.lowestEye, 2.0 - 1e-3);
  EXPECT_GE(m.lowestNear, 0.5 - 1e-3);
  EXPECT_EQ(m.flips, 0);
  EXPECT_EQ(m.stalls, 0);
}

// Level at 600 m, east at 250 m/s through the Großer Feldberg (879 m) and its flanks.
const std::vector<camera::PathKeyframe> kFlank = {{0, 8.40, 50.2325, 600, 90, -5, 0},
                                                  {16, 8.456, 50.2325, 600, 90, -5, 0}};
// South-east at 250 m/s, 420 m above the sea, across the Taunus ridges and the valleys (concave
// notches) between them.
const std::vector<camera::PathKeyframe> kRidges = {{0, 8.36, 50.29, 420, 135, -5, 0},
                                                   {20, 8.41, 50.254, 420, 135, -5, 0}};
// A dive at 1 km/s from 3000 m to the sea-level datum, onto the Feldberg's summit.
const std::vector<camera::PathKeyframe> kDive = {{0, 8.4575, 50.2325, 3000, 0, -60, 0},
                                                 {3, 8.4575, 50.2325, 0, 0, -60, 0}};

// The flight with the glide and with the paper's response alone, each measured and printed.
std::pair<Motion, Motion> playBoth(const std::string& name,
                                   const std::vector<camera::PathKeyframe>& keys) {
  const Motion glide = measure(play(name, keys));
  const Motion paper = measure(play(name, keys, "--no-glide"));
  print((name + ", glide").c_str(), glide);
  print((name + ", the paper's response alone").c_str(), paper);
  return {glide, paper};
}

TEST(PlayMotion, AFlankAt250MetresPerSecondIsAGlide) {
  const auto [glide, paper] = playBoth("flank", kFlank);
  expectGlide(glide);
  // The response alone is the rough ride the measure exists to catch.
  EXPECT_GT(paper.p95Jolt, std::max(0.25 * paper.p95Ground, 3 * paper.p95Free));
}

TEST(PlayMotion, RidgesAndNotchesAt250MetresPerSecondAreAGlide) {
  const auto [glide, paper] = playBoth("ridges", kRidges);
  expectGlide(glide);
  EXPECT_GT(paper.p95Jolt, glide.p95Jolt);
}

TEST(PlayMotion, ADiveAtOneKilometrePerSecondStopsAboveTheFloorWithoutABounce) {
  const Motion m = measure(play("dive", kDive));
  print("dive", m);
  EXPECT_GT(m.acting, 0);
  EXPECT_GE(m.lowestEye, 2.0 - 1e-3);
  EXPECT_GE(m.lowestNear, 0.5 - 1e-3);
  EXPECT_EQ(m.flips, 0);
}

// Two keyframes 150 m above the ground on either side of the Feldberg (879 m): the path follows
// the terrain between them (the height above the ground interpolated), so it never needs the
// controller; interpolating the absolute heights would run into the mountain.
TEST(PlayMotion, AKeyframedPathAboveTheTerrainFollowsItOverAPeak) {
  std::vector<camera::PathKeyframe> keys = {{0, 8.41, 50.2325, 150, 90, -5, 0},
                                            {16, 8.50, 50.2325, 150, 90, -5, 0}};
  for (camera::PathKeyframe& key : keys) key.heightAboveTerrain = true;
  const std::vector<LogRow> rows = play("above-terrain", keys);
  ASSERT_GT(rows.size(), 400u);
  double lowest = 1e9, highest = 0, lifted = 0, overPeak = 0;
  for (const LogRow& row : rows) {
    const double aboveGround = number(row, "scripted_height_m") - number(row, "terrain_height_m");
    lowest = std::min(lowest, aboveGround);
    highest = std::max(highest, aboveGround);
    lifted = std::max(lifted, number(row, "lift_m"));
    EXPECT_EQ(row.at("collided"), "0") << row.at("frame");
    if (std::abs(number(row, "lon_deg") - 8.4575) < 0.002) {
      overPeak = std::max(overPeak, number(row, "scripted_height_m"));
    }
  }
  std::printf(
      "above the terrain: %.1f..%.1f m over the drawn ground, lifted at most %.3f m, %.0f m "
      "over the summit\n",
      lowest, highest, lifted, overPeak);
  // The script's terrain is the finest the pyramid has, the drawn one may be coarser far off.
  EXPECT_GT(lowest, 100.0);
  EXPECT_LT(highest, 200.0);
  EXPECT_GT(overPeak, 879.0 + 100.0);
  EXPECT_LE(lifted, 0.01);  // the controller never had to act
}

}  // namespace
}  // namespace globe::app
