// `globe view`: orbit-control math, and the real window under Xvfb: a screenshot shows terrain,
// keys and the scroll wheel zoom, Escape quits, an idle window uses almost no CPU; fly mode moves
// the camera and keeps it above the terrain, the HUD is drawn, P records a path, double-click
// flies to a point, M measures and X shows the profile.
#include <gtest/gtest.h>
#include <unistd.h>
#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "camera/fly_to.hpp"
#include "camera/orbit_controls.hpp"
#include "formats/image_io.hpp"
#include "geo/ecef.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/imagery_test_layers.hpp"
#include "tests/support/nginx_server.hpp"
#include "tests/support/test_constants.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace {

using globe::camera::CameraPose;
using globe::camera::OrbitControls;

using globe::test::kWgs84;
constexpr double kFov = std::numbers::pi / 4;

TEST(OrbitControls, DragMovesTheCameraAgainstTheDragSoTheGroundFollows) {
  OrbitControls controls(kWgs84, CameraPose::fromDegrees(10, 20, 10000), kFov);
  controls.rotateByDrag(100, 0, 720);  // drag right: the ground moves right, the camera west
  EXPECT_LT(controls.pose().position.longitudeDegrees(), 10);
  EXPECT_DOUBLE_EQ(controls.pose().position.latitudeDegrees(), 20);
  // 100 px at 10 km straight down with a 45° view 720 px high: 100 · 2 · 10 km · tan 22.5° / 720.
  const double meters = 100 * 2 * 10000 * std::tan(kFov / 2) / 720;
  const double expectedDegrees = globe::geo::radiansToDegrees(
      meters / (kWgs84.semiMajorAxisMeters * std::cos(20 * std::numbers::pi / 180)));
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
  EXPECT_NEAR(controls.pose().pitchRadians, -std::numbers::pi / 2 + 0.5, 1e-12);
  controls.tiltByDrag(0, -10000);
  EXPECT_DOUBLE_EQ(controls.pose().pitchRadians, 0);
  controls.tiltByDrag(0, 10000);
  EXPECT_DOUBLE_EQ(controls.pose().pitchRadians, -std::numbers::pi / 2);
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

// Shell functions for scripts that drive `globe view --log > log.txt`: the window says "view idle"
// each time it has handled all it was sent and waits, "view busy" when it draws again, so a
// script waits for what it asked instead of sleeping. `send ARGS` runs `xdotool ARGS` and waits
// until the window has handled it and is still (60 s at most: a slow sanitizer build).
const char* kWaitHelpers =
    "idles() { grep -c '^view idle' log.txt 2>/dev/null; }\n"
    "still() { tail -n1 log.txt 2>/dev/null | grep -q '^view idle'; }\n"
    "settle() { for i in $(seq 1200); do [ \"$(idles)\" -gt \"$1\" ] 2>/dev/null && still && "
    "return 0; sleep 0.05; done; echo \"never idle after line $1\"; }\n"
    "send() { n=$(idles); xdotool \"$@\"; settle \"$n\"; }\n"
    // Until the log has $2 (default 1) lines matching $1, then until the window is still.
    "waitfor() { for i in $(seq 1200); do [ $(grep -c \"$1\" log.txt) -ge ${2:-1} ] && break; "
    "sleep 0.05; done; settle 0; }\n";

// Runs a shell script inside a fresh Xvfb; a per-process starting display number keeps tests run
// in parallel from racing for the same one.
ShellRun runUnderXvfb(const std::string& name, const std::string& script) {
  const auto dir = globe::testing::freshTempDir(name);
  const auto path = dir / "script.sh";
  std::ofstream(path) << "set -u\ncd " << dir.string() << "\n" << kWaitHelpers << script;
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
         globe::testing::bundledPyramid().string() + " " + arguments;
}

// Waits for the window, then for the view to complete and go idle (lines in the log).
const char* kFindWindow =
    "WID=$(timeout 60 xdotool search --sync --onlyvisible --name '^globe')\n"
    "echo wid=$WID\n"
    "PID=$(xdotool getwindowpid $WID)\n"
    "for i in $(seq 600); do grep -q 'view complete' log.txt && break; sleep 0.1; done\n"
    "settle 0\n";

#define SKIP_WITHOUT(program) \
  if (!onPath(program)) GTEST_SKIP() << program " is not installed"

TEST(GlobeViewWindow, ScreenshotShowsTheGlobe) {
  SKIP_WITHOUT("xvfb-run");
  const auto dir = globe::testing::freshTempDir("view-screenshot");
  const auto png = dir / "out.png";
  const ShellRun run = runUnderXvfb(
      "view-screenshot-run",
      globeView("--size 640x360 --frames 30 --camera 138,35,7000000 --screenshot " + png.string()));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  auto image = globe::formats::loadImageRgba(png);
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
          "send key --window $WID plus\nsend key --window $WID plus\n"
          "send key --window $WID KP_Add\n"
          "send mousemove --window $WID 320 180\nsend click --window $WID 4\n"
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

// The path after "wrote <what> " in the log (the file `globe view` says it wrote).
std::string writtenFile(const std::string& output, const std::string& what) {
  const std::string marker = "wrote " + what + " ";
  const size_t at = output.find(marker);
  if (at == std::string::npos) return {};
  const size_t end = output.find_first_of(" \n", at + marker.size());
  return output.substr(at + marker.size(), end - at - marker.size());
}

// The habits people bring: PgUp zooms in as + does (Google Earth), and F11 fills the screen
// (Xvfb's 1280x720): a K screenshot after it is the screen's size, and after F11 again the
// window's.
TEST(GlobeViewWindow, PageUpZoomsAndF11FillsTheScreen) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-habits");
  const ShellRun run = runUnderXvfb(
      "view-habits",
      globeView("--size 320x180 --log --record-dir " + dir.string() +
                " --camera 138.73,35.36,50000 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "for k in 1 2 3 4; do send key --window $WID Prior; done\n"
          // The window manager resizes after the key: until the window says its new size.
          "send key --window $WID F11\nwaitfor '^view size 1280x720'\n"
          "send key --window $WID k\n"
          "send key --window $WID F11\nwaitfor '^view size 320x180' 2\n"
          "send key --window $WID k\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const double height = loggedHeightMeters(run.output);
  EXPECT_GT(height, 0) << run.output;
  EXPECT_LT(height, 30000) << run.output;  // four presses of 0.8 from 50 km
  // In the order the log says they were written (two in the same second are NAME.png and
  // NAME-2.png, which sort the other way).
  std::vector<std::filesystem::path> shots;
  for (size_t at = run.output.find("wrote screenshot "); at != std::string::npos;
       at = run.output.find("wrote screenshot ", at + 1)) {
    shots.push_back(writtenFile(run.output.substr(at), "screenshot"));
  }
  ASSERT_EQ(shots.size(), 2u) << run.output;
  auto full = globe::formats::loadImageRgba(shots[0]);
  auto windowed = globe::formats::loadImageRgba(shots[1]);
  ASSERT_TRUE(full && windowed);
  EXPECT_EQ(full->widthPixels, 1280) << run.output;
  EXPECT_EQ(full->heightPixels, 720) << run.output;
  EXPECT_EQ(windowed->widthPixels, 320) << run.output;
  EXPECT_EQ(windowed->heightPixels, 180) << run.output;
}

TEST(GlobeViewWindow, IdleWindowUsesAlmostNoCpu) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-idle",
      globeView("--size 1280x720 --log --camera 138.60,35.20,3000,30,-12,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "read -r _ _ _ _ _ _ _ _ _ _ _ _ _ u0 s0 _ < /proc/$PID/stat\n"
          "sleep 3\n"  // the span the CPU time is measured over
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
  const ShellRun ground = runShell("echo 138.7275,35.3606 | " + std::string(GLOBE_EXE) + " query " +
                                   globe::testing::bundledPyramid().string() + " --mode exact");
  ASSERT_EQ(ground.exitCode, 0) << ground.output;
  double lon = 0, lat = 0, level = 0, surface = 0;
  ASSERT_EQ(std::sscanf(ground.output.c_str(), "%lf,%lf,%lf,%lf", &lon, &lat, &level, &surface), 4);
  EXPECT_GT(surface, 3700);
  EXPECT_GE(height, surface + 1.0) << "the hard floor is 1 m above the drawn surface";
  EXPECT_LE(height, surface + 2.5) << "raised to the clearance, not launched";
}

}  // namespace

namespace {

struct LoggedCamera {
  double lon = 0, lat = 0, height = -1;
  bool found = false;
};

// The "camera LON,LAT,HEIGHT,..." line `globe view --log` prints on exit.
LoggedCamera loggedCamera(const std::string& output) {
  LoggedCamera camera;
  const size_t at = ("\n" + output).find("\ncamera ");
  if (at == std::string::npos) return camera;
  camera.found = std::sscanf(output.c_str() + at, "camera %lf,%lf,%lf", &camera.lon, &camera.lat,
                             &camera.height) == 3;
  return camera;
}

// The drawn surface's height at a position, from `globe query --mode exact`.
double surfaceHeightMeters(double lon, double lat) {
  char position[64];
  std::snprintf(position, sizeof position, "%.7f,%.7f", lon, lat);
  const ShellRun ground =
      runShell("echo " + std::string(position) + " | " + std::string(GLOBE_EXE) + " query " +
               globe::testing::bundledPyramid().string() + " --mode exact");
  double qLon = 0, qLat = 0, level = 0, surface = -1e9;
  if (std::sscanf(ground.output.c_str(), "%lf,%lf,%lf,%lf", &qLon, &qLat, &level, &surface) != 4)
    ADD_FAILURE() << ground.output;
  return surface;
}


// Fly mode from 300 m above Mount Fuji's southern slope, heading north and a little down: holding
// W flies north (only north), the controller keeps the camera above the drawn surface, and with
// the key up the window idles.
TEST(GlobeViewWindow, FlyModeWFliesForwardAndStaysAboveTheTerrain) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-fly",
      globeView("--size 640x360 --log --camera 138.7275,35.25,1000,0,-5,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send key --window $WID f\n"
          "xdotool keydown --window $WID w\n"
          "sleep 1.5\n"  // W held for 1.5 s: the input itself, not a wait
          // Keys up, the camera still: fly mode and its HUD idle like orbit mode.
          "send keyup --window $WID w\n"
          "read -r _ _ _ _ _ _ _ _ _ _ _ _ _ u0 s0 _ < /proc/$PID/stat\n"
          "sleep 2\n"  // the span the CPU time is measured over
          "read -r _ _ _ _ _ _ _ _ _ _ _ _ _ u1 s1 _ < /proc/$PID/stat\n"
          "echo idle_ticks=$((u1 + s1 - u0 - s0))\n"
          "echo ticks_per_second=$(getconf CLK_TCK)\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const LoggedCamera camera = loggedCamera(run.output);
  ASSERT_TRUE(camera.found) << run.output;
  const double northMeters = (camera.lat - 35.25) * 111000;
  std::printf("flew %.0f m north in fly mode; %.1f m above the surface\n", northMeters,
              camera.height - surfaceHeightMeters(camera.lon, camera.lat));
  RecordProperty("fly_north_meters", std::to_string(northMeters));
  EXPECT_GT(northMeters, 100) << "about 300 m/s for 1.5 s: hundreds of metres\n" << run.output;
  EXPECT_NEAR(camera.lon, 138.7275, 1e-5) << "heading north: no sideways motion\n" << run.output;
  EXPECT_LT(camera.height, 1000) << "pitched 5 deg down: lower\n" << run.output;
  EXPECT_GE(camera.height, surfaceHeightMeters(camera.lon, camera.lat) + 1.0) << run.output;
  ASSERT_EQ(values.count("idle_ticks"), 1u) << run.output;
  const double idleSeconds =
      std::stod(values.at("idle_ticks")) / std::stod(values.at("ticks_per_second"));
  std::printf("CPU during 2 s idle in fly mode: %.2f s\n", idleSeconds);
  EXPECT_LT(idleSeconds, 0.2) << run.output;
}

// The imagery keys change what is drawn: 1 hides the Blue Marble layer (the hypsometric ramp
// shows), L L cycles the lighting auto -> on -> off (the mountains lose their shading). Each run
// writes the terrain without the HUD on exit (--screenshot).
TEST(GlobeViewWindow, LayerAndLightingKeysChangeTheFrame) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-imagery-keys");
  const auto shotAfter = [&](const std::string& name, const std::string& keys) {
    const auto png = dir / (name + ".png");
    const ShellRun run = runUnderXvfb(
        "view-imagery-keys-" + name,
        globeView("--size 320x180 --log --layer " + globe::testing::blueMarbleLayer().string() +
                  " --camera 138.60,35.20,6000,30,-15,0 --screenshot " + png.string() +
                  " > log.txt &\n") +
            "VIEW=$!\n" + kFindWindow + "for k in " + keys + "; do send key --window $WID $k; done\n" +
            "xdotool keydown --window $WID Escape\nwait $VIEW; echo exit=$?\n");
    EXPECT_EQ(valuesOf(run.output)["exit"], "0") << run.output;
    auto image = globe::formats::loadImageRgba(png);
    EXPECT_TRUE(image) << image.error() << run.output;
    return image ? *image : globe::formats::ImageRgba{};
  };
  // Pixels with a channel off by more than 4.
  const auto differing = [](const globe::formats::ImageRgba& a,
                            const globe::formats::ImageRgba& b) {
    size_t count = 0;
    for (size_t k = 0; k + 3 < std::min(a.pixels.size(), b.pixels.size()); k += 4) {
      for (size_t c = 0; c < 3; ++c) {
        if (std::abs(int(a.pixels[k + c]) - int(b.pixels[k + c])) > 4) {
          ++count;
          break;
        }
      }
    }
    return count;
  };
  const auto draped = shotAfter("auto", "");
  const auto hidden = shotAfter("hidden", "1");
  const auto unlit = shotAfter("off", "l l");
  ASSERT_EQ(draped.pixels.size(), size_t{320 * 180 * 4});
  const size_t pixels = 320 * 180;
  std::printf("pixels changed: layer hidden %zu, lighting off %zu of %zu\n",
              differing(draped, hidden), differing(draped, unlit), pixels);
  EXPECT_GT(differing(draped, hidden), pixels / 4) << "the ramp instead of Blue Marble";
  EXPECT_GT(differing(draped, unlit), pixels / 100) << "the relief's shading gone";
}

// V then a name saves the view; `globe views` lists it, exports it as KML and imports it
// elsewhere; `--view NAME` draws it as `--camera` with the same numbers does.
TEST(GlobeViewWindow, VSavesTheViewByNameAndItComesBack) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-saved");
  const std::string config = "XDG_CONFIG_HOME=" + (dir / "config").string() + " ";
  const ShellRun run = runUnderXvfb(
      "view-saved",
      "export " + config + "\n" +
          globeView("--size 320x180 --log --camera 138.60,35.20,15000,30,-40,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send key --window $WID v\n"
          "send type --window $WID --delay 30 'Fuji south'\n"
          "send key --window $WID Return\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  EXPECT_EQ(valuesOf(run.output)["exit"], "0") << run.output;
  EXPECT_NE(run.output.find("saved view Fuji south"), std::string::npos) << run.output;
  const auto globe = [&](const std::string& env, const std::string& arguments) {
    return runShell(env + std::string(GLOBE_EXE) + " " + arguments);
  };
  const ShellRun listed = globe(config, "views --json");
  ASSERT_EQ(listed.exitCode, 0) << listed.output;
  const auto json = nlohmann::json::parse(listed.output.substr(listed.output.find('{')));
  ASSERT_EQ(json["views"].size(), 1u) << listed.output;
  EXPECT_EQ(json["views"][0]["name"], "Fuji south");
  const auto& c = json["views"][0]["camera"];
  EXPECT_NEAR(c[0].get<double>(), 138.60, 1e-6) << listed.output;
  EXPECT_NEAR(c[2].get<double>(), 15000, 1) << listed.output;
  EXPECT_NEAR(c[3].get<double>(), 30, 1e-3) << listed.output;
  // Out as KML, into another user's views.
  const std::string kml = (dir / "views.kml").string();
  ASSERT_EQ(globe(config, "views --export " + kml).exitCode, 0);
  const std::string other = "XDG_CONFIG_HOME=" + (dir / "other").string() + " ";
  const ShellRun imported = globe(other, "views --import " + kml);
  ASSERT_EQ(imported.exitCode, 0) << imported.output;
  EXPECT_NE(globe(other, "views").output.find("Fuji south"), std::string::npos);
  // --view draws what --camera with its numbers draws.
  char camera[200];
  std::snprintf(camera, sizeof camera, "%.9f,%.9f,%.4f,%.9f,%.9f,%.9f", c[0].get<double>(),
                c[1].get<double>(), c[2].get<double>(), c[3].get<double>(), c[4].get<double>(),
                c[5].get<double>());
  const std::string pyramid = globe::testing::bundledPyramid().string();
  ASSERT_EQ(globe(other, "snapshot " + pyramid + " --view 'fuji SOUTH' --size 320x180 -o " +
                             (dir / "a.png").string())
                .exitCode,
            0);
  ASSERT_EQ(globe("", "snapshot " + pyramid + " --camera " + camera + " --size 320x180 -o " +
                          (dir / "b.png").string())
                .exitCode,
            0);
  auto a = globe::formats::loadImageRgba(dir / "a.png");
  auto b = globe::formats::loadImageRgba(dir / "b.png");
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->pixels, b->pixels);
  const ShellRun missing = globe(other, "snapshot " + pyramid + " --view Nowhere -o x.png");
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.output.find("Fuji south"), std::string::npos) << missing.output;
}

// A message in the HUD ("saved view …") goes by itself after 5 s, the idle window waking for it.
TEST(GlobeViewWindow, AMessageGoesAfterFiveSeconds) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-message");
  const ShellRun run = runUnderXvfb(
      "view-message",
      "export XDG_CONFIG_HOME=" + (dir / "config").string() + "\n" +
          globeView("--size 320x180 --log --camera 138.60,35.20,15000,30,-40,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send key --window $WID v\n"
          "send type --window $WID --delay 30 'Fuji'\n"
          "send key --window $WID Return\n"
          "waitfor '^message expired: saved view'\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  EXPECT_EQ(valuesOf(run.output)["exit"], "0") << run.output;
  EXPECT_NE(run.output.find("message expired: saved view \"Fuji\""), std::string::npos)
      << run.output;
}

// A server failing shows in the window, not only on stderr: with one level's packs answered
// HTTP 500 the HUD says what the server said ("! URL: HTTP 500; drawing coarser tiles there"),
// a line more of text than the same view from a healthy server (60 rows against 51).
TEST(GlobeViewWindow, AFailingServerIsSaidInTheHud) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-network");
  std::filesystem::create_directories(dir / "www");
  std::filesystem::copy(globe::testing::bundledPyramid(), dir / "www/pyramid",
                        std::filesystem::copy_options::recursive);
  auto server =
      globe::testing::NginxServer::start({dir / "www", "location /pyramid/L9/ { return 500; }"});
  ASSERT_TRUE(server);
  const auto shotOf = [&](const std::string& name, const std::string& url) {
    const auto record = dir / name;
    std::filesystem::create_directories(record);
    const ShellRun run = runUnderXvfb(
        "view-network-" + name,
        "timeout 120 " + std::string(GLOBE_EXE) + " view " + url +
            " --size 640x360 --log --http-timeout 5 --cache-dir " + (record / "cache").string() +
            " --record-dir " + record.string() +
            " --camera 138.73,35.36,30000,0,-60,0 > log.txt 2>&1 &\n"
            "VIEW=$!\n" +
            kFindWindow + "send key --window $WID k\n"
            "xdotool keydown --window $WID Escape\n"
            "wait $VIEW; echo exit=$?\n"
            "cat log.txt\n");
    EXPECT_EQ(valuesOf(run.output)["exit"], "0") << run.output;
    auto image = globe::formats::loadImageRgba(writtenFile(run.output, "screenshot"));
    EXPECT_TRUE(image) << image.error() << run.output;
    return std::pair{image ? *image : globe::formats::ImageRgba{}, run.output};
  };
  const auto [failing, failingLog] = shotOf("failing", server->url("/pyramid"));
  const auto [healthy, healthyLog] = shotOf("healthy", (dir / "www/pyramid").string());
  EXPECT_NE(failingLog.find("HTTP 500"), std::string::npos) << failingLog;  // stderr too
  // Text rows (a row with white text pixels) in the status area, top left.
  const auto textRows = [](const globe::formats::ImageRgba& image) {
    size_t rows = 0;
    for (int y = 0; y < std::min(image.heightPixels, 300); ++y) {
      size_t white = 0;
      for (int x = 0; x < 400; ++x) {
        const uint8_t* p = &image.pixels[static_cast<size_t>(y * image.widthPixels + x) * 4];
        if (p[0] >= 220 && p[1] >= 220 && p[2] >= 150) ++white;
      }
      rows += white > 2 ? 1 : 0;
    }
    return rows;
  };
  std::printf("status text rows: failing server %zu, healthy %zu\n", textRows(failing),
              textRows(healthy));
  EXPECT_GE(textRows(failing), textRows(healthy) + 6) << "the server's error, a line more";
}

// H shows the help and K takes a screenshot with the HUD: its top-left corner has text where the
// same view without the HUD (--screenshot on exit) has none.
TEST(GlobeViewWindow, HudIsDrawnAndKTakesAScreenshot) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-hud-shots");
  const auto plain = dir / "plain.png";
  const ShellRun run = runUnderXvfb(
      "view-hud",
      globeView("--size 640x360 --log --record-dir " + dir.string() + " --screenshot " +
                plain.string() + " --camera 138.73,35.36,50000 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send key --window $WID h\n"
          "send key --window $WID k\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const std::string shot = writtenFile(run.output, "screenshot");
  ASSERT_FALSE(shot.empty()) << run.output;
  EXPECT_EQ(std::filesystem::path(shot).parent_path(), dir) << shot;
  EXPECT_EQ(std::filesystem::path(shot).filename().string().substr(0, 11), "globe-shot-") << shot;
  auto withHud = globe::formats::loadImageRgba(shot);
  auto without = globe::formats::loadImageRgba(plain);
  ASSERT_TRUE(withHud) << withHud.error();
  ASSERT_TRUE(without) << without.error();
  ASSERT_EQ(withHud->widthPixels, 640);
  ASSERT_EQ(without->widthPixels, 640);
  // Text pixels (white status, light-yellow help) in the status and the help areas.
  const auto textPixels = [](const globe::formats::ImageRgba& image, int y0, int y1) {
    size_t count = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = 0; x < 400; ++x) {
        const uint8_t* p = &image.pixels[static_cast<size_t>(y * image.widthPixels + x) * 4];
        if (p[0] >= 220 && p[1] >= 220 && p[2] >= 150) ++count;
      }
    }
    return count;
  };
  std::printf("text pixels with the HUD: status %zu, help %zu; without: %zu, %zu\n",
              textPixels(*withHud, 0, 100), textPixels(*withHud, 110, 280),
              textPixels(*without, 0, 100), textPixels(*without, 110, 280));
  EXPECT_GT(textPixels(*withHud, 0, 100), textPixels(*without, 0, 100) + 500) << run.output;
  EXPECT_GT(textPixels(*withHud, 110, 280), textPixels(*without, 110, 280) + 500) << run.output;
  size_t differing = 0;
  for (size_t k = 0; k < withHud->pixels.size(); k += 4) {
    if (std::abs(withHud->pixels[k] - without->pixels[k]) > 40) ++differing;
  }
  EXPECT_GT(differing, 5000u) << "the HUD's boxes darken the corner";
  EXPECT_LT(differing, 640u * 360 / 2) << "the rest of the view is the same";
}

