// `globe play --export-camera FILE`: the camera of every rendered frame (after the collision
// response: what was drawn), for compositing programs and scripts, by FILE's extension:
//   .json  {"frames": [{"t", "lon", "lat", "height", "heading", "pitch", "roll", "fovDeg",
//          "ecef": [x, y, z], "quaternion": [w, x, y, z]}], ...}: geodetic and ECEF (metres),
//          the quaternion rotating camera axes (x right, y up, z back: OpenGL's) into ECEF;
//   .csv   the same fields, one row a frame;
//   .jsx   an Adobe After Effects script: a composition at the frames' size and rate with a
//          two-node camera (position, point of interest, Z rotation (the roll) and zoom (from
//          the vertical field of view drawn) keyed on every frame) and a null for each path target and for
//          the origin, in a local frame: east-north-up at the ground under the first frame's
//          camera, in metres, as AE's axes (x east, y down, z north).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "apps/globe/play_log.hpp"
#include "core/result.hpp"
#include "geo/ellipsoid.hpp"

namespace globe::app {

struct CameraTrackSettings {
  double framesPerSecond = 30;
  int widthPixels = 1280, heightPixels = 720;
  std::vector<glm::dvec3> targetsEcefMeters;  // the path's targets (nulls in the .jsx)
};

// Whether the extension is one the export writes (.json, .csv, .jsx, any case); else an error
// naming the file and the three.
Result<void> checkCameraTrackPath(const std::filesystem::path& file);

// The track's text for `file`'s format.
Result<std::string> formatCameraTrack(const std::filesystem::path& file,
                                      const std::vector<FrameRecord>& frames,
                                      const CameraTrackSettings& settings,
                                      const geo::Ellipsoid& ellipsoid);

}  // namespace globe::app
