// Camera paths that look at a point, played by the real program over the bundled pyramid: a JSON
// path with targets and an eased segment, and a KML tour of LookAt views. On every logged frame
// (the camera as drawn) the point is at the frame's centre within 0.3°.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include <sys/wait.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "camera/camera_pose.hpp"
#include "camera/path_easing.hpp"
#include "geo/ecef.hpp"
#include "tests/apps/globe/play_log_rows.hpp"
#include "tests/support/build_paths.hpp"
#include "tests/support/tiler_test_fixture.hpp"

namespace globe::app {
namespace {

namespace fs = std::filesystem;
using test::number;
using test::readLog;

const geo::Ellipsoid kWgs84 = geo::Ellipsoid::wgs84();

// The largest angle (degrees) over the log's frames between the view and the summit.
double worstOffCentre(const fs::path& log, size_t& frames) {
  const glm::dvec3 summit =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 3776));
  const auto rows = readLog(log);
  frames = rows.size();
  double worst = 0;
  for (const auto& row : rows) {
    const camera::CameraPose pose = camera::CameraPose::fromDegrees(
        number(row, "lon_deg"), number(row, "lat_deg"), number(row, "height_m"),
        number(row, "heading_deg"), number(row, "pitch_deg"), number(row, "roll_deg"));
    const camera::CameraFrame frame = camera::cameraFrame(kWgs84, pose);
    const glm::dvec3 to = glm::normalize(summit - frame.positionEcefMeters);
    worst = std::max(worst, geo::radiansToDegrees(
                                std::acos(std::clamp(glm::dot(frame.forward, to), -1.0, 1.0))));
  }
  return worst;
}

int play(const fs::path& path, const fs::path& out, const std::string& extra = "") {
  const std::string command = std::string(GLOBE_EXE) + " play " +
                              globe::testing::bundledPyramid().string() + " " + path.string() +
                              " --no-frames --fps 5 --size 96x54 --out " + out.string() + " " +
                              extra + " > " + (out.string() + ".txt") + " 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string readText(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

const std::string kSummit = R"("target": {"lon": 138.7274, "lat": 35.3606, "height": 3776})";

fs::path writeTargetPath(const fs::path& dir) {
  const fs::path json = dir / "targets.json";
  std::ofstream(json) << R"({"keyframes": [
    {"t": 0, "lon": 138.62, "lat": 35.30, "height": 6000, "ease": "inOut", "fov": 60, )"
                      << kSummit << R"(},
    {"t": 6, "lon": 138.80, "lat": 35.28, "height": 5500, "roll": 4, )" << kSummit << R"(},
    {"t": 12, "lon": 138.80, "lat": 35.44, "height": 5000, "fov": 30, )" << kSummit << "}]}";
  return json;
}

TEST(PlayTargets, TheTargetStaysAtTheFrameCentreOnEveryFrame) {
  const fs::path dir = globe::testing::freshTempDir("play-targets");
  const fs::path json = writeTargetPath(dir);
  ASSERT_EQ(play(json, dir / "json"), 0);
  size_t frames = 0;
  EXPECT_LT(worstOffCentre(dir / "json" / "log.csv", frames), 0.3);
  EXPECT_EQ(frames, 61u);
  // The field of view drawn (from the view's projection): 60° to 30° over the path's eased time
  // (the first segment eased inOut, the second not).
  for (const auto& row : readLog(dir / "json" / "log.csv")) {
    const double t = number(row, "time_s");
    const double eased = t <= 6 ? 6 * camera::easeProgress(camera::kEaseInOut, t / 6) : t;
    EXPECT_NEAR(number(row, "fov_deg"), 60 - 30 * eased / 12, 1e-3) << "t " << t;
  }

  const fs::path kml = dir / "tour.kml";
  std::ofstream(kml) << R"(<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2" xmlns:gx="http://www.google.com/kml/ext/2.2">
<gx:Tour><gx:Playlist>)";
  for (const auto& [duration, heading, tilt, range] :
       {std::tuple{0, 30, 60, 12000}, std::tuple{5, 120, 65, 9000}, std::tuple{5, 210, 55, 11000}}) {
    std::ofstream(kml, std::ios::app)
        << "<gx:FlyTo><gx:duration>" << duration
        << "</gx:duration><gx:flyToMode>smooth</gx:flyToMode><LookAt><longitude>138.7274"
           "</longitude><latitude>35.3606</latitude><altitude>3776</altitude><heading>"
        << heading << "</heading><tilt>" << tilt << "</tilt><range>" << range
        << "</range><altitudeMode>absolute</altitudeMode></LookAt></gx:FlyTo>";
  }
  std::ofstream(kml, std::ios::app) << "</gx:Playlist></gx:Tour></kml>";
  ASSERT_EQ(play(kml, dir / "kml"), 0);
  EXPECT_LT(worstOffCentre(dir / "kml" / "log.csv", frames), 0.3);
  EXPECT_EQ(frames, 51u);
}