// A layer's attribution is drawn at the HUD's bottom right: a K screenshot with an XYZ layer
// that names its source against one of the same layer that names none.
TEST(GlobeViewWindow, TheHudShowsTheLayersAttribution) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-attribution");
  const std::string tiles =
      std::string(GLOBE_SOURCE_DIR) +
      "/tests/data/interop/raster-tiles/xyz-osm-carto-world-z0-3/{z}/{x}/{y}.png";
  const auto shot = [&](const std::string& name, const std::string& layer) {
    const auto record = dir / name;
    std::filesystem::create_directories(record);
    const ShellRun run = runUnderXvfb(
        "view-attribution-" + name,
        globeView("--size 640x360 --log --record-dir " + record.string() + " --layer '" + layer +
                  "' --camera 138.73,35.36,3000000 > log.txt &\n") +
            "VIEW=$!\n" + kFindWindow +
            "send key --window $WID k\n"
            "xdotool keydown --window $WID Escape\n"
            "wait $VIEW; echo exit=$?\n"
            "cat log.txt\n");
    EXPECT_EQ(valuesOf(run.output)["exit"], "0") << run.output;
    auto image = globe::formats::loadImageRgba(writtenFile(run.output, "screenshot"));
    EXPECT_TRUE(image) << image.error() << run.output;
    return image ? *image : globe::formats::ImageRgba{};
  };
  const auto named = shot("named", "xyz:" + tiles + "?attribution=OpenStreetMap%20contributors");
  const auto unnamed = shot("unnamed", "xyz:" + tiles);
  ASSERT_EQ(named.pixels.size(), size_t{640 * 360 * 4});
  ASSERT_EQ(unnamed.pixels.size(), named.pixels.size());
  // Pixels that differ, in the bottom-right corner and elsewhere (but the status lines).
  size_t corner = 0, elsewhere = 0;
  for (int y = 0; y < 360; ++y) {
    for (int x = 0; x < 640; ++x) {
      const size_t k = static_cast<size_t>(y * 640 + x) * 4;
      if (std::abs(named.pixels[k] - unnamed.pixels[k]) <= 40) continue;
      if (x < 400 && y < 110) continue;  // the status lines: timings differ from run to run
      (x >= 320 && y >= 320 ? corner : elsewhere) += 1;
    }
  }
  std::printf("attribution: %zu pixels differ in the corner, %zu elsewhere\n", corner, elsewhere);
  EXPECT_GT(corner, 100u) << "the attribution's text in the bottom-right corner";
  EXPECT_LT(elsewhere, 200u) << "the rest of the view is the same";
}

