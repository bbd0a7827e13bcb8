// Scripted pose → controller against the complete array → complete view for the corrected pose →
// settle → the frame's record (terrain under the camera, clearances).
#include "apps/globe/playback_step.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "apps/globe/elapsed.hpp"
#include "apps/globe/path_conversion.hpp"
#include "camera/camera_path_file.hpp"
#include "collision/exact_surface.hpp"

namespace globe::app {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kMaximumSettleRounds = 8;

// The finest terrain the pyramid has, for keyframes above the terrain (0 m where it cannot be
// read: the path was checked at its keyframes when it was opened).
camera::TerrainHeightAt terrainOf(scene::TerrainScene& scene) {
  return [&scene](double longitudeRadians, double latitudeRadians) {
    const auto height = scene.terrainHeightMeters(longitudeRadians, latitudeRadians);
    return height ? *height : 0.0;
  };
}

// A scripted path proposes absolute poses: the controller can glide over the ground ahead.
camera::ControllerSettings playbackSettings(bool glide) {
  camera::ControllerSettings settings;
  settings.glide.enabled = glide;
  return settings;
}

}  // namespace

Result<ScriptedPlayback> openScriptedPlayback(const std::filesystem::path& pyramid,
                                              const std::filesystem::path& pathFile,
                                              scene::SceneOptions sceneOptions) {
  auto file = camera::readCameraPath(pathFile);
  if (!file) return Error{file.error()};
  sceneOptions.hysteresis = false;
  auto scene = scene::TerrainScene::open(pyramid, sceneOptions);
  if (!scene) return Error{scene.error()};
  auto path = toCameraPath(
      *file, [&](double lon, double lat) { return (*scene)->terrainHeightMeters(lon, lat); },
      (*scene)->ellipsoid());
  if (!path) return makeError(pathFile.string() + ": " + path.error());
  return ScriptedPlayback{std::move(*scene), std::move(*path)};
}

double playbackFrameCount(double durationSeconds, double framesPerSecond) {
  return std::floor(durationSeconds * framesPerSecond + 1e-9) + 1;
}

PlaybackStep::PlaybackStep(scene::TerrainScene& scene, scene::TileGpu& gpu,
                           const camera::CameraPath& path, int widthPixels, int heightPixels,
                           std::chrono::seconds viewTimeout, bool glide, bool realTime)
    : scene_(scene),
      gpu_(gpu),
      path_(path),
      widthPixels_(widthPixels),
      heightPixels_(heightPixels),
      viewTimeout_(viewTimeout),
      realTime_(realTime),
      finestSurface_(scene.store(), scene.ellipsoid()),
      controller_(
          camera::samplePath(path, path.startSeconds(), scene.ellipsoid(), terrainOf(scene)),
          playbackSettings(glide)) {
  if (const auto sunTime = camera::sampleSunTime(path, path.startSeconds())) {
    scene.setSunTime(sunTime);
  }
  if (const auto fovY = camera::sampleFovY(path, path.startSeconds())) scene.setFovY(*fovY);
  setNearPlane();
}

Result<void> PlaybackStep::start(FrameTimings& timings) {
  return completeView(controller_.pose(), timings);
}

Result<void> PlaybackStep::completeView(const camera::CameraPose& pose, FrameTimings& timings) {
  const auto until = Clock::now() + viewTimeout_;
  for (;;) {
    const auto start = Clock::now();
    const scene::FrameInfo info = scene_.update(pose, widthPixels_, heightPixels_, gpu_);
    timings.selectMs += millisecondsSince(start);
    missingTiles_ = info.missingTiles;
    if (info.complete) return {};
    if (Clock::now() > until) {
      return makeError("the view was not complete after " + std::to_string(viewTimeout_.count()) +
                       " s (" + std::to_string(info.requests) + " tiles still wanted)");
    }
    const auto wait = Clock::now();
    scene_.waitForLoads(std::chrono::milliseconds(50));
    timings.loadMs += millisecondsSince(wait);
  }
}

std::vector<camera::GlidePoint> PlaybackStep::scriptAhead(double timeSeconds) const {
  const camera::GlideSettings& glide = controller_.settings().glide;
  std::vector<camera::GlidePoint> ahead;
  const camera::TerrainHeightAt terrain = terrainOf(scene_);
  const int samples = std::max(glide.samples, 1);
  for (int k = 1; k <= samples; ++k) {
    const double t = glide.lookAheadSeconds * k / samples;
    // Past its end the path stays at its last pose.
    const double at = std::min(timeSeconds + t, path_.endSeconds());
    ahead.push_back({camera::samplePath(path_, at, scene_.ellipsoid(), terrain).position, t});
  }
  return ahead;
}

void PlaybackStep::collide(double dtSeconds, FrameRecord& record, bool newView) {
  const auto start = Clock::now();
  const double heightBefore = controller_.pose().position.heightMeters;
  const camera::CollisionState& state =
      controller_.update(dtSeconds, scene_.renderingTileArray(), scene_.ellipsoid());
  record.timings.collisionMs += millisecondsSince(start);
  // With dt 0 nothing moves but the floor and the near-plane push: a lift by the new view's ground.
  if (newView && groundBefore_) {
    record.newGroundLiftMeters +=
        std::max(0.0, controller_.pose().position.heightMeters - heightBefore);
  }
  record.collided = record.collided || state.collided;
  if (record.response == collision::Response::None) record.response = state.response;
}

