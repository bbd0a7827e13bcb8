// One frame of scripted playback up to the drawing: the path's pose through the collision
// controller against complete views. Shared by `globe play` and the soak tool (globe-soak).
#pragma once

#include <vector>

#include <chrono>
#include <filesystem>
#include <memory>

#include "surface/pyramid_surface.hpp"
#include "apps/globe/play_log.hpp"
#include "camera/camera_controller.hpp"
#include "camera/camera_path.hpp"
#include "scene/terrain_scene.hpp"
#include "scene/tile_gpu.hpp"

namespace globe::app {

// A pyramid's scene and a path file's camera path, as both `globe play` and the soak run them.
struct ScriptedPlayback {
  std::unique_ptr<scene::TerrainScene> scene;
  camera::CameraPath path;
};

// Reads the path file (.json or .kml) and opens the pyramid with the selection's hysteresis off
// (each view then depends on its pose only, not on the load order); heights above the terrain
// are resolved against the pyramid. Errors name the file.
Result<ScriptedPlayback> openScriptedPlayback(const std::filesystem::path& pyramid,
                                              const std::filesystem::path& pathFile,
                                              scene::SceneOptions sceneOptions);

// Frames i = 0, 1, ... with i / fps <= durationSeconds (1e-9 frames of slack for rounding), as
// a double so that callers can refuse absurd counts before converting.
double playbackFrameCount(double durationSeconds, double framesPerSecond);

class PlaybackStep {
 public:
  // The controller starts at the path's start pose with the near plane of a widthPixels x
  // heightPixels view, gliding over the ground the path goes over next unless glide is false
  // (the paper's response alone). realTime: frames draw what has arrived instead of waiting for
  // complete views (see frame()). The scene, GPU and path must outlive this.
  PlaybackStep(scene::TerrainScene& scene, scene::TileGpu& gpu, const camera::CameraPath& path,
               int widthPixels, int heightPixels, std::chrono::seconds viewTimeout,
               bool glide = true, bool realTime = false);

  // Makes the view at the scripted start complete: call once before the first frame, so the first
  // collision test runs against a complete array.
  Result<void> start(FrameTimings& timings);

  // One frame at path time `timeSeconds`, `dtSeconds` after the previous one (0 for the first):
  // the scripted pose is proposed (as `kind`: Auto, or Jump where a looping path starts over) and
  // checked against the previous frame's complete array; the view for the corrected pose is
  // completed and the controller run again with dt = 0 until it keeps the pose (the floor and the
  // near-plane push over finer terrain). The record has everything but tilesDrawn and the draw
  // and write timings; the scene's array is then exactly the one to draw. In real time, the view
  // is updated once with what has arrived (as a window draws it) and the controller run once
  // against it: tiles that arrive late show here, as lifts.
  Result<FrameRecord> frame(int frameIndex, double timeSeconds, double dtSeconds,
                            camera::MotionKind kind = camera::MotionKind::Auto);

  const camera::CameraController& controller() const { return controller_; }

 private:
  Result<void> completeView(const camera::CameraPose& pose, FrameTimings& timings);
  // newView: the array changed since the move was checked (its lift is newGroundLiftMeters).
  void collide(double dtSeconds, FrameRecord& record, bool newView = false);
  // The pose, the surface under it and the clearances, into the record.
  Result<FrameRecord> finishRecord(FrameRecord record);
  // The controller's near plane for the scene's field of view (which a path's "fov" changes).
  void setNearPlane();
  // Where the script takes the camera over the glide's look-ahead (camera/terrain_glide.hpp).
  std::vector<camera::GlidePoint> scriptAhead(double timeSeconds) const;

  scene::TerrainScene& scene_;
  scene::TileGpu& gpu_;
  const camera::CameraPath& path_;
  int widthPixels_, heightPixels_;
  std::chrono::seconds viewTimeout_;
  bool realTime_;
  bool groundBefore_ = false;
  size_t missingTiles_ = 0;  // the last view's FrameInfo::missingTiles  // this frame's move ended over ground the checked array held
  surface::PyramidSurface finestSurface_;  // the log's height where no drawn tile lies below
  camera::CameraController controller_;
};

}  // namespace globe::app
