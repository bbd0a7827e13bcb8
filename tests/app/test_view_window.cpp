// `globe view`: orbit-control math, and the real window under Xvfb: a screenshot shows terrain,
// keys and the scroll wheel zoom, Escape quits, and an idle window uses almost no CPU.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include "app/orbit_controls.hpp"
#include "io/image_io.hpp"
#include "tests/tools/tiler/tiler_test_fixture.hpp"

namespace {

using globe::app::OrbitControls;
using globe::camera::CameraPose;

constexpr double kPi = std::numbers::pi;
const auto kWgs84 = globe::geo::Ellipsoid::wgs84();
constexpr double kFov = kPi / 4;

TEST(OrbitControls, DragMovesTheCameraAgainstTheDragSoTheGroundFollows) {
  OrbitControls controls(kWgs84, CameraPose::fromDegrees(10, 20, 10000), kFov);
  controls.rotateByDrag(100, 0, 720);  // drag right: the ground moves right, the camera west
  EXPECT_LT(controls.pose().position.longitudeDegrees(), 10);
  EXPECT_DOUBLE_EQ(controls.pose().position.latitudeDegrees(), 20);
  // 100 px at 10 km straight down with a 45° view 720 px high: 100 · 2 · 10 km · tan 22.5° / 720.
  const double meters = 100 * 2 * 10000 * std::tan(kFov / 2) / 720;
  const double expectedDegrees = globe::geo::radiansToDegrees(
      meters / (kWgs84.semiMajorAxisMeters * std::cos(20 * kPi / 180)));
  EXPECT_NEAR(10 - controls.pose().position.longitudeDegrees(), expectedDegrees, 1e-9);
  controls.rotateByDrag(0, 100, 720);  // drag down: the camera goes north
  EXPECT_GT(controls.pose().position.latitudeDegrees(), 20);
}

TEST(OrbitControls, DragFollowsTheHeadingAndScalesWithHeight) {
  // Heading east: "up" on the screen is east, so a drag down moves the camera east.
  OrbitControls east(kWgs84, CameraPose::fromDegrees(10, 20, 10000, 90), kFov);
  east.rotateByDrag(0, 50, 720);
  EXPECT_GT(east.pose().position.longitudeDegrees(), 10);
  EXPECT_NEAR(east.pose().position.latitudeDegrees(), 20, 1e-9);
  OrbitControls low(kWgs84, CameraPose::fromDegrees(10, 20, 1000), kFov);
  OrbitControls high(kWgs84, CameraPose::fromDegrees(10, 20, 2000), kFov);
  low.rotateByDrag(0, 50, 720);
  high.rotateByDrag(0, 50, 720);
  EXPECT_NEAR(high.pose().position.latitudeDegrees() - 20,
              2 * (low.pose().position.latitudeDegrees() - 20), 1e-9);
}

TEST(OrbitControls, LongitudeWrapsAndLatitudeStaysOffThePoles) {
  // 10 px at 10 km up is ~115 m: east across the antimeridian.
  OrbitControls dateLine(kWgs84, CameraPose::fromDegrees(179.9995, 0, 10000), kFov);
  dateLine.rotateByDrag(-10, 0, 720);
  EXPECT_NEAR(dateLine.pose().position.longitudeDegrees(), -180 + 0.0005, 1e-4);
  OrbitControls pole(kWgs84, CameraPose::fromDegrees(0, 88.9, 1e6), kFov);
  pole.rotateByDrag(0, 400, 720);  // far north: stops at 89°
  EXPECT_NEAR(pole.pose().position.latitudeDegrees(), 89, 1e-9);
}

TEST(OrbitControls, ZoomScalesTheClearanceWithinLimits) {
  OrbitControls controls(kWgs84, CameraPose::fromDegrees(0, 0, 11000), kFov);
  EXPECT_FALSE(controls.setGroundHeight(1000));
  controls.zoom(1);
  EXPECT_NEAR(controls.pose().position.heightMeters, 1000 + 10000 * 0.8, 1e-6);
  controls.zoom(-1);
  EXPECT_NEAR(controls.pose().position.heightMeters, 11000, 1e-6);
  controls.zoom(1000);
  EXPECT_NEAR(controls.pose().position.heightMeters, 1001, 1e-9);  // 1 m above the ground
  controls.zoom(-1000);
  EXPECT_DOUBLE_EQ(controls.pose().position.heightMeters, 4e7);
  controls.reset();
  EXPECT_DOUBLE_EQ(controls.pose().position.heightMeters, 11000);
}

TEST(OrbitControls, TiltTurnsAndClampsThePitch) {
  OrbitControls controls(kWgs84, CameraPose::fromDegrees(0, 0, 5000), kFov);
  controls.tiltByDrag(100, 0);
  EXPECT_NEAR(controls.pose().headingRadians, 100 * OrbitControls::kTiltRadiansPerPixel, 1e-12);
  controls.tiltByDrag(0, -100);  // drag up: towards the horizon
  EXPECT_NEAR(controls.pose().pitchRadians, -kPi / 2 + 0.5, 1e-12);
  controls.tiltByDrag(0, -10000);
  EXPECT_DOUBLE_EQ(controls.pose().pitchRadians, 0);
  controls.tiltByDrag(0, 10000);
  EXPECT_DOUBLE_EQ(controls.pose().pitchRadians, -kPi / 2);
}

TEST(OrbitControls, RisingGroundLiftsTheCamera) {
  OrbitControls controls(kWgs84, CameraPose::fromDegrees(138.73, 35.36, 3000), kFov);
  EXPECT_TRUE(controls.setGroundHeight(3700));
  EXPECT_DOUBLE_EQ(controls.pose().position.heightMeters, 3701);
}

// ---- The real window under Xvfb ----

bool onPath(const std::string& program) {
  return std::system(("command -v " + program + " >/dev/null 2>&1").c_str()) == 0;
}

struct ShellRun {
  int exitCode;
  std::string output;
};

ShellRun runShell(const std::string& command) {
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  std::string output;
  std::array<char, 4096> buffer{};
  while (pipe != nullptr && std::fgets(buffer.data(), buffer.size(), pipe) != nullptr)
    output += buffer.data();
  const int status = pipe != nullptr ? ::pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// Runs a shell script inside a fresh Xvfb; a per-process starting display number keeps tests run
// in parallel from racing for the same one.
ShellRun runUnderXvfb(const std::string& name, const std::string& script) {
  const auto dir = globe::tiler::testing::freshTempDir(name);
  const auto path = dir / "script.sh";
  std::ofstream(path) << "set -u\ncd " << dir.string() << "\n" << script;
  const std::string display = std::to_string(100 + ::getpid() % 800);
  return runShell("xvfb-run -a -n " + display + " -s '-screen 0 1280x720x24' sh " + path.string());
}

// "key=value" lines of a script's output.
std::map<std::string, std::string> valuesOf(const std::string& output) {
  std::map<std::string, std::string> values;
  size_t start = 0;
  while (start < output.size()) {
    size_t end = output.find('\n', start);
    if (end == std::string::npos) end = output.size();
    const std::string line = output.substr(start, end - start);
    if (const size_t eq = line.find('='); eq != std::string::npos && line.find(' ') > eq)
      values[line.substr(0, eq)] = line.substr(eq + 1);
    start = end + 1;
  }
  return values;
}

// The height in the "camera LON,LAT,HEIGHT,..." line `globe view --log` prints on exit.
double loggedHeightMeters(const std::string& output) {
  const size_t at = output.find("\ncamera ");
  if (at == std::string::npos) return -1;
  double lon = 0, lat = 0, height = -1;
  std::sscanf(output.c_str() + at, "\ncamera %lf,%lf,%lf", &lon, &lat, &height);
  return height;
}

std::string globeView(const std::string& arguments) {
  return "timeout 120 " + std::string(GLOBE_EXE) + " view " +
         globe::tiler::testing::bundledPyramid().string() + " " + arguments;
}

// Waits for the window, then for the view to complete (a line in the log).
const char* kFindWindow =
    "WID=$(timeout 60 xdotool search --sync --onlyvisible --name '^globe')\n"
    "echo wid=$WID\n"
    "PID=$(xdotool getwindowpid $WID)\n"
    "for i in $(seq 600); do grep -q 'view complete' log.txt && break; sleep 0.1; done\n";

#define SKIP_WITHOUT(program) \
  if (!onPath(program)) GTEST_SKIP() << program " is not installed"

TEST(GlobeViewWindow, ScreenshotShowsTheGlobe) {
  SKIP_WITHOUT("xvfb-run");
  const auto dir = globe::tiler::testing::freshTempDir("view-screenshot");
  const auto png = dir / "out.png";
  const ShellRun run = runUnderXvfb(
      "view-screenshot-run",
      globeView("--size 640x360 --frames 30 --camera 138,35,7000000 --screenshot " + png.string()));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto image = globe::io::loadImageRgba(png);
  ASSERT_TRUE(image) << image.error();
  ASSERT_EQ(image->widthPixels, 640);
  ASSERT_EQ(image->heightPixels, 360);
  size_t lit = 0, sea = 0, land = 0;
  std::set<int> colours;
  for (size_t k = 0; k + 3 < image->pixels.size(); k += 4) {
    const int r = image->pixels[k], g = image->pixels[k + 1], b = image->pixels[k + 2];
    if (std::max({r, g, b}) < 16) continue;
    ++lit;
    (b > r + 20 && b > g ? sea : land) += 1;
    colours.insert((r / 8) << 10 | (g / 8) << 5 | (b / 8));
  }
  const size_t pixels = 640 * 360;
  EXPECT_GT(lit, pixels / 3) << "the globe should fill much of the window";
  EXPECT_GT(sea, pixels / 20) << "the Pacific should show as blue";
  EXPECT_GT(land, pixels / 50) << "Japan and Asia should show as land colours";
  EXPECT_GT(colours.size(), 200u) << "hill-shading should give many shades";
}

TEST(GlobeViewWindow, KeysAndScrollZoomInAndEscapeQuits) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-keys",
      globeView("--size 640x360 --log --camera 138.73,35.36,50000 > log.txt &\n") + "VIEW=$!\n" +
          kFindWindow +
          "echo title0=$(xdotool getwindowname $WID)\n"
          "xdotool key --window $WID plus plus KP_Add\n"
          "xdotool mousemove --window $WID 320 180 click --window $WID 4\n"
          "for i in $(seq 100); do [ \"$(grep -c 'view complete' log.txt)\" -ge 2 ] && break; "
          "sleep 0.1; done\n"
          "echo title1=$(xdotool getwindowname $WID)\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  EXPECT_NE(values.at("title0").find("height 50000 m"), std::string::npos) << run.output;
  EXPECT_NE(values.at("title0"), values.at("title1")) << run.output;
  // Four notches of 0.8 on the clearance above the ~3,700 m summit: ~22,500 m.
  const double height = loggedHeightMeters(run.output);
  EXPECT_GT(height, 0) << run.output;
  EXPECT_LT(height, 30000) << run.output;
}

TEST(GlobeViewWindow, IdleWindowUsesAlmostNoCpu) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-idle",
      globeView("--size 1280x720 --log --camera 138.60,35.20,3000,30,-12,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "sleep 0.5\n"
          "read -r _ _ _ _ _ _ _ _ _ _ _ _ _ u0 s0 _ < /proc/$PID/stat\n"
          "sleep 3\n"
          "read -r _ _ _ _ _ _ _ _ _ _ _ _ _ u1 s1 _ < /proc/$PID/stat\n"
          "echo idle_ticks=$((u1 + s1 - u0 - s0))\n"
          "echo ticks_per_second=$(getconf CLK_TCK)\n"
          "echo busy_ticks=$((u0 + s0))\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("idle_ticks"), 1u) << run.output;
  EXPECT_NE(run.output.find("view complete"), std::string::npos) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const double tick = 1.0 / std::stod(values.at("ticks_per_second"));
  const double idleSeconds = std::stod(values.at("idle_ticks")) * tick;
  std::printf("CPU while loading and drawing: %.2f s; during 3 s idle: %.2f s\n",
              std::stod(values.at("busy_ticks")) * tick, idleSeconds);
  RecordProperty("idle_cpu_seconds", std::to_string(idleSeconds));
  EXPECT_LT(idleSeconds, 0.3) << run.output;
}

TEST(GlobeViewWindow, NoDisplayIsAClearError) {
  const ShellRun run = runShell("env -u DISPLAY -u WAYLAND_DISPLAY " + globeView("--frames 1"));
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find("no display"), std::string::npos) << run.output;
}

}  // namespace