// A target path whose middle keyframe lies inside Fuji is lifted as every path is: the camera
// never goes under the drawn surface, and the log says where the response moved it.
TEST(PlayTargets, ATargetPathIntoTheMountainIsLifted) {
  const fs::path dir = globe::testing::freshTempDir("play-target-lift");
  const fs::path json = dir / "into.json";
  const std::string lake = R"("target": {"lon": 138.76, "lat": 35.49, "height": 1000})";
  std::ofstream(json) << R"({"keyframes": [
    {"t": 0, "lon": 138.70, "lat": 35.30, "height": 4000, )" << lake << R"(},
    {"t": 4, "lon": 138.7274, "lat": 35.3500, "height": 2500, )" << lake << R"(},
    {"t": 8, "lon": 138.75, "lat": 35.40, "height": 4000, )" << lake << "}]}";
  ASSERT_EQ(play(json, dir / "lift"), 0);
  double lifted = 0;
  for (const auto& row : readLog(dir / "lift" / "log.csv")) {
    EXPECT_GE(number(row, "clearance_m"), 0.0) << row.at("frame");
    lifted = std::max(lifted, number(row, "lift_m"));
  }
  EXPECT_GT(lifted, 100.0) << "the keyframe 2,500 m up Fuji's 3,000 m flank was lifted";
}

// An orbit shot around the summit: every frame looks at it and stays on the circle.
TEST(PlayTargets, AnOrbitShotCirclesAndWatchesItsPoint) {
  const fs::path dir = globe::testing::freshTempDir("play-orbit");
  const fs::path json = dir / "orbit.json";
  std::ofstream(json) << R"({"orbit": {"lon": 138.7274, "lat": 35.3606, "height": 3776,
    "radius": 9000, "altitude": 2500, "degrees": 360, "duration": 12}})";
  ASSERT_EQ(play(json, dir / "o"), 0);
  size_t frames = 0;
  EXPECT_LT(worstOffCentre(dir / "o" / "log.csv", frames), 0.3);
  EXPECT_EQ(frames, 61u);
  const glm::dvec3 summit =
      geo::cartographicToEcef(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 3776));
  const glm::dvec3 up =
      geo::geodeticSurfaceNormal(kWgs84, geo::Cartographic::fromDegrees(138.7274, 35.3606, 0));
  for (const auto& row : readLog(dir / "o" / "log.csv")) {
    const glm::dvec3 at = geo::cartographicToEcef(
        kWgs84, geo::Cartographic::fromDegrees(number(row, "lon_deg"), number(row, "lat_deg"),
                                               number(row, "height_m")));
    const glm::dvec3 off = at - summit;
    EXPECT_NEAR(glm::length(off - up * glm::dot(off, up)), 9000, 90) << row.at("frame");
    EXPECT_NEAR(number(row, "height_m"), 6276, 1) << row.at("frame");
  }
}