Result<FrameRecord> PlaybackStep::frame(int frameIndex, double timeSeconds, double dtSeconds,
                                        camera::MotionKind kind) {
  const geo::Ellipsoid& ellipsoid = scene_.ellipsoid();
  FrameRecord record;
  record.frame = frameIndex;
  record.timeSeconds = timeSeconds;
  // Keyframes with a "time" move the Sun through the flight (else --time's, or none, stays).
  if (const auto sunTime = camera::sampleSunTime(path_, timeSeconds)) scene_.setSunTime(sunTime);
  // Keyframes with a "fov" zoom: the view and the controller's near plane take it.
  if (const auto fovY = camera::sampleFovY(path_, timeSeconds)) {
    scene_.setFovY(*fovY);
    setNearPlane();
  }
  const camera::CameraPose scripted =
      camera::samplePath(path_, timeSeconds, ellipsoid, terrainOf(scene_));
  record.scriptedHeightMeters = scripted.position.heightMeters;
  // The move, against the array drawn last frame (complete, so the same on every run), gliding
  // over the ground where the script goes next.
  controller_.propose(scripted, kind, scriptAhead(timeSeconds));
  collide(dtSeconds, record);
  // Whether the array the move was checked against held ground where the camera went: only then
  // is a lift by the next view's ground a change of the ground under it (a pop). Ground the last
  // array did not hold there (the camera slid out of its view) is new, not changed.
  const camera::CameraPose moved = controller_.pose();
  groundBefore_ =
      collision::exactSurfaceHeight(scene_.renderingTileArray(), ellipsoid,
                                    moved.position.longitudeRadians, moved.position.latitudeRadians)
          .has_value();
  if (realTime_) {
    const auto start = Clock::now();
    missingTiles_ =
        scene_.update(controller_.pose(), widthPixels_, heightPixels_, gpu_).missingTiles;
    record.timings.selectMs += millisecondsSince(start);
    collide(0.0, record, true);
    return finishRecord(std::move(record));
  }
  // The view for the corrected pose, and the controller once more against that array (dt 0:
  // the floor and the near-plane push only) until it keeps the pose.
  bool settled = false;
  for (int round = 0; round < kMaximumSettleRounds && !settled; ++round) {
    if (auto view = completeView(controller_.pose(), record.timings); !view) {
      return Error{view.error()};
    }
    const camera::CameraPose before = controller_.pose();
    collide(0.0, record, true);
    settled = camera::samePose(before, controller_.pose());
  }
  if (!settled) {
    if (auto view = completeView(controller_.pose(), record.timings); !view) {
      return Error{view.error()};
    }
  }
  return finishRecord(std::move(record));
}

void PlaybackStep::setNearPlane() {
  const double fovY = scene_.options().fovYRadians;
  controller_.setNearPlane(
      {camera::projectionForHeight(0, controller_.settings().clearance.eyeMeters, fovY, 1,
                                   scene_.ellipsoid())
           .nearMeters,
       fovY, static_cast<double>(widthPixels_) / std::max(heightPixels_, 1)});
}

Result<FrameRecord> PlaybackStep::finishRecord(FrameRecord record) {
  const geo::Ellipsoid& ellipsoid = scene_.ellipsoid();
  record.pose = controller_.pose();
  // The field of view drawn: from the view's own projection (y scale = 1 / tan(fov / 2)).
  record.fovYDegrees = geo::radiansToDegrees(2.0 * std::atan(1.0 / scene_.view().projection[1][1]));
  record.missingTiles = missingTiles_;
  const auto surfaceHeight = collision::exactSurfaceHeight(scene_.renderingTileArray(), ellipsoid,
                                                           record.pose.position.longitudeRadians,
                                                           record.pose.position.latitudeRadians);
  if (surfaceHeight) {
    record.terrainHeightMeters = surfaceHeight->heightMeters;
    const std::vector<geo::TileId>& drawn = scene_.tiles();
    record.terrainSource = std::find(drawn.begin(), drawn.end(), surfaceHeight->tile) != drawn.end()
                               ? TerrainSource::Drawn
                               : TerrainSource::Nadir;
  } else {
    record.terrainSource = TerrainSource::Finest;
    auto finest = finestSurface_.heightMeters(record.pose.position.longitudeRadians,
                                              record.pose.position.latitudeRadians);
    if (!finest) return Error{finest.error()};
    record.terrainHeightMeters = *finest;
  }
  // The ground the camera is kept above: a tileset's roof where one stands higher (--tileset).
  if (const terrain::SurfaceOverlay* overlay = scene_.renderingTileArray().overlay()) {
    const auto roof = overlay->heightAt(record.pose.position.longitudeRadians,
                                        record.pose.position.latitudeRadians);
    if (roof) record.terrainHeightMeters = std::max(record.terrainHeightMeters, *roof);
  }
  record.clearanceMeters = record.pose.position.heightMeters - record.terrainHeightMeters;
  record.nearClearanceMeters = controller_.state().nearPlaneClearanceMeters;
  return record;
}

}  // namespace globe::app