namespace {

// The controller runs every frame in the window: a camera started 100 m above the ellipsoid at
// Mount Fuji's summit (3,731 m of drawn surface) is raised out of the terrain and stays above it.
TEST(GlobeViewWindow, CameraBelowTheTerrainIsRaisedAboveTheDrawnSurface) {
  SKIP_WITHOUT("xvfb-run");
  const ShellRun run = runUnderXvfb(
      "view-collision",
      globeView("--size 320x180 --frames 40 --log --camera 138.7275,35.3606,100,0,-10,0"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const double height = loggedHeightMeters("\n" + run.output);
  const ShellRun ground =
      runShell("echo 138.7275,35.3606 | " + std::string(GLOBE_EXE) + " query " +
               globe::tiler::testing::bundledPyramid().string() + " --mode exact");
  ASSERT_EQ(ground.exitCode, 0) << ground.output;
  double lon = 0, lat = 0, level = 0, surface = 0;
  ASSERT_EQ(std::sscanf(ground.output.c_str(), "%lf,%lf,%lf,%lf", &lon, &lat, &level, &surface), 4);
  EXPECT_GT(surface, 3700);
  EXPECT_GE(height, surface + 1.0) << "the hard floor is 1 m above the drawn surface";
  EXPECT_LE(height, surface + 2.5) << "raised to the clearance, not launched";
}

}  // namespace
