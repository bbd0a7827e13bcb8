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

#include <glm/geometric.hpp>

#include "camera/camera_pose.hpp"
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

int play(const fs::path& path, const fs::path& out) {
  const std::string command = std::string(GLOBE_EXE) + " play " +
                              globe::testing::bundledPyramid().string() + " " + path.string() +
                              " --no-frames --fps 5 --size 96x54 --out " + out.string() +
                              " > " + (out.string() + ".txt") + " 2>&1";
  return std::system(command.c_str());
}

TEST(PlayTargets, TheTargetStaysAtTheFrameCentreOnEveryFrame) {
  const fs::path dir = globe::testing::freshTempDir("play-targets");
  const std::string summit = R"("target": {"lon": 138.7274, "lat": 35.3606, "height": 3776})";
  const fs::path json = dir / "targets.json";
  std::ofstream(json) << R"({"keyframes": [
    {"t": 0, "lon": 138.62, "lat": 35.30, "height": 6000, "ease": "inOut", )" << summit << R"(},
    {"t": 6, "lon": 138.80, "lat": 35.28, "height": 5500, "roll": 4, )" << summit << R"(},
    {"t": 12, "lon": 138.80, "lat": 35.44, "height": 5000, )" << summit << "}]}";
  ASSERT_EQ(play(json, dir / "json"), 0);
  size_t frames = 0;
  EXPECT_LT(worstOffCentre(dir / "json" / "log.csv", frames), 0.3);
  EXPECT_EQ(frames, 61u);

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

}  // namespace
}  // namespace globe::app
