// Records the flown camera path (P in `globe view`) as keyframes: one every ~0.5 s of motion, at
// each stop and start, and at the end; written as the path JSON `globe play` reads.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "camera/camera_path_file.hpp"
#include "camera/camera_pose.hpp"

namespace globe::app {

struct PathKeyframe {
  double tSeconds = 0;  // since the recording started
  camera::CameraPose pose;
};

class PathRecorder {
 public:
  static constexpr double kIntervalSeconds = 0.5;
  static constexpr double kGapSeconds = 0.25;    // no sample for this long: it stood still
  static constexpr double kResumeSeconds = 0.1;  // a move after a pause began this long before

  bool recording() const { return recording_; }
  const std::vector<PathKeyframe>& keyframes() const { return keyframes_; }

  // Starts a new recording at time `nowSeconds` (any clock) with the pose as keyframe 0.
  void start(double nowSeconds, const camera::CameraPose& pose);
  // The camera's pose at `nowSeconds`; keyframes are taken while it moves every kIntervalSeconds,
  // where it stops, and where it starts again after standing still (so the pause is kept). The
  // keyframes' times only grow; one within 1 ms of the last replaces it.
  void sample(double nowSeconds, const camera::CameraPose& pose);
  // Ends the recording with the pose at `nowSeconds` as the last keyframe (so at least two);
  // returns the keyframes.
  std::vector<PathKeyframe> stop(double nowSeconds, const camera::CameraPose& pose);

 private:
  void append(double nowSeconds, const camera::CameraPose& pose);

  bool recording_ = false;
  double startSeconds_ = 0;
  std::vector<PathKeyframe> keyframes_;
  camera::CameraPose last_{};  // the pose of the last sample
  double lastSeconds_ = 0;
  bool moving_ = false;
};

// The keyframes as a smooth camera path (degrees, metres, seconds; longitude in [-180, 180],
// heading in [0, 360)), for io::writeCameraPathJson.
camera::CameraPathFile recordedPathFile(const std::vector<PathKeyframe>& keyframes);

// `prefix`-YYYYMMDD-HHMMSS`extension` in `directory` (local time now); "-2", "-3", ... added
// before the extension when such a file exists already.
std::filesystem::path timestampedPath(const std::filesystem::path& directory,
                                      const std::string& prefix, const std::string& extension);

}  // namespace globe::app
