// The long-run soak of scripted playback (globe-soak): `globe play`'s per-frame step, the path
// looped for up to millions of frames, with the camera's drift between loops, the process's
// memory and the streaming counters measured along the way. Nothing is drawn.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "core/result.hpp"
#include "scene/terrain_scene.hpp"
#include "streaming/block_cache.hpp"
#include "streaming/tile_loader.hpp"

namespace globe::soak {

struct SoakOptions {
  std::filesystem::path pyramid;
  std::filesystem::path pathFile;  // .json or .kml, as `globe play`
  int64_t frames = 1'000'000;
  double framesPerSecond = 30;
  int widthPixels = 1280, heightPixels = 720;  // the view tiles are selected for
  scene::SceneOptions scene;
  int64_t memorySampleFrames = 1000;  // VmRSS is read every this many frames
  std::vector<int64_t> checkpoints;   // frame counts to report at (the last frame always is)
  int timeoutSeconds = 300;           // for each view to complete
};

// The state after `frames` frames.
struct SoakCheckpoint {
  int64_t frames = 0;
  double wallSeconds = 0;
  // Every frame of a later loop against the same frame of the first: the largest distance
  // between the two eye positions (ECEF) and the largest heading, pitch or roll difference.
  double maximumDriftMeters = 0;
  double maximumDriftRadians = 0;
  int64_t framesDrifted = 0;  // later-loop frames whose pose is not bit-identical to the first's
  int64_t collisionFrames = 0;
  // Frames the controller changed: collided, or lifted off the script by the glide (> 1 cm).
  int64_t responseFrames = 0;
  double minimumClearanceMeters = 0;
  size_t residentBytes = 0;      // VmRSS now
  size_t peakResidentBytes = 0;  // VmHWM
  // The most VmRSS sampled after the first loop, and VmRSS at its end (0 before it ends).
  size_t maximumResidentAfterFirstLoopBytes = 0;
  size_t residentAfterFirstLoopBytes = 0;
  streaming::LoaderCounters loader;
  streaming::BlockCacheCounters cache;
  size_t cacheBudgetBytes = 0;
  uint32_t gpuTiles = 0;
  uint64_t gpuBytes = 0;
};

struct SoakReport {
  int64_t framesPerLoop = 0;
  std::vector<SoakCheckpoint> checkpoints;  // in frame order, the last at options.frames
};

// Frame k shows the path at start + (k mod framesPerLoop) / fps, computed from the integer frame
// number (never accumulated), where framesPerLoop is `globe play`'s frame count for the path; the
// first frame of every later loop is proposed as a jump (the camera teleports back to the start),
// every other frame as in `globe play`, dt = 1 / fps. So frame k and frame k + framesPerLoop
// propose the same pose from the same state: any difference is drift. onCheckpoint (optional) is
// called as each checkpoint is reached. Errors: as `globe play` (path, pyramid, GL, a view that
// does not complete), a path whose loop is shorter than 2 frames, no /proc/self/status.
Result<SoakReport> runSoak(const SoakOptions& options,
                           const std::function<void(const SoakCheckpoint&)>& onCheckpoint = {});

}  // namespace globe::soak