// P starts recording, W flies, P stops and writes a path file `globe play` reads.
TEST(GlobeViewWindow, PRecordsTheFlownPathAsJson) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-record-paths");
  const ShellRun run = runUnderXvfb(
      "view-record",
      globeView("--size 640x360 --log --record-dir " + dir.string() +
                " --camera 138.60,35.20,2500,0,0,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send key --window $WID Tab\n"
          "send key --window $WID p\n"
          "xdotool keydown --window $WID w\n"
          "sleep 1.2\n"  // W held for 1.2 s: the input itself, not a wait
          "send keyup --window $WID w\n"
          "send key --window $WID p\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const std::string file = writtenFile(run.output, "path");
  ASSERT_FALSE(file.empty()) << run.output;
  EXPECT_EQ(std::filesystem::path(file).parent_path(), dir) << file;
  const std::string name = std::filesystem::path(file).filename().string();
  EXPECT_EQ(name.size(), std::string("globe-path-YYYYMMDD-HHMMSS.json").size()) << name;
  std::ifstream in(file);
  const auto json = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(json.is_discarded()) << file;
  EXPECT_EQ(json.at("interpolation"), "smooth");
  const auto& keyframes = json.at("keyframes");
  ASSERT_GE(keyframes.size(), 2u) << json.dump();
  for (size_t k = 0; k < keyframes.size(); ++k) {
    for (const char* field : {"t", "lon", "lat", "height", "heading", "pitch", "roll"})
      EXPECT_TRUE(keyframes[k].at(field).is_number()) << field;
    if (k > 0) {
      EXPECT_GT(keyframes[k].at("t"), keyframes[k - 1].at("t")) << json.dump();
    }
  }
  EXPECT_DOUBLE_EQ(keyframes.front().at("t").get<double>(), 0.0);
  EXPECT_NEAR(keyframes.front().at("lat").get<double>(), 35.20, 1e-6) << json.dump();
  EXPECT_GT(keyframes.back().at("lat").get<double>(), 35.21) << "flew north\n" << json.dump();
  EXPECT_NEAR(keyframes.back().at("lon").get<double>(), 138.60, 1e-5) << json.dump();
}

// The scroll wheel zooms toward the ground under the cursor (Google Earth, CesiumJS): with the
// cursor up and right of the centre of a straight-down view, the camera comes down and moves
// north-east, toward the point, not straight down.
TEST(GlobeViewWindow, ScrollZoomsTowardTheCursor) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-zoom-cursor",
      globeView("--size 640x360 --log --camera 138.5,35.2,60000,0,-90,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send mousemove --window $WID 560 60\n"
          "for k in 1 2 3 4; do send click --window $WID 4; done\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const LoggedCamera camera = loggedCamera(run.output);
  ASSERT_TRUE(camera.found) << run.output;
  EXPECT_GT(camera.lon, 138.55) << "toward the cursor (east)\n" << run.output;
  EXPECT_GT(camera.lat, 35.22) << "toward the cursor (north)\n" << run.output;
  EXPECT_LT(camera.height, 40000) << run.output;
}

// Middle-drag and Ctrl + left-drag turn the view as right-drag does (CesiumJS, Google Earth).
TEST(GlobeViewWindow, MiddleAndCtrlDragTurnTheViewAsRightDragDoes) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  for (const auto& [name, press, release] :
       {std::tuple<std::string, std::string, std::string>{"middle", "mousedown --window $WID 2",
                                                          "mouseup --window $WID 2"},
        {"ctrl", "keydown --window $WID ctrl mousedown --window $WID 1",
         "mouseup --window $WID 1 keyup --window $WID ctrl"}}) {
    SCOPED_TRACE(name);
    const ShellRun run = runUnderXvfb(
        "view-turn-" + name,
        globeView("--size 640x360 --log --camera 138.60,35.20,15000,30,-40,0 > log.txt &\n") +
            "VIEW=$!\n" + kFindWindow +
            "send mousemove --window $WID 320 180\nsend " + press +
            "\n"
            "for x in 340 360 380 400 420; do send mousemove --window $WID $x 170; done\n"
            "send " +
            release + "\n" +
            "xdotool keydown --window $WID Escape\n"
            "wait $VIEW; echo exit=$?\n"
            "cat log.txt\n");
    const auto values = valuesOf(run.output);
    ASSERT_EQ(values.count("exit"), 1u) << run.output;
    EXPECT_EQ(values.at("exit"), "0") << run.output;
    const size_t at = ("\n" + run.output).find("\ncamera ");
    ASSERT_NE(at, std::string::npos) << run.output;
    double lon = 0, lat = 0, height = 0, heading = 0, pitch = 0;
    ASSERT_EQ(std::sscanf(run.output.c_str() + at, "camera %lf,%lf,%lf,%lf,%lf", &lon, &lat,
                          &height, &heading, &pitch),
              5)
        << run.output;
    EXPECT_GT(heading, 40) << "the drag turned the view\n" << run.output;
  }
}

