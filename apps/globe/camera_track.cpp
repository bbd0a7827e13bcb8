// The rendered camera as JSON, CSV or an After Effects script (camera_track.hpp).
#include "apps/globe/camera_track.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "camera/camera_pose.hpp"
#include "geo/ecef.hpp"

namespace globe::app {
namespace {

std::string extensionOf(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

struct TrackFrame {
  double t, lon, lat, height, heading, pitch, roll, fovYDegrees;
  glm::dvec3 ecef, forward, up;
  glm::dquat orientation;  // camera axes (x right, y up, z back) to ECEF
};

TrackFrame trackFrame(const FrameRecord& record, const geo::Ellipsoid& ellipsoid) {
  const camera::CameraPose& pose = record.pose;
  const camera::CameraFrame frame = camera::cameraFrame(ellipsoid, pose);
  double heading = geo::radiansToDegrees(pose.headingRadians);
  if (heading < 0) heading += 360.0;
  return {record.timeSeconds,
          pose.position.longitudeDegrees(),
          pose.position.latitudeDegrees(),
          pose.position.heightMeters,
          heading,
          geo::radiansToDegrees(pose.pitchRadians),
          geo::radiansToDegrees(pose.rollRadians),
          record.fovYDegrees,
          frame.positionEcefMeters,
          frame.forward,
          frame.up,
          glm::normalize(glm::quat_cast(glm::dmat3(frame.right, frame.up, -frame.forward)))};
}

std::string format(const char* pattern, auto... values) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

std::string jsonTrack(const std::vector<TrackFrame>& frames, const CameraTrackSettings& s) {
  std::string text = format("{\"fps\": %.17g, \"width\": %d, \"height\": %d, \"frames\": [\n",
                            s.framesPerSecond, s.widthPixels, s.heightPixels);
  for (size_t i = 0; i < frames.size(); ++i) {
    const TrackFrame& f = frames[i];
    text += format(
        "  {\"t\": %.17g, \"lon\": %.17g, \"lat\": %.17g, \"height\": %.17g, \"heading\": %.17g, "
        "\"pitch\": %.17g, \"roll\": %.17g, \"fovDeg\": %.17g, \"ecef\": [%.17g, %.17g, %.17g], "
        "\"quaternion\": [%.17g, %.17g, %.17g, %.17g]}%s\n",
        f.t, f.lon, f.lat, f.height, f.heading, f.pitch, f.roll, f.fovYDegrees, f.ecef.x,
        f.ecef.y, f.ecef.z, f.orientation.w, f.orientation.x, f.orientation.y, f.orientation.z,
        i + 1 < frames.size() ? "," : "");
  }
  return text + "]}\n";
}

std::string csvTrack(const std::vector<TrackFrame>& frames) {
  std::string text =
      "frame,t,lon,lat,height,heading,pitch,roll,fov_deg,ecef_x,ecef_y,ecef_z,qw,qx,qy,qz\n";
  for (size_t i = 0; i < frames.size(); ++i) {
    const TrackFrame& f = frames[i];
    text += format("%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                   "%.17g,%.17g,%.17g,%.17g\n",
                   i, f.t, f.lon, f.lat, f.height, f.heading, f.pitch, f.roll, f.fovYDegrees,
                   f.ecef.x, f.ecef.y, f.ecef.z, f.orientation.w, f.orientation.x,
                   f.orientation.y, f.orientation.z);
  }
  return text;
}

// ENU at an origin, as After Effects' axes: x east, y down, z north (metres).
struct AfterEffectsFrame {
  glm::dvec3 origin, east, north, up;
  glm::dvec3 operator()(const glm::dvec3& ecef) const {
    const glm::dvec3 d = ecef - origin;
    return {glm::dot(d, east), -glm::dot(d, up), glm::dot(d, north)};
  }
};

AfterEffectsFrame afterEffectsFrame(const FrameRecord& first, const geo::Ellipsoid& ellipsoid) {
  geo::Cartographic ground = first.pose.position;
  ground.heightMeters = 0;
  const camera::EastNorthUp enu = camera::eastNorthUp(ellipsoid, ground);
  return {geo::cartographicToEcef(ellipsoid, ground), enu.east, enu.north, enu.up};
}

std::string vector3(const glm::dvec3& v) { return format("[%.9g, %.9g, %.9g]", v.x, v.y, v.z); }

std::string jsxTrack(const std::vector<FrameRecord>& records, const std::vector<TrackFrame>& frames,
                     const CameraTrackSettings& s, const geo::Ellipsoid& ellipsoid) {
  const AfterEffectsFrame toAe = afterEffectsFrame(records.front(), ellipsoid);
  const double seconds = static_cast<double>(frames.size()) / s.framesPerSecond;
  std::string text =
      "// globe play --export-camera: the rendered camera for After Effects (File > Scripts >\n"
      "// Run Script File). Local frame: east-north-up at the ground under the first frame's\n"
      "// camera, metres, as AE's axes (x east, y down, z north).\n"
      "(function () {\n";
  text += format("  var comp = app.project.items.addComp(\"globe camera\", %d, %d, 1, %.17g, %.17g);\n",
                 s.widthPixels, s.heightPixels, std::max(seconds, 1.0 / s.framesPerSecond),
                 s.framesPerSecond);
  text += "  var camera = comp.layers.addCamera(\"globe camera\", [0, 0]);\n"
          "  camera.autoOrient = AutoOrientType.CAMERA_OR_POINT_OF_INTEREST;\n";
  text += "  var zoom = camera.property(\"ADBE Camera Options Group\").property(\"ADBE Camera Zoom\");\n";
  text += "  var position = camera.property(\"ADBE Transform Group\").property(\"ADBE Position\");\n"
          "  var interest = camera.property(\"ADBE Transform Group\").property(\"ADBE Anchor Point\");\n"
          "  var roll = camera.property(\"ADBE Transform Group\").property(\"ADBE Rotate Z\");\n"
          "  var frames = [\n";
  for (size_t i = 0; i < frames.size(); ++i) {
    const TrackFrame& f = frames[i];
    // The point of interest 1 km ahead along the view; AE's zoom is the focal length in pixels.
    const double zoom =
        0.5 * s.heightPixels / std::tan(0.5 * f.fovYDegrees * 3.14159265358979323846 / 180.0);
    text += "    [" + format("%.9g", static_cast<double>(i) / s.framesPerSecond) + ", " +
            vector3(toAe(f.ecef)) + ", " + vector3(toAe(f.ecef + 1000.0 * f.forward)) + ", " +
            format("%.9g, %.9g", f.roll, zoom) + "]" + (i + 1 < frames.size() ? ",\n" : "\n");
  }
  text += "  ];\n"
          "  for (var i = 0; i < frames.length; i++) {\n"
          "    position.setValueAtTime(frames[i][0], frames[i][1]);\n"
          "    interest.setValueAtTime(frames[i][0], frames[i][2]);\n"
          "    roll.setValueAtTime(frames[i][0], frames[i][3]);\n"
          "    zoom.setValueAtTime(frames[i][0], frames[i][4]);\n"
          "  }\n"
          "  var nulls = [[\"origin\", [0, 0, 0]]";
  for (size_t k = 0; k < s.targetsEcefMeters.size(); ++k) {
    text += format(", [\"target %zu\", ", k + 1) + vector3(toAe(s.targetsEcefMeters[k])) + "]";
  }
  text += "];\n"
          "  for (var n = 0; n < nulls.length; n++) {\n"
          "    var layer = comp.layers.addNull();\n"
          "    layer.name = nulls[n][0];\n"
          "    layer.threeDLayer = true;\n"
          "    layer.property(\"ADBE Transform Group\").property(\"ADBE Position\").setValue(nulls[n][1]);\n"
          "  }\n"
          "  comp.openInViewer();\n"
          "})();\n";
  return text;
}

}  // namespace

Result<void> checkCameraTrackPath(const std::filesystem::path& file) {
  const std::string extension = extensionOf(file);
  if (extension == ".json" || extension == ".csv" || extension == ".jsx") return {};
  return makeError(file.string() + ": --export-camera writes .json, .csv or .jsx, not '" +
                   file.extension().string() + "'");
}

Result<std::string> formatCameraTrack(const std::filesystem::path& file,
                                      const std::vector<FrameRecord>& records,
                                      const CameraTrackSettings& settings,
                                      const geo::Ellipsoid& ellipsoid) {
  if (auto checked = checkCameraTrackPath(file); !checked) return Error{checked.error()};
  if (records.empty()) return makeError(file.string() + ": no frames to export");
  std::vector<TrackFrame> frames;
  for (const FrameRecord& record : records) frames.push_back(trackFrame(record, ellipsoid));
  const std::string extension = extensionOf(file);
  if (extension == ".json") return jsonTrack(frames, settings);
  if (extension == ".csv") return csvTrack(frames);
  return jsxTrack(records, frames, settings, ellipsoid);
}

}  // namespace globe::app
