// Keyframes from the camera's motion, as a camera path file, and time-stamped file names.
#include "apps/globe/path_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <numbers>
#include <system_error>

namespace globe::app {
namespace {

double headingDegrees0To360(double radians) {
  double degrees = std::fmod(geo::radiansToDegrees(radians), 360.0);
  if (degrees < 0) degrees += 360.0;
  return degrees >= 360.0 ? 0.0 : degrees;
}

}  // namespace

void PathRecorder::start(double nowSeconds, const camera::CameraPose& pose) {
  recording_ = true;
  startSeconds_ = nowSeconds;
  keyframes_.clear();
  keyframes_.push_back({0.0, pose});
  last_ = pose;
  lastSeconds_ = nowSeconds;
  moving_ = false;
}

void PathRecorder::append(double nowSeconds, const camera::CameraPose& pose) {
  const double t = nowSeconds - startSeconds_;
  if (!keyframes_.empty() && t <= keyframes_.back().tSeconds + 1e-3) {
    // Not after the last one: within 1 ms it replaces it, earlier ones are dropped.
    if (t >= keyframes_.back().tSeconds - 1e-3) keyframes_.back().pose = pose;
    return;
  }
  keyframes_.push_back({t, pose});
}

void PathRecorder::sample(double nowSeconds, const camera::CameraPose& pose) {
  if (!recording_) return;
  const bool moved = !camera::samePose(pose, last_);
  // The loop samples only while something happens: a long gap means the camera stood still.
  const bool gap = nowSeconds - lastSeconds_ > kGapSeconds;
  if (moved && (!moving_ || gap)) {
    // Moving again after standing still: hold the old pose until the motion resumed.
    append(lastSeconds_, last_);
    append(std::max(lastSeconds_, nowSeconds - kResumeSeconds), last_);
  } else if (!moved && moving_) {
    append(nowSeconds, pose);  // a stop
  }
  if (moved && nowSeconds - startSeconds_ >= keyframes_.back().tSeconds + kIntervalSeconds) {
    append(nowSeconds, pose);
  }
  moving_ = moved;
  last_ = pose;
  lastSeconds_ = nowSeconds;
}

std::vector<PathKeyframe> PathRecorder::stop(double nowSeconds, const camera::CameraPose& pose) {
  if (!recording_) return {};
  sample(nowSeconds, pose);
  append(nowSeconds, pose);  // the path lasts until it was stopped
  recording_ = false;
  return std::move(keyframes_);
}

camera::CameraPathFile recordedPathFile(const std::vector<PathKeyframe>& keyframes) {
  camera::CameraPathFile file;
  file.interpolation = "smooth";
  for (const PathKeyframe& keyframe : keyframes) {
    const camera::CameraPose& p = keyframe.pose;
    camera::PathKeyframe key;
    key.timeSeconds = keyframe.tSeconds;
    key.longitudeDegrees =
        geo::radiansToDegrees(geo::wrapLongitudeRadians(p.position.longitudeRadians));
    key.latitudeDegrees = p.position.latitudeDegrees();
    key.heightMeters = p.position.heightMeters;
    key.headingDegrees = headingDegrees0To360(p.headingRadians);
    key.pitchDegrees = geo::radiansToDegrees(p.pitchRadians);
    key.rollDegrees = geo::radiansToDegrees(p.rollRadians);
    file.keyframes.push_back(key);
  }
  return file;
}

std::filesystem::path timestampedPath(const std::filesystem::path& directory,
                                      const std::string& prefix, const std::string& extension) {
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  char stamp[32];
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  const std::string base = prefix + "-" + stamp;
  std::filesystem::path path = directory / (base + extension);
  std::error_code error;
  for (int n = 2; std::filesystem::exists(path, error) && n < 1000; ++n) {
    path = directory / (base + "-" + std::to_string(n) + extension);
  }
  return path;
}

}  // namespace globe::app