// Right-drag tilts and turns about the ground point at the centre of the view (Google Earth,
// CesiumJS): that point stays at the centre while the camera swings round it.
TEST(GlobeViewWindow, RightDragTurnsAboutTheCentreGroundPoint) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-tilt-pivot",
      globeView("--size 640x360 --log --camera 138.60,35.20,15000,30,-40,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send mousemove --window $WID 320 180\nsend mousedown --window $WID 3\n"
          "for x in 340 360 380 400 420; do send mousemove --window $WID $x 170; done\n"
          "send mouseup --window $WID 3\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const size_t at = ("\n" + run.output).find("\ncamera ");
  ASSERT_NE(at, std::string::npos) << run.output;
  double lon = 0, lat = 0, height = 0, heading = 0, pitch = 0;
  ASSERT_EQ(std::sscanf(run.output.c_str() + at, "camera %lf,%lf,%lf,%lf,%lf", &lon, &lat, &height,
                        &heading, &pitch),
            5)
      << run.output;
  const CameraPose start = CameraPose::fromDegrees(138.60, 35.20, 15000, 30, -40, 0);
  const CameraPose end = CameraPose::fromDegrees(lon, lat, height, heading, pitch, 0);
  EXPECT_GT(heading, 40) << "the drag turned the view\n" << run.output;
  // The centre ray's ground point, on the surface at the height of the start's centre point
  // (found by a few rounds of `globe query`): the same point before and after.
  const globe::geo::Ellipsoid wgs84 = globe::geo::Ellipsoid::wgs84();
  const auto centreGround = [&](const CameraPose& pose, double groundMeters) {
    const auto frame = globe::camera::cameraFrame(wgs84, pose);
    return globe::camera::intersectTerrain(wgs84, frame.positionEcefMeters, frame.forward,
                                           [&](double, double) { return groundMeters; });
  };
  double ground = 0;
  for (int round = 0; round < 4; ++round) {
    const auto point = centreGround(start, ground);
    ASSERT_TRUE(point);
    const auto cartographic = globe::geo::ecefToCartographic(wgs84, *point);
    ASSERT_TRUE(cartographic);
    ground = surfaceHeightMeters(cartographic->longitudeDegrees(), cartographic->latitudeDegrees());
  }
  const auto before = centreGround(start, ground), after = centreGround(end, ground);
  ASSERT_TRUE(before && after);
  const double moved = glm::distance(*before, *after);
  const double camera = glm::distance(globe::camera::cameraFrame(wgs84, start).positionEcefMeters,
                                      globe::camera::cameraFrame(wgs84, end).positionEcefMeters);
  EXPECT_GT(camera, 2000) << "the camera swung round the point\n" << run.output;
  EXPECT_LT(moved, 150) << "the centre's ground point stayed (within the pivot's terrain)\n"
                        << run.output;
}