// --export-camera: the JSON track is the logged camera (geodetic as the log, ECEF and the
// quaternion consistent with it), the CSV has a row a frame, and the After Effects script runs
// (under node, with a stand-in for AE's objects that counts what it is asked) and keys its camera
// on every frame.
TEST(PlayTargets, TheExportedCameraIsTheCameraDrawn) {
  const fs::path dir = globe::testing::freshTempDir("play-export");
  const fs::path path = writeTargetPath(dir);
  ASSERT_EQ(play(path, dir / "j", "--export-camera " + (dir / "cam.json").string()), 0);
  const auto rows = readLog(dir / "j" / "log.csv");
  const auto track = nlohmann::json::parse(readText(dir / "cam.json"));
  ASSERT_EQ(track["frames"].size(), rows.size());
  EXPECT_EQ(rows.size(), 61u);
  for (size_t i = 0; i < rows.size(); ++i) {
    const auto& f = track["frames"][i];
    for (const auto& [field, column, tolerance] :
         {std::tuple{"lon", "lon_deg", 1e-7}, std::tuple{"lat", "lat_deg", 1e-7},
          std::tuple{"height", "height_m", 1e-3}, std::tuple{"heading", "heading_deg", 1e-3},
          std::tuple{"pitch", "pitch_deg", 1e-3}, std::tuple{"roll", "roll_deg", 1e-3}}) {
      EXPECT_NEAR(f[field].get<double>(), number(rows[i], column), tolerance)
          << field << " at frame " << i;
    }
    const glm::dvec3 ecef(f["ecef"][0].get<double>(), f["ecef"][1].get<double>(),
                          f["ecef"][2].get<double>());
    const glm::dvec3 expected = geo::cartographicToEcef(
        kWgs84, geo::Cartographic::fromDegrees(f["lon"].get<double>(), f["lat"].get<double>(),
                                               f["height"].get<double>()));
    EXPECT_LT(glm::length(ecef - expected), 1e-6);
    const glm::dquat q(f["quaternion"][0].get<double>(), f["quaternion"][1].get<double>(),
                       f["quaternion"][2].get<double>(), f["quaternion"][3].get<double>());
    const camera::CameraFrame frame = camera::cameraFrame(
        kWgs84, camera::CameraPose::fromDegrees(f["lon"].get<double>(), f["lat"].get<double>(),
                                                f["height"].get<double>(), f["heading"].get<double>(),
                                                f["pitch"].get<double>(), f["roll"].get<double>()));
    EXPECT_GT(glm::dot(q * glm::dvec3(0, 0, -1), frame.forward), 1.0 - 1e-9) << i;
    EXPECT_GT(glm::dot(q * glm::dvec3(0, 1, 0), frame.up), 1.0 - 1e-9) << i;
    EXPECT_NEAR(f["fovDeg"].get<double>(), number(rows[i], "fov_deg"), 1e-4);
  }

  ASSERT_EQ(play(path, dir / "c", "--export-camera " + (dir / "cam.csv").string()), 0);
  const std::string csv = readText(dir / "cam.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 62);  // the header and a row a frame

  ASSERT_EQ(play(path, dir / "x", "--export-camera " + (dir / "cam.jsx").string()), 0);
  ASSERT_EQ(std::system("command -v node > /dev/null 2>&1"), 0)
      << "node (installed for the web tests by tools/web/install.sh)";
  const fs::path runner = dir / "run-jsx.js";
  std::ofstream(runner) << R"(
const fs = require("fs");
const counts = {};
function property(name) {
  return { property: (n) => property(n),
           setValue: () => { counts[name + ".set"] = (counts[name + ".set"] || 0) + 1; },
           setValueAtTime: (t, v) => {
             if (!isFinite(t) || (Array.isArray(v) && !v.every(isFinite))) throw new Error(name);
             counts[name] = (counts[name] || 0) + 1; } };
}
function layer() { return { property: (n) => property(n) }; }
globalThis.AutoOrientType = { CAMERA_OR_POINT_OF_INTEREST: 1 };
globalThis.app = { project: { items: { addComp: () => ({
  layers: { addCamera: () => layer(),
            addNull: () => { counts.nulls = (counts.nulls || 0) + 1; return layer(); } },
  openInViewer: () => {} }) } } };
eval(fs.readFileSync(process.argv[2], "utf8"));
console.log(JSON.stringify(counts));
)";
  const fs::path counts = dir / "counts.json";
  ASSERT_EQ(std::system(("node " + runner.string() + " " + (dir / "cam.jsx").string() + " > " +
                         counts.string() + " 2>&1")
                            .c_str()),
            0)
      << readText(counts);
  const auto counted = nlohmann::json::parse(readText(counts));
  EXPECT_EQ(counted["ADBE Position"].get<int>(), 61);
  EXPECT_EQ(counted["ADBE Anchor Point"].get<int>(), 61) << "the point of interest";
  EXPECT_EQ(counted["ADBE Rotate Z"].get<int>(), 61);
  EXPECT_EQ(counted["ADBE Camera Zoom"].get<int>(), 61) << "the zoom follows the path's fov";
  EXPECT_EQ(counted["nulls"].get<int>(), 4) << "the origin and the three keyframes' targets";

  const int wrong = play(path, dir / "w", "--export-camera " + (dir / "cam.txt").string());
  EXPECT_EQ(wrong, 2);
  EXPECT_NE(readText(dir / "w.txt").find("--export-camera writes .json, .csv or .jsx, not '.txt'"),
            std::string::npos);
}

}  // namespace
}  // namespace globe::app
