// The soak loop: app::PlaybackStep frame after frame over a looped path, compared loop against
// loop.
#include "tools/soak/playback_soak.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "apps/globe/path_conversion.hpp"
#include "apps/globe/playback_step.hpp"
#include "apps/globe/process_memory.hpp"
#include "camera/camera_path_file.hpp"
#include "geo/ecef.hpp"
#include "tests/support/bookkeeping_gpu.hpp"

namespace globe::soak {
namespace {

using Clock = std::chrono::steady_clock;

double angleDifferenceRadians(double a, double b) {
  return std::abs(std::remainder(a - b, 2 * std::numbers::pi));
}

}  // namespace

Result<SoakReport> runSoak(const SoakOptions& options,
                           const std::function<void(const SoakCheckpoint&)>& onCheckpoint) {
  const auto runStart = Clock::now();
  if (options.frames < 1) return makeError("--frames must be at least 1");
  if (!(std::isfinite(options.framesPerSecond) && options.framesPerSecond > 0 &&
        options.framesPerSecond <= 1000)) {
    return makeError("--fps must be in (0, 1000]");
  }
  if (options.memorySampleFrames < 1) return makeError("the memory sample interval must be >= 1");
  if (!app::readProcessMemory())
    return makeError("cannot read the process memory (/proc/self/status)");
  auto playback = app::openScriptedPlayback(options.pyramid, options.pathFile, options.scene);
  if (!playback) return Error{playback.error()};
  scene::TerrainScene& scene = *playback->scene;
  const camera::CameraPath& path = playback->path;
  const double fps = options.framesPerSecond;
  const double loopFrames = app::playbackFrameCount(path.endSeconds() - path.startSeconds(), fps);
  if (!(loopFrames >= 2 && loopFrames <= 1e7)) {
    return makeError("the path must last between 2 and 10,000,000 frames at this --fps");
  }
  const auto framesPerLoop = static_cast<int64_t>(loopFrames);

  // Nothing is drawn: the GPU only keeps the books of what would be resident (meshes and
  // textures are prepared and released as in `globe play`), so no GL context is opened.
  globe::testing::BookkeepingGpu gpu;
  const geo::Ellipsoid& ellipsoid = scene.ellipsoid();
  app::PlaybackStep step(scene, gpu, path, options.widthPixels, options.heightPixels,
                         std::chrono::seconds(options.timeoutSeconds));
  app::FrameTimings startup;
  if (auto view = step.start(startup); !view) return Error{view.error()};

  std::vector<int64_t> checkpoints = options.checkpoints;
  checkpoints.push_back(options.frames);
  std::sort(checkpoints.begin(), checkpoints.end());
  checkpoints.erase(std::unique(checkpoints.begin(), checkpoints.end()), checkpoints.end());
  auto nextCheckpoint = std::upper_bound(checkpoints.begin(), checkpoints.end(), 0);

  SoakReport report;
  report.framesPerLoop = framesPerLoop;
  std::vector<camera::CameraPose> firstLoop;  // the poses of frames 0 .. framesPerLoop - 1
  firstLoop.reserve(static_cast<size_t>(std::min(framesPerLoop, options.frames)));
  SoakCheckpoint state;
  state.minimumClearanceMeters = std::numeric_limits<double>::infinity();
  for (int64_t k = 0; k < options.frames; ++k) {
    const int64_t inLoop = k % framesPerLoop;
    // Time from integers only: the same double for frame k and frame k + framesPerLoop.
    const double timeSeconds = path.startSeconds() + static_cast<double>(inLoop) / fps;
    const bool restart = k > 0 && inLoop == 0;
    auto record = step.frame(static_cast<int>(std::min<int64_t>(k, INT32_MAX)), timeSeconds,
                             k == 0 ? 0.0 : 1.0 / fps,
                             restart ? camera::MotionKind::Jump : camera::MotionKind::Auto);
    if (!record) return makeError("frame " + std::to_string(k) + ": " + record.error());
    const camera::CameraPose& pose = record->pose;
    if (k < framesPerLoop) {
      firstLoop.push_back(pose);
    } else {
      const camera::CameraPose& reference = firstLoop[static_cast<size_t>(inLoop)];
      if (!camera::samePose(pose, reference)) {
        ++state.framesDrifted;
        const double meters = glm::length(geo::cartographicToEcef(ellipsoid, pose.position) -
                                          geo::cartographicToEcef(ellipsoid, reference.position));
        const double radians =
            std::max({angleDifferenceRadians(pose.headingRadians, reference.headingRadians),
                      angleDifferenceRadians(pose.pitchRadians, reference.pitchRadians),
                      angleDifferenceRadians(pose.rollRadians, reference.rollRadians)});
        // A NaN would fail every comparison: count it as infinite drift.
        state.maximumDriftMeters =
            std::isnan(meters) ? HUGE_VAL : std::max(state.maximumDriftMeters, meters);
        state.maximumDriftRadians =
            std::isnan(radians) ? HUGE_VAL : std::max(state.maximumDriftRadians, radians);
      }
    }
    if (record->collided) ++state.collisionFrames;
    if (record->collided ||
        std::abs(record->pose.position.heightMeters - record->scriptedHeightMeters) > 0.01) {
      ++state.responseFrames;
    }
    state.minimumClearanceMeters = std::min(state.minimumClearanceMeters, record->clearanceMeters);

    const int64_t done = k + 1;
    const bool checkpoint = nextCheckpoint != checkpoints.end() && done == *nextCheckpoint;
    if (done % options.memorySampleFrames == 0 || done == framesPerLoop || checkpoint) {
      const auto memory = app::readProcessMemory();
      if (!memory) return makeError("cannot read the process memory (/proc/self/status)");
      state.residentBytes = memory->residentBytes;
      state.peakResidentBytes = memory->peakResidentBytes;
      if (done == framesPerLoop) state.residentAfterFirstLoopBytes = memory->residentBytes;
      if (done >= framesPerLoop) {
        state.maximumResidentAfterFirstLoopBytes =
            std::max(state.maximumResidentAfterFirstLoopBytes, memory->residentBytes);
      }
    }
    if (checkpoint) {
      state.frames = done;
      state.wallSeconds = std::chrono::duration<double>(Clock::now() - runStart).count();
      state.loader = scene.loader().counters();
      state.cache = scene.cache().counters();
      state.cacheBudgetBytes = scene.cache().budgetBytes();
      state.gpuTiles = static_cast<uint32_t>(gpu.tilesResident());
      state.gpuBytes = gpu.bytesResident();
      report.checkpoints.push_back(state);
      if (onCheckpoint) onCheckpoint(state);
      ++nextCheckpoint;
    }
  }
  return report;
}

}  // namespace globe::soak