// "Go to": G, a place name, Enter: the camera flies there (it ends ~15 km from the place, looking
// at it), from Mount Fuji to Zion; a typo is said on the HUD and nothing moves.
TEST(GlobeViewWindow, GoToReachesThePlace) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-go-to",
      globeView("--size 640x360 --log --camera 138.73,35.36,50000 > log.txt &\n") + "VIEW=$!\n" +
          kFindWindow +
          "send key --window $WID g\n"
          "send type --window $WID --delay 30 'Angels Landing'\n"
          // Enter, then until the flight there is over (the window said where it goes and is
          // still again): typing may still be in the window's queue when `send` returns.
          "n=$(idles); xdotool key --window $WID Return\n"
          "waitfor '^go to '; settle $n\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  EXPECT_NE(run.output.find("go to Angels Landing, US (37.26920, -112.94800)"), std::string::npos)
      << run.output;
  const LoggedCamera camera = loggedCamera(run.output);
  ASSERT_TRUE(camera.found) << run.output;
  // ~15 km from Angels Landing: within 0.2 degrees of it, and above the ground.
  EXPECT_NEAR(camera.lat, 37.2692, 0.2) << run.output;
  EXPECT_NEAR(camera.lon, -112.9480, 0.2) << run.output;
  EXPECT_GT(camera.height, 3000) << run.output;
}

