// Camera path files as plain keyframes in degrees: the JSON path format (read and written) and
// Google Earth KML tours (gx:Tour of gx:FlyTo + Camera, read). Errors name the file, line, field.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "camera/path_easing.hpp"
#include "core/result.hpp"

namespace globe::camera {

// One keyframe as the file states it: seconds, degrees, metres. heightMeters is above the
// ellipsoid, or above the terrain under (lon, lat) when heightAboveTerrain (KML relativeToGround
// and clampToGround, JSON "aboveTerrain": true): the player resolves it against the pyramid.
// A point the camera looks at ("target"): heading and pitch follow it, roll is kept.
struct PathTarget {
  double longitudeDegrees = 0;
  double latitudeDegrees = 0;
  double heightMeters = 0;
  bool heightAboveTerrain = false;  // "aboveTerrain": height above the terrain there
};

struct PathKeyframe {
  double timeSeconds = 0;
  double longitudeDegrees = 0;
  double latitudeDegrees = 0;
  double heightMeters = 0;
  double headingDegrees = 0;  // 0 = north, clockwise
  double pitchDegrees = -90;  // 0 = the horizon, -90 = straight down
  double rollDegrees = 0;
  bool heightAboveTerrain = false;
  // "time": the instant the Sun lights the view at (ISO-8601 with its zone in the file; seconds
  // since 1970, UTC, here), interpolated between the keyframes that have one (--time's light).
  std::optional<double> sunUnixSeconds{};
  // "ease": how the segment leaving this keyframe runs in time (CSS's cubic Bézier; the named
  // curves linear, in, out, inOut), x1 and x2 in 0..1; none: as the path's interpolation.
  std::optional<CubicBezierEase> ease{};
  // "target": the camera looks at it here, and on every frame to the next keyframe that has one
  // (the point interpolated); the keyframe's heading and pitch are then ignored.
  std::optional<PathTarget> target{};
  // "fov": the vertical field of view here (degrees, 1..170), interpolated between the keyframes
  // that have one by the segment's eased share; none anywhere: the program's (45°).
  std::optional<double> fovDegrees{};
};

// Keyframes with strictly increasing times (at least one); interpolation "linear" or "smooth".
struct CameraPathFile {
  std::vector<PathKeyframe> keyframes;
  std::string interpolation = "smooth";
  bool logarithmicAltitude = false;  // "altitude": "logarithmic" (camera_path.hpp)
};

// The ranges every reader checks (and the messages quote).
inline constexpr double kPathMinimumHeightMeters = -11000.0;    // below the deepest trench
inline constexpr double kPathMaximumHeightMeters = 40000000.0;  // 40,000 km
inline constexpr uint64_t kPathFileMaximumBytes = uint64_t{64} << 20;

// The JSON format (docs/playback.md):
//   {"interpolation": "smooth",            optional: "linear" | "smooth" (default)
//    "altitude": "linear",                 optional: "linear" (default) | "logarithmic"
//    "description": "...",                 optional, ignored
//    "keyframes": [{"t": 0, "lon": 138.73, "lat": 35.36, "height": 5000,
//                   "heading": 0, "pitch": -20, "roll": 0, "aboveTerrain": false,
//                   "time": "2024-06-21T06:30+09:00", "ease": "inOut" | [x1, y1, x2, y2],
//                   "fov": 30,
//                   "target": {"lon": 138.73, "lat": 35.36, "height": 0,
//                              "aboveTerrain": true}}, ...]}
// t, lon, lat and height are required; heading (0), pitch (-90), roll (0) and aboveTerrain
// (false) are optional. lon in -180..180, lat in -90..90, pitch in -90..90, height in
// -11,000..40,000,000 m, every number finite, t strictly increasing. Unknown fields are errors
// (a misspelt "heigth" is not silently ignored). Errors: "FILE:LINE: keyframes[2].lat: 95 is
// outside -90..90", malformed JSON at the line of nlohmann's byte position.
Result<CameraPathFile> readCameraPathJson(const std::filesystem::path& path);

// A KML tour: the first gx:Tour's gx:Playlist, in document order. Each gx:FlyTo with a Camera
// is a keyframe: longitude, latitude (required), altitude (required unless clampToGround),
// heading (0), tilt (0; KML tilt 0 = straight down, 90 = the horizon: pitch = tilt - 90, tilt in
// 0..180), roll (0, passed through unchanged). altitudeMode (or gx:altitudeMode): absolute =
// above sea level (taken as above the ellipsoid, as the pyramid's heights are); relativeToGround
// = above the terrain; clampToGround (KML's default when absent) = on the terrain (the camera
// controller then keeps it at its eye clearance); the sea-floor modes are refused. Time: the
// first FlyTo is at t = 0 (its gx:duration is Google Earth's flight from wherever it was, and is
// ignored); each later FlyTo is its gx:duration after the previous one, and a gx:Wait holds the
// previous keyframe for its duration. Interpolation: smooth; a FlyTo with gx:flyToMode bounce
// (KML's default) stops at its view and arcs over a long way (path_generators.hpp
// withBounceArcs), a smooth one runs through it. A FlyTo holding a LookAt
// (longitude, latitude, altitude, heading, tilt 0..90, range, altitudeMode) is a keyframe whose
// camera stands `range` back from the point along heading and tilt and whose target is the
// point (camera/look_at.hpp). A zero time step (an instant jump) is refused with its line.
Result<CameraPathFile> readKmlTour(const std::filesystem::path& path);

// By extension: .json → readCameraPathJson, .kml → readKmlTour (case-insensitive).
Result<CameraPathFile> readCameraPath(const std::filesystem::path& path);

// Writes the JSON format (one keyframe per line, numbers that read back to the same double)
// atomically. Refuses (writing nothing) a path that readCameraPathJson would refuse.
Result<void> writeCameraPathJson(const std::filesystem::path& path, const CameraPathFile& file);

}  // namespace globe::camera