// The compass (top right) shows where north is; a click on it turns the view north up about the
// ground at the centre.
TEST(GlobeViewWindow, CompassClickTurnsNorthUp) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-compass",
      globeView("--size 640x360 --log --camera 138.60,35.20,15000,120,-40,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send mousemove --window $WID 610 16\nsend click --window $WID 1\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const size_t at = ("\n" + run.output).find("\ncamera ");
  ASSERT_NE(at, std::string::npos) << run.output;
  double lon = 0, lat = 0, height = 0, heading = -1;
  ASSERT_EQ(
      std::sscanf(run.output.c_str() + at, "camera %lf,%lf,%lf,%lf", &lon, &lat, &height, &heading),
      4)
      << run.output;
  EXPECT_LT(std::min(heading, 360 - heading), 1.0) << "north up\n" << run.output;
}

// In orbit mode a double-click flies towards the point under the cursor (up and right of the
// centre: north-east) and closer to it.
TEST(GlobeViewWindow, DoubleClickFliesToThePoint) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const ShellRun run = runUnderXvfb(
      "view-double-click",
      globeView("--size 640x360 --log --camera 138.5,35.2,60000,0,-90,0 > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send mousemove --window $WID 480 90\n"
          // The flight starts at the second click: until a "view busy" and then idle again.
          "B=$(grep -c '^view busy' log.txt)\n"
          "xdotool click --window $WID --repeat 2 --delay 80 1\n"
          "for i in $(seq 1200); do [ \"$(grep -c '^view busy' log.txt)\" -gt \"$B\" ] && still "
          "&& break; sleep 0.05; done\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  const LoggedCamera camera = loggedCamera(run.output);
  ASSERT_TRUE(camera.found) << run.output;
  EXPECT_GT(camera.lon, 138.6) << run.output;
  EXPECT_GT(camera.lat, 35.25) << run.output;
  EXPECT_LT(camera.height, 30000) << "0.3 of the way from 60 km up\n" << run.output;
  EXPECT_GE(camera.height, surfaceHeightMeters(camera.lon, camera.lat) + 1.0) << run.output;
}

}  // namespace

// Overlays in the window: a click on a placemark's icon names it (and opens its panel), O opens
// a GeoJSON file whose polygon is then drawn, and a click inside the polygon picks it.
TEST(GlobeViewWindow, ClickPicksPlacemarksAndOOpensAnOverlayFile) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-overlays");
  const auto kml = dir / "summit.kml";
  std::ofstream(kml) << R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2"><Document>
<Placemark><name>Summit marker</name><description>Straight below the camera</description>
<Point><coordinates>138.73,35.36,0</coordinates></Point></Placemark>
</Document></kml>)";
  // South-west of the centre: about 80 px left of and 50 px below it at 20 km.
  const auto geojson = dir / "square.geojson";
  std::ofstream(geojson) << R"({"type": "FeatureCollection", "features": [{"type": "Feature",
  "properties": {"name": "Test square", "fill": "#ff00ff", "fill-opacity": 1.0},
  "geometry": {"type": "Polygon", "coordinates": [[[138.68, 35.33], [138.70, 35.33],
  [138.70, 35.35], [138.68, 35.35], [138.68, 35.33]]]}}]})";
  const auto shot = dir / "final.png";
  const ShellRun run = runUnderXvfb(
      "view-overlays-run",
      globeView("--size 640x360 --log --camera 138.73,35.36,20000,0,-90,0 --overlay " +
                kml.string() + " --screenshot " + shot.string() + " > log.txt &\n") +
          "VIEW=$!\n" + kFindWindow +
          "send mousemove --window $WID 320 180\nsend click --window $WID 1\n"
          "send key --window $WID o\n"
          "send type --window $WID '" +
          geojson.string() +
          "'\n"
          "send key --window $WID Return\n"
          "send mousemove --window $WID 241 228\nsend click --window $WID 1\n"
          "xdotool keydown --window $WID Escape\n"
          "wait $VIEW; echo exit=$?\n"
          "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;
  EXPECT_NE(run.output.find("placemark: Summit marker"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("opened square.geojson"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("placemark: Test square"), std::string::npos) << run.output;
  auto image = globe::formats::loadImageRgba(shot);
  ASSERT_TRUE(image) << image.error();
  const auto count = [&](int x0, int y0, int x1, int y1, auto&& test) {
    size_t n = 0;
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        n += test(&image->pixels[static_cast<size_t>(y * image->widthPixels + x) * 4]);
      }
    }
    return n;
  };
  const auto magenta = [](const uint8_t* p) { return p[0] > 180 && p[1] < 90 && p[2] > 180; };
  EXPECT_GT(count(221, 208, 261, 248, magenta), 800u) << "the opened polygon is drawn";
  EXPECT_EQ(count(300, 0, 640, 360, magenta), 0u) << "and nowhere east of it";
  // The picked placemark's panel at the right edge under the compass rose (which ends 64 px
  // down): its name in white on a dark box.
  const auto white = [](const uint8_t* p) { return p[0] > 235 && p[1] > 235 && p[2] > 235; };
  const auto dark = [](const uint8_t* p) { return p[0] < 60 && p[1] < 60 && p[2] < 60; };
  EXPECT_GT(count(440, 66, 640, 260, white), 40u);
  EXPECT_GT(count(440, 66, 640, 260, dark), 1000u);
}

// The ruler (M) and the elevation chart (X): two clicks 200 px apart measure the geodesic between
// the ground points clicked, four and a click back on the first close a ring whose area is the
// quadrilateral's, Backspace reopens it then removes a point, X draws the chart at the bottom left
// and M ends the ruler.
TEST(GlobeViewWindow, MMeasuresClickedPointsAndXShowsTheirProfile) {
  SKIP_WITHOUT("xvfb-run");
  SKIP_WITHOUT("xdotool");
  const auto dir = globe::testing::freshTempDir("view-ruler");
  const std::string shoot =
      "send key --window $WID k\n"
      "waitfor 'wrote screenshot' $SHOTS; SHOTS=$((SHOTS + 1))\n";
  const ShellRun run = runUnderXvfb(
      "view-ruler-run", globeView("--size 640x360 --log --record-dir " + dir.string() +
                                  " --camera 138.73,35.36,20000,0,-90,0 > log.txt &\n") +
                            "VIEW=$!\n" + kFindWindow +
                            "send key --window $WID m\n"
                            "send mousemove --window $WID 220 180\nsend click --window $WID 1\n"
                            "waitfor '^ruler: 1 points' 1\n"
                            "send mousemove --window $WID 420 180\nsend click --window $WID 1\n"
                            "waitfor '^ruler: 2 points' 1\n"
                            "send mousemove --window $WID 420 80\nsend click --window $WID 1\n"
                            "waitfor '^ruler: 3 points' 1\n"
                            "send mousemove --window $WID 220 80\nsend click --window $WID 1\n"
                            "waitfor '^ruler: 4 points' 1\n"
                            "send mousemove --window $WID 222 181\nsend click --window $WID 1\n"
                            "waitfor 'area' 1\n"
                            "send key --window $WID BackSpace\n"
                            "waitfor '^ruler: 4 points' 3\n"
                            "send key --window $WID BackSpace\n"
                            "waitfor '^ruler: 3 points' 2\n" +
                            "SHOTS=1\n" + shoot +
                            "send key --window $WID x\n"
                            "waitfor '^profile: ' 1\n" +
                            shoot +
                            "send key --window $WID m\n"
                            "waitfor '^ruler: 0 points' 1\n" +
                            shoot +
                            "xdotool keydown --window $WID Escape\n"
                            "wait $VIEW; echo exit=$?\n"
                            "cat log.txt\n");
  const auto values = valuesOf(run.output);
  ASSERT_EQ(values.count("exit"), 1u) << run.output;
  EXPECT_EQ(values.at("exit"), "0") << run.output;

  // The points clicked and each "ruler: N points, L m[, area A m2]" line, in order.
  std::vector<std::array<double, 2>> points;
  struct Measure {
    int points;
    double lengthMeters, areaSquareMeters;
  };
  std::vector<Measure> measures;
  for (size_t at = 0; at < run.output.size();) {
    const size_t end = std::min(run.output.find('\n', at), run.output.size());
    const std::string line = run.output.substr(at, end - at);
    at = end + 1;
    int n = 0;
    double lon = 0, lat = 0, length = 0, area = -1;
    if (std::sscanf(line.c_str(), "ruler point %d: %lf,%lf", &n, &lon, &lat) == 3) {
      points.push_back({lon, lat});
    } else if (std::sscanf(line.c_str(), "ruler: %d points, %lf m, area %lf m2", &n, &length,
                           &area) >= 2) {
      measures.push_back({n, length, area});
    }
  }
  ASSERT_EQ(points.size(), 4u) << run.output;
  ASSERT_EQ(measures.size(), 8u) << run.output;
  const GeographicLib::Geodesic& wgs84 = GeographicLib::Geodesic::WGS84();
  const auto distance = [&](const std::array<double, 2>& a, const std::array<double, 2>& b) {
    double meters = 0;
    wgs84.Inverse(a[1], a[0], b[1], b[0], meters);
    return meters;
  };
  // Two points 200 px apart at ~40 m a pixel; the length is their geodesic's.
  EXPECT_EQ(measures[1].points, 2);
  const double expected = distance(points[0], points[1]);
  std::printf("two points: %.1f m, GeographicLib %.1f m\n", measures[1].lengthMeters, expected);
  EXPECT_GT(expected, 5000);
  EXPECT_LT(expected, 12000);
  EXPECT_NEAR(measures[1].lengthMeters, expected, expected * 0.01);
  // The closed ring: its perimeter, and the area of the quadrilateral on a local plane.
  const Measure& ring = measures[4];
  EXPECT_EQ(ring.points, 4);
  ASSERT_GT(ring.areaSquareMeters, 0) << run.output;
  double perimeter = 0, twiceArea = 0;
  const double metersPerDegreeLat = 110'950, lat0 = points[0][1] * std::numbers::pi / 180;
  const double metersPerDegreeLon = 111'320 * std::cos(lat0) * 1.0011;  // WGS84's N at 35 N
  for (size_t i = 0; i < 4; ++i) {
    const auto& a = points[i];
    const auto& b = points[(i + 1) % 4];
    perimeter += distance(a, b);
    twiceArea +=
        (a[0] - points[0][0]) * metersPerDegreeLon * (b[1] - points[0][1]) * metersPerDegreeLat -
        (b[0] - points[0][0]) * metersPerDegreeLon * (a[1] - points[0][1]) * metersPerDegreeLat;
  }
  std::printf("ring: %.1f m around, %.0f m2; plane %.0f m2\n", ring.lengthMeters,
              ring.areaSquareMeters, std::abs(twiceArea) / 2);
  EXPECT_NEAR(ring.lengthMeters, perimeter, perimeter * 0.01);
  EXPECT_NEAR(ring.areaSquareMeters, std::abs(twiceArea) / 2, std::abs(twiceArea) / 2 * 0.03);
  // Backspace reopened the ring, then removed its last point; M cleared it.
  EXPECT_EQ(measures[5].points, 4);
  EXPECT_LT(measures[5].areaSquareMeters, 0);
  EXPECT_EQ(measures[6].points, 3);
  EXPECT_EQ(measures[7].points, 0);
  EXPECT_EQ(measures[7].lengthMeters, 0);
  EXPECT_NE(run.output.find("profile: "), std::string::npos) << run.output;
  size_t samples = 0;
  double profileLength = 0, low = 0, high = 0;
  const size_t profileAt = run.output.find("\nprofile: ");
  ASSERT_NE(profileAt, std::string::npos) << run.output;
  ASSERT_EQ(std::sscanf(run.output.c_str() + profileAt + 1,
                        "profile: %zu samples, %lf m, min %lf m, max %lf m", &samples,
                        &profileLength, &low, &high),
            4)
      << run.output;
  EXPECT_NEAR(profileLength, measures[6].lengthMeters, 1) << "the three points' path";
  EXPECT_GT(samples, 50u);
  EXPECT_LT(low, high);
  EXPECT_GT(high, 1500) << "Fuji's flanks";

  // The screenshots before X, with the chart, and after M: the chart fills the bottom left.
  std::vector<std::string> shots;
  for (size_t at = 0; (at = run.output.find("wrote screenshot ", at)) != std::string::npos;) {
    at += 17;
    shots.push_back(run.output.substr(at, run.output.find('\n', at) - at));
  }
  ASSERT_EQ(shots.size(), 3u) << run.output;
  std::vector<globe::formats::ImageRgba> images;
  for (const std::string& shot : shots) {
    auto image = globe::formats::loadImageRgba(shot);
    ASSERT_TRUE(image) << image.error();
    images.push_back(std::move(*image));
  }
  const auto differing = [&](const globe::formats::ImageRgba& a,
                             const globe::formats::ImageRgba& b) {
    size_t n = 0;
    for (int y = 360 - 34 - 150; y < 360 - 34; ++y) {
      for (int x = 8; x < 8 + 320; ++x) {
        const size_t k = static_cast<size_t>(y * a.widthPixels + x) * 4;
        n += std::abs(a.pixels[k] - b.pixels[k]) + std::abs(a.pixels[k + 1] - b.pixels[k + 1]) +
                 std::abs(a.pixels[k + 2] - b.pixels[k + 2]) >
             60;
      }
    }
    return n;
  };
  std::printf("chart corner: %zu pixels differ with the chart, %zu after M (of %d)\n",
              differing(images[0], images[1]), differing(images[0], images[2]), 320 * 150);
  EXPECT_GT(differing(images[0], images[1]), 320u * 150 / 3) << shots[1];
  EXPECT_LT(differing(images[0], images[2]), 320u * 150 / 20) << shots[2];
}
